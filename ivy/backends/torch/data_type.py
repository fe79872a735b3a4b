"""torch backend: data types. torch promotes uint16, uint32 and uint64 with no other dtype and its
``can_cast`` allows float64 to float32, so ``can_cast`` and ``result_type`` follow ivy's rules
(those of torch for every other dtype); ``finfo`` and ``iinfo`` return the Array API's fields
with torch's dtype as ``dtype`` (torch's own finfo has a string there)."""

from __future__ import annotations

import torch

from ivy.backends.torch._helpers import NATIVE_DTYPES, native_device, native_dtype
from ivy.backends.torch._helpers import dtype_name as _native_name
from ivy.core import _dtype_rules as rules

_SCALARS = (bool, int, float, complex)


def astype(x, dtype, /, *, copy=True, device=None):
    return x.to(device=native_device(device), dtype=native_dtype(dtype), copy=copy)


def _name(dtype_or_array) -> str:
    if isinstance(dtype_or_array, torch.Tensor):
        return _native_name(dtype_or_array.dtype)
    return _native_name(native_dtype(dtype_or_array))


def can_cast(from_, to, /):
    return rules.can_cast(_name(from_), _name(to))


def result_type(*arrays_and_dtypes):
    names = [_name(a) for a in arrays_and_dtypes if not isinstance(a, _SCALARS)]
    scalars = [a for a in arrays_and_dtypes if isinstance(a, _SCALARS)]
    return NATIVE_DTYPES[rules.result_type(names, scalars)]


def finfo(type, /):
    return rules.finfo(_name(type), NATIVE_DTYPES.__getitem__)


def iinfo(type, /):
    return rules.iinfo(_name(type), NATIVE_DTYPES.__getitem__)


def isdtype(dtype, kind):
    return rules.isdtype(_name(dtype), kind, _name)


def dtype_name(dtype, /):
    if isinstance(dtype, torch.Tensor):
        dtype = dtype.dtype
    if isinstance(dtype, torch.dtype):
        return _native_name(dtype)
    return rules.name_of(dtype)


def enable_float64():
    """torch holds 64-bit types always."""
