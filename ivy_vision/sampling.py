"""Sampling images at continuous pixel coordinates, and warping images between cameras.

Sampling convention. Pixel ``(row i, column j)`` has its centre at ``(x, y) = (j, i)``; the
image's samples span ``[0, W - 1] x [0, H - 1]``.

- ``method='bilinear'`` interpolates the four pixels around the point; ``'nearest'`` takes the
  pixel at ``(floor(x + 0.5), floor(y + 0.5))`` (halves round up).
- ``padding='border'`` extends the edge pixels outwards (the coordinates are clamped to the
  image): it equals ``scipy.ndimage.map_coordinates(order=1, mode='nearest')`` and torch's
  ``grid_sample(align_corners=True, padding_mode='border')``. ``padding='zeros'`` treats every
  pixel outside the image as 0, so a point half a pixel outside gets half the edge value: it
  equals ``map_coordinates(order=1, mode='grid-constant', cval=0)`` and
  ``grid_sample(align_corners=True, padding_mode='zeros')``.

Gradients flow to the image and (bilinear, inside the image) to the coordinates; at integer
coordinates the interpolation has a kink and the gradient is the one-sided one from above.

Example:
    >>> image = np.arange(6.).reshape(2, 3, 1)
    >>> sample_image(image, np.array([[0.5, 0.5]]))
    array([[2.]])
"""

from __future__ import annotations

import math

import ivy
from ivy.typing import Array, Framework, Shape
from ivy_vision import _common as C
from ivy_vision import _splat as S
from ivy_vision._checks import InputError, checked

__all__ = [
    "sample_image",
    "bilinearly_interpolate_image",
    "inverse_warp",
    "forward_warp",
]

METHODS = ("bilinear", "nearest")
PADDINGS = ("border", "zeros")


def _check_options(method, padding):
    if method not in METHODS:
        raise InputError(f"method must be one of {METHODS}; got {method!r}.")
    if padding not in PADDINGS:
        raise InputError(f"padding must be one of {PADDINGS}; got {padding!r}.")


def _floating(xp, image, like):
    if "float" in xp.dtype(image, as_str=True):
        return image
    return xp.astype(image, xp.dtype(like))


def padded_planes(xp, image, padding):
    """The channel planes ``[C, b * (H + 3) * (W + 3)]`` of ``image`` ``[b, H, W, C]`` with a
    border of one pixel before and two after each axis: zeros, or the edge pixels repeated
    (then clamping to the padded image equals clamping to the image). The second pixel after
    lets a point clamped onto the far border read its (zero-weight) next corner without a
    check. Channel-first, so that gathering a pixel's corners reads whole rows of indices
    (about twice as fast as gathering channel-last rows)."""
    b, h, w, c = C.shape_of(xp, image)
    planes = xp.permute_dims(image, (3, 0, 1, 2))
    if padding == "zeros":
        padded = xp.zero_pad(planes, ((0, 0), (0, 0), (1, 2), (1, 2)))
    else:
        last_row = planes[:, :, -1:]
        rows = xp.concat([planes[:, :, 0:1], planes, last_row, last_row], axis=2)
        last_col = rows[..., -1:]
        padded = xp.concat([rows[..., 0:1], rows, last_col, last_col], axis=3)
    return xp.reshape(padded, (c, b * (h + 3) * (w + 3)))


