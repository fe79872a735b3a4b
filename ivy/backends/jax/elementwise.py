"""jax backend: elementwise functions (jax.numpy's own, exported as they are), except the
functions of real numbers (sin, divide...), which compute integer and boolean arrays in float32
(jax would use float64 for int64 under x64; see ``ivy/backends/_reals.py``).

Python scalars on either side keep the array's dtype (jax treats them as weakly typed).
"""

from __future__ import annotations

import jax.numpy as jnp

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


abs = jnp.abs
acos = _reals.unary(jnp.acos, "acos")
acosh = _reals.unary(jnp.acosh, "acosh")
add = jnp.add
asin = _reals.unary(jnp.asin, "asin")
asinh = _reals.unary(jnp.asinh, "asinh")
atan = _reals.unary(jnp.atan, "atan")
atan2 = _reals.binary(jnp.atan2, "atan2")
atanh = _reals.unary(jnp.atanh, "atanh")
bitwise_and = jnp.bitwise_and
bitwise_invert = jnp.bitwise_invert
bitwise_left_shift = jnp.bitwise_left_shift
bitwise_or = jnp.bitwise_or
bitwise_right_shift = jnp.bitwise_right_shift
bitwise_xor = jnp.bitwise_xor
ceil = jnp.ceil
clip = jnp.clip  # with no bounds it returns x itself: jax arrays are immutable
conj = jnp.conj
copysign = _reals.binary(jnp.copysign, "copysign")
cos = _reals.unary(jnp.cos, "cos")
cosh = _reals.unary(jnp.cosh, "cosh")
divide = _reals.binary(jnp.divide, "divide")
equal = jnp.equal
exp = _reals.unary(jnp.exp, "exp")
expm1 = _reals.unary(jnp.expm1, "expm1")
floor = jnp.floor
floor_divide = jnp.floor_divide
greater = jnp.greater
greater_equal = jnp.greater_equal
hypot = _reals.binary(jnp.hypot, "hypot")
imag = jnp.imag
isfinite = jnp.isfinite
isinf = jnp.isinf
isnan = jnp.isnan
less = jnp.less
less_equal = jnp.less_equal
log = _reals.unary(jnp.log, "log")
log10 = _reals.unary(jnp.log10, "log10")
log1p = _reals.unary(jnp.log1p, "log1p")
log2 = _reals.unary(jnp.log2, "log2")
logaddexp = _reals.binary(jnp.logaddexp, "logaddexp")
logical_and = jnp.logical_and
logical_not = jnp.logical_not
logical_or = jnp.logical_or
logical_xor = jnp.logical_xor
maximum = jnp.maximum
minimum = jnp.minimum
multiply = jnp.multiply
negative = jnp.negative
nextafter = _reals.binary(jnp.nextafter, "nextafter")
not_equal = jnp.not_equal
positive = jnp.positive
pow = jnp.pow
real = jnp.real
reciprocal = _reals.unary(jnp.reciprocal, "reciprocal")
remainder = jnp.remainder
round = jnp.round
sign = jnp.sign
signbit = jnp.signbit
sin = _reals.unary(jnp.sin, "sin")
sinh = _reals.unary(jnp.sinh, "sinh")
sqrt = _reals.unary(jnp.sqrt, "sqrt")
square = jnp.square
subtract = jnp.subtract
tan = _reals.unary(jnp.tan, "tan")
tanh = _reals.unary(jnp.tanh, "tanh")
trunc = jnp.trunc


def nan_to_num(x, /, *, nan=0.0, posinf=None, neginf=None):
    return jnp.nan_to_num(x, nan=nan, posinf=posinf, neginf=neginf)
