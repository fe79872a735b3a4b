"""Optical flow: flow from depth and relative pose, depth from flow, projection of flow onto
epipolar lines, flow and velocities of rigidly moving objects, and cost volumes.

Flow ``[..., H, W, 2]`` from frame 1 to frame 2 is the displacement ``(dx, dy)`` in pixels: the
pixel at ``(x, y)`` of frame 1 is seen at ``(x + dx, y + dy)`` in frame 2.

Example:
    >>> flow_from_depth_and_cam_mats(np.array([2., 2., 2.]), np.eye(3, 4) + np.eye(3, 4, 3))
    array([0.5, 0. ])
"""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework
from ivy_vision import _common as C
from ivy_vision import single_view_geometry as svg
from ivy_vision import two_view_geometry as tvg
from ivy_vision._checks import InputError, checked
from ivy_vision.sampling import sample_kernel

__all__ = [
    "flow_from_depth_and_cam_mats",
    "depth_from_flow_and_cam_mats",
    "project_flow_to_epipolar_line",
    "pixel_cost_volume",
    "velocity_from_flow_cam_coords_and_cam_mats",
    "project_cam_coords_with_object_transformations",
    "velocity_from_cam_coords_id_image_and_object_trans",
    "flow_from_cam_coords_id_image_and_object_trans",
]


def _pixels(xp, ds_pixel_coords):
    return xp.safe_divide(ds_pixel_coords[..., 0:2], ds_pixel_coords[..., 2:3])


@checked
def flow_from_depth_and_cam_mats(
    pixel_coords1: Array, cam1to2_full_mat: Array, *, f: Framework = None
) -> Array:
    """Optical flow of depth-scaled pixel coordinates of frame 1 moved into frame 2.

    Args:
        pixel_coords1: depth-scaled pixel coordinates of frame 1 (e.g. from
            :func:`depth_to_ds_pixel_coords`) *[batch_shape, image_shape, 3]*.
        cam1to2_full_mat: camera-1-to-camera-2 full matrices *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Flow from frame 1 to frame 2 *[batch_shape, image_shape, 2]*.

    Example:
        >>> flow_from_depth_and_cam_mats(np.array([0., 0., 1.]), np.eye(3, 4) + np.eye(3, 4, 3))
        array([1., 0.])
    """
    xp = ivy.get_framework(pixel_coords1, cam1to2_full_mat, f=f)
    projected = tvg.ds_pixel_to_ds_pixel_coords(pixel_coords1, cam1to2_full_mat, f=xp)
    return _pixels(xp, projected) - _pixels(xp, pixel_coords1)


def _flow_image(xp, flow):
    C.check_image(xp, flow, "flow", channels=2)
    return C.shape_of(xp, flow)[-3:-1]


@checked
def depth_from_flow_and_cam_mats(
    flow: Array,
    full_mats: Array,
    inv_full_mats: Array | None = None,
    camera_centers: Array | None = None,
    uniform_pixel_coords: Array | None = None,
    triangulation_method: str = "cmp",
    *,
    f: Framework = None,
) -> Array:
    """Depth of frame 1 triangulated from the optical flow to frame 2 and both cameras.

    Args:
        flow: flow from frame 1 to frame 2 *[batch_shape, h, w, 2]*.
        full_mats: full projection matrices of both frames *[batch_shape, 2, 3, 4]*.
        inv_full_mats: their inverses *[batch_shape, 2, 3, 4]*; computed if None.
        camera_centers: camera centres *[batch_shape, 2, 3]*; from ``inv_full_mats`` if None.
        uniform_pixel_coords: pixel coordinates *[(batch_shape,) h, w, 3]*; created if None.
        triangulation_method: ``'cmp'`` (closest mutual points) or ``'dlt'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Planar depth of frame 1 *[batch_shape, h, w, 1]*.

    Example:
        >>> P = np.stack([np.eye(3, 4), np.eye(3, 4) - np.eye(3, 4, 3)])
        >>> flow = np.array([[[-0.5, 0.]]])                 # the pixel (0, 0) moves by -1 / z
        >>> depth_from_flow_and_cam_mats(flow, P)
        array([[[2.]]])
    """
    xp = ivy.get_framework(flow, full_mats, inv_full_mats, camera_centers, f=f)
    dims = _flow_image(xp, flow)
    if uniform_pixel_coords is None:
        uniform_pixel_coords = C.pixel_grid(xp, dims, xp.dtype(flow), xp.dev(flow))
    else:
        C.check_last_dim(xp, uniform_pixel_coords, 3, "uniform_pixel_coords")
    moved = uniform_pixel_coords + xp.concat([flow, xp.zeros_like(flow[..., 0:1])], axis=-1)
    first = xp.broadcast_to(uniform_pixel_coords, C.shape_of(xp, moved))
    pixels = xp.stack([first, moved], axis=-4)
    return tvg.triangulate_depth(
        pixels, full_mats, inv_full_mats, camera_centers, triangulation_method, f=xp
    )[..., 2:3]


