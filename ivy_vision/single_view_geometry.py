"""Single-view geometry: pixel coordinates, camera matrices, projection and unprojection.

Conventions (those of the original ivy_vision, after Hartley & Zisserman):

- pixel coordinates: origin at the centre of the top-left pixel, ``x`` rightwards (the column),
  ``y`` downwards (the row); pixel ``(row i, column j)`` is at ``(x, y) = (j, i)``;
- depth-scaled homogeneous pixel coordinates ``[u*d, v*d, d]`` with ``d`` the planar depth (the
  ``z`` coordinate in the camera frame); radial depth is the distance from the camera centre;
- camera frame: ``x`` right, ``y`` down, ``z`` forward;
- calibration ``K = [[fx, 0, px], [0, fy, py], [0, 0, 1]]``, extrinsic ``E = R [I | -C]`` (world
  to camera; ``C`` the camera centre, ``R`` the world-to-camera rotation), full ``P = K E`` and
  their inverses ``K^-1``, ``E^-1 = [R^T | C]``, ``P^-1`` (the top three rows of the inverse of
  the homogeneous ``4 x 4`` matrix);
- camera and world coordinates are returned homogeneous ``[x, y, z, 1]``, as in the original;
  inputs may be ``[..., 3]`` or homogeneous ``[..., 4]``.

Shapes: images are ``[*batch, H, W, C]``. A matrix ``[*batch, m, n]`` carries the batch
dimensions; coordinate arrays have the same leading batch dimensions (or ones that broadcast),
then any image dimensions.

Example:
    >>> K = focal_lengths_and_pp_offsets_to_calib_mat(np.array([2., 2.]), np.array([1., 1.]))
    >>> cam_to_ds_pixel_coords(np.array([0.5, 0., 2.]), K)
    array([3., 2., 2.])
"""

from __future__ import annotations

import ivy
from ivy.checks import check_floating_dtype
from ivy.typing import Array, Device, Dtype, Framework, Shape
from ivy_vision import _common as C
from ivy_vision._checks import InputError, checked
from ivy_vision.projective_geometry import check_invertible

__all__ = [
    "create_uniform_pixel_coords_image",
    "persp_angles_to_focal_lengths",
    "focal_lengths_to_persp_angles",
    "focal_lengths_and_pp_offsets_to_calib_mat",
    "calib_mat_to_focal_lengths_and_pp_offsets",
    "invert_calib_mat",
    "rot_mat_and_cam_center_to_ext_mat",
    "ext_mat_to_rot_mat_and_cam_center",
    "calib_and_ext_to_full_mat",
    "inv_ext_mat_to_camera_center",
    "depth_to_ds_pixel_coords",
    "ds_pixel_coords_to_pixel_coords",
    "depth_to_radial_depth",
    "radial_depth_to_depth",
    "ds_pixel_coords_to_radial_depth",
    "cam_to_ds_pixel_coords",
    "cam_coords_to_depth",
    "ds_pixel_to_cam_coords",
    "depth_to_cam_coords",
    "world_to_cam_coords",
    "cam_to_world_coords",
    "world_to_ds_pixel_coords",
    "world_coords_to_depth",
    "ds_pixel_to_world_coords",
    "depth_to_world_coords",
    "pixel_coords_to_world_ray_vectors",
]


# ----------------------------------------------------------------------------------------------
# Pixel coordinates
# ----------------------------------------------------------------------------------------------


@checked
def create_uniform_pixel_coords_image(
    image_dims: Shape,
    batch_shape: Shape | None = None,
    *,
    normalized: bool = False,
    homogeneous: bool = True,
    dtype: Dtype = "float32",
    device: Device | None = None,
    f: Framework = None,
) -> Array:
    """Image of the pixel coordinates ``[x, y, 1]`` of every pixel (``x`` the column, ``y`` the
    row, origin at the top-left pixel's centre).

    Scaling it by a depth image gives depth-scaled pixel coordinates ``[u*d, v*d, d]``.

    Args:
        image_dims: ``(height, width)``.
        batch_shape: leading batch dimensions to broadcast to (none by default).
        normalized: divide ``x`` by the width and ``y`` by the height (values in ``[0, 1)``).
        homogeneous: append the homogeneous 1 (3 channels) or not (2 channels).
        dtype: floating dtype of the result (an integer dtype raises: normalised coordinates
            would round to zeros).
        device: device of the result (the backend's default if None).
        f: framework name or namespace; the global framework if None.

    Returns:
        Pixel coordinates *[batch_shape, height, width, 3]* (or *2* channels).

    Example:
        >>> create_uniform_pixel_coords_image((2, 3), f='numpy')[1, 2]
        array([2., 1., 1.], dtype=float32)
    """
    xp = ivy.get_framework(f=f)
    h, w = C.image_dims_of(image_dims)
    check_floating_dtype(dtype)  # (integer pixel coordinates, normalised, would be zeros)
    grid = C.pixel_grid(xp, (h, w), dtype, device, homogeneous_coords=homogeneous)
    if normalized:
        scale = [1.0 / w, 1.0 / h] + ([1.0] if homogeneous else [])
        grid = grid * xp.asarray(scale, dtype=xp.dtype(grid), device=xp.dev(grid))
    if batch_shape:
        grid = xp.broadcast_to(grid, (*tuple(batch_shape), *C.shape_of(xp, grid)))
    return grid


