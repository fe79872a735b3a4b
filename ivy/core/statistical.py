"""Reductions. ``axis`` is None (all axes), an int or a tuple; ``keepdims`` keeps reduced axes.

Integer sums and products accumulate in int64 on every backend. ``logsumexp``, ``median`` and
``quantile`` compute integers and bools in float32, the default float dtype.
"""

from __future__ import annotations

import builtins
import math
import numbers
import operator
from collections.abc import Sequence
from typing import Literal

from ivy import framework_handler as _fh
from ivy.core._dispatch import composition, dispatch
from ivy.core._floats import floating
from ivy.typing import Array, Dtype, Framework

__all__ = [
    "sum",
    "prod",
    "mean",
    "min",
    "max",
    "var",
    "std",
    "cumulative_sum",
    "cumulative_prod",
    "logsumexp",
    "median",
    "quantile",
]


@dispatch
def sum(
    x: Array,
    /,
    *,
    axis: int | tuple[int, ...] | None = None,
    dtype: Dtype | None = None,
    keepdims: bool = False,
    f: Framework = None,
) -> Array:
    """Sum of ``x`` over ``axis``. Example: ``ivy.sum(np.ones((2, 3)), axis=1)`` -> [3., 3.]."""


@dispatch
def prod(
    x: Array,
    /,
    *,
    axis: int | tuple[int, ...] | None = None,
    dtype: Dtype | None = None,
    keepdims: bool = False,
    f: Framework = None,
) -> Array:
    """Product of ``x`` over ``axis``."""


@dispatch
def mean(
    x: Array,
    /,
    *,
    axis: int | tuple[int, ...] | None = None,
    keepdims: bool = False,
    f: Framework = None,
) -> Array:
    """Arithmetic mean of a floating ``x`` over ``axis``."""


@dispatch
def min(
    x: Array,
    /,
    *,
    axis: int | tuple[int, ...] | None = None,
    keepdims: bool = False,
    f: Framework = None,
) -> Array:
    """Minimum of ``x`` over ``axis`` (nan propagates)."""


@dispatch
def max(
    x: Array,
    /,
    *,
    axis: int | tuple[int, ...] | None = None,
    keepdims: bool = False,
    f: Framework = None,
) -> Array:
    """Maximum of ``x`` over ``axis`` (nan propagates)."""


@dispatch
def var(
    x: Array,
    /,
    *,
    axis: int | tuple[int, ...] | None = None,
    correction: float = 0.0,
    keepdims: bool = False,
    f: Framework = None,
) -> Array:
    """Variance over ``axis``, dividing by ``N - correction`` (1 gives the sample variance)."""


@dispatch
def std(
    x: Array,
    /,
    *,
    axis: int | tuple[int, ...] | None = None,
    correction: float = 0.0,
    keepdims: bool = False,
    f: Framework = None,
) -> Array:
    """Standard deviation over ``axis``, dividing by ``N - correction``."""


@dispatch
def cumulative_sum(
    x: Array,
    /,
    *,
    axis: int | None = None,
    dtype: Dtype | None = None,
    include_initial: bool = False,
    f: Framework = None,
) -> Array:
    """Running sums along ``axis`` (None only for 1-D ``x``), starting with 0 when
    ``include_initial``. Bools and signed integers accumulate in int64, unsigned ones in uint64.

    Example: ``ivy.cumulative_sum(np.array([1, 2, 3]))`` -> ``[1, 3, 6]``.
    """


@dispatch
def cumulative_prod(
    x: Array,
    /,
    *,
    axis: int | None = None,
    dtype: Dtype | None = None,
    include_initial: bool = False,
    f: Framework = None,
) -> Array:
    """Running products along ``axis`` (None only for 1-D ``x``), starting with 1 when
    ``include_initial``; dtypes as :func:`cumulative_sum` (Array API 2024.12)."""


@dispatch
def logsumexp(
    x: Array,
    /,
    *,
    axis: int | tuple[int, ...] | None = None,
    keepdims: bool = False,
    f: Framework = None,
) -> Array:
    """``log(sum(exp(x)))`` over ``axis``, computed stably (shifted by the maximum).

    Infinities give the limits: all ``-inf`` (or no element) gives ``-inf``, any ``+inf`` gives
    ``inf``; NaN propagates.

    Args:
        x: array; integers and bools are computed in float32.
        axis: None (all axes), an int or a tuple of ints.
        keepdims: keep the reduced axes with size 1.

    Returns:
        The reduction, of ``x``'s floating dtype.

    Example: ``ivy.logsumexp(np.array([0., np.log(3.)]))`` -> ``log(4.)``.
    """