def sample_planes(xp, planes, dims, xq, yq, method, padding):
    """Sample padded channel planes (:func:`padded_planes` of images of ``dims = (b, H, W)``)
    at coordinates already shifted by +1 into the padded image, ``xq``, ``yq`` ``[b, n]``.
    Returns ``[C, b, n]``.

    The coordinates are clamped to the padded image, so that points beyond the border get the
    padding value and both paddings share one code path; the four corners of every point are
    gathered in one call. A NaN coordinate is moved to the padded corner ``(0, 0)`` before any
    index is computed from it (a NaN cast to an integer is an arbitrary index: numpy and
    tensorflow raise, torch reads out of bounds, jax clamps), and its sample is 0 on both
    paddings."""
    b, h, w = dims
    c = C.shape_of(xp, planes)[0]
    n = C.shape_of(xp, xq)[-1]
    unknown = xp.isnan(xq + yq)  # either is NaN (or they are opposite infinities)
    xq = xp.where(unknown, xp.zeros_like(xq), xq)
    yq = xp.where(unknown, xp.zeros_like(yq), yq)
    xq = xp.clip(xq, 0.0, float(w + 1))
    yq = xp.clip(yq, 0.0, float(h + 1))
    index_type = C.index_dtype(xp)

    def flat_index(row, col):
        index = xp.astype(row, index_type) * (w + 3) + xp.astype(col, index_type)
        if b > 1:
            base = xp.arange(b, dtype=index_type, device=xp.dev(xq)) * ((h + 3) * (w + 3))
            index = index + base[:, None]
        return index

    if method == "nearest":
        index = flat_index(xp.floor(yq + 0.5), xp.floor(xq + 0.5))
        out = xp.reshape(xp.take(planes, xp.reshape(index, (-1,)), axis=1), (c, b, n))
    else:
        x0, y0 = xp.floor(xq), xp.floor(yq)
        wx, wy = xq - x0, yq - y0
        top = flat_index(y0, x0)
        corners = xp.asarray([0, 1, w + 3, w + 4], dtype=index_type, device=xp.dev(xq))
        index = xp.reshape(top, (1, b * n)) + corners[:, None]  # corner-major [4, b*n]
        values = xp.reshape(xp.take(planes, xp.reshape(index, (-1,)), axis=1), (c, 4, b, n))
        upper = values[:, 0] + (values[:, 1] - values[:, 0]) * wx
        lower = values[:, 2] + (values[:, 3] - values[:, 2]) * wx
        out = upper + (lower - upper) * wy
    if padding == "zeros":  # the padded corner (0, 0) is 0 already
        return out
    return xp.where(unknown, xp.zeros_like(out), out)  # not the corner pixel


def channels_last(xp, planes_out, shape):
    """``[C, b, n]`` -> ``shape`` (``[*batch, *points, C]``)."""
    return xp.reshape(xp.permute_dims(planes_out, (1, 2, 0)), shape)


def sample_kernel(xp, image, coords, method, padding):
    """Sample ``image`` ``[*B, H, W, C]`` at ``coords`` ``[*B, *I, 2]`` -> ``[*B, *I, C]``."""
    h, w = C.check_image(xp, image, "image")
    C.check_last_dim(xp, coords, 2, "the sampling coordinates")
    ishape = C.shape_of(xp, image)
    ib = ishape[:-3]
    cb, points = C.split_batch(xp, coords, ib, "the sampling coordinates", "image")
    batch = C.broadcast_batch(cb, ib, "the sampling coordinates", "image")
    c = ishape[-1]
    b, n = math.prod(batch), math.prod(points)
    if ib != batch:
        image = xp.broadcast_to(image, (*batch, h, w, c))
    if cb != batch:
        coords = xp.broadcast_to(coords, (*batch, *points, 2))
    image = xp.reshape(_floating(xp, image, coords), (b, h, w, c))
    coords = xp.reshape(coords, (b, n, 2))
    planes = padded_planes(xp, image, padding)
    xq, yq = coords[..., 0] + 1.0, coords[..., 1] + 1.0
    out = sample_planes(xp, planes, (b, h, w), xq, yq, method, padding)
    return channels_last(xp, out, (*batch, *points, c))


@checked
def sample_image(
    image: Array,
    pixel_coords: Array,
    *,
    method: str = "bilinear",
    padding: str = "border",
    f: Framework = None,
) -> Array:
    """Sample images at continuous pixel coordinates (see the module docstring for the
    conventions).

    Args:
        image: images *[batch_shape, h, w, c]*; integer images are sampled in the coordinates'
            dtype.
        pixel_coords: ``(x, y)`` sampling coordinates *[batch_shape, sample_shape, 2]*.
        method: ``'bilinear'`` or ``'nearest'``.
        padding: ``'border'`` (edge pixels extend outwards) or ``'zeros'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Sampled values *[batch_shape, sample_shape, c]*.

    Example:
        >>> image = np.arange(4.).reshape(2, 2, 1)
        >>> sample_image(image, np.array([[-0.5, 0.], [0.5, 1.]]), padding='zeros')
        array([[0. ],
               [2.5]])
    """
    xp = ivy.get_framework(image, pixel_coords, f=f)
    _check_options(method, padding)
    return sample_kernel(xp, image, pixel_coords, method, padding)


