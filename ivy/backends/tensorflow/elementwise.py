"""tensorflow backend: elementwise functions.

Unary functions are tf's own objects, except those that tf refuses on integers (ceil, isnan...):
these call tf's function first and handle integers only when it refuses them.

Binary functions call tf's own function directly when the inputs are tensors or Python scalars
that tf converts correctly, and promote dtypes by Array API rules only when tf refuses them (tf
never promotes, and inside tf.function it refuses a Python scalar on the left unless it has the
scalar's default dtype).

Bitwise functions promote first and treat bools as the logical functions do. copysign, hypot,
logaddexp, signbit (and nextafter in float16), which tf lacks, are built from its primitives: signs
are read from the bits, so -0.0 and negative NaNs count as negative.
"""

from __future__ import annotations

import functools
import math

import numpy as np
import tensorflow as tf

from ivy import framework_handler as _fh
from ivy.backends import _int_pow, _int_scalars, _signed_zeros
from ivy.backends._clip_args import clip_bounds
from ivy.backends._complex_special import namespace, wrap
from ivy.backends.tensorflow._helpers import (
    REFUSED,
    TENSOR_TYPES,
    as_inexact,
    fast,
    promote,
    tensor,
    tensor_of,
)
from ivy.errors import DtypeError

acos = tf.math.acos
acosh = tf.math.acosh
asin = tf.math.asin
asinh = tf.math.asinh
atan = tf.math.atan
atanh = tf.math.atanh
conj = tf.math.conj
cos = tf.math.cos
cosh = tf.math.cosh
exp = tf.math.exp
imag = tf.math.imag
log = tf.math.log
positive = tf.identity
real = tf.math.real
sin = tf.math.sin
sinh = tf.math.sinh
square = tf.math.square
tan = tf.math.tan


def round(x, /):  # noqa: A001 - the Array API name
    """tf's (halves to even); complex numbers round each part (tf has no kernel for them)."""
    if getattr(x, "dtype", None) in (tf.complex64, tf.complex128):
        return tf.complex(tf.math.round(tf.math.real(x)), tf.math.round(tf.math.imag(x)))
    return tf.math.round(x)


def _log_base(x, base: float):
    out = log(x)
    if out.dtype.is_complex:  # divide each part by the real ln(base) (a complex division
        # would make the imaginary part of log(0) = -inf + 0j NaN)
        scale = tf.constant(1.0 / math.log(base), out.dtype.real_dtype)
        return tf.complex(tf.math.real(out) * scale, tf.math.imag(out) * scale)
    return out / math.log(base)


def log2(x, /):
    return _log_base(x, 2.0)


def log10(x, /):
    return _log_base(x, 10.0)


def _unsigned_kernel(native, name: str, of_unsigned, of_bool=None):
    """tf's ``native``, which has no kernel for unsigned integers (``of_unsigned`` computes
    them exactly) nor for bools (``of_bool``; None: refused as tf refuses them)."""

    def fn(x, /):
        try:
            return native(x)
        except REFUSED:
            x = tensor(x)
            if x.dtype.is_unsigned:
                return of_unsigned(x)
            if x.dtype is tf.bool and of_bool is not None:
                return of_bool(x)
            raise

    fn.__name__ = fn.__qualname__ = name
    return fn


abs = _unsigned_kernel(tf.math.abs, "abs", tf.identity, tf.identity)
negative = _unsigned_kernel(tf.math.negative, "negative", lambda x: tf.zeros_like(x) - x)
sign = _unsigned_kernel(tf.math.sign, "sign", lambda x: tf.cast(x > 0, x.dtype), tf.identity)


def reciprocal(x, /):
    return tf.math.reciprocal(as_inexact(x))  # tf's would divide integers as integers


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
    """Truth values: nonzero is true (tf's cast of a complex number to bool reads its real part
    only)."""
    out = []
    for v in values:
        v = tensor(v)
        out.append(v if v.dtype is tf.bool else tf.not_equal(v, tf.zeros((), v.dtype)))
    return out