_QUANTILE_METHODS = ("linear", "lower", "higher", "nearest", "midpoint")


def _reduced_last(xp, x, axis, name):
    """``x`` with the axes of ``axis`` moved last and flattened into one.

    Only the sizes of the reduced axes need to be known (inside ``tf.function``), unless some
    axes are kept and more than one is reduced.

    Returns:
        ``(flat, n, axes)``: ``flat`` of shape ``kept + (n,)`` and the reduced axes, sorted.
    """
    shape = tuple(xp.shape(x))
    ndim = len(shape)
    if axis is None:
        axes = tuple(range(ndim))
    else:
        axes = (axis,) if isinstance(axis, numbers.Integral) else tuple(axis)
        if any(not -ndim <= a < ndim for a in axes):
            raise ValueError(f"{name}: axis {axis} is out of bounds for {ndim} dimensions.")
        axes = tuple(sorted(operator.index(a) % ndim for a in axes))
        if len(set(axes)) != len(axes):
            raise ValueError(f"{name}: repeated axis in {axis}.")
    kept = [a for a in range(ndim) if a not in axes]
    if any(shape[a] is None for a in axes) or (len(axes) > 1 and None in shape):
        raise ValueError(
            f"{name} needs the sizes of the axes it reduces (and of all axes when it reduces "
            f"several), unknown here (inside tf.function); give the tf.function an "
            f"input_signature with known sizes."
        )
    n = math.prod(shape[a] for a in axes)
    if kept + list(axes) != list(range(ndim)):
        x = xp.permute_dims(x, tuple(kept + list(axes)))
    if len(axes) != 1:  # flatten the reduced axes into one (a 0-d x gets one of size 1)
        x = xp.reshape(x, tuple(shape[a] for a in kept) + (n,))
    return x, n, axes


def _keep_dims(xp, out, axes, lead):
    """``out`` (the reduction, after ``lead`` leading axes) with the reduced ``axes`` put back
    with size 1."""
    for a in axes:
        out = xp.expand_dims(out, axis=a + lead)
    return out


@composition
def median(
    x: Array,
    /,
    *,
    axis: int | tuple[int, ...] | None = None,
    keepdims: bool = False,
    f: Framework = None,
) -> Array:
    """Median of ``x`` over ``axis``: the middle element, or the mean of the two middle ones, as
    ``numpy.median`` computes it.

    A reduction that holds a NaN, or no element, gives NaN.

    Args:
        x: real array; integers and bools are computed in float32.
        axis: None (all axes), an int or a tuple of ints.
        keepdims: keep the reduced axes with size 1.

    Returns:
        The medians, of ``x``'s floating dtype.

    Example: ``ivy.median(np.array([[3., 1.], [2., 4.]]), axis=1)`` -> ``[2., 3.]``.
    """
    xp = _fh.get_framework(x, f=f)
    flat, n, axes = _reduced_last(xp, floating(xp, x), axis, "median")
    if n == 0:
        out = xp.sum(flat, axis=-1) * float("nan")
    else:
        s = xp.sort(flat, axis=-1)
        mid = n // 2
        middle = s[..., mid] if n % 2 else (s[..., mid - 1] + s[..., mid]) / 2
        out = xp.where(xp.isnan(s[..., -1]), float("nan"), middle)  # NaN sorts last
    return _keep_dims(xp, out, axes, 0) if keepdims else out


def _positions_from_numbers(qs, n, method):
    """``(lower, upper, weight)`` lists for the quantiles ``qs`` (Python floats) of ``n`` sorted
    values, computed in Python's float64 as numpy computes them."""
    lower, upper, weight = [], [], []
    for q in qs:
        p = q * (n - 1)
        if method == "linear":
            lo = builtins.min(math.floor(p), n - 1)  # (min is ivy.min here)
            hi, t = builtins.min(lo + 1, n - 1), p - lo
        elif method == "midpoint":
            lo, hi = math.floor(p), math.ceil(p)
            t = 0.0 if lo == hi else 0.5
        else:
            i = {"lower": math.floor, "higher": math.ceil, "nearest": round}[method](p)
            lo, hi, t = i, i, 0.0  # round() rounds halves to even, as numpy.around
        lower.append(lo)
        upper.append(hi)
        weight.append(t)
    return lower, upper, weight


