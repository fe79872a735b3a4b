"""Indexing: gathering and scattering."""

from __future__ import annotations

from ivy.core._dispatch import dispatch

__all__ = ["take", "gather_nd", "scatter_nd", "one_hot"]


@dispatch
def take(x, indices, /, *, axis=None, f=None):
    """Elements of ``x`` at the 1-D integer ``indices`` along ``axis`` (None: of the flattened
    array)."""


@dispatch
def gather_nd(params, indices, /, *, f=None):
    """Gather slices of ``params`` by index tuples in the last axis of ``indices``.

    With ``indices`` of shape ``[..., K]`` the result has shape ``indices.shape[:-1] +
    params.shape[K:]``. Example: ``gather_nd(x, [[0, 1], [2, 0]])`` -> ``[x[0, 1], x[2, 0]]``.
    """


@dispatch("indices", "updates")
def scatter_nd(indices, updates, /, shape, *, reduction="sum", f=None):
    """Scatter ``updates`` into zeros of ``shape`` at index tuples ``indices`` (``[..., K]``).

    ``reduction`` combines updates that land on the same place: ``'sum'``, ``'replace'`` (one of
    them, unspecified which), ``'min'`` or ``'max'`` (places that receive no update stay 0).
    """


@dispatch
def one_hot(indices, depth, /, *, dtype=None, f=None):
    """One-hot encoding of integer ``indices`` along a new last axis of size ``depth``;
    float32 by default."""