def _grid_for(xp, like, image_dims, uniform_pixel_coords):
    """The pixel grid ``[H, W, 3]`` in ``like``'s dtype, or the given one (checked)."""
    if uniform_pixel_coords is not None:
        C.check_last_dim(xp, uniform_pixel_coords, 3, "uniform_pixel_coords")
        return uniform_pixel_coords
    return C.pixel_grid(xp, image_dims, xp.dtype(like), xp.dev(like))


def _rays(xp, grid, mat):
    """``mat[..., :3] @ grid`` for a pixel grid ``[H, W, 3]`` (shared by the batch) or a batched
    one ``[*B, H, W, 3]``: ``[*B, H, W, 3]``."""
    gshape = C.shape_of(xp, grid)
    mshape = C.shape_of(xp, mat)
    m = mat[..., 0:3]
    if len(gshape) == 3:
        flat = xp.reshape(grid, (gshape[0] * gshape[1], 3))
        out = xp.matmul(flat, xp.swapaxes(m, -1, -2))
        return xp.reshape(out, (*mshape[:-2], gshape[0], gshape[1], mshape[-2]))
    return C.transform(xp, grid, m, "uniform_pixel_coords", "the matrix")


def _check_depth(xp, depth, what="depth"):
    C.check_image(xp, depth, what, channels=1)


def _broadcast_image_batch(xp, image, mat, what, mat_what):
    """Check that the batch dimensions of an image ``[*Bi, H, W, C]`` and a matrix
    ``[*Bm, r, c]`` broadcast (numpy's rules, aligned on the right)."""
    C.broadcast_right(C.shape_of(xp, image)[:-3], C.shape_of(xp, mat)[:-2], what, mat_what)


@checked
def depth_to_ds_pixel_coords(
    depth: Array, uniform_pixel_coords: Array | None = None, *, f: Framework = None
) -> Array:
    """Depth-scaled homogeneous pixel coordinates ``[u*d, v*d, d]`` of a depth image.

    Args:
        depth: planar depth images *[batch_shape, h, w, 1]*.
        uniform_pixel_coords: pixel coordinates *[(batch_shape,) h, w, 3]*; created if None.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Depth-scaled pixel coordinates *[batch_shape, h, w, 3]*.

    Example:
        >>> depth_to_ds_pixel_coords(np.full((1, 2, 1), 2.))
        array([[[0., 0., 2.],
                [2., 0., 2.]]])
    """
    xp = ivy.get_framework(depth, f=f)
    _check_depth(xp, depth)
    grid = _grid_for(xp, depth, C.shape_of(xp, depth)[-3:-1], uniform_pixel_coords)
    return grid * depth


@checked
def ds_pixel_coords_to_pixel_coords(ds_pixel_coords: Array, *, f: Framework = None) -> Array:
    """Pixel coordinates ``[u, v]`` of depth-scaled pixel coordinates ``[u*d, v*d, d]``.

    Where ``d == 0`` (a point in the camera's focal plane) the result is 0.

    Args:
        ds_pixel_coords: depth-scaled pixel coordinates *[batch_shape, image_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Pixel coordinates *[batch_shape, image_shape, 2]*.

    Example:
        >>> ds_pixel_coords_to_pixel_coords(np.array([4., 6., 2.]))
        array([2., 3.])
    """
    xp = ivy.get_framework(ds_pixel_coords, f=f)
    C.check_last_dim(xp, ds_pixel_coords, 3, "ds_pixel_coords")
    return xp.safe_divide(ds_pixel_coords[..., 0:2], ds_pixel_coords[..., 2:3])


# ----------------------------------------------------------------------------------------------
# Intrinsics and extrinsics
# ----------------------------------------------------------------------------------------------