@checked
def project_flow_to_epipolar_line(
    flow: Array,
    fund_mat: Array,
    uniform_pixel_coords: Array | None = None,
    *,
    f: Framework = None,
) -> Array:
    """Project flow so that each moved pixel lies on its epipolar line in frame 2 (the closest
    point of the line ``F [x, y, 1]``).

    Args:
        flow: flow from frame 1 to frame 2 *[batch_shape, h, w, 2]*.
        fund_mat: fundamental matrices with ``x_2^T F x_1 = 0`` *[batch_shape, 3, 3]*.
        uniform_pixel_coords: pixel coordinates *[(batch_shape,) h, w, 3]*; created if None.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Projected flow *[batch_shape, h, w, 2]*.

    Example:
        >>> F = np.array([[0., 0, 0], [0, 0, -1], [0, 1, 0]])    # epipolar lines: same row
        >>> project_flow_to_epipolar_line(np.array([[[3., 0.7]]]), F)
        array([[[3., 0.]]])
    """
    xp = ivy.get_framework(flow, fund_mat, f=f)
    dims = _flow_image(xp, flow)
    C.check_matrix(xp, fund_mat, 3, 3, "fund_mat")
    if uniform_pixel_coords is None:
        uniform_pixel_coords = C.pixel_grid(xp, dims, xp.dtype(flow), xp.dev(flow))
    grid = xp.broadcast_to(uniform_pixel_coords, (*C.shape_of(xp, fund_mat)[:-2], *dims, 3))
    lines = C.transform(xp, grid, fund_mat, "uniform_pixel_coords", "fund_mat")
    a, b, c = lines[..., 0:1], lines[..., 1:2], lines[..., 2:3]
    moved = grid[..., 0:2] + flow
    distance = xp.safe_divide(a * moved[..., 0:1] + b * moved[..., 1:2] + c, a * a + b * b)
    projected = moved - distance * xp.concat([a, b], axis=-1)
    return projected - grid[..., 0:2]


