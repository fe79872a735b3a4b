"""jax backend: sorting (jax.numpy's own: NaN is the largest value, last ascending and first
descending; a stable descending sort keeps equal elements in their order)."""

from __future__ import annotations

import jax.numpy as jnp

__all__ = ["argsort", "sort"]

argsort = jnp.argsort
sort = jnp.sort