def _wh(xp, like, image_dims):
    h, w = C.image_dims_of(image_dims)
    return xp.asarray([float(w), float(h)], dtype=xp.dtype(like), device=xp.dev(like))


@checked
def persp_angles_to_focal_lengths(
    persp_angles: Array, image_dims: Shape, *, f: Framework = None
) -> Array:
    """Focal lengths (in pixels) of the perspective angles (full fields of view).

    ``f_x = W / (2 tan(theta_x / 2))`` and ``f_y = H / (2 tan(theta_y / 2))``: the angles span
    the image from the left edge of its first column to the right edge of its last.

    Args:
        persp_angles: fields of view ``[theta_x, theta_y]`` in radians *[batch_shape, 2]*.
        image_dims: ``(height, width)``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Focal lengths ``[f_x, f_y]`` *[batch_shape, 2]*.

    Example:
        >>> persp_angles_to_focal_lengths(np.array([np.pi / 2, np.pi / 2]), (100, 200)).round(9)
        array([100.,  50.])
    """
    xp = ivy.get_framework(persp_angles, f=f)
    C.check_last_dim(xp, persp_angles, 2, "persp_angles")
    wh = _wh(xp, persp_angles, image_dims)
    return wh / (2.0 * xp.tan(persp_angles / 2.0))


@checked
def focal_lengths_to_persp_angles(
    focal_lengths: Array, image_dims: Shape, *, f: Framework = None
) -> Array:
    """Perspective angles (full fields of view) of focal lengths, the inverse of
    :func:`persp_angles_to_focal_lengths`.

    Args:
        focal_lengths: ``[f_x, f_y]`` in pixels *[batch_shape, 2]*.
        image_dims: ``(height, width)``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``[theta_x, theta_y]`` in radians *[batch_shape, 2]*.

    Example:
        >>> focal_lengths_to_persp_angles(np.array([100., 50.]), (100, 200)) / np.pi
        array([0.5, 0.5])
    """
    xp = ivy.get_framework(focal_lengths, f=f)
    C.check_last_dim(xp, focal_lengths, 2, "focal_lengths")
    wh = _wh(xp, focal_lengths, image_dims)
    return 2.0 * xp.atan(wh / (2.0 * focal_lengths))


@checked
def focal_lengths_and_pp_offsets_to_calib_mat(
    focal_lengths: Array, pp_offsets: Array, *, f: Framework = None
) -> Array:
    """Calibration matrix ``K = [[fx, 0, px], [0, fy, py], [0, 0, 1]]``.

    Args:
        focal_lengths: ``[fx, fy]`` in pixels *[batch_shape, 2]*.
        pp_offsets: principal point ``[px, py]`` in pixels *[batch_shape, 2]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Calibration matrices *[batch_shape, 3, 3]*.

    Example:
        >>> focal_lengths_and_pp_offsets_to_calib_mat(np.array([2., 3.]), np.array([4., 5.]))
        array([[2., 0., 4.],
               [0., 3., 5.],
               [0., 0., 1.]])
    """
    xp = ivy.get_framework(focal_lengths, pp_offsets, f=f)
    C.check_last_dim(xp, focal_lengths, 2, "focal_lengths")
    C.check_last_dim(xp, pp_offsets, 2, "pp_offsets")
    C.broadcast_right(
        C.shape_of(xp, focal_lengths)[:-1],
        C.shape_of(xp, pp_offsets)[:-1],
        "focal_lengths",
        "pp_offsets",
    )
    fl, pp = xp.broadcast_arrays(focal_lengths, pp_offsets)
    fx, fy, px, py = fl[..., 0], fl[..., 1], pp[..., 0], pp[..., 1]
    zero, one = xp.zeros_like(fx), xp.ones_like(fx)
    return xp.stack_matrix([[fx, zero, px], [zero, fy, py], [zero, zero, one]])


@checked
def calib_mat_to_focal_lengths_and_pp_offsets(calib_mat: Array, *, f: Framework = None) -> tuple:
    """Focal lengths and principal point of calibration matrices.

    Args:
        calib_mat: calibration matrices *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``(focal_lengths, pp_offsets)``, each *[batch_shape, 2]*.

    Example:
        >>> calib_mat_to_focal_lengths_and_pp_offsets(np.array([[2., 0, 4], [0, 3, 5], [0, 0, 1]]))
        (array([2., 3.]), array([4., 5.]))
    """
    xp = ivy.get_framework(calib_mat, f=f)
    C.check_matrix(xp, calib_mat, 3, 3, "calib_mat")
    focal = xp.stack([calib_mat[..., 0, 0], calib_mat[..., 1, 1]], axis=-1)
    return focal, calib_mat[..., 0:2, 2]


