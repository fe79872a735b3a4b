"""Sorting, along one axis.

NaN sorts as the largest value (last ascending, first descending) and -0.0 equals 0.0, on every
backend. ``stable=True`` (the default) keeps equal elements in their order, in descending sorts
too.
"""

from __future__ import annotations

from ivy.core._dispatch import dispatch

__all__ = ["argsort", "sort"]


@dispatch
def argsort(x, /, *, axis=-1, descending=False, stable=True, f=None):
    """Indices (int64) that sort ``x`` along ``axis``.

    Example: ``ivy.argsort(np.array([3., 1., 2.]))`` -> ``[1, 2, 0]``.
    """


@dispatch
def sort(x, /, *, axis=-1, descending=False, stable=True, f=None):
    """A sorted copy of ``x`` along ``axis``.

    Example: ``ivy.sort(np.array([3., 1., 2.]), descending=True)`` -> ``[3., 2., 1.]``.
    """