def _binary(native, name: str, fallback=promote, bools: bool = False):
    """ivy function ``name`` calling tf's ``native``; ``fallback`` converts refused inputs;
    with ``bools``, booleans (which tf has no kernel for) compute exactly through int8."""

    def fn(x1, x2, /):
        # Fast path: what tf converts as ivy would (``fast``), but not two ints, which tf would
        # make int32.
        if fast(x1) and fast(x2) and not (type(x1) is int and type(x2) is int):
            try:
                return native(x1, x2)
            except REFUSED:
                pass
        if type(x1) is int or type(x2) is int:  # beyond the tensor's dtype?
            x1, x2 = _int_scalars.operands(native, name, x1, x2)
            if x2 is None:
                return x1
        args = fallback(x1, x2)
        if bools and args[0].dtype is tf.bool:
            out = native(*(tf.cast(v, tf.int8) for v in args))
            return out if out.dtype is tf.bool else tf.cast(out, tf.bool)
        return native(*args)

    fn.__name__ = fn.__qualname__ = name
    fn.__doc__ = (
        f"``tf.math.{native.__name__}`` with Python scalars on either side and dtype promotion."
    )
    # For two tensors tf's native either answers as ivy would (same dtypes: tf never promotes)
    # or refuses: the dispatchers call it directly and hand what it refuses to ``fn``.
    fn.__ivy_native__ = native
    return fn


add = _binary(tf.math.add, "add", bools=True)
atan2 = _binary(tf.math.atan2, "atan2", lambda *v: _real_operands(*v))
_divide = _binary(tf.math.divide, "divide")
equal = _binary(tf.math.equal, "equal")
_floor_divide = _binary(tf.math.floordiv, "floor_divide")
greater = _binary(tf.math.greater, "greater", bools=True)
greater_equal = _binary(tf.math.greater_equal, "greater_equal", bools=True)
less = _binary(tf.math.less, "less", bools=True)
less_equal = _binary(tf.math.less_equal, "less_equal", bools=True)


def _zero_ties(native, lower: bool):
    """tf's ``minimum`` or ``maximum`` with IEEE's signed zeros at a tie of zeros (tf returns the
    first operand; ``ivy/backends/_signed_zeros.py``)."""

    def fn(x1, x2):
        out = native(x1, x2)
        if not out.dtype.is_floating:
            return out
        return _signed_zeros.zero_ties(tf.where, x1, x2, out, lower)

    fn.__name__ = native.__name__
    return fn


maximum = _binary(_zero_ties(tf.math.maximum, False), "maximum", bools=True)
minimum = _binary(_zero_ties(tf.math.minimum, True), "minimum", bools=True)
multiply = _binary(tf.math.multiply, "multiply", bools=True)
not_equal = _binary(tf.math.not_equal, "not_equal")


def floor_divide(x1, x2, /):
    """Integers: tf's. Floats as numpy, torch and jax compute them, from the exact remainder
    (tf's ``floor(x1 / x2)`` rounds the quotient first: 2.5 // 0.001 is 2500 there, 2499
    elsewhere)."""
    a, b = promote(x1, x2)
    if not a.dtype.is_floating:
        return _floor_divide(a, b)
    if a.dtype is tf.float16:  # (no float16 kernel for the remainder)
        return tf.cast(floor_divide(tf.cast(a, tf.float32), tf.cast(b, tf.float32)), tf.float16)
    mod = tf.truncatemod(a, b)  # C's fmod: exact
    div = (a - mod) / b
    div = tf.where((mod != 0) & ((b < 0) != (mod < 0)), div - 1, div)
    floor = tf.math.floor(div)
    floor = tf.where(div - floor > 0.5, floor + 1, floor)
    floor = tf.where(div == 0, tf.zeros_like(div) * (a / b), floor)  # a signed zero
    return tf.where(b == 0, a / b, floor)