@checked
def pixel_cost_volume(
    image1: Array, image2: Array, search_range: int, *, f: Framework = None
) -> Array:
    """Correlation cost volume of FlowNet: the channel mean of ``image1 * image2`` shifted by
    every offset in ``[-search_range, search_range]^2`` (``image2`` zero-padded).

    Args:
        image1: images *[batch_shape, h, w, d]*.
        image2: images *[batch_shape, h, w, d]*.
        search_range: the largest offset, in pixels.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Costs *[batch_shape, h, w, (2 search_range + 1)^2]*, offsets in row-major order
        ``(dy, dx)`` from ``(-r, -r)``.

    Example:
        >>> pixel_cost_volume(np.ones((2, 2, 1)), np.ones((2, 2, 1)), 1)[0, 0]
        array([0., 0., 0., 0., 1., 1., 0., 1., 1.])
    """
    xp = ivy.get_framework(image1, image2, f=f)
    h, w = C.check_image(xp, image1, "image1")
    if C.shape_of(xp, image1) != C.shape_of(xp, image2):
        raise InputError(
            f"image1 {C.shape_of(xp, image1)} and image2 {C.shape_of(xp, image2)} must "
            f"have the same shape."
        )
    r = int(search_range)
    nd = len(C.shape_of(xp, image2))
    padded = xp.zero_pad(image2, ((0, 0),) * (nd - 3) + ((r, r), (r, r), (0, 0)))
    costs = [
        xp.mean(image1 * padded[..., dy : dy + h, dx : dx + w, :], axis=-1, keepdims=True)
        for dy in range(2 * r + 1)
        for dx in range(2 * r + 1)
    ]
    return xp.concat(costs, axis=-1)


@checked
def velocity_from_flow_cam_coords_and_cam_mats(
    flow_t_to_tm1: Array,
    cam_coords_t: Array,
    cam_coords_tm1: Array,
    cam_tm1_to_t_ext_mat: Array,
    delta_t: Array,
    uniform_pixel_coords: Array | None = None,
    *,
    f: Framework = None,
) -> tuple:
    """Velocities of the scene points relative to the camera, from the flow back to the previous
    frame and both frames' camera coordinates.

    The points of frame ``t - 1`` are sampled (bilinearly) where the flow points, moved into
    frame ``t`` with ``cam_tm1_to_t_ext_mat``, and differenced with frame ``t``.

    Args:
        flow_t_to_tm1: flow from frame ``t`` to ``t - 1`` *[batch_shape, h, w, 2]*.
        cam_coords_t: camera coordinates of frame ``t`` *[batch_shape, h, w, 3 or 4]*.
        cam_coords_tm1: camera coordinates of frame ``t - 1`` *[batch_shape, h, w, 3 or 4]*.
        cam_tm1_to_t_ext_mat: camera motion ``t - 1 -> t`` *[batch_shape, 3, 4]*.
        delta_t: time steps *[batch_shape, 1]*.
        uniform_pixel_coords: pixel coordinates *[(batch_shape,) h, w, 3]*; created if None.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``(velocity [batch_shape, h, w, 3], validity [batch_shape, h, w, 1])``: valid where the
        flow lands inside the image.

    Example:
        >>> coords = np.ones((1, 1, 3))
        >>> velocity_from_flow_cam_coords_and_cam_mats(
        ...     np.zeros((1, 1, 2)), coords, coords, np.eye(3, 4), np.array([0.5]))[0]
        array([[[0., 0., 0.]]])
    """
    xp = ivy.get_framework(
        flow_t_to_tm1, cam_coords_t, cam_coords_tm1, cam_tm1_to_t_ext_mat, delta_t, f=f
    )
    h, w = _flow_image(xp, flow_t_to_tm1)
    if uniform_pixel_coords is None:
        uniform_pixel_coords = C.pixel_grid(
            xp, (h, w), xp.dtype(flow_t_to_tm1), xp.dev(flow_t_to_tm1)
        )
    warp = uniform_pixel_coords[..., 0:2] + flow_t_to_tm1
    previous = sample_kernel(xp, cam_coords_tm1[..., 0:3], warp, "bilinear", "border")
    moved = tvg.cam_to_cam_coords(previous, cam_tm1_to_t_ext_mat, f=xp)[..., 0:3]
    dt = xp.reshape(delta_t, (*C.shape_of(xp, delta_t)[:-1], 1, 1, 1))
    velocity = (cam_coords_t[..., 0:3] - moved) / dt
    x, y = warp[..., 0:1], warp[..., 1:2]
    valid = xp.logical_and(xp.logical_and(x >= 0, x <= w - 1), xp.logical_and(y >= 0, y <= h - 1))
    return velocity, valid


