"""tensorflow backend: elementwise functions.

Unary functions are tf's own objects, except those that tf refuses on integers (ceil, isnan...):
these call tf's function first and handle integers only when it refuses them.

Binary functions call tf's own function directly when the inputs are tensors or Python scalars
that tf converts correctly, and promote dtypes by Array API rules only when tf refuses them (tf
never promotes, and inside tf.function it refuses a Python scalar on the left unless it has the
scalar's default dtype).
"""

from __future__ import annotations

import math

import tensorflow as tf

from ivy.backends.tensorflow._helpers import FAST_TYPES, REFUSED, promote, tensor

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
    "ceil",
    "clip",
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
    "isfinite",
    "isinf",
    "isnan",
    "less",
    "less_equal",
    "log",
    "log10",
    "log1p",
    "log2",
    "logical_and",
    "logical_not",
    "logical_or",
    "logical_xor",
    "maximum",
    "minimum",
    "multiply",
    "negative",
    "not_equal",
    "positive",
    "pow",
    "remainder",
    "round",
    "sign",
    "sin",
    "sinh",
    "sqrt",
    "square",
    "subtract",
    "tan",
    "tanh",
    "trunc",
]


abs = tf.math.abs
acos = tf.math.acos
acosh = tf.math.acosh
asin = tf.math.asin
asinh = tf.math.asinh
atan = tf.math.atan
atanh = tf.math.atanh
cos = tf.math.cos
cosh = tf.math.cosh
exp = tf.math.exp
expm1 = tf.math.expm1
log = tf.math.log
log1p = tf.math.log1p
negative = tf.math.negative
positive = tf.identity
round = tf.math.round
sign = tf.math.sign
sin = tf.math.sin
sinh = tf.math.sinh
sqrt = tf.math.sqrt
square = tf.math.square
tan = tf.math.tan
tanh = tf.math.tanh


def log2(x, /):
    return tf.math.log(x) / math.log(2.0)


def log10(x, /):
    return tf.math.log(x) / math.log(10.0)


def _rounding(native, name: str):
    """tf's rounding ``native``, which refuses integers; integers are returned as they are."""

    def fn(x, /):
        try:
            return native(x)
        except REFUSED:
            x = tensor(x)
            if x.dtype.is_integer:
                return x
            raise

    fn.__name__ = fn.__qualname__ = name
    return fn


def _trunc(x):
    return tf.where(x < 0, tf.math.ceil(x), tf.math.floor(x))


ceil = _rounding(tf.math.ceil, "ceil")
floor = _rounding(tf.math.floor, "floor")
trunc = _rounding(_trunc, "trunc")


def _classification(native, name: str, of_integer: bool, both):
    """tf's ``native`` (is_nan...), which refuses integers (answer ``of_integer`` everywhere)
    and complex numbers (``both`` combines the answers for the real and imaginary parts)."""

    def fn(x, /):
        try:
            return native(x)
        except REFUSED:
            x = tensor(x)
            if x.dtype.is_integer or x.dtype is tf.bool:
                return tf.fill(tf.shape(x), of_integer)
            if x.dtype.is_complex:
                return both(native(tf.math.real(x)), native(tf.math.imag(x)))
            raise

    fn.__name__ = fn.__qualname__ = name
    return fn


isfinite = _classification(tf.math.is_finite, "isfinite", True, tf.math.logical_and)
isinf = _classification(tf.math.is_inf, "isinf", False, tf.math.logical_or)
isnan = _classification(tf.math.is_nan, "isnan", False, tf.math.logical_or)


def _as_bools(*values) -> list:
    out = []
    for v in values:
        v = tensor(v)
        out.append(v if v.dtype is tf.bool else tf.cast(v, tf.bool))
    return out


def _binary(native, name: str, fallback=promote):
    """ivy function ``name`` calling tf's ``native``; ``fallback`` converts refused inputs."""

    def fn(x1, x2, /):
        # Fast path: tensors, Python floats and bools, and ints that fit every dtype (but not
        # two ints, which tf would make int32).
        if (type(x1) in FAST_TYPES or (type(x1) is int and 0 <= x1 < 128)) and (
            type(x2) in FAST_TYPES or (type(x2) is int and 0 <= x2 < 128 and type(x1) is not int)
        ):
            try:
                return native(x1, x2)
            except REFUSED:
                pass
        return native(*fallback(x1, x2))

    fn.__name__ = fn.__qualname__ = name
    fn.__doc__ = (
        f"``tf.math.{native.__name__}`` with Python scalars on either side and dtype promotion."
    )
    return fn


add = _binary(tf.math.add, "add")
atan2 = _binary(tf.math.atan2, "atan2")
divide = _binary(tf.math.divide, "divide")
equal = _binary(tf.math.equal, "equal")
floor_divide = _binary(tf.math.floordiv, "floor_divide")
greater = _binary(tf.math.greater, "greater")
greater_equal = _binary(tf.math.greater_equal, "greater_equal")
less = _binary(tf.math.less, "less")
less_equal = _binary(tf.math.less_equal, "less_equal")
maximum = _binary(tf.math.maximum, "maximum")
minimum = _binary(tf.math.minimum, "minimum")
multiply = _binary(tf.math.multiply, "multiply")
not_equal = _binary(tf.math.not_equal, "not_equal")
pow = _binary(tf.math.pow, "pow")
remainder = _binary(tf.math.floormod, "remainder")
subtract = _binary(tf.math.subtract, "subtract")
logical_and = _binary(tf.math.logical_and, "logical_and", _as_bools)
logical_or = _binary(tf.math.logical_or, "logical_or", _as_bools)
logical_xor = _binary(tf.math.logical_xor, "logical_xor", _as_bools)


def logical_not(x, /):
    x = tensor(x)
    return tf.math.logical_not(x if x.dtype is tf.bool else tf.cast(x, tf.bool))


def clip(x, /, min=None, max=None):
    if min is not None:
        x = maximum(x, min)
    if max is not None:
        x = minimum(x, max)
    return tensor(x)
