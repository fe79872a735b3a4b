"""jax backend: searching. Indices come in the default int (int64 with x64 enabled, else int32)."""

from __future__ import annotations

import jax.numpy as jnp

__all__ = ["argmax", "argmin", "where"]

argmax = jnp.argmax
argmin = jnp.argmin
where = jnp.where
