"""jax backend: gathering and scattering.

As everywhere in jax, out-of-bounds indices do not raise (they cannot under ``jax.jit``):
``take``, ``take_along_axis``, ``gather_nd`` and ``gather_flat`` return a fill value there (NaN for floats, the smallest integer for
ints; jax's ``mode='fill'``), and ``scatter_nd`` and ``scatter_flat`` drop those updates. ``indices_where`` has a result shape
that depends on the values, so it cannot run under ``jax.jit``.
"""

from __future__ import annotations

import jax
import jax.numpy as jnp

from ivy.backends.jax._helpers import native_dtype

indices_where = jnp.argwhere

_SCATTER_METHODS = {"sum": "add", "replace": "set", "min": "min", "max": "max"}


def take(x, indices, /, *, axis=None):
    return jnp.take(x, jnp.asarray(indices), axis=axis)  # jnp.take refuses Python lists


def _index_tuple(indices):
    indices = jnp.asarray(indices)
    return tuple(indices[..., k] for k in range(indices.shape[-1]))


def gather_nd(params, indices, /):
    return jnp.asarray(params).at[_index_tuple(indices)].get(mode="fill")


def scatter_nd(indices, updates, /, shape, *, reduction="sum"):
    method = _SCATTER_METHODS.get(reduction)
    if method is None:
        raise ValueError(
            f"scatter_nd: unknown reduction {reduction!r}; use 'sum', 'replace', 'min' or 'max'."
        )
    updates = jnp.asarray(updates)
    idx = _index_tuple(indices)
    out = jnp.zeros(shape, updates.dtype)
    if method in ("min", "max"):
        # Start every updated place from one of its own updates, so that untouched places stay 0.
        out = out.at[idx].set(updates)
    return getattr(out.at[idx], method)(updates)


def one_hot(indices, depth, /, *, dtype=None):
    return jax.nn.one_hot(indices, depth, dtype=native_dtype(dtype) or jnp.float32)


def gather_flat(params, indices, /):
    return jnp.take(params, jnp.asarray(indices))  # flattened; jnp.take refuses Python lists


def scatter_flat(indices, updates, /, size, *, reduction="sum"):
    return scatter_nd(jnp.asarray(indices)[..., None], updates, (size,), reduction=reduction)


def take_along_axis(x, indices, /, *, axis=-1):
    return jnp.take_along_axis(jnp.asarray(x), jnp.asarray(indices), axis=axis)