def _wide_pow(x1, x2):
    """x1 ** x2 for tensors of one dtype; unsigned integers (no tf kernel) through int64, whose
    wrap-around modulo 2**64 is theirs."""
    a, b = promote(x1, x2)
    if not a.dtype.is_unsigned:
        return tf.math.pow(a, b)
    if a.dtype is tf.uint64:
        out = tf.math.pow(tf.bitcast(a, tf.int64), tf.bitcast(b, tf.int64))
        return tf.bitcast(out, tf.uint64)
    return tf.cast(tf.math.pow(tf.cast(a, tf.int64), tf.cast(b, tf.int64)), a.dtype)


_pow = _binary(tf.math.pow, "pow")


def _any_pow(x1, x2):
    try:
        return _pow(x1, x2)
    except REFUSED:
        return _wide_pow(x1, x2)


def _integral(x) -> bool:
    if isinstance(x, TENSOR_TYPES):
        return x.dtype.is_integer
    return type(x) is int or isinstance(x, np.integer)


def pow(x1, x2, /):
    """``x1 ** x2``; integers to negative integer powers as ``ivy/backends/_int_pow.py`` says
    (tf's own error is a framework error, and a compiled program would raise it when run)."""
    if not (_integral(x2) and _integral(x1)):  # the common case, first
        return _any_pow(x1, x2)
    return _int_pow.integer_pow(
        _any_pow,
        x1,
        x2,
        integral=_integral,
        values_known=lambda x: not isinstance(x, TENSOR_TYPES) or tf.executing_eagerly(),
        any_negative=lambda x: bool(tf.reduce_any(x < 0)) if isinstance(x, TENSOR_TYPES) else x < 0,
        where=lambda c, a, b: tf.where(c, a, b),
        backend="tensorflow",
    )


remainder = _binary(tf.math.floormod, "remainder")
subtract = _binary(tf.math.subtract, "subtract")
logical_and = _binary(tf.math.logical_and, "logical_and", _as_bools)
logical_or = _binary(tf.math.logical_or, "logical_or", _as_bools)
logical_xor = _binary(tf.math.logical_xor, "logical_xor", _as_bools)


def divide(x1, x2, /):
    """``x1 / x2``; integers and bools are divided in float32 (tf would use float64)."""
    for v in (x1, x2):
        if isinstance(v, TENSOR_TYPES) and (v.dtype.is_floating or v.dtype.is_complex):
            return _divide(x1, x2)
    return _divide(*_real_operands(x1, x2))


def logical_not(x, /):
    return tf.math.logical_not(_as_bools(x)[0])


def clip(x, /, min=None, max=None):
    """The result has ``x``'s dtype whatever the bounds' (``ivy/backends/_clip_args.py``)."""
    x = tensor(x)
    min, max = clip_bounds(_fh.load_backend("tensorflow"), x, min, max)
    if x.dtype is tf.bool:
        if min is not None:
            x = tf.math.logical_or(x, tensor_of(min, tf.bool))
        return x if max is None else tf.math.logical_and(x, tensor_of(max, tf.bool))
    # tf's own maximum and minimum: their gradient passes to x at a bound (ivy's split it at
    # a tie of zeros), as torch's clamp and ivy.jax.clip
    if min is not None:
        x = tf.math.maximum(x, tensor_of(min, x.dtype))
    if max is not None:
        x = tf.math.minimum(x, tensor_of(max, x.dtype))
    return x


# ----------------------------------------------------------------------------------------------
# Bitwise functions: tf's refuse bools (the logical functions do the same there) and never promote.
# ----------------------------------------------------------------------------------------------


def _bitwise(native, logical, name: str):
    """ivy function ``name``: tf's ``native`` on promoted integers, ``logical`` on bools."""

    def fn(x1, x2, /):
        a, b = promote(x1, x2)
        if a.dtype is tf.bool:
            if logical is None:
                raise TypeError(f"{name} needs integer inputs, got bool.")
            return logical(a, b)
        return native(a, b)

    fn.__name__ = fn.__qualname__ = name
    return fn


bitwise_and = _bitwise(tf.bitwise.bitwise_and, tf.math.logical_and, "bitwise_and")
bitwise_or = _bitwise(tf.bitwise.bitwise_or, tf.math.logical_or, "bitwise_or")
bitwise_xor = _bitwise(tf.bitwise.bitwise_xor, tf.math.logical_xor, "bitwise_xor")


