"""Result types shared by the backends: the named tuples of the Array API's ``unique_*``
functions (numpy and jax return their own named tuples, with the same fields) and of
:func:`ivy.top_k`."""

from __future__ import annotations

from typing import NamedTuple

from ivy.typing import Array

__all__ = ["TopKResult", "UniqueAllResult", "UniqueCountsResult", "UniqueInverseResult"]


class UniqueAllResult(NamedTuple):
    """``values`` (sorted unique values), ``indices`` (of their first occurrence in the flattened
    input), ``inverse_indices`` (shaped like the input) and ``counts``."""

    values: Array
    indices: Array
    inverse_indices: Array
    counts: Array


class UniqueCountsResult(NamedTuple):
    """``values`` (sorted unique values) and their ``counts``."""

    values: Array
    counts: Array


class UniqueInverseResult(NamedTuple):
    """``values`` (sorted unique values) and ``inverse_indices`` (shaped like the input)."""

    values: Array
    inverse_indices: Array


class TopKResult(NamedTuple):
    """``values`` (the ``k`` largest or smallest elements along the axis) and their ``indices``
    (int64) in the input."""

    values: Array
    indices: Array
