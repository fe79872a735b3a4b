"""Interpolation along an axis, written once as a composition."""

from __future__ import annotations

from ivy import framework_handler as _fh
from ivy.core._dispatch import composition
from ivy.core._floats import common_floating
from ivy.typing import Array, Framework, Scalar

__all__ = ["linear_resample", "interp"]


def _floating(xp, x):
    """``x``, or ``x`` cast to float32 when it is not of a floating or complex dtype."""
    name = xp.dtype(x, as_str=True)
    return x if "float" in name or "complex" in name else xp.astype(x, "float32")


@composition
def linear_resample(x: Array, num_samples: int, /, *, axis: int = -1, f: Framework = None) -> Array:
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


@composition
def interp(
    x: Array | Scalar,
    xp: Array,
    fp: Array,
    /,
    *,
    left: float | None = None,
    right: float | None = None,
    f: Framework = None,
) -> Array:
    """Piecewise-linear interpolation of the points ``(xp, fp)`` at ``x``, as ``numpy.interp``.

    Between ``xp[i] <= x < xp[i + 1]`` the value is ``fp[i] + (x - xp[i]) * slope_i``, exactly
    ``fp[i]`` at ``xp[i]`` and ``fp[-1]`` at ``xp[-1]``; outside ``[xp[0], xp[-1]]`` it is ``left``
    or ``right``; a NaN ``x`` gives NaN. Differentiable with respect to ``x`` and ``fp``.

    Args:
        x: where to interpolate, any shape (or a Python scalar).
        xp: 1-D increasing x-coordinates of the points (not checked, as in numpy).
        fp: 1-D real values at ``xp``, of the same length (at least 1).
        left: value for ``x < xp[0]``; default ``fp[0]``.
        right: value for ``x > xp[-1]``; default ``fp[-1]``.

    Returns:
        ``x``'s shape; the promoted floating dtype of ``x``, ``xp`` and ``fp`` (float32 when all
        are integers).

    Example: ``ivy.interp(np.array([0.5, 3.]), np.array([0., 1., 2.]), np.array([0., 10., 0.]))``
    -> ``[5., 0.]``.
    """
    ns = _fh.get_framework(x, xp, fp, f=f)
    x, xp, fp = common_floating(ns, x, xp, fp)
    n = tuple(ns.shape(xp))
    if None in n:
        raise ValueError(
            "interp needs the length of xp, which is unknown here (inside tf.function); give "
            "the tf.function an input_signature with a known length."
        )
    if len(n) != 1 or tuple(ns.shape(fp)) != n or n[0] < 1:
        raise ValueError(
            f"interp: xp and fp must be 1-D of the same length (at least 1); got shapes "
            f"{tuple(ns.shape(xp))} and {tuple(ns.shape(fp))}."
        )
    n = n[0]
    first, last = fp[0], fp[-1]
    if n == 1:
        out = ns.where(ns.isnan(x), float("nan"), first)
    else:
        j = ns.clip(ns.searchsorted(xp, x, side="right") - 1, 0, n - 2)
        x0, x1 = ns.gather_flat(xp, j), ns.gather_flat(xp, j + 1)
        f0, f1 = ns.gather_flat(fp, j), ns.gather_flat(fp, j + 1)
        slope = ns.divide(ns.subtract(f1, f0), ns.subtract(x1, x0))
        out = ns.add(ns.multiply(slope, ns.subtract(x, x0)), f0)
        # numpy's fallbacks where that is NaN (an infinite slope or value): from the right end,
        # then the common value of a flat segment
        out = ns.where(ns.isnan(out), ns.add(ns.multiply(slope, ns.subtract(x, x1)), f1), out)
        flat = ns.logical_and(
            ns.logical_and(ns.isnan(out), ns.equal(f0, f1)), ns.logical_not(ns.isnan(x))
        )
        out = ns.where(flat, f0, out)
        out = ns.where(ns.equal(x, xp[-1]), last, out)
    out = ns.where(ns.less(x, xp[0]), first if left is None else left, out)
    return ns.where(ns.greater(x, xp[-1]), last if right is None else right, out)
