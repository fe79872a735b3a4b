"""Searching: arg-reductions and selection."""

from __future__ import annotations

from typing import Literal

from ivy.core._dispatch import dispatch
from ivy.typing import Array, Framework, Scalar

__all__ = [
    "argmax",
    "argmin",
    "where",
    "count_nonzero",
    "nonzero",
    "searchsorted",
]


@dispatch
def argmax(
    x: Array, /, *, axis: int | None = None, keepdims: bool = False, f: Framework = None
) -> Array:
    """Index (int64) of the first maximum over ``axis``, or of the flattened array if None."""


@dispatch
def argmin(
    x: Array, /, *, axis: int | None = None, keepdims: bool = False, f: Framework = None
) -> Array:
    """Index (int64) of the first minimum over ``axis``, or of the flattened array if None."""


@dispatch("condition", "x1", "x2")
def where(
    condition: Array, x1: Array | Scalar, x2: Array | Scalar, /, *, f: Framework = None
) -> Array:
    """Elements of ``x1`` where ``condition`` is true, else of ``x2`` (all broadcast)."""


@dispatch
def count_nonzero(
    x: Array,
    /,
    *,
    axis: int | tuple[int, ...] | None = None,
    keepdims: bool = False,
    f: Framework = None,
) -> Array:
    """Number (int64) of nonzero elements over ``axis`` (NaN counts as nonzero; Array API
    2024.12)."""


@dispatch
def nonzero(x: Array, /, *, f: Framework = None) -> tuple[Array, ...]:
    """Tuple of int64 index arrays, one per axis, of the nonzero elements of ``x`` in row-major
    order. ``x`` must have at least one axis. Inside ``jax.jit`` it raises
    :class:`ivy.errors.UnsupportedError` (the result's size depends on the values)."""


@dispatch("x1", "x2")
def searchsorted(
    x1: Array,
    x2: Array,
    /,
    *,
    side: Literal["left", "right"] = "left",
    sorter: Array | None = None,
    f: Framework = None,
) -> Array:
    """Indices (int64) where the values ``x2`` would be inserted into the sorted 1-D ``x1``
    (sorted by the indices ``sorter`` when given) to keep it sorted: before equal values with
    ``side='left'``, after them with ``'right'``.

    NaN sorts after every number, as :func:`ivy.sort` puts it (the standard leaves the order
    of NaN open): NaNs of ``x1`` are at its end, a number is inserted before them, and a NaN of
    ``x2`` before the first NaN (``'left'``) or at the end (``'right'``), on every backend."""
