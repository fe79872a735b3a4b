"""Two-view geometry: reprojection between cameras, fundamental and essential matrices,
closest points of two rays, and triangulation.

Camera-to-camera matrices map frame 1 to frame 2: ``cam1to2_ext_mat`` takes camera-1 points to
camera-2 points (``E_2 E_1^-1``), ``cam1to2_full_mat`` takes depth-scaled pixel coordinates of
camera 1 to those of camera 2 (``P_2 P_1^-1``). Both are ``[..., 3, 4]``.

Example:
    >>> ds_pixel_to_ds_pixel_coords(np.array([2., 4., 2.]), np.eye(3, 4))
    array([2., 4., 2.])
"""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework
from ivy_vision import _common as C
from ivy_vision import omnidirectional as omni
from ivy_vision._checks import InputError, checked
from ivy_vision.projective_geometry import check_invertible, invert_affine

__all__ = [
    "ds_pixel_to_ds_pixel_coords",
    "cam_to_cam_coords",
    "sphere_to_sphere_coords",
    "angular_pixel_to_angular_pixel_coords",
    "ext_mats_to_cam1to2_ext_mat",
    "full_mats_to_cam1to2_full_mat",
    "get_fundamental_matrix",
    "get_essential_matrix",
    "closest_mutual_points_along_two_skew_rays",
    "triangulate_depth",
]


@checked
def ds_pixel_to_ds_pixel_coords(
    ds_pixel_coords1: Array, cam1to2_full_mat: Array, *, f: Framework = None
) -> Array:
    """Reproject depth-scaled pixel coordinates of camera 1 into camera 2 (through the depth
    and the relative pose held by ``cam1to2_full_mat``).

    Args:
        ds_pixel_coords1: ``[u*d, v*d, d]`` in camera 1 *[batch_shape, image_shape, 3]*.
        cam1to2_full_mat: camera-1-to-camera-2 full matrices ``P_2 P_1^-1``
            *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Depth-scaled pixel coordinates in camera 2 *[batch_shape, image_shape, 3]*.

    Example:
        >>> ds_pixel_to_ds_pixel_coords(np.array([0., 0., 2.]), np.eye(3, 4) + np.eye(3, 4, 3))
        array([1., 0., 2.])
    """
    xp = ivy.get_framework(ds_pixel_coords1, cam1to2_full_mat, f=f)
    C.check_last_dim(xp, ds_pixel_coords1, 3, "ds_pixel_coords1")
    C.check_matrix(xp, cam1to2_full_mat, 3, 4, "cam1to2_full_mat")
    return C.affine(xp, ds_pixel_coords1, cam1to2_full_mat, "ds_pixel_coords1", "cam1to2_full_mat")


@checked
def cam_to_cam_coords(cam_coords1: Array, cam1to2_ext_mat: Array, *, f: Framework = None) -> Array:
    """Transform camera-1 points to homogeneous camera-2 points.

    Args:
        cam_coords1: camera-1 points *[batch_shape, image_shape, 3 or 4]*.
        cam1to2_ext_mat: camera-1-to-camera-2 extrinsic matrices *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Camera-2 points ``[x, y, z, 1]`` *[batch_shape, image_shape, 4]*.

    Example:
        >>> cam_to_cam_coords(np.array([1., 2., 3.]), np.eye(3, 4))
        array([1., 2., 3., 1.])
    """
    xp = ivy.get_framework(cam_coords1, cam1to2_ext_mat, f=f)
    C.check_last_dim(xp, cam_coords1, (3, 4), "cam_coords1")
    C.check_matrix(xp, cam1to2_ext_mat, 3, 4, "cam1to2_ext_mat")
    points = C.affine(xp, cam_coords1[..., 0:3], cam1to2_ext_mat, "cam_coords1", "cam1to2_ext_mat")
    return C.homogeneous(xp, points)


