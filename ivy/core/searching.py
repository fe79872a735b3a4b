"""Searching: arg-reductions and selection."""

from __future__ import annotations

from ivy.core._dispatch import dispatch

__all__ = ["argmax", "argmin", "where"]


@dispatch
def argmax(x, /, *, axis=None, keepdims=False, f=None):
    """Index (int64) of the first maximum over ``axis``, or of the flattened array if None."""


@dispatch
def argmin(x, /, *, axis=None, keepdims=False, f=None):
    """Index (int64) of the first minimum over ``axis``, or of the flattened array if None."""


@dispatch("condition", "x1", "x2")
def where(condition, x1, x2, /, *, f=None):
    """Elements of ``x1`` where ``condition`` is true, else of ``x2`` (all broadcast)."""
