"""torch backend: elementwise functions.

Most are torch's own functions, exported as they are: they take Python scalars on either side
(``add(2.0, x)``). Comparisons are the ``operator`` functions, which reach the tensor's own
comparison from either side (``torch.gt(2.0, x)`` fails). The thin shims below make a Python scalar
operand work where torch rejects it (``torch.maximum(x, 2.0)`` fails).
"""

from __future__ import annotations

import functools
import operator

import numpy as np
import torch

from ivy import framework_handler as _fh
from ivy.backends import _int_pow, _int_scalars, _signed_zeros
from ivy.backends._clip_args import clip_bounds
from ivy.backends._complex_special import namespace, wrap
from ivy.backends.torch._helpers import (
    NATIVE_DTYPES,
    as_inexact,
    dtype_name,
    values_known,
    with_tensor_operands,
)
from ivy.backends.torch._unsigned import WIDE_UNSIGNED, unsigned_safe
from ivy.backends.torch.creation import asarray
from ivy.core import _dtype_rules as rules

# torch's complex acos, expm1, log1p and tanh miss some of the Array API's special values
# (acos(0j), expm1(inf + 0j)...): torch's own, with those put back for complex results.
_standard_complex = functools.partial(
    wrap, xp=namespace(torch), complex_dtypes=(torch.complex64, torch.complex128)
)
acos = _standard_complex(torch.acos, "acos")
acosh = torch.acosh
asin = torch.asin
asinh = torch.asinh
atan = torch.atan
atanh = torch.atanh
ceil = torch.ceil
conj = torch.conj_physical  # a new tensor, not a lazily conjugated view
cos = torch.cos
cosh = torch.cosh
exp = torch.exp
expm1 = _standard_complex(torch.expm1, "expm1")
floor = torch.floor
isfinite = torch.isfinite
isinf = torch.isinf
isnan = torch.isnan
log = torch.log
log10 = torch.log10
log1p = _standard_complex(torch.log1p, "log1p")
log2 = torch.log2
positive = torch.positive
reciprocal = torch.reciprocal


def round(x, /):  # noqa: A001 - the Array API name
    """torch's (halves to even); complex numbers round each part (torch has no kernel)."""
    if x.is_complex():
        return torch.complex(torch.round(x.real), torch.round(x.imag))
    return torch.round(x)


signbit = torch.signbit
sin = torch.sin
sinh = torch.sinh
sqrt = torch.sqrt
tan = torch.tan
tanh = _standard_complex(torch.tanh, "tanh")
trunc = torch.trunc

# What torch refuses for uint16, uint32 and uint64 is computed through int64 (``_unsigned.py``).
negative = unsigned_safe(torch.negative, "negative", "arith", (0,))
square = unsigned_safe(torch.square, "square", "arith", (0,))
bitwise_invert = unsigned_safe(torch.bitwise_not, "bitwise_invert", "arith", (0,))
logical_not = unsigned_safe(torch.logical_not, "logical_not", "arith", (0,))


def abs(x, /):  # noqa: A001 - the Array API name
    try:
        return torch.abs(x)
    except (NotImplementedError, RuntimeError):
        if x.dtype is torch.bool or x.dtype in WIDE_UNSIGNED:
            return x.clone()  # torch has no abs of bools and wide unsigned integers
        raise


abs.__ivy_native__ = torch.abs


def real(x, /):
    return torch.real(x) if x.is_complex() else x.clone()


def imag(x, /):
    return torch.imag(x) if x.is_complex() else torch.zeros_like(x)  # torch refuses real input


def _binary(native, name: str, kind: str):
    """ivy's binary function ``name`` on torch's ``native``: Array API promotion, also of 0-d
    tensors, which torch would promote as Python scalars (a 0-d int64 tensor plus an int8 one is
    int64, not int8); Python scalars on either side; uint16, uint32 and uint64 computed through
    int64 where torch has no kernel (``kind``, see ``_unsigned.py``)."""
    wide = unsigned_safe(native, name, kind)

    def fn(x1, x2, /):
        try:
            if x1.dtype is x2.dtype:
                return native(x1, x2)
        except AttributeError:  # a Python scalar
            if type(x1) is int or type(x2) is int:  # beyond the tensor's dtype?
                x1, x2 = _int_scalars.operands(wide, name, x1, x2)
                if x2 is None:
                    return x1
            return wide(*with_tensor_operands(x1, x2)) if not _scalar_ok(x1, x2) else wide(x1, x2)
        except _REFUSED:
            return wide(x1, x2)
        if isinstance(x1, np.generic) or isinstance(x2, np.generic):  # numpy scalars: as
            return fn(*(v.item() if isinstance(v, np.generic) else v for v in (x1, x2)))  # Python's
        return wide(*_promoted(x1, x2))

    fn.__name__ = fn.__qualname__ = name
    fn.__doc__ = f"``{getattr(native, '__name__', name)}`` with Array API type promotion."
    return fn


_REFUSED = (NotImplementedError, RuntimeError)


