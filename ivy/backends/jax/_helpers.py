"""Dtype and device conversion shared by the jax backend's modules.

jax decides at call time whether 64-bit types exist (``jax.config.jax_enable_x64``), so the
default int and the 64-bit checks read that setting on every call.
"""

from __future__ import annotations

import jax
import jax.numpy as jnp
import numpy as np

from ivy.dtypes import DTYPE_NAMES
from ivy.errors import UnsupportedError

NATIVE_DTYPES = {name: jnp.bool_ if name == "bool" else getattr(jnp, name) for name in DTYPE_NAMES}
_BY_NUMPY = {np.dtype(t): t for t in NATIVE_DTYPES.values()}
_NEEDS_X64 = {
    np.dtype(np.float64): "float32",
    np.dtype(np.int64): "int32",
    np.dtype(np.uint64): "uint32",
    np.dtype(np.complex128): "complex64",
}


def _x64() -> bool:
    return jax.config.jax_enable_x64


# The dtypes jax holds only while 64-bit types are on (read at each look-up: x64 may be switched
# on after import).
X64_DTYPES = {name: _x64 for name in ("int64", "uint64", "float64", "complex128")}
# jax.numpy's own inspection says no to both, since neither works inside jax.jit; ivy's
# functions are eager unless compiled, and there both work.
ARRAY_API_CAPABILITIES = {
    "boolean indexing": True,
    "data-dependent shapes": True,
    "max dimensions": None,
}


def devices() -> list:
    """The devices jax sees: those of its default backend, and the CPU."""
    found = list(jax.devices())
    return found + [d for d in jax.devices("cpu") if d not in found]


def default_int():
    """int64 when jax has 64-bit types enabled, else int32 (jax cannot hold int64 then)."""
    return jnp.int64 if jax.config.jax_enable_x64 else jnp.int32


def check_x64(dtype) -> None:
    """Raise UnsupportedError for a 64-bit dtype while jax has 64-bit types disabled."""
    dt = np.dtype(dtype)
    if dt in _NEEDS_X64 and not jax.config.jax_enable_x64:
        raise UnsupportedError(
            f"jax has 64-bit types disabled, so it cannot make {dt.name} arrays. Call "
            f"jax.config.update('jax_enable_x64', True) at startup, or use {_NEEDS_X64[dt]}."
        )


def native_dtype(dtype):
    """jax dtype for a dtype name or object; None stays None. 64-bit dtypes need x64."""
    if dtype is None:
        return None
    if isinstance(dtype, str):
        try:
            dtype = NATIVE_DTYPES[dtype]
        except KeyError:
            raise TypeError(
                f"Unknown dtype {dtype!r}; use one of {', '.join(DTYPE_NAMES)}."
            ) from None
    dt = np.dtype(dtype)
    check_x64(dt)
    return _BY_NUMPY.get(dt, dt.type)  # e.g. bfloat16 passes through as jax's own type


def has_own_dtype(obj) -> bool:
    """True when ``obj`` carries a dtype (an array, or a list of arrays), so it must be kept."""
    while isinstance(obj, (list, tuple)) and obj:
        obj = obj[0]
    return hasattr(obj, "dtype")


def check_x64_of(obj) -> None:
    """Raise if an array in ``obj`` (an array or nested lists of them) is 64-bit without x64."""
    if jax.config.jax_enable_x64:
        return
    if isinstance(obj, (list, tuple)):
        for item in obj:
            check_x64_of(item)
    elif hasattr(obj, "dtype"):
        check_x64(obj.dtype)


def default_dtype_of_value(value):
    """The dtype a Python value gets by default: bool, the default int, float32 or complex64."""
    if isinstance(value, (bool, np.bool_)):
        return jnp.bool_
    if isinstance(value, (int, np.integer)):
        return default_int()
    if isinstance(value, (float, np.floating)):
        return jnp.float32
    if isinstance(value, (complex, np.complexfloating)):
        return jnp.complex64
    return None


_DEVICES: dict[str, jax.Device] = {}


def native_device(device):
    """jax Device for ``'cpu'``, ``'gpu:0'``, ... (or a jax Device); None stays None."""
    if device is None or isinstance(device, jax.Device):
        return device
    try:
        return _DEVICES[device]
    except (KeyError, TypeError):
        pass
    platform, _, index = str(device).partition(":")
    try:
        found = jax.devices(platform)[int(index or 0)]
    except (RuntimeError, ValueError, IndexError):
        from ivy import framework_handler as _fh
        from ivy.errors import unavailable_device

        raise unavailable_device(device, _fh.load_backend("jax")) from None
    _DEVICES[device] = found
    return found


_NAMES: dict[jax.Device, str] = {}


def device_name(d) -> str:
    """'cpu' for the first CPU device, else 'gpu:N' (N: its place in ``jax.devices('gpu')``)."""
    try:
        return _NAMES[d]
    except KeyError:
        pass
    index = jax.devices(d.platform).index(d)
    name = "cpu" if d.platform == "cpu" and index == 0 else f"{d.platform}:{index}"
    _NAMES[d] = name
    return name


def default_device():
    """The device jax places new arrays and compiled computations on by default."""
    d = jax.config.jax_default_device
    if d is None:
        return jax.devices()[0]
    return native_device(d) if isinstance(d, str) else d


def as_inexact(x):
    """``x``, with an integer or boolean array converted to float32: how functions of real
    numbers treat such inputs on every backend (see ``ivy/backends/_reals.py``)."""
    x = jnp.asarray(x)
    return x if x.dtype.kind in "fc" else x.astype(jnp.float32)


def dtype_name(dtype) -> str:
    return np.dtype(dtype).name


# What the shared layer's functions find besides ``xp`` (ivy/backends/array_api/_unbound.py).
SHARED = {
    "array_types": (jax.Array,),
    "native_dtype": native_dtype,
    "native_device": native_device,
    "as_inexact": as_inexact,
    "dtype_name": dtype_name,
    "device_name": device_name,
    "concrete": lambda value: not isinstance(value, jax.core.Tracer),
}


def set_precision(precision: str):
    """jax's default precision of float32 matrix products and convolutions
    (``jax_default_matmul_precision``: ``'highest'`` full float32, ``'high'`` bf16 passes or
    TF32 where the platform has them); returns what restores the value found."""
    saved = jax.config.jax_default_matmul_precision
    jax.config.update("jax_default_matmul_precision", precision)
    return lambda: jax.config.update("jax_default_matmul_precision", saved)