@checked
def invert_calib_mat(calib_mat: Array, *, f: Framework = None) -> Array:
    """Inverse of upper-triangular calibration matrices (skew allowed), in closed form.

    A singular calibration matrix (a zero focal length) raises a ValueError in eager mode.

    Args:
        calib_mat: calibration matrices ``[[fx, s, px], [0, fy, py], [0, 0, 1]]``
            *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``K^-1`` *[batch_shape, 3, 3]*.

    Example:
        >>> invert_calib_mat(np.array([[2., 0, 4], [0, 4, 8], [0, 0, 1]]))
        array([[ 0.5 ,  0.  , -2.  ],
               [ 0.  ,  0.25, -2.  ],
               [ 0.  ,  0.  ,  1.  ]])
    """
    xp = ivy.get_framework(calib_mat, f=f)
    C.check_matrix(xp, calib_mat, 3, 3, "calib_mat")
    check_invertible(
        xp,
        calib_mat,
        "the calibration matrix",
        "its focal lengths must be non-zero.",
    )
    fx, s, px = calib_mat[..., 0, 0], calib_mat[..., 0, 1], calib_mat[..., 0, 2]
    fy, py, k22 = calib_mat[..., 1, 1], calib_mat[..., 1, 2], calib_mat[..., 2, 2]
    zero = xp.zeros_like(fx)
    a, d = 1.0 / fx, 1.0 / fy
    b = (zero - s) * (a * d)
    c = -(px * a + py * b)
    e = -py * d
    one = 1.0 / k22
    return xp.stack_matrix([[a, b, c * one], [zero, d, e * one], [zero, zero, one]])


def _center_vector(xp, camera_center):
    C.check_last_dim(xp, camera_center, 3, "camera_center")
    return camera_center


@checked
def rot_mat_and_cam_center_to_ext_mat(
    rotation_mat: Array, camera_center: Array, *, f: Framework = None
) -> Array:
    """Extrinsic matrix ``E = R [I | -C] = [R | -R C]``.

    Args:
        rotation_mat: world-to-camera rotations ``R`` *[batch_shape, 3, 3]*.
        camera_center: camera centres ``C`` in the world frame *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Extrinsic matrices *[batch_shape, 3, 4]*.

    Example:
        >>> rot_mat_and_cam_center_to_ext_mat(np.eye(3), np.array([1., 2., 3.]))
        array([[ 1.,  0.,  0., -1.],
               [ 0.,  1.,  0., -2.],
               [ 0.,  0.,  1., -3.]])
    """
    xp = ivy.get_framework(rotation_mat, camera_center, f=f)
    C.check_matrix(xp, rotation_mat, 3, 3, "rotation_mat")
    center = _center_vector(xp, camera_center)
    t = -xp.matvec(rotation_mat, center)
    rb, tb = C.shape_of(xp, rotation_mat)[:-2], C.shape_of(xp, t)[:-1]
    if rb != tb:
        batch = C.broadcast_batch(rb, tb, "rotation_mat", "camera_center")
        rotation_mat = xp.broadcast_to(rotation_mat, (*batch, 3, 3))
        t = xp.broadcast_to(t, (*batch, 3))
    return xp.concat([rotation_mat, t[..., None]], axis=-1)


@checked
def ext_mat_to_rot_mat_and_cam_center(ext_mat: Array, *, f: Framework = None) -> tuple:
    """Rotation and camera centre of extrinsic matrices ``[R | t]``: ``C = -R^T t``.

    Args:
        ext_mat: extrinsic matrices *[batch_shape, 3, 4]* with orthonormal ``R``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``(rotation_mat [batch_shape, 3, 3], camera_center [batch_shape, 3])``.

    Example:
        >>> ext_mat_to_rot_mat_and_cam_center(np.eye(3, 4))[1]
        array([-0., -0., -0.])
    """
    xp = ivy.get_framework(ext_mat, f=f)
    C.check_matrix(xp, ext_mat, 3, 4, "ext_mat")
    rot = ext_mat[..., 0:3]
    return rot, -xp.matvec(xp.swapaxes(rot, -1, -2), ext_mat[..., 3])