def _scalar_ok(x1, x2) -> bool:
    """torch's functions take a Python scalar on the right, and on the left for a few."""
    return isinstance(x1, torch.Tensor)


def _promoted(x1, x2):
    """Two tensors of different dtypes, in the dtype ivy's rules give them."""
    dtype = _PROMOTED.get((x1.dtype, x2.dtype))
    if dtype is None:
        dtype = _PROMOTED[(x1.dtype, x2.dtype)] = NATIVE_DTYPES[
            rules.promote(dtype_name(x1.dtype), dtype_name(x2.dtype))
        ]
    return (x1 if x1.dtype is dtype else x1.to(dtype)), (x2 if x2.dtype is dtype else x2.to(dtype))


_PROMOTED: dict = {}

add = _binary(torch.add, "add", "arith")
subtract = _binary(torch.subtract, "subtract", "arith")
multiply = _binary(torch.multiply, "multiply", "arith")
_divide = _binary(torch.divide, "divide", "arith")


def divide(x1, x2, /):
    """``x1 / x2``; integers and bools of two dtypes (int64 with uint64 promotes to float64)
    are divided in float32, as integers of one dtype are."""
    d1, d2 = getattr(x1, "dtype", None), getattr(x2, "dtype", None)
    if (
        d1 is not d2
        and isinstance(d1, torch.dtype)  # two tensors (a numpy scalar has a numpy dtype)
        and isinstance(d2, torch.dtype)
        and not _inexact(d1, d2)
    ):
        x1, x2 = x1.to(torch.float32), x2.to(torch.float32)
    return _divide(x1, x2)


def _inexact(*dtypes) -> bool:
    return any(d.is_floating_point or d.is_complex for d in dtypes)


_pow = _binary(torch.pow, "pow", "arith")


def _integral(x) -> bool:
    if isinstance(x, torch.Tensor):
        return not (x.is_floating_point() or x.is_complex() or x.dtype is torch.bool)
    return type(x) is int or isinstance(x, np.integer)


def _signed_integral(x) -> bool:
    """An exponent that can be negative (torch has no comparison kernels for uint16+)."""
    return _integral(x) and (not isinstance(x, torch.Tensor) or x.dtype.is_signed)


def pow(x1, x2, /):
    """``x1 ** x2``; integers to negative integer powers as ``ivy/backends/_int_pow.py`` says."""
    if not (_signed_integral(x2) and _integral(x1)):  # the common case, first
        return _pow(x1, x2)
    return _int_pow.integer_pow(
        _pow,
        x1,
        x2,
        integral=_integral,
        values_known=values_known,
        any_negative=lambda x: bool((x < 0).any()) if isinstance(x, torch.Tensor) else x < 0,
        where=torch.where,
        backend="torch",
    )


_HALF = (torch.float16, torch.bfloat16)


def _floor_divide(x1, x2, /):
    """torch's, with half-precision floats computed in float32 as numpy does (torch's own
    float16 result rounds the quotient: -2.5 // 0.003 is -835 there, -834 in numpy)."""
    out = torch.floor_divide(x1, x2)
    if out.dtype in _HALF:
        wide = torch.floor_divide(
            *(v.float() if isinstance(v, torch.Tensor) else v for v in (x1, x2))
        )
        return wide.to(out.dtype)
    return out


floor_divide = _binary(_floor_divide, "floor_divide", "divide")
remainder = _binary(torch.remainder, "remainder", "divide")
bitwise_and = _binary(torch.bitwise_and, "bitwise_and", "arith")
bitwise_or = _binary(torch.bitwise_or, "bitwise_or", "arith")
bitwise_xor = _binary(torch.bitwise_xor, "bitwise_xor", "arith")
bitwise_left_shift = _binary(torch.bitwise_left_shift, "bitwise_left_shift", "arith")
bitwise_right_shift = _binary(torch.bitwise_right_shift, "bitwise_right_shift", "divide")
# (operator functions reach the tensor's comparison from either side: torch.gt(2.0, x) fails)
equal = _binary(operator.eq, "equal", "order")
not_equal = _binary(operator.ne, "not_equal", "order")
less = _binary(operator.lt, "less", "order")
less_equal = _binary(operator.le, "less_equal", "order")
greater = _binary(operator.gt, "greater", "order")
greater_equal = _binary(operator.ge, "greater_equal", "order")


def atan2(x1, x2, /):
    return torch.atan2(*_inexact_operands(x1, x2))


def copysign(x1, x2, /):
    return torch.copysign(*_inexact_operands(x1, x2))


def hypot(x1, x2, /):
    return torch.hypot(*_inexact_operands(x1, x2))


def logaddexp(x1, x2, /):
    return torch.logaddexp(*_inexact_operands(x1, x2))


def nextafter(x1, x2, /):
    return torch.nextafter(*_inexact_operands(x1, x2))


def _logical(native, name: str):
    wide = unsigned_safe(native, name, "arith")

    def fn(x1, x2, /):
        return wide(*with_tensor_operands(x1, x2))

    fn.__name__ = fn.__qualname__ = name
    return fn