@checked
def bilinearly_interpolate_image(
    image: Array, sampling_pixel_coords: Array, *, f: Framework = None
) -> Array:
    """Bilinear interpolation of images at pixel coordinates, with the border extended (the
    original ivy_vision's function; :func:`sample_image` with its defaults).

    Args:
        image: images *[batch_shape, h, w, c]*.
        sampling_pixel_coords: ``(x, y)`` coordinates *[batch_shape, sample_shape, 2]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Interpolated values *[batch_shape, sample_shape, c]*.

    Example:
        >>> bilinearly_interpolate_image(np.arange(4.).reshape(2, 2, 1), np.array([[0.5, 0.5]]))
        array([[1.5]])
    """
    xp = ivy.get_framework(image, sampling_pixel_coords, f=f)
    return sample_kernel(xp, image, sampling_pixel_coords, "bilinear", "border")


def project_depth(xp, depth, full_mat, uniform_pixel_coords):
    """Depth-scaled pixel coordinates in another camera of every pixel of a depth image, as
    ``d * (M [u, v, 1]) + t`` for ``full_mat = [M | t]``, channel-first: ``[*B, 3, H*W]`` (each
    component contiguous, which the sampling reads fastest). For the default pixel grid the
    rays ``M [u, v, 1]`` are sums of a row term and a column term (no matrix product over the
    image)."""
    C.check_image(xp, depth, "the depth image", channels=1)
    C.check_matrix(xp, full_mat, 3, 4, "the camera-to-camera full matrix")
    C.broadcast_right(
        C.shape_of(xp, depth)[:-3],
        C.shape_of(xp, full_mat)[:-2],
        "the depth image",
        "the camera-to-camera full matrix",
    )
    dshape = C.shape_of(xp, depth)
    h, w = dshape[-3:-1]
    planar_depth = xp.reshape(depth, (*dshape[:-3], 1, h * w))
    if uniform_pixel_coords is None:
        dtype, device = xp.dtype(depth), xp.dev(depth)
        cols = xp.arange(w, dtype=dtype, device=device)
        rows = xp.arange(h, dtype=dtype, device=device)
        m = full_mat[..., None, None]  # [*B, 3, 4, 1, 1]
        rays = m[..., 0, :, :] * cols + (m[..., 1, :, :] * rows[:, None] + m[..., 2, :, :])
        rays = xp.reshape(rays, (*C.shape_of(xp, rays)[:-2], h * w))
    else:
        C.check_last_dim(xp, uniform_pixel_coords, 3, "uniform_pixel_coords")
        gshape = C.shape_of(xp, uniform_pixel_coords)
        grid = xp.swapaxes(xp.reshape(uniform_pixel_coords, (*gshape[:-3], h * w, 3)), -1, -2)
        rays = xp.matmul(full_mat[..., 0:3], grid)
    return rays * planar_depth + full_mat[..., 3:4]


def _shift_by_one(xp, full_mat):
    """``full_mat`` whose projections land one pixel right and down (``x + 1``, ``y + 1``): the
    coordinates of the padded images, for free."""
    return xp.concat(
        [full_mat[..., 0:2, :] + full_mat[..., 2:3, :], full_mat[..., 2:3, :]], axis=-2
    )