@checked
def sphere_to_sphere_coords(
    sphere_coords1: Array, cam1to2_ext_mat: Array, *, f: Framework = None
) -> Array:
    """Ego-sphere coordinates of camera 1 as seen from camera 2.

    Args:
        sphere_coords1: ``[phi, theta, r]`` in camera 1 *[batch_shape, image_shape, 3]*.
        cam1to2_ext_mat: camera-1-to-camera-2 extrinsic matrices *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Sphere coordinates in camera 2 *[batch_shape, image_shape, 3]*.

    Example:
        >>> sphere_to_sphere_coords(np.array([0., np.pi / 2, 2.]), np.eye(3, 4)) / [1, np.pi, 1]
        array([0. , 0.5, 2. ])
    """
    xp = ivy.get_framework(sphere_coords1, cam1to2_ext_mat, f=f)
    cam1 = omni.sphere_to_cam_coords(sphere_coords1, f=xp)
    return omni.cam_to_sphere_coords(cam_to_cam_coords(cam1, cam1to2_ext_mat, f=xp), f=xp)


@checked
def angular_pixel_to_angular_pixel_coords(
    angular_pixel_coords1: Array,
    cam1to2_ext_mat: Array,
    pixels_per_degree: float,
    *,
    f: Framework = None,
) -> Array:
    """Angular pixel coordinates of camera 1 as seen from camera 2.

    Args:
        angular_pixel_coords1: ``[x, y, r]`` in camera 1 *[batch_shape, image_shape, 3]*.
        cam1to2_ext_mat: camera-1-to-camera-2 extrinsic matrices *[batch_shape, 3, 4]*.
        pixels_per_degree: pixels per degree of both equirectangular images.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Angular pixel coordinates in camera 2 *[batch_shape, image_shape, 3]*.

    Example:
        >>> angular_pixel_to_angular_pixel_coords(np.array([180., 90., 1.]), np.eye(3, 4), 1.)
        array([180.,  90.,   1.])
    """
    xp = ivy.get_framework(angular_pixel_coords1, cam1to2_ext_mat, f=f)
    sphere1 = omni.angular_pixel_to_sphere_coords(angular_pixel_coords1, pixels_per_degree, f=xp)
    sphere2 = sphere_to_sphere_coords(sphere1, cam1to2_ext_mat, f=xp)
    return omni.sphere_to_angular_pixel_coords(sphere2, pixels_per_degree, f=xp)


def _compose_affine(xp, a, b):
    """``[A | a] [B | b; 0 1] = [A B | A b + a]``."""
    return xp.concat(
        [xp.matmul(a[..., 0:3], b[..., 0:3]), xp.matmul(a[..., 0:3], b[..., 3:4]) + a[..., 3:4]],
        axis=-1,
    )


@checked
def ext_mats_to_cam1to2_ext_mat(ext_mat1: Array, ext_mat2: Array, *, f: Framework = None) -> Array:
    """Camera-1-to-camera-2 extrinsic matrix ``E_2 E_1^-1`` of two extrinsic matrices.

    Args:
        ext_mat1: extrinsic matrices of camera 1 *[batch_shape, 3, 4]*.
        ext_mat2: extrinsic matrices of camera 2 *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``cam1to2_ext_mat`` *[batch_shape, 3, 4]*.

    Example:
        >>> ext_mats_to_cam1to2_ext_mat(np.eye(3, 4), np.eye(3, 4))
        array([[1., 0., 0., 0.],
               [0., 1., 0., 0.],
               [0., 0., 1., 0.]])
    """
    xp = ivy.get_framework(ext_mat1, ext_mat2, f=f)
    C.check_matrix(xp, ext_mat1, 3, 4, "ext_mat1")
    C.check_matrix(xp, ext_mat2, 3, 4, "ext_mat2")
    check_invertible(xp, ext_mat1[..., 0:3], "the rotation of ext_mat1", "it must be a rotation.")
    return _compose_affine(xp, ext_mat2, invert_affine(xp, ext_mat1))