def _shift(native, name: str, left: bool):
    """tf's shift ``native``, with numpy's answers for shift counts that are negative or not
    less than the width (tf takes such counts modulo the width): 0 for left shifts, 0 or -1
    (the sign) for right shifts."""
    bitwise = _bitwise(native, None, name)

    def fn(x1, x2, /):
        out = bitwise(x1, x2)
        a, b = promote(x1, x2)
        valid = (
            (b >= 0) & (b < a.dtype.size * 8) if not b.dtype.is_unsigned else b < a.dtype.size * 8
        )
        if left or a.dtype.is_unsigned:
            fill = tf.zeros_like(out)
        else:
            fill = tf.where(a < 0, tf.constant(-1, a.dtype), tf.constant(0, a.dtype))
        return tf.where(valid, out, fill)

    fn.__name__ = fn.__qualname__ = name
    return fn


bitwise_left_shift = _shift(tf.bitwise.left_shift, "bitwise_left_shift", True)
bitwise_right_shift = _shift(tf.bitwise.right_shift, "bitwise_right_shift", False)


def bitwise_invert(x, /):
    x = tensor(x)
    return tf.math.logical_not(x) if x.dtype is tf.bool else tf.bitwise.invert(x)


# ----------------------------------------------------------------------------------------------
# Floating-point functions tf lacks, from its own primitives (the sign bit read from the bits).
# ----------------------------------------------------------------------------------------------

_BITS = {tf.float16: tf.int16, tf.bfloat16: tf.int16, tf.float32: tf.int32, tf.float64: tf.int64}


def _complex_refused(name: str) -> DtypeError:
    return DtypeError(
        "takes no complex floating input. Cast first (ivy.astype).",
        function=name,
        argument="x" if name == "signbit" else "x1, x2",
        backend="tensorflow",
    )


def signbit(x, /):
    x = tensor(x)
    if x.dtype.is_complex:
        raise _complex_refused("signbit")
    bits = _BITS.get(x.dtype)
    if bits is None:  # integers (numpy's answer); bools are never negative
        return x < 0 if x.dtype.is_integer else tf.zeros_like(x, tf.bool)
    return tf.bitcast(x, bits) < 0


def copysign(x1, x2, /):
    """The magnitude of ``x1`` with the sign bit of ``x2`` (-0.0 and -nan count as negative)."""
    a, b = _real_operands(x1, x2)
    bits = _BITS[a.dtype]
    magnitude = tf.bitwise.bitwise_and(tf.bitcast(a, bits), tf.bitwise.invert(_sign_mask(bits)))
    sign = tf.bitwise.bitwise_and(tf.bitcast(b, bits), _sign_mask(bits))
    return tf.bitcast(tf.bitwise.bitwise_or(magnitude, sign), a.dtype)


def _sign_mask(bits):
    """The sign bit alone, as an integer of dtype ``bits`` (the most negative value)."""
    return tf.constant(bits.min, bits)


def hypot(x1, x2, /):
    """sqrt(x1**2 + x2**2) without overflow or underflow; inf wherever an input is infinite."""
    a, b = _real_operands(x1, x2)
    if a.dtype.is_complex:
        raise _complex_refused("hypot")
    a, b = tf.math.abs(a), tf.math.abs(b)
    hi, lo = tf.math.maximum(a, b), tf.math.minimum(a, b)
    ratio = tf.math.divide_no_nan(lo, hi)
    out = hi * tf.math.sqrt(1 + ratio * ratio)
    return tf.where(tf.math.is_inf(a) | tf.math.is_inf(b), tf.constant(math.inf, out.dtype), out)


def logaddexp(x1, x2, /):
    """log(exp(x1) + exp(x2)) without overflow."""
    a, b = _real_operands(x1, x2)
    out = tf.math.maximum(a, b) + tf.math.log1p(tf.math.exp(-tf.math.abs(a - b)))
    return tf.where(a == b, a + math.log(2.0), out)  # equal infinities: a - b would be nan