@checked
def calib_and_ext_to_full_mat(calib_mat: Array, ext_mat: Array, *, f: Framework = None) -> Array:
    """Full projection matrix ``P = K E``.

    Args:
        calib_mat: calibration matrices *[batch_shape, 3, 3]*.
        ext_mat: extrinsic matrices *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Full projection matrices *[batch_shape, 3, 4]*.

    Example:
        >>> calib_and_ext_to_full_mat(2 * np.eye(3), np.eye(3, 4))[0]
        array([2., 0., 0., 0.])
    """
    xp = ivy.get_framework(calib_mat, ext_mat, f=f)
    C.check_matrix(xp, calib_mat, 3, 3, "calib_mat")
    C.check_matrix(xp, ext_mat, 3, 4, "ext_mat")
    C.broadcast_batch(
        C.shape_of(xp, calib_mat)[:-2],
        C.shape_of(xp, ext_mat)[:-2],
        "calib_mat",
        "ext_mat",
    )
    return xp.matmul(calib_mat, ext_mat)


@checked
def inv_ext_mat_to_camera_center(inv_ext_mat: Array, *, f: Framework = None) -> Array:
    """Camera centre: the last column of an inverse extrinsic (or inverse full) matrix.

    Args:
        inv_ext_mat: inverse extrinsic matrices ``[R^T | C]`` *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Camera centres *[batch_shape, 3]*.

    Example:
        >>> inv_ext_mat_to_camera_center(np.array([[1., 0, 0, 5], [0, 1, 0, 6], [0, 0, 1, 7]]))
        array([5., 6., 7.])
    """
    xp = ivy.get_framework(inv_ext_mat, f=f)
    C.check_matrix(xp, inv_ext_mat, 3, 4, "inv_ext_mat")
    return inv_ext_mat[..., 3]


# ----------------------------------------------------------------------------------------------
# Depth
# ----------------------------------------------------------------------------------------------


def _ray_lengths(xp, depth, inv_calib_mat, uniform_pix_coords):
    _check_depth(xp, depth, "the depth image")
    C.check_matrix(xp, inv_calib_mat, 3, 3, "inv_calib_mat")
    _broadcast_image_batch(xp, depth, inv_calib_mat, "the depth image", "inv_calib_mat")
    grid = _grid_for(xp, depth, C.shape_of(xp, depth)[-3:-1], uniform_pix_coords)
    return xp.safe_norm(_rays(xp, grid, inv_calib_mat), axis=-1, keepdims=True)


@checked
def depth_to_radial_depth(
    depth: Array,
    inv_calib_mat: Array,
    uniform_pix_coords: Array | None = None,
    *,
    f: Framework = None,
) -> Array:
    """Radial depth (distance from the camera centre) of a planar depth image.

    Args:
        depth: planar depth images *[batch_shape, h, w, 1]*.
        inv_calib_mat: inverse calibration matrices *[batch_shape, 3, 3]*.
        uniform_pix_coords: pixel coordinates *[(batch_shape,) h, w, 3]*; created if None.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Radial depth images *[batch_shape, h, w, 1]*.

    Example:
        >>> depth_to_radial_depth(np.ones((1, 2, 1)), np.eye(3))[0, 1]
        array([1.41421356])
    """
    xp = ivy.get_framework(depth, inv_calib_mat, f=f)
    return depth * _ray_lengths(xp, depth, inv_calib_mat, uniform_pix_coords)


@checked
def radial_depth_to_depth(
    radial_depth: Array,
    inv_calib_mat: Array,
    uniform_pix_coords: Array | None = None,
    *,
    f: Framework = None,
) -> Array:
    """Planar depth of a radial depth image, the inverse of :func:`depth_to_radial_depth`.

    Args:
        radial_depth: radial depth images *[batch_shape, h, w, 1]*.
        inv_calib_mat: inverse calibration matrices *[batch_shape, 3, 3]*.
        uniform_pix_coords: pixel coordinates *[(batch_shape,) h, w, 3]*; created if None.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Planar depth images *[batch_shape, h, w, 1]*.

    Example:
        >>> radial_depth_to_depth(np.full((1, 2, 1), 2 ** 0.5), np.eye(3))[0, 1]
        array([1.])
    """
    xp = ivy.get_framework(radial_depth, inv_calib_mat, f=f)
    return radial_depth / _ray_lengths(xp, radial_depth, inv_calib_mat, uniform_pix_coords)


