"""numpy backend: array creation (float32 by default, as on every backend)."""

from __future__ import annotations

import numpy as np

from ivy.backends._creation_args import check_python_data, check_step, linspace_dtype
from ivy.backends._dlpack import exportable, on_host, refuse_copy_between_devices
from ivy.backends.numpy._helpers import (
    check_device,
    default_dtype_of_value,
    has_own_dtype,
    native_dtype,
)
from ivy.framework_handler import get_framework

_DOWNCAST = {np.dtype(np.float64): np.float32, np.dtype(np.complex128): np.complex64}


def asarray(obj, /, *, dtype=None, device=None, copy=None):
    check_device(device)
    if not isinstance(obj, (np.ndarray, np.generic)) and hasattr(obj, "__dlpack__"):
        obj = _from_other_framework(obj)
    if dtype is not None:
        return np.asarray(obj, dtype=native_dtype(dtype), copy=copy)
    x = np.asarray(obj, copy=copy)
    if not has_own_dtype(obj):
        check_python_data(x, "numpy")
        if x.dtype in _DOWNCAST:
            return x.astype(_DOWNCAST[x.dtype])
    return x


def _from_other_framework(obj):
    """A tensor of another framework: detach it if it can be, then let numpy read it."""
    detach = getattr(obj, "detach", None)
    if detach is not None:
        obj = detach().cpu()
    return obj


def zeros(shape, *, dtype=None, device=None):
    check_device(device)
    return np.zeros(shape, dtype=native_dtype(dtype) or np.float32)


def ones(shape, *, dtype=None, device=None):
    check_device(device)
    return np.ones(shape, dtype=native_dtype(dtype) or np.float32)


def empty(shape, *, dtype=None, device=None):
    check_device(device)
    return np.empty(shape, dtype=native_dtype(dtype) or np.float32)


def full(shape, fill_value, *, dtype=None, device=None):
    check_device(device)
    dt = native_dtype(dtype) or default_dtype_of_value(fill_value)
    return np.full(shape, fill_value, dtype=dt)


def arange(start, /, stop=None, step=1, *, dtype=None, device=None):
    check_device(device)
    check_step(step, "numpy")
    if dtype is None:
        ints = all(isinstance(v, (int, np.integer)) for v in (start, stop, step) if v is not None)
        dtype = np.int64 if ints else np.float32
    if stop is None:
        start, stop = 0, start
    return np.arange(start, stop, step, dtype=native_dtype(dtype))


def linspace(start, stop, /, num, *, dtype=None, device=None, endpoint=True):
    check_device(device)
    dtype = linspace_dtype(start, stop, dtype, "numpy") or dtype
    return np.linspace(start, stop, num, endpoint=endpoint, dtype=native_dtype(dtype))


def eye(n_rows, n_cols=None, /, *, k=0, dtype=None, device=None):
    check_device(device)
    return np.eye(n_rows, n_cols, k=k, dtype=native_dtype(dtype) or np.float32)


def zeros_like(x, /, *, dtype=None, device=None):
    check_device(device)
    return np.zeros_like(x, dtype=native_dtype(dtype))


def ones_like(x, /, *, dtype=None, device=None):
    check_device(device)
    return np.ones_like(x, dtype=native_dtype(dtype))


def empty_like(x, /, *, dtype=None, device=None):
    check_device(device)
    return np.empty_like(x, dtype=native_dtype(dtype))


def full_like(x, /, fill_value, *, dtype=None, device=None):
    check_device(device)
    return np.full_like(x, fill_value, dtype=native_dtype(dtype))


tril = np.tril
triu = np.triu


def from_dlpack(x, /, *, device=None, copy=None):
    check_device(device)
    original = x
    x, copy_after = exportable(x)
    if not on_host(x):  # an accelerator's array: its framework copies it to the host
        refuse_copy_between_devices(copy, "from an accelerator to the host")
        return np.asarray(get_framework(original).to_numpy(original))
    if copy_after:
        out = np.from_dlpack(x)
        return out.copy() if copy else out
    return np.from_dlpack(x, copy=copy)


def meshgrid(*arrays, indexing="xy"):
    return list(np.meshgrid(*arrays, indexing=indexing))
