"""Unique values of an array, flattened and sorted, as the Array API's named tuples.

Each NaN is a distinct value (with a count of 1); -0.0 and 0.0 are one value. Indices and counts
are int64 (jax without x64: int32). The size of the results depends on the values, so inside
``jax.jit`` these functions raise :class:`ivy.errors.UnsupportedError`; inside ``tf.function`` and
``torch.compile`` they work.
"""

from __future__ import annotations

from ivy.core._dispatch import dispatch
from ivy.core._results import UniqueAllResult, UniqueCountsResult, UniqueInverseResult
from ivy.typing import Array, Framework

__all__ = ["unique_all", "unique_counts", "unique_inverse", "unique_values"]


@dispatch
def unique_all(x: Array, /, *, f: Framework = None) -> UniqueAllResult:
    """Named tuple ``(values, indices, inverse_indices, counts)``: the sorted unique values, the
    index of the first occurrence of each in the flattened ``x``, the index into ``values`` of
    each element of ``x`` (shaped like ``x``), and how often each occurs.

    Example: ``ivy.unique_all(np.array([2, 1, 2])).counts`` -> ``[1, 2]``.
    """


@dispatch
def unique_counts(x: Array, /, *, f: Framework = None) -> UniqueCountsResult:
    """Named tuple ``(values, counts)``: the sorted unique values and how often each occurs."""


@dispatch
def unique_inverse(x: Array, /, *, f: Framework = None) -> UniqueInverseResult:
    """Named tuple ``(values, inverse_indices)``: the sorted unique values, and the index into
    ``values`` of each element of ``x`` (shaped like ``x``)."""


@dispatch
def unique_values(x: Array, /, *, f: Framework = None) -> Array:
    """The sorted unique values of ``x`` (flattened)."""
