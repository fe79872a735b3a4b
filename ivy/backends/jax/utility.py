"""jax backend: utilities (truth tests, differences, conversion to numpy and lists, shape,
dtype, device)."""

from __future__ import annotations

import jax
import jax.numpy as jnp
import numpy as np

from ivy.backends.jax._helpers import default_device, device_name

shape = jnp.shape


def to_numpy(x, /):
    # A writable copy: numpy's view of a jax array is read-only (jax arrays are immutable).
    return np.array(x)


def to_list(x, /):
    return np.asarray(x).tolist()


def dtype(x, /, *, as_str=False):
    return x.dtype.name if as_str else x.dtype


def dev(x, /):
    if isinstance(x, jax.core.Tracer):
        # Traced values (jit, grad, vmap) have no device of their own: report where jax computes.
        return device_name(default_device())
    devices = getattr(x, "devices", None)
    if devices is None:  # a numpy array or Python value given with f='jax'
        return "cpu"
    devices = devices()
    if len(devices) != 1:
        raise ValueError(
            f"dev: the array is sharded over {len(devices)} devices, so it has no single device; "
            f"inspect x.sharding instead, or gather it onto one device with jax.device_put."
        )
    return device_name(next(iter(devices)))
