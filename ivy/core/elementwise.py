"""Elementwise functions, with Array API broadcasting and type promotion.

Binary functions accept Python scalars on either side: ``ivy.add(x, 1.0)``.
"""

from __future__ import annotations

from ivy.core._dispatch import dispatch

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
def abs(x, /, *, f=None):
    """Absolute value."""


@dispatch
def acos(x, /, *, f=None):
    """Inverse cosine, in radians."""


@dispatch
def acosh(x, /, *, f=None):
    """Inverse hyperbolic cosine."""


@dispatch
def asin(x, /, *, f=None):
    """Inverse sine, in radians."""


@dispatch
def asinh(x, /, *, f=None):
    """Inverse hyperbolic sine."""


@dispatch
def atan(x, /, *, f=None):
    """Inverse tangent, in radians."""


@dispatch
def atanh(x, /, *, f=None):
    """Inverse hyperbolic tangent."""


@dispatch
def ceil(x, /, *, f=None):
    """Smallest integer-valued number not less than x."""


@dispatch
def cos(x, /, *, f=None):
    """Cosine of x in radians."""


@dispatch
def cosh(x, /, *, f=None):
    """Hyperbolic cosine."""


@dispatch
def exp(x, /, *, f=None):
    """Exponential e**x."""


@dispatch
def expm1(x, /, *, f=None):
    """exp(x) - 1, accurate for small x."""


@dispatch
def floor(x, /, *, f=None):
    """Largest integer-valued number not greater than x."""


@dispatch
def isfinite(x, /, *, f=None):
    """True where x is finite."""


@dispatch
def isinf(x, /, *, f=None):
    """True where x is +inf or -inf."""


@dispatch
def isnan(x, /, *, f=None):
    """True where x is nan."""


@dispatch
def log(x, /, *, f=None):
    """Natural logarithm."""


@dispatch
def log1p(x, /, *, f=None):
    """log(1 + x), accurate for small x."""


@dispatch
def log2(x, /, *, f=None):
    """Base-2 logarithm."""


@dispatch
def log10(x, /, *, f=None):
    """Base-10 logarithm."""


@dispatch
def logical_not(x, /, *, f=None):
    """Logical NOT of x (as bool)."""


@dispatch
def negative(x, /, *, f=None):
    """-x."""


@dispatch
def positive(x, /, *, f=None):
    """+x."""


@dispatch
def round(x, /, *, f=None):
    """Round to the nearest integer-valued number, halves to even."""


@dispatch
def sign(x, /, *, f=None):
    """Sign of x: -1, 0 or 1."""


@dispatch
def sin(x, /, *, f=None):
    """Sine of x in radians."""


@dispatch
def sinh(x, /, *, f=None):
    """Hyperbolic sine."""


@dispatch
def sqrt(x, /, *, f=None):
    """Square root."""


@dispatch
def square(x, /, *, f=None):
    """x * x."""


@dispatch
def tan(x, /, *, f=None):
    """Tangent of x in radians."""


@dispatch
def tanh(x, /, *, f=None):
    """Hyperbolic tangent."""


@dispatch
def trunc(x, /, *, f=None):
    """Round toward zero."""


@dispatch("x1", "x2")
def add(x1, x2, /, *, f=None):
    """x1 + x2."""


@dispatch("x1", "x2")
def atan2(x1, x2, /, *, f=None):
    """Angle of the point (x2, x1), in radians, in [-pi, pi]."""


@dispatch("x1", "x2")
def divide(x1, x2, /, *, f=None):
    """x1 / x2 (true division)."""


@dispatch("x1", "x2")
def equal(x1, x2, /, *, f=None):
    """x1 == x2."""


@dispatch("x1", "x2")
def floor_divide(x1, x2, /, *, f=None):
    """Floor of x1 / x2."""


@dispatch("x1", "x2")
def greater(x1, x2, /, *, f=None):
    """x1 > x2."""


@dispatch("x1", "x2")
def greater_equal(x1, x2, /, *, f=None):
    """x1 >= x2."""


@dispatch("x1", "x2")
def less(x1, x2, /, *, f=None):
    """x1 < x2."""


