"""torch backend: elementwise functions.

Most are torch's own functions, exported as they are: they take Python scalars on either side
(``add(2.0, x)``). Comparisons are the ``operator`` functions, which reach the tensor's own
comparison from either side (``torch.gt(2.0, x)`` fails). The thin shims below make a Python scalar
operand work where torch rejects it (``torch.maximum(x, 2.0)`` fails).
"""

from __future__ import annotations

import operator

import torch

from ivy.backends.torch._helpers import as_inexact, with_tensor_operands
from ivy.backends.torch.creation import asarray

abs = torch.abs
acos = torch.acos
acosh = torch.acosh
add = torch.add
asin = torch.asin
asinh = torch.asinh
atan = torch.atan
atanh = torch.atanh
bitwise_and = torch.bitwise_and
bitwise_invert = torch.bitwise_not
bitwise_left_shift = torch.bitwise_left_shift
bitwise_or = torch.bitwise_or
bitwise_right_shift = torch.bitwise_right_shift
bitwise_xor = torch.bitwise_xor
ceil = torch.ceil
conj = torch.conj_physical  # a new tensor, not a lazily conjugated view
cos = torch.cos
cosh = torch.cosh
divide = torch.divide
equal = operator.eq
exp = torch.exp
expm1 = torch.expm1
floor = torch.floor
floor_divide = torch.floor_divide
greater = operator.gt
greater_equal = operator.ge
imag = torch.imag
isfinite = torch.isfinite
isinf = torch.isinf
isnan = torch.isnan
less = operator.lt
less_equal = operator.le
log = torch.log
log10 = torch.log10
log1p = torch.log1p
log2 = torch.log2
logical_not = torch.logical_not
multiply = torch.multiply
negative = torch.negative
not_equal = operator.ne
positive = torch.positive
pow = torch.pow
real = torch.real
reciprocal = torch.reciprocal
remainder = torch.remainder
round = torch.round
signbit = torch.signbit
sin = torch.sin
sinh = torch.sinh
sqrt = torch.sqrt
square = torch.square
subtract = torch.subtract
tan = torch.tan
tanh = torch.tanh
trunc = torch.trunc


def atan2(x1, x2, /):
    return torch.atan2(*with_tensor_operands(x1, x2))


def copysign(x1, x2, /):
    return torch.copysign(*with_tensor_operands(x1, x2))


def hypot(x1, x2, /):
    return torch.hypot(*_inexact_operands(x1, x2))


def logaddexp(x1, x2, /):
    return torch.logaddexp(*_inexact_operands(x1, x2))


def nextafter(x1, x2, /):
    return torch.nextafter(*_inexact_operands(x1, x2))


def logical_and(x1, x2, /):
    return torch.logical_and(*with_tensor_operands(x1, x2))


def logical_or(x1, x2, /):
    return torch.logical_or(*with_tensor_operands(x1, x2))


def logical_xor(x1, x2, /):
    return torch.logical_xor(*with_tensor_operands(x1, x2))


def maximum(x1, x2, /):
    if isinstance(x1, torch.Tensor) and isinstance(x2, torch.Tensor):
        return torch.maximum(x1, x2)
    x, scalar = (x1, x2) if isinstance(x1, torch.Tensor) else (x2, x1)
    if x.dtype is torch.bool:
        return torch.maximum(*with_tensor_operands(x1, x2))
    return torch.clamp(x, min=scalar)  # faster than making the scalar a tensor; nan propagates


def minimum(x1, x2, /):
    if isinstance(x1, torch.Tensor) and isinstance(x2, torch.Tensor):
        return torch.minimum(x1, x2)
    x, scalar = (x1, x2) if isinstance(x1, torch.Tensor) else (x2, x1)
    if x.dtype is torch.bool:
        return torch.minimum(*with_tensor_operands(x1, x2))
    return torch.clamp(x, max=scalar)  # faster than making the scalar a tensor; nan propagates


def sign(x, /):
    if x.is_floating_point():
        return torch.where(torch.isnan(x), x, torch.sign(x))  # torch.sign(nan) is 0
    return torch.sgn(x)  # complex: x / |x|, as numpy 2 and the Array API


def clip(x, /, min=None, max=None):
    x, min, max = (_tensor_or_scalar(v) for v in (x, min, max))
    if min is None and max is None:
        return x.clone()
    return torch.clamp(x, min, max)


def _tensor_or_scalar(value):
    """``value`` as it is if a tensor, a Python number or None, else (a numpy array, a list...)
    as a tensor: ``ivy.clip(np.array([-1., 2.]), 0, 1, f='torch')`` is a tensor."""
    if value is None or isinstance(value, (torch.Tensor, int, float)):
        return value
    return asarray(value)


def nan_to_num(x, /, *, nan=0.0, posinf=None, neginf=None):
    return torch.nan_to_num(x, nan=nan, posinf=posinf, neginf=neginf)


def _inexact_operands(x1, x2):
    """Tensor operands of one dtype for functions torch defines on floats only: integer and
    boolean operands become float32 (ivy's rule, ``ivy/backends/_reals.py``), or the dtype of
    the floating operand."""
    a, b = with_tensor_operands(x1, x2)
    if a.is_floating_point() or a.is_complex():
        return a, b if b.dtype is a.dtype else b.to(torch.promote_types(a.dtype, b.dtype))
    if b.is_floating_point() or b.is_complex():
        return a.to(b.dtype), b
    return as_inexact(a), as_inexact(b)
