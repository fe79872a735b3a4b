"""Sorting and selecting the ``k`` largest (or smallest) elements, along one axis.

NaN sorts as the largest value (last ascending, first descending) and -0.0 equals 0.0, on every
backend. ``stable=True`` (the default) keeps equal elements in their order, in descending sorts
too.
"""

from __future__ import annotations

from ivy.core._dispatch import dispatch
from ivy.core._results import TopKResult
from ivy.typing import Array, Framework

__all__ = ["argsort", "sort", "top_k"]


@dispatch
def argsort(
    x: Array,
    /,
    *,
    axis: int = -1,
    descending: bool = False,
    stable: bool = True,
    f: Framework = None,
) -> Array:
    """Indices (int64) that sort ``x`` along ``axis``.

    Example: ``ivy.argsort(np.array([3., 1., 2.]))`` -> ``[1, 2, 0]``.
    """


@dispatch
def sort(
    x: Array,
    /,
    *,
    axis: int = -1,
    descending: bool = False,
    stable: bool = True,
    f: Framework = None,
) -> Array:
    """A sorted copy of ``x`` along ``axis``.

    Example: ``ivy.sort(np.array([3., 1., 2.]), descending=True)`` -> ``[3., 2., 1.]``.
    """


@dispatch
def top_k(
    x: Array,
    k: int,
    /,
    *,
    axis: int = -1,
    largest: bool = True,
    sorted: bool = True,
    f: Framework = None,
) -> TopKResult:
    """The ``k`` largest (or smallest) elements of ``x`` along ``axis`` and their indices.

    Elements are ordered as :func:`sort` orders them: NaN is the largest value and -0.0 equals
    0.0; among equal elements the one of lower index comes first, on every backend (torch's own
    ``topk`` leaves ties in no defined order, so its backend puts them in order).

    Args:
        x: real or bool array of at least one axis.
        k: how many elements to take, from 0 to the size of ``axis``.
        axis: the axis to select along.
        largest: take the largest elements (else the smallest).
        sorted: return them sorted, the best first. With ``sorted=False`` the same ``k``
            elements come in an order that may differ between backends.

    Returns:
        A named tuple ``(values, indices)``: ``x``'s shape with ``k`` along ``axis``; the
        values of ``x``'s dtype and their int64 indices along ``axis``.

    Example: ``ivy.top_k(np.array([1., 3., 2., 3.]), 2)`` -> ``TopKResult(values=[3., 3.],
    indices=[1, 3])``.
    """
