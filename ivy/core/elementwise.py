"""Elementwise functions, with Array API broadcasting and type promotion.

Binary functions accept Python scalars on either side: ``ivy.add(x, 1.0)``.
"""

from __future__ import annotations

from ivy.core._dispatch import dispatch
from ivy.typing import Array, Framework, Scalar

__all__ = [
    "abs",
    "acos",
    "acosh",
    "add",
    "asin",
    "asinh",
    "atan",
    "atan2",
    "atanh",
    "bitwise_and",
    "bitwise_invert",
    "bitwise_left_shift",
    "bitwise_or",
    "bitwise_right_shift",
    "bitwise_xor",
    "ceil",
    "clip",
    "conj",
    "copysign",
    "cos",
    "cosh",
    "divide",
    "equal",
    "exp",
    "expm1",
    "floor",
    "floor_divide",
    "greater",
    "greater_equal",
    "hypot",
    "imag",
    "isfinite",
    "isinf",
    "isnan",
    "less",
    "less_equal",
    "log",
    "log10",
    "log1p",
    "log2",
    "logaddexp",
    "logical_and",
    "logical_not",
    "logical_or",
    "logical_xor",
    "maximum",
    "minimum",
    "multiply",
    "nan_to_num",
    "negative",
    "nextafter",
    "not_equal",
    "positive",
    "pow",
    "real",
    "reciprocal",
    "remainder",
    "round",
    "sign",
    "signbit",
    "sin",
    "sinh",
    "sqrt",
    "square",
    "subtract",
    "tan",
    "tanh",
    "trunc",
]


@dispatch
def abs(x: Array, /, *, f: Framework = None) -> Array:
    """Absolute value."""


@dispatch(reals=True)
def acos(x: Array, /, *, f: Framework = None) -> Array:
    """Inverse cosine, in radians."""


@dispatch(reals=True)
def acosh(x: Array, /, *, f: Framework = None) -> Array:
    """Inverse hyperbolic cosine."""


@dispatch(reals=True)
def asin(x: Array, /, *, f: Framework = None) -> Array:
    """Inverse sine, in radians."""


@dispatch(reals=True)
def asinh(x: Array, /, *, f: Framework = None) -> Array:
    """Inverse hyperbolic sine."""


@dispatch(reals=True)
def atan(x: Array, /, *, f: Framework = None) -> Array:
    """Inverse tangent, in radians."""


@dispatch(reals=True)
def atanh(x: Array, /, *, f: Framework = None) -> Array:
    """Inverse hyperbolic tangent."""


@dispatch
def ceil(x: Array, /, *, f: Framework = None) -> Array:
    """Smallest integer-valued number not less than x."""


@dispatch(reals=True)
def cos(x: Array, /, *, f: Framework = None) -> Array:
    """Cosine of x in radians."""


@dispatch(reals=True)
def cosh(x: Array, /, *, f: Framework = None) -> Array:
    """Hyperbolic cosine."""


@dispatch(reals=True)
def exp(x: Array, /, *, f: Framework = None) -> Array:
    """Exponential e**x."""


@dispatch(reals=True)
def expm1(x: Array, /, *, f: Framework = None) -> Array:
    """exp(x) - 1, accurate for small x."""


@dispatch
def floor(x: Array, /, *, f: Framework = None) -> Array:
    """Largest integer-valued number not greater than x."""


@dispatch
def isfinite(x: Array, /, *, f: Framework = None) -> Array:
    """True where x is finite."""


@dispatch
def isinf(x: Array, /, *, f: Framework = None) -> Array:
    """True where x is +inf or -inf."""


@dispatch
def isnan(x: Array, /, *, f: Framework = None) -> Array:
    """True where x is nan."""


@dispatch(reals=True)
def log(x: Array, /, *, f: Framework = None) -> Array:
    """Natural logarithm."""


@dispatch(reals=True)
def log1p(x: Array, /, *, f: Framework = None) -> Array:
    """log(1 + x), accurate for small x."""


@dispatch(reals=True)
def log2(x: Array, /, *, f: Framework = None) -> Array:
    """Base-2 logarithm."""


@dispatch(reals=True)
def log10(x: Array, /, *, f: Framework = None) -> Array:
    """Base-10 logarithm."""


@dispatch
def logical_not(x: Array, /, *, f: Framework = None) -> Array:
    """Logical NOT of x (as bool)."""


@dispatch
def negative(x: Array, /, *, f: Framework = None) -> Array:
    """-x."""


@dispatch
def positive(x: Array, /, *, f: Framework = None) -> Array:
    """+x."""


@dispatch
def round(x: Array, /, *, f: Framework = None) -> Array:
    """Round to the nearest integer-valued number, halves to even."""


@dispatch
def sign(x: Array, /, *, f: Framework = None) -> Array:
    """Sign of x: -1, 0 or 1."""


@dispatch(reals=True)
def sin(x: Array, /, *, f: Framework = None) -> Array:
    """Sine of x in radians."""


@dispatch(reals=True)
def sinh(x: Array, /, *, f: Framework = None) -> Array:
    """Hyperbolic sine."""


@dispatch(reals=True)
def sqrt(x: Array, /, *, f: Framework = None) -> Array:
    """Square root."""


@dispatch
def square(x: Array, /, *, f: Framework = None) -> Array:
    """x * x."""


@dispatch(reals=True)
def tan(x: Array, /, *, f: Framework = None) -> Array:
    """Tangent of x in radians."""


@dispatch(reals=True)
def tanh(x: Array, /, *, f: Framework = None) -> Array:
    """Hyperbolic tangent."""


