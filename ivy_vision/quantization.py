"""Rendering point clouds into images: ``quantize_to_image`` scatters points with features to
their nearest pixels, fusing the points that share a pixel by their variances or keeping the
nearest one with a depth buffer.

Example:
    >>> mean, var, count = quantize_to_image(np.array([[0.2, 0.1], [0.9, 0.1]]), (1, 2),
    ...                                      np.array([[1.], [3.]]))
    >>> mean[0, :, 2], count[0, :, 0]
    (array([1., 3.]), array([1., 1.]))
"""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework, Shape
from ivy_vision import _common as C
from ivy_vision import _splat as S
from ivy_vision._checks import InputError, checked

__all__ = ["quantize_to_image"]


def _as_array(xp, value, shape, like):
    """A float (broadcast to ``shape``) or an array broadcastable to it."""
    if isinstance(value, (int, float)):
        return xp.full(shape, float(value), dtype=xp.dtype(like), device=xp.dev(like))
    return xp.broadcast_to(xp.astype(value, xp.dtype(like)), shape)


@checked
def quantize_to_image(
    pixel_coords: Array,
    final_image_dims: Shape,
    feat: Array | None = None,
    feat_prior=None,
    with_db: bool = False,
    pixel_coords_var=1e-3,
    feat_var=1e-3,
    pixel_coords_prior_var=1e12,
    feat_prior_var=1e12,
    var_threshold=(1e-3, 1e12),
    uniform_pixel_coords: Array | None = None,
    *,
    f: Framework = None,
) -> tuple:
    """Render points with features into an image: each point goes to its nearest pixel
    ``(floor(x + 0.5), floor(y + 0.5))``; the image's channels are the points' pixel
    coordinates ``(x, y)`` followed by their features.

    Points that share a pixel are fused by inverse-variance weighting (``mean = sum(m / v) /
    sum(1 / v)``, and a variance ``count / sum(1 / v)`` that does not shrink with the number of
    points, since they are not independent measurements); with the depth buffer
    (``with_db``, the first feature being the depth) the point of least depth wins instead
    (exact ties are averaged). Variances are floored at ``var_threshold[0]``; points with any
    variance at or above ``var_threshold[1]``, or outside the image, are left out. Pixels that
    receive no point hold the prior: their own pixel coordinates and ``feat_prior``, with the
    prior variances. The shapes do not depend on the data, so it compiles.

    Args:
        pixel_coords: ``(x, y)`` pixel coordinates *[batch_shape, num_points, 2]*.
        final_image_dims: ``(height, width)`` of the image.
        feat: point features (depth first for ``with_db``) *[batch_shape, num_points, d]*.
        feat_prior: features of empty pixels, a float or *[batch_shape, h, w, d]*; 0 if None.
        with_db: keep the nearest point of each pixel instead of fusing them.
        pixel_coords_var: variance of the pixel coordinates, a float or
            *[batch_shape, num_points, 2]*.
        feat_var: variance of the features, a float or *[batch_shape, num_points, d]*.
        pixel_coords_prior_var: prior variance of the pixel coordinates, a float or
            *[batch_shape, h, w, 2]*.
        feat_prior_var: prior variance of the features, a float or *[batch_shape, h, w, d]*.
        var_threshold: ``(floor, ceiling)`` of the variances.
        uniform_pixel_coords: pixel coordinates *[(batch_shape,) h, w, 2 or 3]*; created if
            None.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``(mean [batch_shape, h, w, 2 + d], variance [batch_shape, h, w, 2 + d],
        count [batch_shape, h, w, 1])``, the count being the number of points in each pixel.

    Example:
        >>> mean, var, count = quantize_to_image(np.array([[0., 0.], [0.1, 0.]]), (1, 1),
        ...     np.array([[2., 5.], [1., 7.]]), with_db=True)       # depth 1 is nearer
        >>> mean[0, 0], count[0, 0]
        (array([0.1, 0. , 1. , 7. ]), array([2.]))
    """
    xp = ivy.get_framework(pixel_coords, feat, f=f)
    C.check_last_dim(xp, pixel_coords, 2, "pixel_coords")
    shape = C.shape_of(xp, pixel_coords)
    if len(shape) < 2:
        raise InputError(f"pixel_coords must be [..., num_points, 2]; got shape {shape}.")
    batch, n = shape[:-2], shape[-2]
    h, w = C.image_dims_of(final_image_dims, "final_image_dims")
    d = 0 if feat is None else C.shape_of(xp, feat)[-1]
    if feat is not None and C.shape_of(xp, feat)[:-1] != shape[:-1]:
        raise InputError(
            f"feat {C.shape_of(xp, feat)} must be [..., num_points, d] with the leading "
            f"shape {shape[:-1]} of pixel_coords."
        )
    if with_db and d == 0:
        raise InputError("with_db needs features whose first channel is the depth.")
    like = pixel_coords
    means = (
        pixel_coords
        if feat is None
        else xp.concat([pixel_coords, xp.astype(feat, xp.dtype(like))], axis=-1)
    )
    variances = _as_array(xp, pixel_coords_var, (*batch, n, 2), like)
    if d:
        variances = xp.concat([variances, _as_array(xp, feat_var, (*batch, n, d), like)], axis=-1)
    low, high = float(var_threshold[0]), float(var_threshold[1])
    valid = xp.logical_and(
        xp.all(variances < high, axis=-1),
        xp.all(xp.isfinite(means), axis=-1),
    )
    flat, valid = S.pixel_indices(xp, pixel_coords[..., 0], pixel_coords[..., 1], valid, (h, w))
    size = h * w
    index, b = S.global_indices(xp, flat, size)
    total = b * size + 1
    width = 2 + d
    means = xp.reshape(xp.where(valid[..., None], means, xp.zeros_like(means)), (b * n, width))
    variances = xp.reshape(
        xp.where(valid[..., None], variances, xp.ones_like(variances)), (b * n, width)
    )
    weight = xp.astype(xp.reshape(valid, (-1,)), xp.dtype(like))
    count = xp.scatter_flat(index, weight, total)[:, None]
    if with_db:
        winners = S.min_depth_winners(xp, index, means[:, 2], total)
        win = weight * xp.astype(winners, xp.dtype(like))
        wins = xp.scatter_flat(index, win, total)[:, None]
        sums = S.scatter_rows(
            xp, index, xp.concat([means, variances], axis=-1) * win[:, None], total
        )
        fused = xp.safe_divide(sums, wins)
        mean, var = fused[:, :width], fused[:, width:]
    else:
        precision = weight[:, None] / variances
        sums = S.scatter_rows(xp, index, xp.concat([means * precision, precision], axis=-1), total)
        mean = xp.safe_divide(sums[:, :width], sums[:, width:])
        var = xp.safe_divide(xp.broadcast_to(count, (total, width)), sums[:, width:])
    var = xp.maximum(var, xp.full_like(var, low))
    mean = S.unflatten(xp, mean, batch, (h, w), b)
    var = S.unflatten(xp, var, batch, (h, w), b)
    count = S.unflatten(xp, count, batch, (h, w), b)
    if uniform_pixel_coords is None:
        prior_xy = C.pixel_grid(xp, (h, w), xp.dtype(like), xp.dev(like), False)
    else:
        prior_xy = uniform_pixel_coords[..., 0:2]
    prior = [xp.broadcast_to(prior_xy, (*batch, h, w, 2))]
    prior_var = [_as_array(xp, pixel_coords_prior_var, (*batch, h, w, 2), like)]
    if d:
        prior.append(
            _as_array(xp, 0.0 if feat_prior is None else feat_prior, (*batch, h, w, d), like)
        )
        prior_var.append(_as_array(xp, feat_prior_var, (*batch, h, w, d), like))
    empty = count == 0
    mean = xp.where(empty, xp.concat(prior, axis=-1), mean)
    var = xp.where(empty, xp.concat(prior_var, axis=-1), var)
    return mean, var, count