@dispatch("x1", "x2")
def less_equal(x1, x2, /, *, f=None):
    """x1 <= x2."""


@dispatch("x1", "x2")
def logical_and(x1, x2, /, *, f=None):
    """x1 AND x2 (as bool)."""


@dispatch("x1", "x2")
def logical_or(x1, x2, /, *, f=None):
    """x1 OR x2 (as bool)."""


@dispatch("x1", "x2")
def logical_xor(x1, x2, /, *, f=None):
    """x1 XOR x2 (as bool)."""


@dispatch("x1", "x2")
def maximum(x1, x2, /, *, f=None):
    """Elementwise maximum (nan propagates)."""


@dispatch("x1", "x2")
def minimum(x1, x2, /, *, f=None):
    """Elementwise minimum (nan propagates)."""


@dispatch("x1", "x2")
def multiply(x1, x2, /, *, f=None):
    """x1 * x2."""


@dispatch("x1", "x2")
def not_equal(x1, x2, /, *, f=None):
    """x1 != x2."""


@dispatch("x1", "x2")
def pow(x1, x2, /, *, f=None):
    """x1 ** x2."""


@dispatch("x1", "x2")
def remainder(x1, x2, /, *, f=None):
    """x1 mod x2, with the sign of x2."""


@dispatch("x1", "x2")
def subtract(x1, x2, /, *, f=None):
    """x1 - x2."""


@dispatch("x", "min", "max")
def clip(x, /, min=None, max=None, *, f=None):
    """Clamp ``x`` to ``[min, max]``; either bound may be None, a scalar or an array.

    Example: ``ivy.clip(np.array([-1., 2.]), 0, 1, f='torch')`` -> tensor([0., 1.]).
    """


@dispatch
def bitwise_invert(x, /, *, f=None):
    """Bitwise NOT of an integer or bool ``x`` (for bools: logical NOT)."""


@dispatch
def conj(x, /, *, f=None):
    """Complex conjugate (real inputs are returned unchanged)."""


@dispatch
def imag(x, /, *, f=None):
    """Imaginary part of a complex ``x``, as a real array of the same precision."""


@dispatch
def real(x, /, *, f=None):
    """Real part of a complex ``x``, as a real array of the same precision (real ``x``: itself)."""


@dispatch
def reciprocal(x, /, *, f=None):
    """1 / x, for floating ``x`` (Array API 2024.12)."""


@dispatch
def signbit(x, /, *, f=None):
    """True where the sign bit of a floating ``x`` is set: -0.0 and negative NaNs included."""


@dispatch("x1", "x2")
def bitwise_and(x1, x2, /, *, f=None):
    """Bitwise AND of integers or bools."""


@dispatch("x1", "x2")
def bitwise_left_shift(x1, x2, /, *, f=None):
    """Integers ``x1`` shifted left by ``x2`` bits (``x2`` nonnegative)."""


@dispatch("x1", "x2")
def bitwise_or(x1, x2, /, *, f=None):
    """Bitwise OR of integers or bools."""


@dispatch("x1", "x2")
def bitwise_right_shift(x1, x2, /, *, f=None):
    """Integers ``x1`` shifted right by ``x2`` bits (arithmetic: the sign is kept)."""


@dispatch("x1", "x2")
def bitwise_xor(x1, x2, /, *, f=None):
    """Bitwise XOR of integers or bools."""


@dispatch("x1", "x2")
def copysign(x1, x2, /, *, f=None):
    """The magnitude of ``x1`` with the sign of ``x2`` (the sign bit: -0.0 counts as negative)."""


@dispatch("x1", "x2")
def hypot(x1, x2, /, *, f=None):
    """sqrt(x1**2 + x2**2), without overflow or underflow; inf if either is infinite."""


@dispatch("x1", "x2")
def logaddexp(x1, x2, /, *, f=None):
    """log(exp(x1) + exp(x2)), without overflow."""


@dispatch("x1", "x2")
def nextafter(x1, x2, /, *, f=None):
    """The next representable floating value after ``x1`` toward ``x2`` (Array API 2024.12)."""


@dispatch
def nan_to_num(x, /, *, nan=0.0, posinf=None, neginf=None, f=None):
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