@checked(exact=("id_image", "obj_ids"))
def project_cam_coords_with_object_transformations(
    cam_coords_1: Array,
    id_image: Array,
    obj_ids: Array,
    obj_trans: Array,
    cam_1_to_2_ext_mat: Array,
    *,
    f: Framework = None,
) -> tuple:
    """Camera-2 coordinates of the points of frame 1, moving with their objects.

    Pixels whose id is one of ``obj_ids`` are moved by that object's transformation, which maps
    camera-1 coordinates of its points to camera-2 coordinates (object motion and camera motion
    together); every other pixel moves with the static scene, by ``cam_1_to_2_ext_mat``.

    Args:
        cam_coords_1: camera coordinates of frame 1 *[batch_shape, h, w, 3 or 4]*.
        id_image: object id of every pixel *[batch_shape, h, w, 1]*.
        obj_ids: ids of the moving objects *[batch_shape, num_obj, 1]*.
        obj_trans: their camera-1-to-camera-2 transformations *[batch_shape, num_obj, 3, 4]*.
        cam_1_to_2_ext_mat: camera-1-to-camera-2 extrinsic matrices *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``(cam_coords_2 [batch_shape, h, w, 4], motion_mask [batch_shape, h, w, 1])``, the mask
        true on moving objects.

    Example:
        >>> shift = np.eye(3, 4) + np.eye(3, 4, 3)                  # the object moves by +1
        >>> coords, moving = project_cam_coords_with_object_transformations(
        ...     np.ones((1, 2, 3)), np.array([[[1.], [0.]]]), np.array([[1.]]), shift[None],
        ...     np.eye(3, 4))
        >>> coords[..., 0]
        array([[2., 1.]])
    """
    xp = ivy.get_framework(cam_coords_1, id_image, obj_ids, obj_trans, cam_1_to_2_ext_mat, f=f)
    C.check_image(xp, cam_coords_1, "cam_coords_1", channels=(3, 4))
    C.check_image(xp, id_image, "id_image", channels=1)
    tshape = C.shape_of(xp, obj_trans)
    if len(tshape) < 3 or tshape[-2:] != (3, 4):
        raise InputError(f"obj_trans must be [..., num_obj, 3, 4]; got shape {tshape}.")
    C.check_last_dim(xp, obj_ids, 1, "obj_ids")
    nb = len(tshape) - 3
    points = cam_coords_1[..., 0:3]
    # every object's transformation applied to every pixel: [*B, h, w, num_obj, 3]
    trans = xp.reshape(obj_trans, (*tshape[:nb], 1, 1, tshape[-3], 3, 4))
    moved = xp.matvec(trans[..., 0:3], points[..., None, :]) + trans[..., 3]
    ids_shape = C.shape_of(xp, obj_ids)  # (no -1: an empty batch leaves it undetermined)
    ids = xp.reshape(obj_ids[..., 0], (*ids_shape[:-2], 1, 1, ids_shape[-2]))
    selected = xp.astype(xp.equal(ids, id_image), xp.dtype(moved))  # [*B, h, w, num_obj]
    motion_mask = xp.sum(selected, axis=-1, keepdims=True) > 0
    object_motion = xp.sum(moved * selected[..., None], axis=-2)
    static = tvg.cam_to_cam_coords(points, cam_1_to_2_ext_mat, f=xp)[..., 0:3]
    return C.homogeneous(xp, xp.where(motion_mask, object_motion, static)), motion_mask