logical_and = _logical(torch.logical_and, "logical_and")
logical_or = _logical(torch.logical_or, "logical_or")
logical_xor = _logical(torch.logical_xor, "logical_xor")


def _zero_ties(native, lower: bool):
    """torch's ``minimum`` or ``maximum`` with IEEE's signed zeros at a tie of zeros (torch
    returns the first operand; ``ivy/backends/_signed_zeros.py``)."""

    def fn(x1, x2):
        out = native(x1, x2)
        if not out.is_floating_point():
            return out
        return _signed_zeros.zero_ties(torch.where, x1, x2, out, lower)

    fn.__name__ = native.__name__
    return fn


def _extremum(native, bound: str, name: str):
    """maximum or minimum: torch's own for tensors (promoted as ivy's rules say), ``clamp`` with
    a Python scalar (faster than making the scalar a tensor; NaN propagates); IEEE's signed
    zeros at a tie of zeros."""
    lower = bound == "max"
    tensors = _binary(_zero_ties(native, lower), name, "order")
    clamped = unsigned_safe(torch.clamp, name, "order", (0, 1, 2))

    def fn(x1, x2, /):
        if isinstance(x1, torch.Tensor) and isinstance(x2, torch.Tensor):
            return tensors(x1, x2)
        x, scalar = (x1, x2) if isinstance(x1, torch.Tensor) else (x2, x1)
        if type(scalar) is int:
            _int_scalars.operands(native, name, x1, x2)  # (raises beyond x's dtype)
        if x.dtype is torch.bool or x.dtype.is_complex or not isinstance(scalar, (int, float)):
            return tensors(*with_tensor_operands(x1, x2))
        if isinstance(scalar, float) and not (x.is_floating_point()):
            return tensors(*with_tensor_operands(x1, x2))  # int and float: a float result
        out = clamped(x, scalar, None) if bound == "min" else clamped(x, None, scalar)
        if scalar == 0 and out.is_floating_point():  # a tie of zeros is possible
            return _signed_zeros.zero_ties(torch.where, x, scalar, out, lower)
        return out

    fn.__name__ = fn.__qualname__ = name
    return fn


maximum = _extremum(torch.maximum, "min", "maximum")
minimum = _extremum(torch.minimum, "max", "minimum")


def sign(x, /):
    if x.is_floating_point():
        return torch.where(torch.isnan(x), x, torch.sign(x))  # torch.sign(nan) is 0
    if x.dtype in WIDE_UNSIGNED:  # no kernel: 0 or 1
        return (x != 0).to(x.dtype)
    if x.dtype is torch.bool:
        return x.clone()
    return _complex_sign(x)  # complex: x / |x|, as numpy 2 and the Array API


# (NaN + NaN j wherever a part is infinite or NaN: torch.sgn gives 0 + NaN j for some)
_complex_sign = _standard_complex(torch.sgn, "sign")


_clamp = unsigned_safe(torch.clamp, "clip", "order", (0, 1, 2))


def clip(x, /, min=None, max=None):
    """The result has ``x``'s dtype whatever the bounds' (``ivy/backends/_clip_args.py``)."""
    x = x if isinstance(x, torch.Tensor) else asarray(x)
    if min is None and max is None:
        return x.clone()
    low, high = clip_bounds(_namespace(), x, min, max)
    if isinstance(low, torch.Tensor) != isinstance(high, torch.Tensor) and None not in (low, high):
        # torch.clamp takes two tensors or two numbers
        low, high = (
            v if isinstance(v, torch.Tensor) else torch.full((), v, dtype=x.dtype, device=x.device)
            for v in (low, high)
        )
    if x.dtype is torch.bool:
        return _bool_clip(x, low, high)
    return _clamp(x, low, high)


def _bool_clip(x, low, high):
    if low is not None:
        x = torch.logical_or(x, torch.as_tensor(low, device=x.device))
    if high is not None:
        x = torch.logical_and(x, torch.as_tensor(high, device=x.device))
    return x


def _namespace():
    return _fh.load_backend("torch")


def nan_to_num(x, /, *, nan=0.0, posinf=None, neginf=None):
    return torch.nan_to_num(x, nan=nan, posinf=posinf, neginf=neginf)


def _inexact_operands(x1, x2):
    """Tensor operands of one dtype for functions torch defines on floats only: integer and
    boolean operands become float32 (ivy's rule, ``ivy/backends/_reals.py``), or the dtype of
    the floating operand; two floating operands take their promoted dtype (also when one is
    0-d, which torch would promote as a Python scalar)."""
    a, b = with_tensor_operands(x1, x2)
    fa, fb = a.is_floating_point() or a.is_complex(), b.is_floating_point() or b.is_complex()
    if fa and fb:
        return _promoted(a, b) if a.dtype is not b.dtype else (a, b)
    if fa:
        return a, b.to(a.dtype)
    if fb:
        return a.to(b.dtype), b
    return as_inexact(a), as_inexact(b)
