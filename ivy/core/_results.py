"""Result types shared by the backends: the named tuples of the Array API's ``unique_*``
functions (numpy and jax return their own named tuples, with the same fields) and of
:func:`ivy.top_k`."""

from __future__ import annotations

from typing import Any, NamedTuple

__all__ = ["TopKResult", "UniqueAllResult", "UniqueCountsResult", "UniqueInverseResult"]


class UniqueAllResult(NamedTuple):
    """``values`` (sorted unique values), ``indices`` (of their first occurrence in the flattened
    input), ``inverse_indices`` (shaped like the input) and ``counts``."""

    values: Any
    indices: Any
    inverse_indices: Any
    counts: Any


class UniqueCountsResult(NamedTuple):
    """``values`` (sorted unique values) and their ``counts``."""

    values: Any
    counts: Any


class UniqueInverseResult(NamedTuple):
    """``values`` (sorted unique values) and ``inverse_indices`` (shaped like the input)."""

    values: Any
    inverse_indices: Any


class TopKResult(NamedTuple):
    """``values`` (the ``k`` largest or smallest elements along the axis) and their ``indices``
    (int64) in the input."""

    values: Any
    indices: Any
