"""Smoothing images with per-pixel weights or variances (``'VALID'`` windows: the result is
``kernel_dim - 1`` pixels smaller in each direction).

Example:
    >>> mean, weights = weighted_image_smooth(np.ones((3, 3, 1)), np.ones((3, 3, 1)), 3)
    >>> mean, weights
    (array([[[1.]]]), array([[[1.]]]))
"""

from __future__ import annotations

import math

import ivy
from ivy.typing import Array, Framework
from ivy_vision import _common as C
from ivy_vision._checks import InputError, checked

__all__ = [
    "weighted_image_smooth",
    "smooth_image_from_var_image",
    "smooth_image_fom_var_image",
]


def _window_sums(xp, image, kernel):
    """Per-channel sums over ``'VALID'`` windows weighted by ``kernel`` ``[k, k, C]``."""
    shape = C.shape_of(xp, image)
    *batch, h, w, c = shape
    out = xp.depthwise_conv2d(xp.reshape(image, (math.prod(batch), h, w, c)), kernel, 1, "VALID")
    return xp.reshape(out, (*batch, *C.shape_of(xp, out)[1:]))


def _check(xp, mean, other, kernel_dim, other_what):
    h, w = C.check_image(xp, mean, "mean")
    if C.shape_of(xp, other) != C.shape_of(xp, mean):
        raise InputError(
            f"mean {C.shape_of(xp, mean)} and {other_what} {C.shape_of(xp, other)} must "
            f"have the same shape."
        )
    k = int(kernel_dim)
    if k < 1 or k > min(h, w):
        raise InputError(f"kernel_dim must be in [1, {min(h, w)}]; got {kernel_dim}.")
    return k


@checked
def weighted_image_smooth(
    mean: Array, weights: Array, kernel_dim: int, *, f: Framework = None
) -> tuple:
    """Weighted mean of every ``kernel_dim x kernel_dim`` window, per channel.

    Args:
        mean: images *[batch_shape, h, w, d]*.
        weights: non-negative weights of every pixel *[batch_shape, h, w, d]*.
        kernel_dim: the window size.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``(smoothed [batch_shape, h - k + 1, w - k + 1, d], mean_weights [...])``: the weighted
        means (0 where all weights are 0) and the windows' mean weights.

    Example:
        >>> image = np.array([[[1.], [3.]]])
        >>> weighted_image_smooth(image, np.array([[[1.], [3.]]]), 1)[0][..., 0]
        array([[1., 3.]])
    """
    xp = ivy.get_framework(mean, weights, f=f)
    k = _check(xp, mean, weights, kernel_dim, "weights")
    d = C.shape_of(xp, mean)[-1]
    kernel = xp.ones((k, k, d), dtype=xp.dtype(mean), device=xp.dev(mean))
    weight_sums = _window_sums(xp, weights, kernel)
    smoothed = xp.safe_divide(_window_sums(xp, mean * weights, kernel), weight_sums)
    return smoothed, weight_sums / float(k * k)


@checked
def smooth_image_from_var_image(
    mean: Array, var: Array, kernel_dim: int, kernel_scale, *, f: Framework = None
) -> tuple:
    """Fuse every ``kernel_dim x kernel_dim`` window of an image with per-pixel variances.

    A neighbour at distance ``r`` from the window's centre counts as a measurement of the centre
    with variance ``var * (1 + kernel_scale * r)``; the window is fused by inverse-variance
    weighting, ``mean = sum(m / v') / sum(1 / v')``. The fused variance is
    ``k^2 / sum(1 / v')``: the measurements are not independent, so fusing ``k^2`` equal ones
    keeps their variance instead of dividing it by ``k^2``.

    Args:
        mean: images *[batch_shape, h, w, d]*.
        var: positive variances *[batch_shape, h, w, d]*.
        kernel_dim: the window size ``k`` (odd, for a centred window).
        kernel_scale: growth of the variance with distance, a float or per channel *[d]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``(mean [batch_shape, h - k + 1, w - k + 1, d], var [...])``.

    Example:
        >>> smooth_image_from_var_image(np.ones((3, 3, 1)), np.full((3, 3, 1), 2.), 3, 0.)
        (array([[[1.]]]), array([[[2.]]]))
    """
    xp = ivy.get_framework(mean, var, f=f)
    k = _check(xp, mean, var, kernel_dim, "var")
    d = C.shape_of(xp, mean)[-1]
    offsets = xp.arange(k, dtype=xp.dtype(mean), device=xp.dev(mean)) - float(k // 2)
    distance = xp.sqrt(offsets[:, None] ** 2 + offsets[None, :] ** 2)[..., None]
    scale = xp.astype(xp.asarray(kernel_scale, device=xp.dev(mean)), xp.dtype(mean))
    kernel = 1.0 / (1.0 + distance * scale)  # [k, k, d or 1]: how much a neighbour counts
    kernel = xp.broadcast_to(kernel, (k, k, d))
    precision = 1.0 / var
    total = _window_sums(xp, precision, kernel)
    fused_mean = _window_sums(xp, mean * precision, kernel) / total
    return fused_mean, float(k * k) / total


@checked
def smooth_image_fom_var_image(
    mean: Array, var: Array, kernel_dim: int, kernel_scale, *, f: Framework = None
) -> tuple:
    """The original ivy_vision's spelling of :func:`smooth_image_from_var_image`.

    Args:
        mean: images *[batch_shape, h, w, d]*.
        var: positive variances *[batch_shape, h, w, d]*.
        kernel_dim: the window size.
        kernel_scale: growth of the variance with distance, a float or per channel *[d]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``(mean, var)`` as :func:`smooth_image_from_var_image`.

    Example:
        >>> smooth_image_fom_var_image(np.ones((1, 1, 1)), np.ones((1, 1, 1)), 1, 0.)[1]
        array([[[1.]]])
    """
    return smooth_image_from_var_image(mean, var, kernel_dim, kernel_scale, f=f)