@dispatch
def trunc(x: Array, /, *, f: Framework = None) -> Array:
    """Round toward zero."""


@dispatch("x1", "x2")
def add(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """x1 + x2."""


@dispatch("x1", "x2", reals=True)
def atan2(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """Angle of the point (x2, x1), in radians, in [-pi, pi]."""


@dispatch("x1", "x2", reals=True)
def divide(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """x1 / x2 (true division)."""


@dispatch("x1", "x2")
def equal(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """x1 == x2."""


@dispatch("x1", "x2")
def floor_divide(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """Floor of x1 / x2."""


@dispatch("x1", "x2")
def greater(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """x1 > x2."""


@dispatch("x1", "x2")
def greater_equal(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """x1 >= x2."""


@dispatch("x1", "x2")
def less(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """x1 < x2."""


@dispatch("x1", "x2")
def less_equal(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """x1 <= x2."""


@dispatch("x1", "x2")
def logical_and(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """x1 AND x2 (as bool)."""


@dispatch("x1", "x2")
def logical_or(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """x1 OR x2 (as bool)."""


@dispatch("x1", "x2")
def logical_xor(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """x1 XOR x2 (as bool)."""


@dispatch("x1", "x2")
def maximum(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """Elementwise maximum (nan propagates)."""


@dispatch("x1", "x2")
def minimum(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """Elementwise minimum (nan propagates)."""


@dispatch("x1", "x2")
def multiply(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """x1 * x2."""


@dispatch("x1", "x2")
def not_equal(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """x1 != x2."""


@dispatch("x1", "x2")
def pow(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """x1 ** x2.

    Integers to negative integer powers are refused where the values are known (ValueError, on
    every backend: cast the base to a floating dtype first); inside a compiled program they give
    the integer part of the real power (``ivy/backends/_int_pow.py``).
    """


@dispatch("x1", "x2")
def remainder(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """x1 mod x2, with the sign of x2."""


@dispatch("x1", "x2")
def subtract(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """x1 - x2."""


@dispatch("x", "min", "max")
def clip(
    x: Array,
    /,
    min: Array | Scalar | None = None,
    max: Array | Scalar | None = None,
    *,
    f: Framework = None,
) -> Array:
    """Clamp ``x`` to ``[min, max]``; either bound may be None, a scalar or an array.

    Example: ``ivy.clip(np.array([-1., 2.]), 0, 1, f='torch')`` -> tensor([0., 1.]).
    """


@dispatch
def bitwise_invert(x: Array, /, *, f: Framework = None) -> Array:
    """Bitwise NOT of an integer or bool ``x`` (for bools: logical NOT)."""


@dispatch
def conj(x: Array, /, *, f: Framework = None) -> Array:
    """Complex conjugate (real inputs are returned unchanged)."""


@dispatch
def imag(x: Array, /, *, f: Framework = None) -> Array:
    """Imaginary part of a complex ``x``, as a real array of the same precision."""


@dispatch
def real(x: Array, /, *, f: Framework = None) -> Array:
    """Real part of a complex ``x``, as a real array of the same precision (real ``x``: itself)."""


@dispatch(reals=True)
def reciprocal(x: Array, /, *, f: Framework = None) -> Array:
    """1 / x, for floating ``x`` (Array API 2024.12)."""


@dispatch
def signbit(x: Array, /, *, f: Framework = None) -> Array:
    """True where the sign bit of a floating ``x`` is set: -0.0 and negative NaNs included."""


@dispatch("x1", "x2")
def bitwise_and(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """Bitwise AND of integers or bools."""


@dispatch("x1", "x2")
def bitwise_left_shift(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """Integers ``x1`` shifted left by ``x2`` bits (``x2`` nonnegative)."""


@dispatch("x1", "x2")
def bitwise_or(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """Bitwise OR of integers or bools."""


@dispatch("x1", "x2")
def bitwise_right_shift(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """Integers ``x1`` shifted right by ``x2`` bits (arithmetic: the sign is kept)."""


@dispatch("x1", "x2")
def bitwise_xor(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """Bitwise XOR of integers or bools."""


@dispatch("x1", "x2", reals=True)
def copysign(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """The magnitude of ``x1`` with the sign of ``x2`` (the sign bit: -0.0 counts as negative)."""


@dispatch("x1", "x2", reals=True)
def hypot(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """sqrt(x1**2 + x2**2), without overflow or underflow; inf if either is infinite."""


@dispatch("x1", "x2", reals=True)
def logaddexp(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """log(exp(x1) + exp(x2)), without overflow."""


@dispatch("x1", "x2", reals=True)
def nextafter(x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None) -> Array:
    """The next representable floating value after ``x1`` toward ``x2`` (Array API 2024.12)."""


@dispatch
def nan_to_num(
    x: Array,
    /,
    *,
    nan: float = 0.0,
    posinf: float | None = None,
    neginf: float | None = None,
    f: Framework = None,
) -> Array:
    """``x`` with NaN replaced by ``nan`` and infinities by ``posinf`` and ``neginf``, as
    ``numpy.nan_to_num``.

    Args:
        x: array; integers and bools are returned unchanged, complex numbers have their real and
            imaginary parts replaced separately.
        nan: the value for NaN.
        posinf: the value for ``+inf``; None: the largest finite value of ``x``'s dtype.
        neginf: the value for ``-inf``; None: the most negative finite value of ``x``'s dtype.

    Returns:
        An array of ``x``'s dtype and shape.

    Example: ``ivy.nan_to_num(np.array([np.nan, np.inf, 1.]), posinf=9.)`` -> ``[0., 9., 1.]``.
    """