@checked
def ds_pixel_coords_to_radial_depth(
    ds_pixel_coords: Array, inv_calib_mat: Array, *, f: Framework = None
) -> Array:
    """Radial depth of depth-scaled pixel coordinates: ``|K^-1 [u*d, v*d, d]|``.

    Args:
        ds_pixel_coords: depth-scaled pixel coordinates *[batch_shape, image_shape, 3]*.
        inv_calib_mat: inverse calibration matrices *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Radial depths *[batch_shape, image_shape, 1]*.

    Example:
        >>> ds_pixel_coords_to_radial_depth(np.array([3., 0., 4.]), np.eye(3))
        array([5.])
    """
    xp = ivy.get_framework(ds_pixel_coords, inv_calib_mat, f=f)
    C.check_last_dim(xp, ds_pixel_coords, 3, "ds_pixel_coords")
    C.check_matrix(xp, inv_calib_mat, 3, 3, "inv_calib_mat")
    cam = C.transform(xp, ds_pixel_coords, inv_calib_mat, "ds_pixel_coords", "inv_calib_mat")
    return xp.safe_norm(cam, axis=-1, keepdims=True)


# ----------------------------------------------------------------------------------------------
# Between pixel, camera and world frames
# ----------------------------------------------------------------------------------------------


def _points(xp, coords, what):
    """3-D points ``[..., 3]`` of plain or homogeneous coordinates ``[..., 3 | 4]``."""
    C.check_last_dim(xp, coords, (3, 4), what)
    return coords[..., 0:3]


@checked
def cam_to_ds_pixel_coords(
    coords_wrt_cam: Array, calib_mat: Array, *, f: Framework = None
) -> Array:
    """Project camera-frame points to depth-scaled pixel coordinates: ``K [x, y, z]``.

    Args:
        coords_wrt_cam: camera-frame points *[batch_shape, image_shape, 3 or 4]*.
        calib_mat: calibration matrices *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Depth-scaled pixel coordinates *[batch_shape, image_shape, 3]*.

    Example:
        >>> cam_to_ds_pixel_coords(np.array([1., 1., 2., 1.]), np.eye(3))
        array([1., 1., 2.])
    """
    xp = ivy.get_framework(coords_wrt_cam, calib_mat, f=f)
    C.check_matrix(xp, calib_mat, 3, 3, "calib_mat")
    points = _points(xp, coords_wrt_cam, "coords_wrt_cam")
    return C.transform(xp, points, calib_mat, "coords_wrt_cam", "calib_mat")


@checked
def cam_coords_to_depth(coords_wrt_cam: Array, calib_mat: Array, *, f: Framework = None) -> Array:
    """Planar depth of camera-frame points (their ``z``, via the calibration matrix).

    Args:
        coords_wrt_cam: camera-frame points *[batch_shape, image_shape, 3 or 4]*.
        calib_mat: calibration matrices *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Depths *[batch_shape, image_shape, 1]*.

    Example:
        >>> cam_coords_to_depth(np.array([1., 1., 2.]), np.eye(3))
        array([2.])
    """
    return cam_to_ds_pixel_coords(coords_wrt_cam, calib_mat, f=f)[..., 2:3]


@checked
def ds_pixel_to_cam_coords(
    ds_pixel_coords: Array, inv_calib_mat: Array, *, f: Framework = None
) -> Array:
    """Unproject depth-scaled pixel coordinates to homogeneous camera-frame points.

    Args:
        ds_pixel_coords: ``[u*d, v*d, d]`` *[batch_shape, image_shape, 3]*.
        inv_calib_mat: inverse calibration matrices *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Camera-frame points ``[x, y, z, 1]`` *[batch_shape, image_shape, 4]*.

    Example:
        >>> ds_pixel_to_cam_coords(np.array([1., 1., 2.]), np.eye(3))
        array([1., 1., 2., 1.])
    """
    xp = ivy.get_framework(ds_pixel_coords, inv_calib_mat, f=f)
    C.check_last_dim(xp, ds_pixel_coords, 3, "ds_pixel_coords")
    C.check_matrix(xp, inv_calib_mat, 3, 3, "inv_calib_mat")
    cam = C.transform(xp, ds_pixel_coords, inv_calib_mat, "ds_pixel_coords", "inv_calib_mat")
    return C.homogeneous(xp, cam)


def _unproject_depth(xp, depth, mat, uniform_pixel_coords, mat_what):
    """``mat @ [d*u, d*v, d(, 1)]`` for every pixel, as ``d * (M @ [u, v, 1]) (+ t)``."""
    _check_depth(xp, depth)
    _broadcast_image_batch(xp, depth, mat, "depth", mat_what)
    grid = _grid_for(xp, depth, C.shape_of(xp, depth)[-3:-1], uniform_pixel_coords)
    points = _rays(xp, grid, mat) * depth
    if C.shape_of(xp, mat)[-1] == 4:
        points = points + mat[..., None, None, :, 3]
    return C.homogeneous(xp, points)