@checked
def full_mats_to_cam1to2_full_mat(
    full_mat1: Array, full_mat2: Array, *, f: Framework = None
) -> Array:
    """Camera-1-to-camera-2 full matrix ``P_2 P_1^-1`` of two full projection matrices.

    Args:
        full_mat1: full projection matrices of camera 1 *[batch_shape, 3, 4]*.
        full_mat2: full projection matrices of camera 2 *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``cam1to2_full_mat`` *[batch_shape, 3, 4]*.

    Example:
        >>> full_mats_to_cam1to2_full_mat(np.eye(3, 4), 2 * np.eye(3, 4))[0]
        array([2., 0., 0., 0.])
    """
    xp = ivy.get_framework(full_mat1, full_mat2, f=f)
    C.check_matrix(xp, full_mat1, 3, 4, "full_mat1")
    C.check_matrix(xp, full_mat2, 3, 4, "full_mat2")
    check_invertible(
        xp,
        full_mat1[..., 0:3],
        "the left 3x3 block of full_mat1",
        "its calibration matrix needs non-zero focal lengths.",
    )
    return _compose_affine(xp, full_mat2, invert_affine(xp, full_mat1))


@checked
def get_fundamental_matrix(
    full_mat1: Array,
    full_mat2: Array,
    camera_center1: Array | None = None,
    pinv_full_mat1: Array | None = None,
    *,
    f: Framework = None,
) -> Array:
    """Fundamental matrix ``F = [e_2]_x P_2 P_1^+`` with ``x_2^T F x_1 = 0`` for corresponding
    homogeneous pixels, ``e_2 = P_2 [C_1, 1]`` the epipole in image 2.

    Args:
        full_mat1: full projection matrices of camera 1 *[batch_shape, 3, 4]*.
        full_mat2: full projection matrices of camera 2 *[batch_shape, 3, 4]*.
        camera_center1: centre of camera 1 *[batch_shape, 3]*; computed if None.
        pinv_full_mat1: pseudo-inverse of ``full_mat1`` *[batch_shape, 4, 3]*; computed if None.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Fundamental matrices *[batch_shape, 3, 3]* (rank 2, scale as computed).

    Example:
        >>> P1, P2 = np.eye(3, 4), np.eye(3, 4) - np.eye(3, 4, 3)   # camera 2 moved along +x
        >>> F = get_fundamental_matrix(P1, P2)
        >>> float(np.array([2., 1., 1.]) @ F @ np.array([1., 1., 1.]))  # same row: epipolar
        0.0
    """
    xp = ivy.get_framework(full_mat1, full_mat2, camera_center1, pinv_full_mat1, f=f)
    C.check_matrix(xp, full_mat1, 3, 4, "full_mat1")
    C.check_matrix(xp, full_mat2, 3, 4, "full_mat2")
    if camera_center1 is None:
        check_invertible(
            xp,
            full_mat1[..., 0:3],
            "the left 3x3 block of full_mat1",
            "its calibration matrix needs non-zero focal lengths.",
        )
        camera_center1 = invert_affine(xp, full_mat1)[..., 3]
    else:
        C.check_last_dim(xp, camera_center1, 3, "camera_center1")
    if pinv_full_mat1 is None:
        transposed = xp.swapaxes(full_mat1, -1, -2)
        pinv_full_mat1 = xp.matmul(transposed, xp.inv(xp.matmul(full_mat1, transposed)))
    else:
        C.check_matrix(xp, pinv_full_mat1, 4, 3, "pinv_full_mat1")
    epipole2 = xp.matvec(full_mat2[..., 0:3], camera_center1) + full_mat2[..., 3]
    skew = xp.vector_to_skew_symmetric_matrix(epipole2)
    return xp.matmul(skew, xp.matmul(full_mat2, pinv_full_mat1))


@checked
def get_essential_matrix(ext_mat1: Array, ext_mat2: Array, *, f: Framework = None) -> Array:
    """Essential matrix ``E = [t]_x R`` of the relative pose ``[R | t] = E_2 E_1^-1``, with
    ``y_2^T E y_1 = 0`` for corresponding normalised image points ``y = K^-1 x``.

    Args:
        ext_mat1: extrinsic matrices of camera 1 *[batch_shape, 3, 4]*.
        ext_mat2: extrinsic matrices of camera 2 *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Essential matrices *[batch_shape, 3, 3]*.

    Example:
        >>> get_essential_matrix(np.eye(3, 4), np.eye(3, 4) - np.eye(3, 4, 3))
        array([[ 0.,  0.,  0.],
               [ 0.,  0.,  1.],
               [ 0., -1.,  0.]])
    """
    xp = ivy.get_framework(ext_mat1, ext_mat2, f=f)
    rel = ext_mats_to_cam1to2_ext_mat(ext_mat1, ext_mat2, f=xp)
    return xp.matmul(xp.vector_to_skew_symmetric_matrix(rel[..., 3]), rel[..., 0:3])


