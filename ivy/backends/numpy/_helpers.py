"""Dtype and device conversion shared by the numpy backend's modules."""

from __future__ import annotations

import numpy as np

from ivy.dtypes import DTYPE_NAMES

NATIVE_DTYPES = {name: np.bool_ if name == "bool" else getattr(np, name) for name in DTYPE_NAMES}
_NAMES = {np.dtype(t): name for name, t in NATIVE_DTYPES.items()}


def native_dtype(dtype):
    """numpy dtype for a dtype name or object; None stays None."""
    if dtype is None:
        return None
    if isinstance(dtype, str):
        try:
            return NATIVE_DTYPES[dtype]
        except KeyError:
            raise TypeError(
                f"Unknown dtype {dtype!r}; use one of {', '.join(DTYPE_NAMES)}."
            ) from None
    return np.dtype(dtype).type


def dtype_name(dtype) -> str:
    return _NAMES[np.dtype(dtype)]


def check_device(device) -> None:
    """numpy arrays live on the CPU only."""
    if device not in (None, "cpu", "cpu:0"):
        from ivy import framework_handler as _fh
        from ivy.errors import unavailable_device

        raise unavailable_device(device, _fh.load_backend("numpy"))


def has_own_dtype(obj) -> bool:
    """True when ``obj`` carries a dtype (an array, or a list of arrays), so it must be kept."""
    while isinstance(obj, (list, tuple)) and obj:
        obj = obj[0]
    return hasattr(obj, "dtype")


def default_dtype_of_value(value):
    """The dtype a Python value gets by default: bool, int64, float32 or complex64."""
    if isinstance(value, (bool, np.bool_)):
        return np.bool_
    if isinstance(value, (int, np.integer)):
        return np.int64
    if isinstance(value, (float, np.floating)):
        return np.float32
    if isinstance(value, (complex, np.complexfloating)):
        return np.complex64
    return None


def as_inexact(x):
    """``x``, with an integer or boolean array converted to float32: how functions of real
    numbers treat such inputs on every backend (see ``ivy/backends/_reals.py``)."""
    x = np.asarray(x)
    return x if x.dtype.kind in "fc" else x.astype(np.float32)


def native_device(device):
    """numpy's only device: None (numpy's functions take ``device='cpu'`` or None)."""
    check_device(device)
    return None if device is None else "cpu"  # (numpy's functions take "cpu", not "cpu:0")


def device_name(device) -> str:
    return "cpu"


# What the shared layer's functions find besides ``xp`` (ivy/backends/array_api/_unbound.py).
SHARED = {
    "array_types": (np.ndarray, np.generic),
    "native_dtype": native_dtype,
    "native_device": native_device,
    "as_inexact": as_inexact,
    "dtype_name": dtype_name,
    "device_name": device_name,
    "concrete": lambda value: True,
}
