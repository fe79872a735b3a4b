"""tensorflow backend: data types. tf has no type promotion of its own: ``can_cast`` and
``result_type`` follow ivy's rules, which the backend's functions apply (see ``_helpers``)."""

from __future__ import annotations

import tensorflow as tf

from ivy.backends.tensorflow._helpers import NATIVE_DTYPES, native_dtype, placed
from ivy.core import _dtype_rules as rules

_SCALARS = (bool, int, float, complex)


def astype(x, dtype, /, *, copy=True, device=None):
    """tf tensors are immutable, so ``copy`` changes nothing."""
    if device is None:
        return tf.cast(x, native_dtype(dtype))
    with placed(device):
        return tf.identity(tf.cast(x, native_dtype(dtype)))


def _name(dtype_or_array) -> str:
    dt = getattr(dtype_or_array, "dtype", None)
    if dt is not None and not isinstance(dtype_or_array, (tf.DType, type)):
        dtype_or_array = dt  # a tensor, variable or numpy array
    return rules.name_of(native_dtype(dtype_or_array).name)


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
    if not isinstance(dtype, (tf.dtypes.DType, type, str)):
        dtype = getattr(dtype, "dtype", dtype)  # a tensor, a variable or a numpy array
    if isinstance(dtype, tf.dtypes.DType):
        return rules.name_of(dtype.name)
    return rules.name_of(dtype)


def enable_float64():
    """tensorflow holds 64-bit types always."""