def _check_pairs(xp, x, batch, what, batch_what) -> int:
    """Raise a ValueError unless ``x`` is ``[*batch, 2, *image_shape, 3]`` (its batch
    broadcasting with ``batch``); return the number of image dimensions."""
    nb = len(batch)
    shape = C.shape_of(xp, x)
    if len(shape) < nb + 2 or shape[nb] != 2 or shape[-1] != 3:
        raise InputError(
            f"{what} must be [*batch, 2, *image_shape, 3] with the batch shape {batch} of "
            f"{batch_what}; got shape {shape}."
        )
    C.broadcast_batch(shape[:nb], batch, what, batch_what)
    return len(shape) - nb - 2


def _rays_pair(xp, world_ray_vectors, nb):
    index = (slice(None),) * nb
    return world_ray_vectors[(*index, 0)], world_ray_vectors[(*index, 1)]


@checked
def closest_mutual_points_along_two_skew_rays(
    camera_centers: Array, world_ray_vectors: Array, *, f: Framework = None
) -> Array:
    """Closest points of pairs of rays ``C_1 + t_1 d_1`` and ``C_2 + t_2 d_2``, pixel by pixel.

    Parallel rays have no unique closest points; there the points are the camera centres.

    Args:
        camera_centers: the two ray origins *[batch_shape, 2, 3]*.
        world_ray_vectors: ray directions of two images *[batch_shape, 2, image_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Homogeneous closest points on ray 1 and on ray 2 *[batch_shape, 2, image_shape, 4]*.

    Example:
        >>> centers = np.array([[0., 0, 0], [1, 0, 0]])
        >>> rays = np.array([[[1., 1, 0]], [[0., 1, 1]]])   # skew rays
        >>> closest_mutual_points_along_two_skew_rays(centers, rays)[:, 0] * 3
        array([[2., 2., 0., 3.],
               [3., 1., 1., 3.]])
    """
    xp = ivy.get_framework(camera_centers, world_ray_vectors, f=f)
    cshape = C.shape_of(xp, camera_centers)
    if len(cshape) < 2 or cshape[-2:] != (2, 3):
        raise InputError(f"camera_centers must be [..., 2, 3]; got shape {cshape}.")
    nb = len(cshape) - 2
    ni = _check_pairs(xp, world_ray_vectors, cshape[:-2], "world_ray_vectors", "camera_centers")
    c1, c2 = camera_centers[..., 0, :], camera_centers[..., 1, :]
    c1 = xp.reshape(c1, (*cshape[:nb], *(1,) * ni, 3))
    c2 = xp.reshape(c2, (*cshape[:nb], *(1,) * ni, 3))
    d1, d2 = _rays_pair(xp, world_ray_vectors, nb)
    n = xp.cross(d1, d2)
    n1, n2 = xp.cross(d1, n), xp.cross(d2, n)
    t1 = xp.safe_divide(
        xp.sum((c2 - c1) * n2, axis=-1, keepdims=True), xp.sum(d1 * n2, axis=-1, keepdims=True)
    )
    t2 = xp.safe_divide(
        xp.sum((c1 - c2) * n1, axis=-1, keepdims=True), xp.sum(d2 * n1, axis=-1, keepdims=True)
    )
    points = xp.stack([c1 + t1 * d1, c2 + t2 * d2], axis=nb)
    return C.homogeneous(xp, points)


def _pixel_rays(xp, inv_full_mats, ds_pixel_coords, nb):
    """World directions of depth-scaled pixel coordinates ``[*B, 2, *I, 3]``."""
    ni = len(C.shape_of(xp, ds_pixel_coords)) - nb - 2
    m = inv_full_mats[..., 0:3]
    m = xp.reshape(m, (*C.shape_of(xp, m)[:-2], *(1,) * ni, 3, 3))
    return xp.matvec(m, ds_pixel_coords)


