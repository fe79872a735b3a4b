"""jax backend: array creation (float32 by default, as on every backend)."""

from __future__ import annotations

import jax
import jax.numpy as jnp
import numpy as np

from ivy.backends._constants import ConstantCache
from ivy.backends._creation_args import beyond_int64, check_fill_value, check_step, linspace_dtype
from ivy.backends._dlpack import exportable, on_host, refuse_copy_between_devices
from ivy.backends.jax._helpers import (
    check_x64_of,
    default_dtype_of_value,
    default_int,
    has_own_dtype,
    native_device,
    native_dtype,
)

# Python floats and complexes are float32 / complex64 by default, whatever jax's x64 setting.
_DOWNCAST = {np.dtype(np.float64): jnp.float32, np.dtype(np.complex128): jnp.complex64}


def asarray(obj, /, *, dtype=None, device=None, copy=None):
    dtype, device = native_dtype(dtype), native_device(device)
    if copy is False and _needs_copy(obj, dtype, device):
        raise ValueError(
            "asarray: copy=False, but a copy is needed: jax copies numpy arrays, lists and other "
            "frameworks' tensors, and any change of dtype or device. Pass copy=None to allow it."
        )
    if not isinstance(obj, (jax.Array, np.ndarray, np.generic)) and (
        hasattr(obj, "__dlpack__") or hasattr(obj, "__array__")
    ):
        obj = _from_other_framework(obj)
    if isinstance(obj, jax.core.Tracer):
        # a traced value is placed by its computation; jax 0.10 cannot place a vmap or jvp
        # tracer ("'SingleDeviceSharding' object has no attribute 'spec'")
        device = None
    if dtype is not None or has_own_dtype(obj):
        if dtype is None:
            check_x64_of(obj)
        return jnp.asarray(obj, dtype=dtype, copy=copy, device=device)
    # Python values: float32 / complex64 / the default int, and not weakly typed.
    try:
        x = jnp.asarray(obj, copy=copy, device=device)
    except OverflowError:  # ("Python int too large to convert to C long")
        raise beyond_int64("jax") from None
    return jnp.asarray(x, dtype=_DOWNCAST.get(x.dtype, x.dtype))


def _needs_copy(obj, dtype, device) -> bool:
    if not isinstance(obj, jax.Array):
        return True
    if dtype is not None and np.dtype(dtype) != obj.dtype:
        return True
    return device is not None and not isinstance(obj, jax.core.Tracer) and obj.devices() != {device}


def _from_other_framework(obj):
    """A tensor of another framework (torch, tensorflow) as a numpy array, detached, on the CPU."""
    detach = getattr(obj, "detach", None)
    if detach is not None:
        obj = detach().cpu()
    return np.asarray(obj)


def zeros(shape, *, dtype=None, device=None):
    return jnp.zeros(shape, native_dtype(dtype) or jnp.float32, device=native_device(device))


def ones(shape, *, dtype=None, device=None):
    return jnp.ones(shape, native_dtype(dtype) or jnp.float32, device=native_device(device))


def empty(shape, *, dtype=None, device=None):
    return jnp.empty(shape, native_dtype(dtype) or jnp.float32, device=native_device(device))


def full(shape, fill_value, *, dtype=None, device=None):
    dt = native_dtype(dtype) or default_dtype_of_value(fill_value)
    check_fill_value(fill_value, jnp.dtype(dt).name, "jax")
    return jnp.full(shape, fill_value, dt, device=native_device(device))


def arange(start, /, stop=None, step=1, *, dtype=None, device=None):
    check_step(step, "jax")
    if dtype is None:
        ints = all(isinstance(v, (int, np.integer)) for v in (start, stop, step) if v is not None)
        dt = default_int() if ints else jnp.float32
    else:
        dt = native_dtype(dtype)
    if stop is None:
        start, stop = 0, start
    return jnp.arange(start, stop, step, dt, device=native_device(device))


def linspace(start, stop, /, num, *, dtype=None, device=None, endpoint=True):
    dt = native_dtype(linspace_dtype(start, stop, dtype, "jax") or dtype)
    return jnp.linspace(start, stop, num, endpoint, dtype=dt, device=native_device(device))


def eye(n_rows, n_cols=None, /, *, k=0, dtype=None, device=None):
    dt = native_dtype(dtype) or jnp.float32
    return jnp.eye(n_rows, n_cols, k, dt, device=native_device(device))


def zeros_like(x, /, *, dtype=None, device=None):
    return jnp.zeros_like(x, native_dtype(dtype), device=native_device(device))


def ones_like(x, /, *, dtype=None, device=None):
    return jnp.ones_like(x, native_dtype(dtype), device=native_device(device))


def empty_like(x, /, *, dtype=None, device=None):
    return jnp.empty_like(x, native_dtype(dtype), device=native_device(device))


def full_like(x, /, fill_value, *, dtype=None, device=None):
    return jnp.full_like(x, fill_value, native_dtype(dtype), device=native_device(device))


if jax.__version_info__ < (0, 11):
    meshgrid = jnp.meshgrid  # a list, as the Array API (2023.12) says
else:  # jax 0.11 returns a tuple

    def meshgrid(*arrays, indexing="xy"):
        return list(jnp.meshgrid(*arrays, indexing=indexing))


tril = jnp.tril
triu = jnp.triu


def from_dlpack(x, /, *, device=None, copy=None):
    """Host memory is imported on jax's CPU device (jax's own import would ask the default
    device, an accelerator's client, to take a host buffer, which its PJRT plugin refuses), and
    moved to ``device`` when that is an accelerator; a device array moves to ``device`` after
    its import. Without ``device`` the result stays where ``x`` is, as the standard says."""
    target = native_device(device)
    producer, copy_after = exportable(x)
    source = x if copy_after else producer  # (jax imports tf's tensors itself)
    if on_host(producer):
        if target is None or target.platform == "cpu":
            cpu = target or jax.devices("cpu")[0]
            out = jax.dlpack.from_dlpack(source, device=cpu, copy=copy)
        else:
            refuse_copy_between_devices(copy, "from the host to an accelerator")
            return jax.device_put(np.from_dlpack(producer), target)
    else:
        out = jax.dlpack.from_dlpack(source, copy=copy)
        if target is not None and out.devices() != {target}:
            refuse_copy_between_devices(copy, f"to {target}")
            return jax.device_put(out, target)
    # jax 0.10 shares a torch tensor's memory even with copy=True: copy it here.
    return jnp.array(out, copy=True) if copy else out


_CONSTANTS = ConstantCache()


def constant(value, /, *, dtype=None, device=None):
    """Under ``jax.jit`` the value is a constant of the program; eagerly, the array is made once
    per dtype, device and x64 setting and kept (never a tracer: a trace's arrays are its own)."""
    if not isinstance(value, np.ndarray):
        return asarray(value, dtype=dtype, device=device)
    key = (native_dtype(dtype), native_device(device), jax.config.jax_enable_x64)
    return _CONSTANTS.get(
        value,
        key,
        lambda v: asarray(v, dtype=dtype, device=device, copy=True),  # (no alias of v)
        keep=lambda out: not isinstance(out, jax.core.Tracer),
    )