@checked
def depth_to_cam_coords(
    depth: Array,
    inv_calib_mat: Array,
    uniform_pixel_coords: Array | None = None,
    *,
    f: Framework = None,
) -> Array:
    """Homogeneous camera-frame points of every pixel of a planar depth image.

    Args:
        depth: planar depth images *[batch_shape, h, w, 1]*.
        inv_calib_mat: inverse calibration matrices *[batch_shape, 3, 3]*.
        uniform_pixel_coords: pixel coordinates *[(batch_shape,) h, w, 3]*; created if None.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Camera-frame points *[batch_shape, h, w, 4]*.

    Example:
        >>> depth_to_cam_coords(np.full((1, 2, 1), 2.), np.eye(3))[0, 1]
        array([2., 0., 2., 1.])
    """
    xp = ivy.get_framework(depth, inv_calib_mat, f=f)
    C.check_matrix(xp, inv_calib_mat, 3, 3, "inv_calib_mat")
    return _unproject_depth(xp, depth, inv_calib_mat, uniform_pixel_coords, "inv_calib_mat")


@checked
def world_to_cam_coords(coords_wrt_world: Array, ext_mat: Array, *, f: Framework = None) -> Array:
    """Transform world-frame points to homogeneous camera-frame points: ``E [X, 1]``.

    Args:
        coords_wrt_world: world-frame points *[batch_shape, image_shape, 3 or 4]*.
        ext_mat: extrinsic matrices *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Camera-frame points *[batch_shape, image_shape, 4]*.

    Example:
        >>> world_to_cam_coords(np.array([1., 2., 3.]), np.eye(3, 4))
        array([1., 2., 3., 1.])
    """
    xp = ivy.get_framework(coords_wrt_world, ext_mat, f=f)
    C.check_matrix(xp, ext_mat, 3, 4, "ext_mat")
    points = _points(xp, coords_wrt_world, "coords_wrt_world")
    return C.homogeneous(xp, C.affine(xp, points, ext_mat, "coords_wrt_world", "ext_mat"))


@checked
def cam_to_world_coords(coords_wrt_cam: Array, inv_ext_mat: Array, *, f: Framework = None) -> Array:
    """Transform camera-frame points to homogeneous world-frame points: ``E^-1 [x, 1]``.

    Args:
        coords_wrt_cam: camera-frame points *[batch_shape, image_shape, 3 or 4]*.
        inv_ext_mat: inverse extrinsic matrices ``[R^T | C]`` *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        World-frame points *[batch_shape, image_shape, 4]*.

    Example:
        >>> cam_to_world_coords(np.array([1., 2., 3.]), np.eye(3, 4))
        array([1., 2., 3., 1.])
    """
    xp = ivy.get_framework(coords_wrt_cam, inv_ext_mat, f=f)
    C.check_matrix(xp, inv_ext_mat, 3, 4, "inv_ext_mat")
    points = _points(xp, coords_wrt_cam, "coords_wrt_cam")
    return C.homogeneous(xp, C.affine(xp, points, inv_ext_mat, "coords_wrt_cam", "inv_ext_mat"))


@checked
def world_to_ds_pixel_coords(
    coords_wrt_world: Array, full_mat: Array, *, f: Framework = None
) -> Array:
    """Project world-frame points to depth-scaled pixel coordinates: ``P [X, 1]``.

    Args:
        coords_wrt_world: world-frame points *[batch_shape, image_shape, 3 or 4]*.
        full_mat: full projection matrices *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Depth-scaled pixel coordinates *[batch_shape, image_shape, 3]*.

    Example:
        >>> world_to_ds_pixel_coords(np.array([1., 2., 3.]), np.eye(3, 4))
        array([1., 2., 3.])
    """
    xp = ivy.get_framework(coords_wrt_world, full_mat, f=f)
    C.check_matrix(xp, full_mat, 3, 4, "full_mat")
    points = _points(xp, coords_wrt_world, "coords_wrt_world")
    return C.affine(xp, points, full_mat, "coords_wrt_world", "full_mat")


@checked
def world_coords_to_depth(
    coords_wrt_world: Array, full_mat: Array, *, f: Framework = None
) -> Array:
    """Planar depth of world-frame points seen by a camera.

    Args:
        coords_wrt_world: world-frame points *[batch_shape, image_shape, 3 or 4]*.
        full_mat: full projection matrices *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Depths *[batch_shape, image_shape, 1]*.

    Example:
        >>> world_coords_to_depth(np.array([1., 2., 3.]), np.eye(3, 4))
        array([3.])
    """
    return world_to_ds_pixel_coords(coords_wrt_world, full_mat, f=f)[..., 2:3]


