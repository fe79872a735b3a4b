"""jax backend: gathering and scattering.

Out-of-bounds indices raise :class:`ivy.errors.IndexOutOfBoundsError` in eager calls, as on
every backend (``ivy/backends/_index_checks.py``). Inside ``jax.jit`` indices have no values to
check, and jax's own behaviour applies: ``take``, ``take_along_axis``, ``gather_nd`` and
``gather_flat`` return a fill value there (NaN for floats, the smallest integer for ints; jax's
``mode='fill'``), ``scatter_nd``, ``scatter_flat`` and ``put_rows`` drop those updates, and ``one_hot`` gives a
row of zeros. ``indices_where`` has a result shape that depends on the values, so it cannot run
under ``jax.jit``.
"""

from __future__ import annotations

import jax
import jax.numpy as jnp

from ivy.backends._index_checks import check_bounds, check_bounds_per_column, check_rows
from ivy.backends.jax._helpers import native_dtype

indices_where = jnp.argwhere

_SCATTER_METHODS = {"sum": "add", "replace": "set", "min": "min", "max": "max"}


def _eager(*values) -> bool:
    return not any(isinstance(v, jax.core.Tracer) for v in values)


def take(x, indices, /, *, axis=None):
    indices = jnp.asarray(indices)  # jnp.take refuses Python lists
    if _eager(indices):
        size = x.size if axis is None else x.shape[axis]
        check_bounds(indices, size, function="take", backend="jax")
    return jnp.take(x, indices, axis=axis)


def _index_tuple(indices):
    indices = jnp.asarray(indices)
    return tuple(indices[..., k] for k in range(indices.shape[-1]))


def gather_nd(params, indices, /):
    params, indices = jnp.asarray(params), jnp.asarray(indices)
    if _eager(indices):
        check_bounds_per_column(indices, params.shape, function="gather_nd", backend="jax")
    return params.at[_index_tuple(indices)].get(mode="fill")


def scatter_nd(indices, updates, /, shape, *, reduction="sum"):
    method = _SCATTER_METHODS.get(reduction)
    if method is None:
        raise ValueError(
            f"scatter_nd: unknown reduction {reduction!r}; use 'sum', 'replace', 'min' or 'max'."
        )
    updates, indices = jnp.asarray(updates), jnp.asarray(indices)
    shape = (shape,) if isinstance(shape, int) else tuple(shape)
    if _eager(indices):
        check_bounds_per_column(indices, shape, function="scatter_nd", backend="jax")
    idx = _index_tuple(indices)
    out = jnp.zeros(shape, updates.dtype)
    if method in ("min", "max"):
        # Start every updated place from one of its own updates, so that untouched places stay 0.
        out = out.at[idx].set(updates)
    return getattr(out.at[idx], method)(updates)


def one_hot(indices, depth, /, *, dtype=None):
    if _eager(indices):
        check_bounds(indices, depth, function="one_hot", backend="jax", negative=False)
    return jax.nn.one_hot(indices, depth, dtype=native_dtype(dtype) or jnp.float32)


def gather_flat(params, indices, /):
    return take(params, indices)  # flattened (axis None)


def scatter_flat(indices, updates, /, size, *, reduction="sum"):
    return scatter_nd(jnp.asarray(indices)[..., None], updates, (size,), reduction=reduction)


def take_along_axis(x, indices, /, *, axis=-1):
    x, indices = jnp.asarray(x), jnp.asarray(indices)
    if _eager(indices):
        check_bounds(indices, x.shape[axis], function="take_along_axis", backend="jax")
    return jnp.take_along_axis(x, indices, axis=axis)


def put_rows(x, indices, updates, /):
    """``x.at[indices].set(updates)``: a scatter of the rows, which XLA writes in place where
    ``x``'s buffer may be reused (donated to a jitted function)."""
    x, indices = jnp.asarray(x), jnp.asarray(indices)
    updates = jnp.asarray(updates)
    integer = jnp.issubdtype(indices.dtype, jnp.integer)
    check_rows(x.shape, indices.shape, updates.shape, integer=integer, backend="jax")
    if _eager(indices):
        check_bounds(indices, x.shape[0], function="put_rows", backend="jax")
    return x.at[indices].set(updates.astype(x.dtype))