def _positions_from_array(xp, q, n, method):
    """``(lower, upper, weight)`` arrays for the quantiles in the 1-D array ``q``."""
    p = q * (n - 1)
    if method in ("lower", "higher", "nearest"):
        i = {"lower": xp.floor, "higher": xp.ceil, "nearest": xp.round}[method](p)
        i = xp.clip(xp.astype(i, "int64"), 0, n - 1)
        return i, i, xp.zeros_like(p)
    lo = xp.clip(xp.astype(xp.floor(p), "int64"), 0, n - 1)
    if method == "linear":
        hi = xp.clip(lo + 1, 0, n - 1)
        return lo, hi, xp.where(hi == lo, 0.0, p - xp.astype(lo, xp.dtype(p)))
    hi = xp.clip(xp.astype(xp.ceil(p), "int64"), 0, n - 1)
    return lo, hi, xp.where(hi == lo, xp.zeros_like(p), 0.5)


@composition
def quantile(
    x: Array,
    q: float | Sequence[float] | Array,
    /,
    *,
    axis: int | tuple[int, ...] | None = None,
    keepdims: bool = False,
    method: Literal["linear", "lower", "higher", "nearest", "midpoint"] = "linear",
    f: Framework = None,
) -> Array:
    """The ``q``-th quantiles of ``x`` over ``axis``, as ``numpy.quantile`` computes them.

    With the ``n`` values sorted, quantile ``q`` lies at position ``p = q * (n - 1)``:
    ``'linear'`` interpolates between the values around ``p`` (numpy's default, the 7th method of
    Hyndman and Fan), ``'lower'``/``'higher'`` take the value at ``floor(p)``/``ceil(p)``,
    ``'nearest'`` at ``p`` rounded (halves to even) and ``'midpoint'`` the mean of those two. A
    reduction that holds a NaN, or no element, gives NaN (numpy raises for no element; it also
    gives NaN where ``p`` falls exactly on a value next to an infinity, which ivy returns).

    Args:
        x: real array; integers and bools are computed in float32.
        q: a quantile in ``[0, 1]`` (a Python float), a sequence of them or a 1-D array (whose
            values are not checked).
        axis: None (all axes), an int or a tuple of ints.
        keepdims: keep the reduced axes with size 1.
        method: ``'linear'``, ``'lower'``, ``'higher'``, ``'nearest'`` or ``'midpoint'``.

    Returns:
        The quantiles, of ``x``'s floating dtype: the shape of the reduction, after a leading
        axis of ``len(q)`` when ``q`` is a sequence or a 1-D array.

    Example: ``ivy.quantile(np.array([1., 2., 3., 4.]), [0.25, 0.5])`` -> ``[1.75, 2.5]``.
    """
    if method not in _QUANTILE_METHODS:
        raise ValueError(
            f"quantile: unknown method {method!r}; use one of {', '.join(_QUANTILE_METHODS)}."
        )
    xp = _fh.get_framework(x, f=f)
    flat, n, axes = _reduced_last(xp, floating(xp, x), axis, "quantile")
    dt = xp.dtype(flat)
    numbers_given = isinstance(q, (numbers.Real, list, tuple))
    if numbers_given:
        scalar_q = isinstance(q, numbers.Real)
        qs = [float(v) for v in ([q] if scalar_q else q)]
        if any(not 0.0 <= v <= 1.0 for v in qs):
            raise ValueError(f"quantile: q must be in [0, 1]; got {q!r}.")
        m = len(qs)
    else:
        q_shape = tuple(xp.shape(q))
        if len(q_shape) > 1:
            raise ValueError(f"quantile: q must be a float or 1-D; got shape {q_shape}.")
        scalar_q = not q_shape
        m = 1 if scalar_q else q_shape[0]
    if n == 0:
        nothing = xp.sum(flat, axis=-1, keepdims=True) * float("nan")
        out = xp.concat([nothing] * m, axis=-1)
    else:
        s = xp.sort(flat, axis=-1)
        if numbers_given:
            lo, hi, t = _positions_from_numbers(qs, n, method)
            device = xp.dev(s)
            lo, hi = xp.asarray(lo, device=device), xp.asarray(hi, device=device)
            t = xp.asarray(t, dtype=dt, device=device)
        else:
            lo, hi, t = _positions_from_array(xp, xp.reshape(xp.astype(q, dt), (m,)), n, method)
        a = xp.take(s, lo, axis=-1)
        if method in ("lower", "higher", "nearest"):
            out = a
        else:  # numpy's interpolation (monotonic, exact at both ends), and exact on a value
            b = xp.take(s, hi, axis=-1)
            d = b - a
            lerp = xp.where(t >= 0.5, b - d * (1 - t), a + d * t)
            out = xp.where(t == 0, a, lerp)
        out = xp.where(xp.isnan(s[..., -1:]), float("nan"), out)  # NaN sorts last
    out = out[..., 0] if scalar_q else xp.moveaxis(out, -1, 0)
    return _keep_dims(xp, out, axes, 0 if scalar_q else 1) if keepdims else out