@checked
def inverse_warp(
    image_src: Array,
    depth_tgt: Array,
    tgt_to_src_full_mat: Array,
    uniform_pixel_coords: Array | None = None,
    *,
    method: str = "bilinear",
    padding: str = "zeros",
    with_validity: bool = False,
    f: Framework = None,
) -> Array | tuple:
    """Inverse warping: the image a target camera would see, sampled from a source image
    through the target's depth and the relative pose.

    Every target pixel is unprojected with its depth, projected into the source camera
    (``tgt_to_src_full_mat = P_src P_tgt^-1``) and the source image is sampled there. Pixels
    whose projection lies behind the source camera are 0.

    Args:
        image_src: source images *[batch_shape, hs, ws, c]*.
        depth_tgt: planar depth images of the target camera *[batch_shape, h, w, 1]*.
        tgt_to_src_full_mat: target-to-source full matrices *[batch_shape, 3, 4]*.
        uniform_pixel_coords: target pixel coordinates *[(batch_shape,) h, w, 3]*; created if
            None.
        method: ``'bilinear'`` or ``'nearest'`` sampling.
        padding: ``'zeros'`` (outside the source image is 0, as kornia's warp_frame_depth) or
            ``'border'``.
        with_validity: also return where the target depth is positive and its projection lies
            in front of the source camera and inside its image.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Warped images *[batch_shape, h, w, c]*, and with ``with_validity`` a boolean mask
        *[batch_shape, h, w, 1]*.

    Example:
        >>> image = np.arange(6.).reshape(2, 3, 1)
        >>> inverse_warp(image, np.ones((2, 3, 1)), np.eye(3, 4))[..., 0]   # same camera
        array([[0., 1., 2.],
               [3., 4., 5.]])
    """
    xp = ivy.get_framework(image_src, depth_tgt, tgt_to_src_full_mat, f=f)
    _check_options(method, padding)
    C.check_matrix(xp, tgt_to_src_full_mat, 3, 4, "tgt_to_src_full_mat")
    h, w = C.check_image(xp, depth_tgt, "depth_tgt", channels=1)
    hs, ws = C.check_image(xp, image_src, "image_src")
    C.reject_channel_first(xp, image_src, "image_src", (h, w), "depth_tgt")
    # missing depth (NaN, as depth sensors report it, or infinite) is replaced by 0 before the
    # projection, so that no NaN reaches an index or a gradient, and the pixel is invalid
    measured = xp.isfinite(depth_tgt)
    depth = xp.where(measured, depth_tgt, xp.zeros_like(depth_tgt))
    shifted = _shift_by_one(xp, tgt_to_src_full_mat)
    projected = project_depth(xp, depth, shifted, uniform_pixel_coords)
    batch = C.broadcast_right(
        C.shape_of(xp, projected)[:-2],
        C.shape_of(xp, image_src)[:-3],
        "the target depth",
        "image_src",
    )
    c = C.shape_of(xp, image_src)[-1]
    b = math.prod(batch)
    z = projected[..., 2, :]
    dshape = C.shape_of(xp, depth_tgt)
    measured = xp.reshape(measured, (*dshape[:-3], h * w))
    in_front = xp.logical_and(z > 0, measured)
    inverse_z = 1.0 / xp.where(in_front, z, xp.ones_like(z))
    # coordinates in the padded source image (x + 1, y + 1)
    xq, yq = projected[..., 0, :] * inverse_z, projected[..., 1, :] * inverse_z
    if padding == "zeros":  # behind the camera: sample the zero border
        xq = xp.where(in_front, xq, xp.zeros_like(xq))
    image = xp.reshape(
        xp.broadcast_to(_floating(xp, image_src, z), (*batch, hs, ws, c)), (b, hs, ws, c)
    )
    if C.shape_of(xp, xq) != (*batch, h * w):
        xq = xp.broadcast_to(xq, (*batch, h * w))
        yq = xp.broadcast_to(yq, (*batch, h * w))
    planes = padded_planes(xp, image, padding)
    warped = sample_planes(
        xp,
        planes,
        (b, hs, ws),
        xp.reshape(xq, (b, h * w)),
        xp.reshape(yq, (b, h * w)),
        method,
        padding,
    )
    front = xp.reshape(xp.broadcast_to(in_front, (*batch, h * w)), (b, h * w))
    if padding == "border":
        warped = xp.where(front, warped, xp.zeros_like(warped))
    warped = channels_last(xp, warped, (*batch, h, w, c))
    if not with_validity:
        return warped
    inside = xp.logical_and(
        xp.logical_and(xq >= 0.5, xq <= ws + 0.5), xp.logical_and(yq >= 0.5, yq <= hs + 0.5)
    )
    positive = xp.reshape(depth, (*dshape[:-3], h * w)) > 0
    inside = xp.logical_and(inside, positive)
    valid = xp.logical_and(front, xp.reshape(xp.broadcast_to(inside, (*batch, h * w)), (b, h * w)))
    return warped, xp.reshape(valid, (*batch, h, w, 1))


