"""Searching: arg-reductions and selection."""

from __future__ import annotations

from ivy.core._dispatch import dispatch

__all__ = [
    "argmax",
    "argmin",
    "where",
    "count_nonzero",
    "nonzero",
    "searchsorted",
]


@dispatch
def argmax(x, /, *, axis=None, keepdims=False, f=None):
    """Index (int64) of the first maximum over ``axis``, or of the flattened array if None."""


@dispatch
def argmin(x, /, *, axis=None, keepdims=False, f=None):
    """Index (int64) of the first minimum over ``axis``, or of the flattened array if None."""


@dispatch("condition", "x1", "x2")
def where(condition, x1, x2, /, *, f=None):
    """Elements of ``x1`` where ``condition`` is true, else of ``x2`` (all broadcast)."""


@dispatch
def count_nonzero(x, /, *, axis=None, keepdims=False, f=None):
    """Number (int64) of nonzero elements over ``axis`` (NaN counts as nonzero; Array API
    2024.12)."""


@dispatch
def nonzero(x, /, *, f=None):
    """Tuple of int64 index arrays, one per axis, of the nonzero elements of ``x`` in row-major
    order. ``x`` must have at least one axis. Inside ``jax.jit`` it raises
    :class:`ivy.errors.UnsupportedError` (the result's size depends on the values)."""


@dispatch("x1", "x2")
def searchsorted(x1, x2, /, *, side="left", sorter=None, f=None):
    """Indices (int64) where the values ``x2`` would be inserted into the sorted 1-D ``x1``
    (sorted by the indices ``sorter`` when given) to keep it sorted: before equal values with
    ``side='left'``, after them with ``'right'``."""