@checked(exact=("id_image", "obj_ids"))
def velocity_from_cam_coords_id_image_and_object_trans(
    cam_coords_t: Array,
    id_image: Array,
    obj_ids: Array,
    obj_trans: Array,
    delta_t: Array,
    *,
    f: Framework = None,
) -> Array:
    """Velocities of moving objects' points in the camera frame, from each object's motion
    over the time step (a static camera; static pixels get 0).

    Args:
        cam_coords_t: camera coordinates of frame ``t`` *[batch_shape, h, w, 3 or 4]*.
        id_image: object id of every pixel *[batch_shape, h, w, 1]*.
        obj_ids: ids of the moving objects *[batch_shape, num_obj, 1]*.
        obj_trans: each object's transformation from its pose at ``t`` to its pose at
            ``t - 1``, in the camera frame *[batch_shape, num_obj, 3, 4]*.
        delta_t: time steps *[batch_shape, 1]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Velocities *[batch_shape, h, w, 3]*.

    Example:
        >>> back = np.eye(3, 4) - np.eye(3, 4, 3)                  # the object came from -x
        >>> velocity_from_cam_coords_id_image_and_object_trans(
        ...     np.ones((1, 1, 3)), np.ones((1, 1, 1)), np.array([[1.]]), back[None],
        ...     np.array([0.5]))
        array([[[2., 0., 0.]]])
    """
    xp = ivy.get_framework(cam_coords_t, id_image, obj_ids, obj_trans, delta_t, f=f)
    batch = C.shape_of(xp, obj_trans)[:-3]
    identity = xp.broadcast_to(
        xp.eye(3, 4, dtype=xp.dtype(obj_trans), device=xp.dev(obj_trans)), (*batch, 3, 4)
    )
    previous, moving = project_cam_coords_with_object_transformations(
        cam_coords_t, id_image, obj_ids, obj_trans, identity, f=xp
    )
    dt = xp.reshape(delta_t, (*C.shape_of(xp, delta_t)[:-1], 1, 1, 1))
    velocity = (cam_coords_t[..., 0:3] - previous[..., 0:3]) / dt
    return xp.where(moving, velocity, xp.zeros_like(velocity))


@checked(exact=("id_image", "obj_ids"))
def flow_from_cam_coords_id_image_and_object_trans(
    cam_coords_f1: Array,
    id_image: Array,
    obj_ids: Array,
    obj_trans: Array,
    calib_mat: Array,
    cam_1_to_2_ext_mat: Array,
    *,
    f: Framework = None,
) -> Array:
    """Optical flow of a scene with rigidly moving objects (see
    :func:`project_cam_coords_with_object_transformations` for the transformations).

    Args:
        cam_coords_f1: camera coordinates of frame 1 *[batch_shape, h, w, 3 or 4]*.
        id_image: object id of every pixel *[batch_shape, h, w, 1]*.
        obj_ids: ids of the moving objects *[batch_shape, num_obj, 1]*.
        obj_trans: their camera-1-to-camera-2 transformations *[batch_shape, num_obj, 3, 4]*.
        calib_mat: calibration matrices (the same camera in both frames) *[batch_shape, 3, 3]*.
        cam_1_to_2_ext_mat: camera motion *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Flow from frame 1 to frame 2 *[batch_shape, h, w, 2]*.

    Example:
        >>> shift = np.eye(3, 4) + np.eye(3, 4, 3)
        >>> flow_from_cam_coords_id_image_and_object_trans(
        ...     np.ones((1, 2, 3)), np.array([[[1.], [0.]]]), np.array([[1.]]), shift[None],
        ...     np.eye(3), np.eye(3, 4))[..., 0]
        array([[1., 0.]])
    """
    xp = ivy.get_framework(
        cam_coords_f1, id_image, obj_ids, obj_trans, calib_mat, cam_1_to_2_ext_mat, f=f
    )
    coords2, _ = project_cam_coords_with_object_transformations(
        cam_coords_f1, id_image, obj_ids, obj_trans, cam_1_to_2_ext_mat, f=xp
    )
    pixels1 = svg.cam_to_ds_pixel_coords(cam_coords_f1, calib_mat, f=xp)
    pixels2 = svg.cam_to_ds_pixel_coords(coords2, calib_mat, f=xp)
    return _pixels(xp, pixels2) - _pixels(xp, pixels1)
