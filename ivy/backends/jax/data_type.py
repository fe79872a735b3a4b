"""jax backend: dtype conversion."""

from __future__ import annotations

import jax.numpy as jnp

from ivy.backends.jax._helpers import native_dtype

__all__ = ["astype"]


def astype(x, dtype, /, *, copy=True):
    return jnp.astype(x, native_dtype(dtype), copy=copy)