def nextafter(x1, x2, /):
    """tf's nextafter (float32 and float64); float16 steps its bits as IEEE 754 says."""
    a, b = _real_operands(x1, x2)
    if a.dtype is tf.float32 or a.dtype is tf.float64:
        return tf.math.nextafter(a, b)
    bits = _BITS[a.dtype]
    ia = tf.bitcast(a, bits)
    step = tf.where((b > a) == (a > 0), tensor_of(1, bits), tensor_of(-1, bits))
    out = tf.bitcast(ia + step, a.dtype)
    tiniest = tf.bitcast(
        tf.bitwise.bitwise_or(
            tensor_of(1, bits), tf.bitwise.bitwise_and(tf.bitcast(b, bits), _sign_mask(bits))
        ),
        a.dtype,
    )
    out = tf.where(a == 0, tiniest, out)
    out = tf.where(a == b, b, out)
    return tf.where(tf.math.is_nan(a) | tf.math.is_nan(b), tf.constant(math.nan, a.dtype), out)


def _real_operands(*values):
    """``values`` promoted to one dtype, floating: float32 unless one of them is floating
    (integers of two dtypes too: int64 with uint64 promotes to float64)."""
    if len(values) == 2 and (type(values[0]) is int or type(values[1]) is int):
        values = _int_scalars.operands(None, "divide", *values)  # beyond the dtype: a float
    tensors = promote(*values)
    if any(isinstance(v, (float, complex)) or _is_inexact(v) for v in values):
        return _floating(*tensors)
    return [tf.cast(t, tf.float32) for t in tensors]


def _is_inexact(value) -> bool:
    dtype = getattr(value, "dtype", None)
    if dtype is None:
        return False
    dtype = tf.as_dtype(dtype)
    return dtype.is_floating or dtype.is_complex


def _floating(*tensors):
    """``tensors`` (of one dtype) cast to float32 unless floating."""
    return [as_inexact(t) for t in tensors]


def nan_to_num(x, /, *, nan=0.0, posinf=None, neginf=None):
    x = tensor(x)
    dt = x.dtype
    if dt.is_complex:

        def part(v):
            return nan_to_num(v, nan=nan, posinf=posinf, neginf=neginf)

        return tf.complex(part(tf.math.real(x)), part(tf.math.imag(x)))
    if not dt.is_floating:
        return x

    def value(v):  # a Python number, rounded to dt (overflowing to inf as numpy does)
        return tf.cast(tf.constant(v, tf.float64), dt)

    big = value(dt.max if posinf is None else posinf)
    small = value(dt.min if neginf is None else neginf)
    x = tf.where(tf.math.is_nan(x), value(nan), x)
    return tf.where(tf.math.is_inf(x), tf.where(x > 0, big, small), x)


# tf's complex expm1, log1p, sqrt and tanh miss some of the Array API's special values
# (expm1(inf + 0j), log1p(inf + NaN j), sqrt(0 - 0j), tanh(inf + bj) = 1 - 0j...): tf's own, with
# those put back for complex results (ivy/backends/_complex_special.py).
def _fill_like(x, value):
    return tf.fill(tf.shape(x), tf.constant(value, x.dtype))


_standard_complex = functools.partial(
    wrap,
    xp=namespace(
        where=tf.where,
        isnan=tf.math.is_nan,
        isinf=tf.math.is_inf,
        isfinite=tf.math.is_finite,
        real=tf.math.real,
        imag=tf.math.imag,
        abs=tf.math.abs,
        copysign=copysign,
        cos=tf.math.cos,
        sin=tf.math.sin,
        full_like=_fill_like,
        complex=tf.complex,
    ),
    complex_dtypes=(tf.complex64, tf.complex128),
)
expm1 = _standard_complex(tf.math.expm1, "expm1")
log1p = _standard_complex(tf.math.log1p, "log1p")
sqrt = _standard_complex(tf.math.sqrt, "sqrt")
tanh = _standard_complex(tf.math.tanh, "tanh")
