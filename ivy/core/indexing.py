"""Indexing: gathering and scattering, along an axis, by index tuples (``_nd``) or into flattened
arrays (``_flat``), replacing rows (``put_rows``), and the coordinates of true elements."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, Literal

from ivy.core._dispatch import dispatch
from ivy.typing import Array, Dtype, Framework, Shape

__all__ = [
    "take",
    "take_along_axis",
    "gather_nd",
    "scatter_nd",
    "one_hot",
    "gather_flat",
    "scatter_flat",
    "put_rows",
    "indices_where",
]


@dispatch
def take(x: Array, indices: Array, /, *, axis: int | None = None, f: Framework = None) -> Array:
    """Elements of ``x`` at the 1-D integer ``indices`` along ``axis`` (None: of the flattened
    array)."""


@dispatch("x", "indices")
def take_along_axis(x: Array, indices: Array, /, *, axis: int = -1, f: Framework = None) -> Array:
    """Elements of ``x`` picked along ``axis`` by ``indices`` (Array API 2024.12): ``out[..., j,
    ...] = x[..., indices[..., j, ...], ...]`` with ``j`` at position ``axis``.

    Args:
        x: array of at least one axis.
        indices: integer array of ``x``'s number of axes; along ``axis`` any length, along the
            others sizes that broadcast with ``x``'s. Negative indices count from the end.
        axis: the axis to pick along.

    Returns:
        An array of ``x``'s dtype: ``indices``' size along ``axis``, the broadcast sizes
        elsewhere.

    Example: ``ivy.take_along_axis(x, ivy.argsort(x, axis=1), axis=1)`` is ``ivy.sort(x,
    axis=1)``; ``ivy.take_along_axis(np.array([[1, 2], [3, 4]]), np.array([[1], [0]]))`` ->
    ``[[2], [3]]``.
    """


@dispatch
def gather_nd(params: Array, indices: Array | Sequence[Any], /, *, f: Framework = None) -> Array:
    """Gather slices of ``params`` by index tuples in the last axis of ``indices``.

    With ``indices`` of shape ``[..., K]`` the result has shape ``indices.shape[:-1] +
    params.shape[K:]``. Example: ``gather_nd(x, [[0, 1], [2, 0]])`` -> ``[x[0, 1], x[2, 0]]``.
    """


@dispatch("indices", "updates")
def scatter_nd(
    indices: Array,
    updates: Array,
    /,
    shape: Shape,
    *,
    reduction: Literal["sum", "replace", "min", "max"] = "sum",
    f: Framework = None,
) -> Array:
    """Scatter ``updates`` into zeros of ``shape`` at index tuples ``indices`` (``[..., K]``).

    ``reduction`` combines updates that land on the same place: ``'sum'``, ``'replace'`` (one of
    them, unspecified which), ``'min'`` or ``'max'`` (places that receive no update stay 0).
    """


@dispatch
def one_hot(
    indices: Array, depth: int, /, *, dtype: Dtype | None = None, f: Framework = None
) -> Array:
    """One-hot encoding of integer ``indices`` along a new last axis of size ``depth``;
    float32 by default."""


@dispatch
def gather_flat(params: Array, indices: Array, /, *, f: Framework = None) -> Array:
    """Elements of the flattened ``params`` at integer ``indices`` of any shape.

    Args:
        params: array of any shape, read in row-major order.
        indices: integer array; negative indices count from the end.

    Returns:
        An array of ``indices``' shape and ``params``' dtype.

    Example: ``ivy.gather_flat(np.array([[1, 2], [3, 4]]), np.array([3, 0]))`` -> ``[4, 1]``.
    """


@dispatch("indices", "updates")
def scatter_flat(
    indices: Array,
    updates: Array,
    /,
    size: int,
    *,
    reduction: Literal["sum", "replace", "min", "max"] = "sum",
    f: Framework = None,
) -> Array:
    """Scatter ``updates`` into a 1-D array of zeros of length ``size`` at flat ``indices``.

    Args:
        indices: integer array, of ``updates``' shape.
        updates: values.
        size: length of the result.
        reduction: how updates that land on the same place combine: ``'sum'``, ``'replace'``
            (one of them, unspecified which), ``'min'`` or ``'max'``; places that receive no
            update stay 0.

    Returns:
        ``[size]`` of ``updates``' dtype.

    Example: ``ivy.scatter_flat(np.array([0, 2, 0]), np.array([1., 2., 3.]), 4)`` ->
    ``[4., 0., 2., 0.]``.
    """


@dispatch
def put_rows(x: Array, indices: Array, updates: Array, /, *, f: Framework = None) -> Array:
    """``x`` with its rows ``indices`` (along axis 0) replaced by ``updates``: the functional
    form of ``x[indices] = updates``, the inverse of ``take(x, indices, axis=0)``.

    The work is that of the rows written, not of ``x``: jax ``x.at[indices].set``, tensorflow
    ``tensor_scatter_nd_update``, torch ``index_copy`` (out of place), numpy a copy then the
    assignment. The result is a new array and ``x`` is left as it was, so eager calls copy ``x``
    (a copy, no arithmetic); a compiler that may reuse ``x``'s buffer (``ivy.compile_fn(fn,
    donate_argnums=...)`` on jax) writes the rows in place. Differentiable where the framework
    is: gradients flow to ``updates`` and to the rows of ``x`` that are kept.

    Args:
        x: array of at least one axis, ``[n, ...]``.
        indices: 1-D integer array ``[k]`` of rows of ``x``; negative ones count from the end.
            Where a row appears twice, which of its updates is written is unspecified.
        updates: ``[k, ...]``, the rows to write (``x.shape[1:]`` after the first axis),
            converted to ``x``'s dtype as an assignment would.

    Returns:
        An array of ``x``'s shape and dtype.

    Raises:
        ShapeError: ``indices`` is not 1-D, ``x`` has no axis, or ``updates`` is not ``[k,
            *x.shape[1:]]``.
        DtypeError: ``indices`` is not an integer array.
        IndexOutOfBoundsError: an index out of range (in eager calls; inside ``jax.jit`` such
            rows are dropped, as jax's scatters do).

    Example: ``ivy.put_rows(np.zeros((3, 2)), np.array([2, 0]), np.array([[1., 1.], [2.,
    2.]]))`` -> ``[[2., 2.], [0., 0.], [1., 1.]]``.
    """


@dispatch
def indices_where(x: Array, /, *, f: Framework = None) -> Array:
    """Coordinates of the true (non-zero) elements of ``x``, in row-major order.

    Returns:
        int64 ``[num_true, x.ndim]``, ready for :func:`gather_nd`. The shape depends on the
        values, so this does not compile under ``jax.jit``.

    Example: ``ivy.indices_where(np.array([[True, False], [False, True]]))`` ->
    ``[[0, 0], [1, 1]]``.
    """
