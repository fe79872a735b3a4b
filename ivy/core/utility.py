"""Truth tests, closeness and differences. ``axis`` is None (all axes), an int or a tuple."""

from __future__ import annotations

from ivy import framework_handler as _fh
from ivy.core._dispatch import composition, dispatch
from ivy.core._floats import common_floating
from ivy.typing import Array, Framework, Scalar

__all__ = ["all", "any", "diff", "isclose", "allclose"]


@dispatch
def all(  # noqa: A001 - the Array API name
    x: Array,
    /,
    *,
    axis: int | tuple[int, ...] | None = None,
    keepdims: bool = False,
    f: Framework = None,
) -> Array:
    """True where every element over ``axis`` is nonzero (NaN counts as nonzero); True for an
    empty reduction."""


@dispatch
def any(  # noqa: A001 - the Array API name
    x: Array,
    /,
    *,
    axis: int | tuple[int, ...] | None = None,
    keepdims: bool = False,
    f: Framework = None,
) -> Array:
    """True where some element over ``axis`` is nonzero (NaN counts as nonzero); False for an
    empty reduction."""


@dispatch
def diff(
    x: Array,
    /,
    *,
    axis: int = -1,
    n: int = 1,
    prepend: Array | None = None,
    append: Array | None = None,
    f: Framework = None,
) -> Array:
    """The ``n``-th forward difference along ``axis`` (``x[i+1] - x[i]``; for bools, ``!=``),
    after joining ``prepend`` before and ``append`` after ``x`` along that axis.

    Example: ``ivy.diff(np.array([1, 4, 9, 16]))`` -> ``[3, 5, 7]``.
    """


@composition
def isclose(
    x1: Array | Scalar,
    x2: Array | Scalar,
    /,
    *,
    rtol: float = 1e-05,
    atol: float = 1e-08,
    equal_nan: bool = False,
    f: Framework = None,
) -> Array:
    """Where ``x1`` and ``x2`` are equal within a tolerance, as ``numpy.isclose``:
    ``|x1 - x2| <= atol + rtol * |x2|`` for finite ``x2``, or ``x1 == x2`` (so infinities of the
    same sign are close), or both NaN with ``equal_nan``.

    The test is not symmetric: ``rtol`` scales ``|x2|``, the reference.

    Args:
        x1: array (or Python scalar).
        x2: array (or Python scalar), broadcastable with ``x1``.
        rtol: relative tolerance.
        atol: absolute tolerance.
        equal_nan: count NaNs in the same place as close.

    Returns:
        A bool array of the broadcast shape. Integers and bools are compared in float32 (the
        default float dtype), mixed floating dtypes in their promoted dtype.

    Example: ``ivy.isclose(np.array([1., 1.1, np.inf]), np.array([1. + 1e-9, 1., np.inf]))`` ->
    ``[True, False, True]``.
    """
    xp = _fh.get_framework(x1, x2, f=f)
    a, b = common_floating(xp, x1, x2)
    # The tolerance test decides only between finite numbers (infinities and NaN are equal or
    # not): zeros elsewhere keep the arithmetic free of inf - inf and 0 * inf.
    finite = xp.logical_and(xp.isfinite(a), xp.isfinite(b))
    a0, b0 = xp.where(finite, a, 0.0), xp.where(finite, b, 0.0)
    tolerance = xp.add(atol, xp.multiply(rtol, xp.abs(b0)))
    within = xp.logical_and(xp.less_equal(xp.abs(xp.subtract(a0, b0)), tolerance), finite)
    out = xp.logical_or(within, xp.equal(a, b))
    if equal_nan:
        out = xp.logical_or(out, xp.logical_and(xp.isnan(a), xp.isnan(b)))
    return out


@composition
def allclose(
    x1: Array | Scalar,
    x2: Array | Scalar,
    /,
    *,
    rtol: float = 1e-05,
    atol: float = 1e-08,
    equal_nan: bool = False,
    f: Framework = None,
) -> Array:
    """Whether every element of ``x1`` is close to the corresponding element of ``x2``, as
    :func:`isclose` decides (``numpy.allclose``).

    Args:
        x1: array (or Python scalar).
        x2: array (or Python scalar), broadcastable with ``x1``.
        rtol: relative tolerance.
        atol: absolute tolerance.
        equal_nan: count NaNs in the same place as close.

    Returns:
        A 0-d bool array (true for empty inputs).

    Example: ``bool(ivy.allclose(np.array([1., 2.]), np.array([1., 2. + 1e-7])))`` -> ``True``.
    """
    xp = _fh.get_framework(x1, x2, f=f)
    return xp.all(isclose(x1, x2, rtol=rtol, atol=atol, equal_nan=equal_nan, f=xp))
