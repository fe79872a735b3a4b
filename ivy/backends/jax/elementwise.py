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


def _float32(x):
    return x.astype(jnp.float32)


def _astype(x, dtype):
    return x.astype(dtype)


def _on_reals(native, name):
    """``native`` computing integer and boolean arrays in float32 (ivy's rule, see _reals)."""
    return _reals.unary(native, name, _float32)


def _on_reals2(native, name):
    return _reals.binary(native, name, _float32, _astype)


abs = jnp.abs
acos = _on_reals(jnp.acos, "acos")
acosh = _on_reals(jnp.acosh, "acosh")
add = jnp.add
asin = _on_reals(jnp.asin, "asin")
asinh = _on_reals(jnp.asinh, "asinh")
atan = _on_reals(jnp.atan, "atan")
atan2 = _on_reals2(jnp.atan2, "atan2")
atanh = _on_reals(jnp.atanh, "atanh")
bitwise_and = jnp.bitwise_and
bitwise_invert = jnp.bitwise_invert
bitwise_left_shift = jnp.bitwise_left_shift
bitwise_or = jnp.bitwise_or
bitwise_right_shift = jnp.bitwise_right_shift
bitwise_xor = jnp.bitwise_xor
ceil = jnp.ceil
clip = jnp.clip  # with no bounds it returns x itself: jax arrays are immutable
conj = jnp.conj
copysign = _on_reals2(jnp.copysign, "copysign")
cos = _on_reals(jnp.cos, "cos")
cosh = _on_reals(jnp.cosh, "cosh")
divide = _on_reals2(jnp.divide, "divide")
equal = jnp.equal
exp = _on_reals(jnp.exp, "exp")
expm1 = _on_reals(jnp.expm1, "expm1")
floor = jnp.floor
floor_divide = jnp.floor_divide
greater = jnp.greater
greater_equal = jnp.greater_equal
hypot = _on_reals2(jnp.hypot, "hypot")
imag = jnp.imag
isfinite = jnp.isfinite
isinf = jnp.isinf
isnan = jnp.isnan
less = jnp.less
less_equal = jnp.less_equal
log = _on_reals(jnp.log, "log")
log10 = _on_reals(jnp.log10, "log10")
log1p = _on_reals(jnp.log1p, "log1p")
log2 = _on_reals(jnp.log2, "log2")
logaddexp = _on_reals2(jnp.logaddexp, "logaddexp")
logical_and = jnp.logical_and
logical_not = jnp.logical_not
logical_or = jnp.logical_or
logical_xor = jnp.logical_xor
maximum = jnp.maximum
minimum = jnp.minimum
multiply = jnp.multiply
negative = jnp.negative
nextafter = _on_reals2(jnp.nextafter, "nextafter")
not_equal = jnp.not_equal
positive = jnp.positive
pow = jnp.pow
real = jnp.real
reciprocal = _on_reals(jnp.reciprocal, "reciprocal")
remainder = jnp.remainder
round = jnp.round
sign = jnp.sign
signbit = jnp.signbit
sin = _on_reals(jnp.sin, "sin")
sinh = _on_reals(jnp.sinh, "sinh")
sqrt = _on_reals(jnp.sqrt, "sqrt")
square = jnp.square
subtract = jnp.subtract
tan = _on_reals(jnp.tan, "tan")
tanh = _on_reals(jnp.tanh, "tanh")
trunc = jnp.trunc


def nan_to_num(x, /, *, nan=0.0, posinf=None, neginf=None):
    return jnp.nan_to_num(x, nan=nan, posinf=posinf, neginf=neginf)