@checked
def ds_pixel_to_world_coords(
    ds_pixel_coords: Array, inv_full_mat: Array, *, f: Framework = None
) -> Array:
    """Unproject depth-scaled pixel coordinates to homogeneous world-frame points.

    Args:
        ds_pixel_coords: ``[u*d, v*d, d]`` *[batch_shape, image_shape, 3]*.
        inv_full_mat: inverse full projection matrices *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        World-frame points *[batch_shape, image_shape, 4]*.

    Example:
        >>> ds_pixel_to_world_coords(np.array([1., 2., 3.]), np.eye(3, 4))
        array([1., 2., 3., 1.])
    """
    xp = ivy.get_framework(ds_pixel_coords, inv_full_mat, f=f)
    C.check_last_dim(xp, ds_pixel_coords, 3, "ds_pixel_coords")
    C.check_matrix(xp, inv_full_mat, 3, 4, "inv_full_mat")
    return C.homogeneous(
        xp, C.affine(xp, ds_pixel_coords, inv_full_mat, "ds_pixel_coords", "inv_full_mat")
    )


@checked
def depth_to_world_coords(
    depth: Array,
    inv_full_mat: Array,
    uniform_pixel_coords: Array | None = None,
    *,
    f: Framework = None,
) -> Array:
    """Homogeneous world-frame points of every pixel of a planar depth image.

    Args:
        depth: planar depth images *[batch_shape, h, w, 1]*.
        inv_full_mat: inverse full projection matrices *[batch_shape, 3, 4]*.
        uniform_pixel_coords: pixel coordinates *[(batch_shape,) h, w, 3]*; created if None.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        World-frame points *[batch_shape, h, w, 4]*.

    Example:
        >>> depth_to_world_coords(np.full((1, 1, 1), 2.), np.eye(3, 4))[0, 0]
        array([0., 0., 2., 1.])
    """
    xp = ivy.get_framework(depth, inv_full_mat, f=f)
    C.check_matrix(xp, inv_full_mat, 3, 4, "inv_full_mat")
    return _unproject_depth(xp, depth, inv_full_mat, uniform_pixel_coords, "inv_full_mat")


@checked
def pixel_coords_to_world_ray_vectors(
    inv_full_mat: Array,
    pixel_coords: Array | None = None,
    camera_center: Array | None = None,
    *,
    image_dims: Shape | None = None,
    f: Framework = None,
) -> Array:
    """Unit world-frame directions of the rays through pixels, from the camera centre.

    A point on the ray of a pixel is ``camera_center + lambda * ray`` with ``lambda`` its radial
    depth.

    Args:
        inv_full_mat: inverse full projection matrices *[batch_shape, 3, 4]*.
        pixel_coords: pixel coordinates ``[u, v]`` or ``[u, v, 1]`` (or depth-scaled ones with
            positive depth) *[batch_shape, image_shape, 2 or 3]*; every pixel of an image of
            ``image_dims`` if None.
        camera_center: camera centres *[batch_shape, 3]*; the last column of ``inv_full_mat``
            if None.
        image_dims: ``(height, width)``, needed when ``pixel_coords`` is None.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Unit ray directions *[batch_shape, image_shape, 3]*.

    Example:
        >>> pixel_coords_to_world_ray_vectors(np.eye(3, 4), np.array([0., 0., 1.]))
        array([0., 0., 1.])
    """
    xp = ivy.get_framework(inv_full_mat, pixel_coords, camera_center, f=f)
    C.check_matrix(xp, inv_full_mat, 3, 4, "inv_full_mat")
    if pixel_coords is None:
        if image_dims is None:
            raise InputError("give pixel_coords or image_dims (height, width).")
        grid = C.pixel_grid(
            xp, C.image_dims_of(image_dims), xp.dtype(inv_full_mat), xp.dev(inv_full_mat)
        )
        vectors = _rays(xp, grid, inv_full_mat)
    else:
        if C.check_last_dim(xp, pixel_coords, (2, 3), "pixel_coords") == 2:
            pixel_coords = C.homogeneous(xp, pixel_coords)
        vectors = C.transform(
            xp, pixel_coords, inv_full_mat[..., 0:3], "pixel_coords", "inv_full_mat"
        )
    if camera_center is not None:
        C.check_last_dim(xp, camera_center, 3, "camera_center")
        ni = len(C.shape_of(xp, vectors)) - len(C.shape_of(xp, camera_center))
        offset = inv_full_mat[..., 3] - camera_center
        vectors = vectors + xp.reshape(offset, (*C.shape_of(xp, offset)[:-1], *(1,) * ni, 3))
    return C.normalize(xp, vectors)
