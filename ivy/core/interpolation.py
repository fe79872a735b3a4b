"""Interpolation along an axis, written once as a composition."""

from __future__ import annotations

from ivy import framework_handler as _fh
from ivy.core._dispatch import composition

__all__ = ["linear_resample"]


def _floating(xp, x):
    """``x``, or ``x`` cast to float32 when it is not of a floating or complex dtype."""
    name = xp.dtype(x, as_str=True)
    return x if "float" in name or "complex" in name else xp.astype(x, "float32")


@composition
def linear_resample(x, num_samples, /, *, axis=-1, f=None):
    """Resample ``x`` along ``axis`` at ``num_samples`` evenly spaced points, linearly
    interpolated.

    The samples span the axis from its first to its last element (both kept exactly); sample
    ``i`` is at position ``i * (n - 1) / (num_samples - 1)`` (a single sample: position 0).

    Args:
        x: array with ``n >= 1`` elements along ``axis``; integers are computed in float32.
        num_samples: the number of samples, at least 1.
        axis: the resampled axis.

    Returns:
        ``x``'s shape with ``num_samples`` along ``axis``.

    Example: ``ivy.linear_resample(np.array([0., 10.]), 5)`` -> ``[0., 2.5, 5., 7.5, 10.]``.
    """
    xp = _fh.get_framework(x, f=f)
    shape = xp.shape(x)
    ndim = len(shape)
    if not -ndim <= axis < ndim:
        raise ValueError(f"linear_resample: axis {axis} is out of bounds for {ndim} dimensions.")
    axis %= ndim
    n = shape[axis]
    if n < 1 or num_samples < 1:
        raise ValueError(
            f"linear_resample: needs at least one element and one sample; got {n} elements "
            f"along axis {axis} and num_samples={num_samples}."
        )
    x = _floating(xp, x)
    step = (n - 1) / (num_samples - 1) if num_samples > 1 else 0.0
    positions = [i * step for i in range(num_samples)]
    lower = [min(int(p), n - 1) for p in positions]
    upper = [min(i + 1, n - 1) for i in lower]
    weights = [p - i for p, i in zip(positions, lower)]
    below = xp.take(x, xp.asarray(lower), axis=axis)
    above = xp.take(x, xp.asarray(upper), axis=axis)
    w = xp.asarray(weights, dtype=xp.dtype(x, as_str=True))
    w = xp.reshape(w, (num_samples,) + (1,) * (ndim - axis - 1))
    return below * (1 - w) + above * w
