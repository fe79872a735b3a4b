"""Gradient-safe numerics: functions that stay finite, with finite gradients, at their singular
points, plus the small building blocks applied code keeps needing (Taylor switches, batched
matrix-vector products, stacking scalars into vectors and matrices).

The rule at every singular point is the "double where": ``where(c, f(x), g(x))`` differentiates
both branches, so a branch that is singular where it is *not* selected still poisons the gradient
(``0 * inf = nan``). Each function here first replaces the input of the singular expression by a
harmless value where that expression is not selected, then selects its output. No epsilon is ever
added inside a square root or a denominator and no value is clamped, so away from the singular
point every result is exact.

Example:
    >>> import numpy as np, ivy
    >>> ivy.safe_norm(np.zeros(3))                          # 0, and its gradient is 0, not nan
    array(0.)
    >>> ivy.safe_atan2(np.zeros(2), np.zeros(2))            # 0 at the origin, finite gradient
    array([0., 0.])
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ivy import framework_handler as _fh
from ivy.core._dispatch import composition
from ivy.typing import Array, Framework

__all__ = [
    "safe_sqrt",
    "safe_norm",
    "safe_hypot",
    "safe_atan2",
    "safe_divide",
    "horner",
    "taylor_switch",
    "matvec",
    "stack_vector",
    "stack_matrix",
]

#: Below this value of ``x**2``, :func:`taylor_switch` uses the series (``|x| < 1e-2``): four
#: terms of a series in ``x**2`` then leave an error below ``1e-20``, far under float64 precision.
SMALL_SQ = 1e-4


@composition
def safe_sqrt(x: Array, /, *, f: Framework = None) -> Array:
    """Square root whose gradient at 0 is 0 instead of infinity.

    Rule at the singular point: for ``x <= 0`` the result is 0 and its gradient is 0 (so a
    negative input, usually a rounding error of a sum of squares, gives 0, not NaN); for
    ``x > 0`` it is exactly ``sqrt(x)`` with the exact gradient.

    Args:
        x: floating array.
        f: framework name or namespace; inferred from ``x`` if None.

    Returns:
        An array of ``x``'s shape and dtype.

    Example: ``ivy.safe_sqrt(np.array([4.0, 0.0, -1e-18]))`` -> ``[2., 0., 0.]``.
    """
    xp = _fh.get_framework(x, f=f)
    positive = x > 0
    root = xp.sqrt(xp.where(positive, x, xp.ones_like(x)))
    return xp.where(positive, root, xp.zeros_like(x))


@composition
def safe_norm(
    x: Array, /, *, axis: int | tuple[int, ...] = -1, keepdims: bool = False, f: Framework = None
) -> Array:
    """Euclidean norm along ``axis`` whose gradient at the zero vector is 0 instead of NaN.

    Rule at the singular point: the norm of a zero vector is 0 with gradient 0 (the subgradient
    of smallest norm); elsewhere the value and gradient are exact (``x / |x|``).

    Args:
        x: floating array.
        axis: the axis (or axes) of the vectors; the last by default.
        keepdims: keep the reduced axes with length 1.
        f: framework name or namespace; inferred from ``x`` if None.

    Returns:
        The norms, of ``x``'s dtype.

    Example: ``ivy.safe_norm(np.array([[3.0, 4.0], [0.0, 0.0]]))`` -> ``[5., 0.]``.
    """
    xp = _fh.get_framework(x, f=f)
    return safe_sqrt(xp.sum(x * x, axis=axis, keepdims=keepdims), f=xp)


@composition
def safe_hypot(x1: Array, x2: Array, /, *, f: Framework = None) -> Array:
    """``sqrt(x1**2 + x2**2)`` whose gradient at ``(0, 0)`` is ``(0, 0)`` instead of NaN.

    Rule at the singular point: as :func:`safe_norm` of the vector ``(x1, x2)``. Unlike
    ``ivy.hypot`` it does not guard against overflow of the squares (values beyond ``1e154`` in
    float64, ``1e19`` in float32).

    Args:
        x1: floating array.
        x2: floating array broadcastable with ``x1``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        The broadcast shape, of the promoted dtype.

    Example: ``ivy.safe_hypot(np.array([3.0, 0.0]), np.array([4.0, 0.0]))`` -> ``[5., 0.]``.
    """
    xp = _fh.get_framework(x1, x2, f=f)
    return safe_sqrt(x1 * x1 + x2 * x2, f=xp)


@composition
def safe_atan2(x1: Array, x2: Array, /, *, f: Framework = None) -> Array:
    """``atan2(x1, x2)`` (the angle of the point ``(x2, x1)``) with finite gradients at the origin.

    Rule at the singular point: at ``x1 == x2 == 0`` the angle is 0 and the gradient is that of
    ``atan2(x1, 1)`` there, ``(1, 0)`` for ``(x1, x2)``; ``ivy.atan2``'s own gradient is
    ``0 / 0 = NaN``. Signed zeros are not distinguished at the origin (``atan2(0, -0)`` is 0, not
    pi). Everywhere else value and gradient are exact.

    Args:
        x1: the y-coordinates, floating array.
        x2: the x-coordinates, broadcastable with ``x1``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Angles in ``[-pi, pi]``, of the broadcast shape and promoted dtype.

    Example: ``ivy.safe_atan2(np.array([1.0, 0.0]), np.array([0.0, 0.0]))`` -> ``[1.5708, 0.]``.
    """
    xp = _fh.get_framework(x1, x2, f=f)
    origin = xp.logical_and(x1 == 0, x2 == 0)
    return xp.atan2(x1, xp.where(origin, xp.ones_like(x2), x2))


@composition
def safe_divide(x1: Array, x2: Array, /, *, fill: float = 0.0, f: Framework = None) -> Array:
    """``x1 / x2`` where ``x2 != 0``, and ``fill`` where ``x2 == 0``, with finite gradients.

    Rule at the singular point: where ``x2 == 0`` the result is ``fill`` and its gradient with
    respect to both inputs is 0; elsewhere value and gradients are exact. Use it where a zero
    denominator means "no data" (a mean over zero samples, a ray parallel to a plane), never to
    hide a division that should not happen.

    Args:
        x1: numerator, floating array.
        x2: denominator, broadcastable with ``x1``.
        fill: the value where ``x2 == 0``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        The broadcast shape, of the promoted dtype.

    Example: ``ivy.safe_divide(np.array([1.0, 1.0]), np.array([2.0, 0.0]))`` -> ``[0.5, 0.]``.
    """
    xp = _fh.get_framework(x1, x2, f=f)
    zero = x2 == 0
    quotient = x1 / xp.where(zero, xp.ones_like(x2), x2)
    return xp.where(zero, xp.full_like(quotient, fill), quotient)


@composition
def horner(x: Array, coeffs: Sequence[float], /, *, f: Framework = None) -> Array:
    """The polynomial ``coeffs[0] + coeffs[1] * x + coeffs[2] * x**2 + ...`` by Horner's rule.

    Args:
        x: floating array.
        coeffs: the coefficients, lowest power first (Python floats or broadcastable arrays).
        f: framework name or namespace; inferred from ``x`` if None.

    Returns:
        An array of ``x``'s shape and dtype.

    Example: ``ivy.horner(np.array([2.0]), (1.0, 0.0, 3.0))`` -> ``[13.]`` (``1 + 3 x**2``).
    """
    if len(coeffs) == 0:
        raise ValueError("horner: coeffs is empty; give at least one coefficient.")
    if len(coeffs) == 1:
        return x * 0 + coeffs[0]
    acc = x * coeffs[-1] + coeffs[-2]
    for c in reversed(coeffs[:-2]):
        acc = acc * x + c
    return acc


@composition
def taylor_switch(
    x_sq: Array,
    series: Sequence[float] | Sequence[Sequence[float]],
    exact: Callable[[Array], Array | tuple[Array, ...]],
    /,
    *,
    threshold: float = SMALL_SQ,
    f: Framework = None,
) -> Array | tuple[Array, ...]:
    """A function of ``x`` that is singular-looking at 0 (``sin(x) / x``, ``(1 - cos x) / x**2``),
    computed from ``x_sq = x**2`` exactly everywhere, with exact gradients at 0.

    Where ``x_sq < threshold`` the result is the series ``sum(series[i] * x_sq**i)``; elsewhere it
    is ``exact(x)`` with ``x = sqrt(x_sq)``. The series branch needs no square root, so the
    gradient at ``x_sq == 0`` is the series' own; the exact branch sees ``x = 1`` where it is not
    selected, so its gradient stays finite there (the double where). Four terms of a series in
    ``x**2`` are exact to float64 precision below the default threshold (``|x| < 1e-2``).

    Rule at the singular point: the value and gradient at ``x_sq == 0`` are those of the series.

    Args:
        x_sq: the square of the argument, ``>= 0`` (usually a sum of squares, such as the squared
            angle of a rotation vector).
        series: coefficients in powers of ``x_sq``, lowest first; or a tuple of such tuples, one
            per output when ``exact`` returns a tuple.
        exact: ``exact(x) -> array`` (or a tuple of arrays), the closed form, given
            ``x = sqrt(x_sq)`` (>= 0).
        threshold: where to switch, in units of ``x**2``.
        f: framework name or namespace; inferred from ``x_sq`` if None.

    Returns:
        One array (or a tuple, as ``exact`` returns) broadcast with ``x_sq``.

    Example: ``sinc`` without the singularity:
        >>> sinc = lambda x_sq: ivy.taylor_switch(
        ...     x_sq, (1.0, -1 / 6, 1 / 120, -1 / 5040), lambda x: ivy.sin(x) / x)
        >>> sinc(np.array([0.0, np.pi ** 2]))
        array([1.00000000e+00, 3.89817183e-17])
    """
    xp = _fh.get_framework(x_sq, f=f)
    small = x_sq < threshold
    x = xp.sqrt(xp.where(small, xp.ones_like(x_sq), x_sq))
    closed = exact(x)
    if isinstance(closed, tuple):
        if len(series) != len(closed):
            raise ValueError(
                f"taylor_switch: exact returned {len(closed)} arrays but series has "
                f"{len(series)} coefficient tuples; give one tuple of coefficients per output."
            )
        return tuple(xp.where(small, horner(x_sq, s, f=xp), c) for s, c in zip(series, closed))
    return xp.where(small, horner(x_sq, series, f=xp), closed)


@composition
def matvec(x1: Array, x2: Array, /, *, f: Framework = None) -> Array:
    """Batched matrix-vector products: ``x1 @ x2`` for matrices ``[..., M, N]`` and vectors
    ``[..., N]``; the batch dimensions broadcast.

    Args:
        x1: matrices ``[..., M, N]``.
        x2: vectors ``[..., N]``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``[..., M]``, of the promoted dtype.

    Example: ``ivy.matvec(np.eye(3) * 2, np.ones((5, 3)))`` -> five vectors ``[2., 2., 2.]``.
    """
    xp = _fh.get_framework(x1, x2, f=f)
    return xp.matmul(x1, x2[..., None])[..., 0]


@composition
def stack_vector(components: Sequence[Array], /, *, f: Framework = None) -> Array:
    """Stack same-shaped arrays into vectors along a new last axis.

    Args:
        components: ``n`` arrays of one shape ``S``.
        f: framework name or namespace; inferred from the components if None.

    Returns:
        ``S + (n,)``.

    Example: ``ivy.stack_vector([x, y, z])`` -> points ``[..., 3]``.
    """
    xp = _fh.get_framework(*components, f=f)
    return xp.stack(list(components), axis=-1)


@composition
def stack_matrix(rows: Sequence[Sequence[Array]], /, *, f: Framework = None) -> Array:
    """Build matrices ``[..., n, m]`` from ``n`` rows of ``m`` same-shaped arrays.

    It stacks without reshaping, so it works where the batch shape is unknown until run time
    (inside ``tf.function`` with a ``None`` batch dimension).

    Args:
        rows: ``n`` sequences of ``m`` arrays of one shape ``S``.
        f: framework name or namespace; inferred from the entries if None.

    Returns:
        ``S + (n, m)``.

    Example: ``ivy.stack_matrix([[c, -s], [s, c]])`` -> 2-D rotation matrices ``[..., 2, 2]``.
    """
    xp = _fh.get_framework(*[a for row in rows for a in row], f=f)
    return xp.stack([xp.stack(list(row), axis=-1) for row in rows], axis=-2)
