"""jax backend: linear algebra (jax.numpy's own functions, which have the Array API signatures)."""

from __future__ import annotations

import jax.numpy as jnp

__all__ = ["matmul", "cross", "svd", "inv", "pinv", "vector_norm"]

matmul = jnp.matmul
cross = jnp.linalg.cross
svd = jnp.linalg.svd
inv = jnp.linalg.inv
pinv = jnp.linalg.pinv
vector_norm = jnp.linalg.vector_norm
