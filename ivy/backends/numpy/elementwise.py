"""numpy backend: elementwise functions (numpy ufuncs, exported as they are), except the
functions of real numbers (sin, divide...), which compute integer and boolean arrays in float32
where numpy would use float64 or float16 (see ``ivy/backends/_reals.py``)."""

from __future__ import annotations

import numpy as np

from ivy.backends import _reals

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


abs = np.abs
acos = _reals.unary(np.acos, "acos")
acosh = _reals.unary(np.acosh, "acosh")
add = np.add
asin = _reals.unary(np.asin, "asin")
asinh = _reals.unary(np.asinh, "asinh")
atan = _reals.unary(np.atan, "atan")
atan2 = _reals.binary(np.atan2, "atan2")
atanh = _reals.unary(np.atanh, "atanh")
bitwise_and = np.bitwise_and
bitwise_invert = np.bitwise_invert
bitwise_left_shift = np.bitwise_left_shift
bitwise_or = np.bitwise_or
bitwise_right_shift = np.bitwise_right_shift
bitwise_xor = np.bitwise_xor
ceil = np.ceil
conj = np.conj
copysign = _reals.binary(np.copysign, "copysign")
cos = _reals.unary(np.cos, "cos")
cosh = _reals.unary(np.cosh, "cosh")
divide = _reals.binary(np.divide, "divide")
equal = np.equal
exp = _reals.unary(np.exp, "exp")
expm1 = _reals.unary(np.expm1, "expm1")
floor = np.floor
floor_divide = np.floor_divide
greater = np.greater
greater_equal = np.greater_equal
hypot = _reals.binary(np.hypot, "hypot")
imag = np.imag
isfinite = np.isfinite
isinf = np.isinf
isnan = np.isnan
less = np.less
less_equal = np.less_equal
log = _reals.unary(np.log, "log")
log10 = _reals.unary(np.log10, "log10")
log1p = _reals.unary(np.log1p, "log1p")
log2 = _reals.unary(np.log2, "log2")
logaddexp = _reals.binary(np.logaddexp, "logaddexp")
logical_and = np.logical_and
logical_not = np.logical_not
logical_or = np.logical_or
logical_xor = np.logical_xor
maximum = np.maximum
minimum = np.minimum
multiply = np.multiply
negative = np.negative
nextafter = _reals.binary(np.nextafter, "nextafter")
not_equal = np.not_equal
positive = np.positive
pow = np.pow
real = np.real


def _reciprocal(x):
    return np.divide(1.0, x)  # np.reciprocal would divide integers as integers (1 // x)


reciprocal = _reals.unary(_reciprocal, "reciprocal")
remainder = np.remainder
round = np.round
sign = np.sign
signbit = np.signbit
sin = _reals.unary(np.sin, "sin")
sinh = _reals.unary(np.sinh, "sinh")
sqrt = _reals.unary(np.sqrt, "sqrt")
square = np.square
subtract = np.subtract
tan = _reals.unary(np.tan, "tan")
tanh = _reals.unary(np.tanh, "tanh")
trunc = np.trunc


def clip(x, /, min=None, max=None):
    if min is None and max is None:
        return np.asarray(x).copy()
    return np.clip(x, min, max)


def nan_to_num(x, /, *, nan=0.0, posinf=None, neginf=None):
    return np.nan_to_num(x, nan=nan, posinf=posinf, neginf=neginf)