def _triangulate_cmp(xp, ds_pixel_coords, full_mats, inv_full_mats, camera_centers, nb):
    if inv_full_mats is None:
        check_invertible(
            xp,
            full_mats[..., 0:3],
            "the left 3x3 block of full_mats",
            "their calibration matrices need non-zero focal lengths.",
        )
        inv_full_mats = invert_affine(xp, full_mats)
    C.check_matrix(xp, inv_full_mats, 3, 4, "inv_full_mats")
    if camera_centers is None:
        camera_centers = inv_full_mats[..., 3]
    rays = _pixel_rays(xp, inv_full_mats, ds_pixel_coords, nb)
    points = closest_mutual_points_along_two_skew_rays(camera_centers, rays, f=xp)
    return points[(*(slice(None),) * nb, 0)]


def _triangulate_dlt(xp, ds_pixel_coords, full_mats, nb):
    index = (slice(None),) * nb
    ni = len(C.shape_of(xp, ds_pixel_coords)) - nb - 2
    pixels = xp.safe_divide(ds_pixel_coords[..., 0:2], ds_pixel_coords[..., 2:3])
    rows = []
    for cam in (0, 1):
        p = full_mats[(*index, cam)]
        p = xp.reshape(p, (*C.shape_of(xp, p)[:-2], *(1,) * ni, 3, 4))
        uv = pixels[(*index, cam)]
        rows.append(uv[..., 0:1] * p[..., 2, :] - p[..., 0, :])
        rows.append(uv[..., 1:2] * p[..., 2, :] - p[..., 1, :])
    a = xp.stack(rows, axis=-2)
    x = xp.svd(a, full_matrices=True)[2][..., -1, :]
    return xp.safe_divide(x, x[..., 3:4])


@checked
def triangulate_depth(
    ds_pixel_coords: Array,
    full_mats: Array,
    inv_full_mats: Array | None = None,
    camera_centers: Array | None = None,
    method: str = "cmp",
    *,
    f: Framework = None,
) -> Array:
    """Triangulate corresponding pixels of two cameras; return them as depth-scaled pixel
    coordinates of camera 1.

    Methods: ``'cmp'`` takes the point of the ray of camera 1 closest to the ray of camera 2
    (it keeps the pixel of camera 1 exactly); ``'dlt'`` solves the homogeneous linear system
    of both projections by SVD.

    Args:
        ds_pixel_coords: pixel coordinates ``[u, v, 1]`` (or depth-scaled, depth > 0) of both
            cameras *[batch_shape, 2, image_shape, 3]*.
        full_mats: full projection matrices of both cameras *[batch_shape, 2, 3, 4]*.
        inv_full_mats: their inverses *[batch_shape, 2, 3, 4]*; computed if None (``'cmp'``).
        camera_centers: camera centres *[batch_shape, 2, 3]*; from ``inv_full_mats`` if None.
        method: ``'cmp'`` or ``'dlt'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Depth-scaled pixel coordinates in camera 1 *[batch_shape, image_shape, 3]*.

    Example:
        >>> P = np.stack([np.eye(3, 4), np.eye(3, 4) - np.eye(3, 4, 3)])
        >>> pixels = np.array([[[0.5, 0., 1.]], [[0., 0., 1.]]])  # x = 1 / z - 1 / z: z = 2
        >>> triangulate_depth(pixels, P)
        array([[1., 0., 2.]])
    """
    xp = ivy.get_framework(ds_pixel_coords, full_mats, inv_full_mats, camera_centers, f=f)
    if method not in ("cmp", "dlt"):
        raise InputError(f"method must be 'cmp' or 'dlt'; got {method!r}.")
    fshape = C.shape_of(xp, full_mats)
    if len(fshape) < 3 or fshape[-3:] != (2, 3, 4):
        raise InputError(f"full_mats must be [..., 2, 3, 4]; got shape {fshape}.")
    nb = len(fshape) - 3
    _check_pairs(xp, ds_pixel_coords, fshape[:-3], "ds_pixel_coords", "full_mats")
    if method == "cmp":
        world = _triangulate_cmp(xp, ds_pixel_coords, full_mats, inv_full_mats, camera_centers, nb)
    else:
        world = _triangulate_dlt(xp, ds_pixel_coords, full_mats, nb)
    p1 = full_mats[(*(slice(None),) * nb, 0)]
    return C.affine(xp, world[..., 0:3], p1, "the triangulated points", "full_mats")
