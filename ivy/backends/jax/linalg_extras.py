"""jax backend: linear algebra beyond the Array API extension."""

from __future__ import annotations

import jax.numpy as jnp

__all__ = ["einsum"]

einsum = jnp.einsum
