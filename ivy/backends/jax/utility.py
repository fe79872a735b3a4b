"""jax backend: truth tests and differences (jax.numpy's own)."""

from __future__ import annotations

import jax.numpy as jnp

__all__ = ["all", "any", "diff"]

all = jnp.all  # noqa: A001 - the Array API names
any = jnp.any  # noqa: A001
diff = jnp.diff