@checked
def forward_warp(
    image_src: Array,
    depth_src: Array,
    src_to_tgt_full_mat: Array,
    target_image_dims: Shape | None = None,
    uniform_pixel_coords: Array | None = None,
    *,
    with_db: bool = True,
    f: Framework = None,
) -> tuple:
    """Forward warping (splatting): every source pixel is projected into the target camera
    and written to the nearest target pixel.

    With the depth buffer (``with_db``), the nearest point to the target camera wins each
    pixel (the mean of exact ties); without it, the points landing in a pixel are averaged.
    Source pixels without depth (``<= 0``) are left out; target pixels that receive no point
    are 0 and invalid.

    Args:
        image_src: source images *[batch_shape, h, w, c]*.
        depth_src: planar depth images of the source camera *[batch_shape, h, w, 1]*.
        src_to_tgt_full_mat: source-to-target full matrices ``P_tgt P_src^-1``
            *[batch_shape, 3, 4]*.
        target_image_dims: ``(height, width)`` of the target image; the source's if None.
        uniform_pixel_coords: source pixel coordinates *[(batch_shape,) h, w, 3]*; created if
            None.
        with_db: use a depth buffer.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``(image_tgt [batch_shape, ht, wt, c], depth_tgt [batch_shape, ht, wt, 1],
        validity [batch_shape, ht, wt, 1])`` (the target depth is planar, of the target
        camera).

    Example:
        >>> image = np.arange(6.).reshape(2, 3, 1)
        >>> forward_warp(image, np.ones((2, 3, 1)), np.eye(3, 4))[0][..., 0]   # same camera
        array([[0., 1., 2.],
               [3., 4., 5.]])
    """
    xp = ivy.get_framework(image_src, depth_src, src_to_tgt_full_mat, f=f)
    h, w = C.check_image(xp, depth_src, "depth_src", channels=1)
    C.reject_channel_first(xp, image_src, "image_src", (h, w), "depth_src")
    if C.check_image(xp, image_src, "image_src") != (h, w):
        raise InputError(
            f"image_src {C.shape_of(xp, image_src)} and depth_src "
            f"{C.shape_of(xp, depth_src)} must have the same height and width."
        )
    dims = (
        (h, w)
        if target_image_dims is None
        else C.image_dims_of(target_image_dims, "target_image_dims")
    )
    # missing depth (NaN or infinite) becomes 0, a source pixel without depth: left out
    depth_src = xp.where(xp.isfinite(depth_src), depth_src, xp.zeros_like(depth_src))
    projected = project_depth(xp, depth_src, src_to_tgt_full_mat, uniform_pixel_coords)
    batch = C.broadcast_right(
        C.shape_of(xp, projected)[:-2],
        C.shape_of(xp, image_src)[:-3],
        "the source depth",
        "image_src",
    )
    projected = xp.broadcast_to(projected, (*batch, 3, h * w))
    image_src = _floating(xp, image_src, projected)
    c = C.shape_of(xp, image_src)[-1]
    image_src = xp.broadcast_to(image_src, (*batch, h, w, c))
    z = projected[..., 2, :]
    in_front = z > 0
    inverse_z = 1.0 / xp.where(in_front, z, xp.ones_like(z))
    x, y = projected[..., 0, :] * inverse_z, projected[..., 1, :] * inverse_z
    values = xp.concat([xp.reshape(image_src, (*batch, h * w, c)), z[..., None]], axis=-1)
    measured = xp.reshape(depth_src, (*C.shape_of(xp, depth_src)[:-3], h * w)) > 0
    flat, valid = S.pixel_indices(xp, x, y, xp.logical_and(in_front, measured), dims)
    size = dims[0] * dims[1]
    index, b = S.global_indices(xp, flat, size)
    total = b * size + 1
    values = xp.reshape(values, (b * h * w, c + 1))
    weight = xp.astype(xp.reshape(valid, (-1,)), xp.dtype(values))
    if with_db:
        winners = S.min_depth_winners(xp, index, xp.reshape(z, (-1,)), total)
        weight = weight * xp.astype(winners, xp.dtype(values))
    sums = S.scatter_rows(xp, index, values * weight[:, None], total)
    counts = xp.scatter_flat(index, weight, total)[:, None]
    means = S.unflatten(xp, xp.safe_divide(sums, counts), batch, dims, b)
    validity = S.unflatten(xp, counts > 0, batch, dims, b)
    return means[..., :-1], means[..., -1:], validity
