"""Tests of the core group ``indexing`` (``ivy/core/indexing.py``), on every backend.

Ivy's own functions beyond the Array API, on every backend, against references written here
with Python loops or plain numpy float64: gather_flat, scatter_flat, indices_where, cumsum,
cumprod, einsum, constant_pad, zero_pad, linear_resample, interp, vector_to_skew_symmetric_matrix,
cosine_similarity, clip_vector_norm, clip_by_global_norm, nan_to_num, isclose, allclose and
to_framework.

take, take_along_axis, gather_nd, scatter_nd, put_rows and one_hot against references written
with Python loops.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import ivy
from tests.helpers import (
    api,
    check,
    check_gradients,
    native,
    numpy_of,
)


@pytest.mark.parametrize("dtype", ["float32", "float64", "int64"])
@pytest.mark.parametrize("indices", [[3, 0, 5], [[0, 11], [-1, 4]], 7, []], ids=str)
def test_gather_flat(backend, dtype, indices):
    params = (np.arange(12).reshape(3, 4) * 1.5 - 4).astype(dtype)
    flat = list(params.reshape(-1))
    idx = np.array(indices, np.int64)
    expected = np.array([flat[i] for i in idx.reshape(-1)], dtype).reshape(idx.shape)
    for fn in api(backend, "gather_flat"):
        check(fn(native(params, backend), native(idx, backend)), expected, backend)
        check(fn(native(params, backend), native(idx.astype(np.int32), backend)), expected, backend)


def _scatter_flat_reference(indices, updates, size, reduction):
    received: dict[int, list] = {}
    for i, u in zip(indices, updates):
        received.setdefault(int(i) % size, []).append(u)
    out = np.zeros(size, updates.dtype)
    combine = {"sum": sum, "min": min, "max": max}[reduction]
    for i, values in received.items():
        out[i] = combine(values)
    return out, received


@pytest.mark.parametrize("dtype", ["float32", "int64"])
@pytest.mark.parametrize("reduction", ["sum", "min", "max", "replace"])
def test_scatter_flat(backend, dtype, reduction):
    idx = np.array([4, 0, 4, 2, 4, 0], np.int64)  # duplicates, and places left untouched
    updates = np.array([3, -1, 7, 2, -5, 6], dtype) * (1.5 if dtype == "float32" else 1)
    updates = updates.astype(dtype)
    expected, received = _scatter_flat_reference(
        idx, updates, 6, "sum" if reduction == "replace" else reduction
    )
    for fn in api(backend, "scatter_flat"):
        out = fn(native(idx, backend), native(updates, backend), 6, reduction=reduction)
        if reduction == "replace":  # one of the updates, unspecified which
            got = numpy_of(out)
            for i, values in received.items():
                assert got[i] in values
                expected[i] = got[i]
        check(out, expected, backend)
    out = api(backend, "scatter_flat")[0](native(idx, backend), native(updates, backend), 6)
    check(out, _scatter_flat_reference(idx, updates, 6, "sum")[0], backend)  # sum by default


def test_scatter_flat_of_batched_indices(backend):
    idx = np.array([[0, 3], [3, 1]], np.int64)
    updates = np.array([[1.0, 2.0], [4.0, 8.0]], np.float32)
    expected = np.array([1.0, 8.0, 0.0, 6.0, 0.0], np.float32)
    for fn in api(backend, "scatter_flat"):
        check(fn(native(idx, backend), native(updates, backend), 5), expected, backend)


@pytest.mark.parametrize(
    "values",
    [[[True, False, True], [False, False, True]], [0.0, 2.5, 0.0, -1.0], [[0, 0]], True, False],
    ids=str,
)
def test_indices_where(backend, values):
    x = np.array(values)
    rows = [index for index in np.ndindex(x.shape) if x[index]]
    expected = np.array(rows, np.int64).reshape(len(rows), x.ndim)
    for fn in api(backend, "indices_where"):
        check(fn(native(x, backend)), expected, backend)


def test_indices_where_feeds_gather_nd(backend):
    x = np.array([[1.0, -2.0], [3.0, -4.0]], np.float32)
    xp = getattr(ivy, backend)
    where = ivy.indices_where(native(x > 0, backend))
    check(xp.gather_nd(native(x, backend), where), np.array([1.0, 3.0], np.float32), backend)


DTYPES = ("float32", "float64", "int64")


def _params(dtype, shape=(3, 4, 5)):
    return (np.arange(math.prod(shape)).reshape(shape) * 1.5 - 7).astype(dtype)


@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("axis", [None, 0, 1, -1])
def test_take(backend, dtype, axis):
    a = _params(dtype, (3, 4))
    indices = np.array([2, 0, 2, 1], dtype=np.int64)
    if axis is None:
        expected = np.array([a.ravel()[i] for i in indices])
    else:
        expected = np.stack([np.moveaxis(a, axis, 0)[i] for i in indices], axis=axis % a.ndim)
    for fn in api(backend, "take"):
        check(fn(native(a, backend), native(indices, backend), axis=axis), expected, backend)


def test_take_with_int32_indices_and_empty_indices(backend):
    a = _params("float32", (3, 4))
    for fn in api(backend, "take"):
        out = fn(native(a, backend), native(np.array([3, 1], np.int32), backend), axis=1)
        check(out, a[:, [3, 1]], backend)
        out = fn(native(a, backend), native(np.zeros(0, np.int64), backend), axis=0)
        check(out, np.zeros((0, 4), np.float32), backend)


def _take_along_reference(a, indices, axis):
    """``out[p] = a[p with p[axis] replaced by indices[p]]``, broadcasting size-1 index axes."""
    axis %= a.ndim
    shape = tuple(indices.shape[d] if d == axis else a.shape[d] for d in range(a.ndim))
    out = np.empty(shape, a.dtype)
    for p in np.ndindex(shape):
        at = tuple(0 if indices.shape[d] == 1 and d != axis else p[d] for d in range(a.ndim))
        source = list(p)
        source[axis] = int(indices[at])  # negative counts from the end
        out[p] = a[tuple(source)]
    return out


@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("axis", [0, 1, 2, -1, -3])
def test_take_along_axis(backend, dtype, axis):
    a = _params(dtype, (3, 4, 5))
    n = a.shape[axis]
    shape = list(a.shape)
    shape[axis] = 6  # more picks than elements: repeats
    indices = np.random.default_rng(axis + 5).integers(-n, n, shape)  # negative ones too
    expected = _take_along_reference(a, indices, axis)
    for fn in api(backend, "take_along_axis"):
        check(fn(native(a, backend), native(indices, backend), axis=axis), expected, backend)


def test_take_along_axis_defaults_to_the_last_axis_and_inverts_argsort(backend):
    a = np.array([[3.0, 1.0, 2.0], [0.5, -1.0, 4.0]])
    order = np.array([[1, 2, 0], [1, 0, 2]])
    for fn in api(backend, "take_along_axis"):
        check(fn(native(a, backend), native(order, backend)), np.sort(a, axis=-1), backend)


def test_take_along_axis_broadcasts_int32_and_empty_indices(backend):
    a = _params("float64", (3, 4))
    for fn in api(backend, "take_along_axis"):
        row = np.array([[3, -4]], np.int32)  # size 1 along axis 0: the same picks for every row
        out = fn(native(a, backend), native(row, backend), axis=1)
        check(out, _take_along_reference(a, row, 1), backend)
        none = np.zeros((0, 4), np.int64)
        check(fn(native(a, backend), native(none, backend), axis=0), np.zeros((0, 4)), backend)


def test_take_along_axis_gradients(diff_backend):
    indices = native(np.array([[0, 0, 2], [1, 2, 1]]), diff_backend)  # repeats accumulate

    def fn(x):
        return ivy.take_along_axis(x, indices, axis=1)

    check_gradients(diff_backend, fn, [np.random.default_rng(3).normal(size=(2, 3))])


def _gather_reference(params, indices):
    k = indices.shape[-1]
    rows = [params[tuple(i)] for i in indices.reshape(-1, k)]
    out_shape = indices.shape[:-1] + params.shape[k:]
    return np.array(rows, dtype=params.dtype).reshape(out_shape)


GATHER_INDICES = {
    "full index, 1 batch axis": [[0, 1, 2], [2, 3, 4], [1, 0, 0]],
    "partial index (K=2)": [[0, 1], [2, 0]],
    "partial index (K=1)": [[2], [0], [2], [1]],
    "2 batch axes": [[[0, 0], [1, 3]], [[2, 2], [0, 3]], [[1, 1], [1, 1]]],
    "single tuple": [1, 2],
}


@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("indices", list(GATHER_INDICES.values()), ids=list(GATHER_INDICES))
def test_gather_nd(backend, dtype, indices):
    params = _params(dtype)
    idx = np.array(indices, dtype=np.int64)
    expected = _gather_reference(params, idx)
    for fn in api(backend, "gather_nd"):
        check(fn(native(params, backend), native(idx, backend)), expected, backend)
        check(fn(native(params, backend), native(idx.astype(np.int32), backend)), expected, backend)


def test_gather_nd_with_list_indices(backend):
    """The docstring example: ``gather_nd(x, [[0, 1], [2, 0]])`` -> ``[x[0, 1], x[2, 0]]``."""
    params = _params("float32", (3, 2))
    for fn in api(backend, "gather_nd"):
        check(fn(native(params, backend), [[0, 1], [2, 0]]), params[[0, 2], [1, 0]], backend)


def _scatter_reference(indices, updates, shape, reduction):
    """Zeros of ``shape``; each place that receives updates gets their sum / min / max."""
    k = indices.shape[-1]
    received: dict[tuple, list] = {}
    flat_updates = updates.reshape((-1,) + tuple(shape[k:]))
    for index, update in zip(indices.reshape(-1, k), flat_updates):
        received.setdefault(tuple(index), []).append(update)
    out = np.zeros(shape, dtype=updates.dtype)
    combine = {"sum": np.sum, "min": np.min, "max": np.max, "replace": np.max}[reduction]
    for index, values in received.items():
        out[index] = combine(np.stack(values), axis=0)
    return out, received


# indices, updates shape, output shape: duplicates included, and untouched places.
SCATTER_CASES = {
    "elements, duplicates": ([[0, 1], [2, 3], [0, 1], [1, 0], [0, 1]], (5,), (3, 4)),
    "rows (K=1), duplicates": ([[2], [0], [2]], (3, 4), (4, 4)),
    "batched indices": ([[[0, 0], [1, 1]], [[1, 1], [2, 0]]], (2, 2), (3, 2)),
}


@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("reduction", ["sum", "min", "max"])
@pytest.mark.parametrize("case", list(SCATTER_CASES.values()), ids=list(SCATTER_CASES))
def test_scatter_nd_reductions(backend, dtype, reduction, case):
    indices, updates_shape, shape = case
    idx = np.array(indices, dtype=np.int64)
    updates = (np.arange(math.prod(updates_shape)).reshape(updates_shape) * 2.5 - 4).astype(dtype)
    expected, _ = _scatter_reference(idx, updates, shape, reduction)
    args = native(idx, backend), native(updates, backend)
    for fn in api(backend, "scatter_nd"):
        check(fn(*args, shape, reduction=reduction), expected, backend)
    if reduction == "sum":  # the default
        check(api(backend, "scatter_nd")[0](*args, shape), expected, backend)
        check(api(backend, "scatter_nd")[0](*args, shape=list(shape)), expected, backend)


@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("case", list(SCATTER_CASES.values()), ids=list(SCATTER_CASES))
def test_scatter_nd_replace(backend, dtype, case):
    """'replace' writes one of the updates that land on a place (unspecified which)."""
    indices, updates_shape, shape = case
    idx = np.array(indices, dtype=np.int64)
    updates = (np.arange(math.prod(updates_shape)).reshape(updates_shape) * 2.5 - 4).astype(dtype)
    _, received = _scatter_reference(idx, updates, shape, "replace")
    for fn in api(backend, "scatter_nd"):
        out = fn(native(idx, backend), native(updates, backend), shape, reduction="replace")
        check(out, _replace_expected(out, received, shape, dtype), backend)


def _replace_expected(out, received, shape, dtype):
    """The reference for 'replace', given which of its updates ``out`` chose at each place."""
    got = numpy_of(out)
    expected = np.zeros(shape, dtype)
    for index, values in received.items():
        chosen = [v for v in values if np.array_equal(v, got[index])]
        assert chosen, f"scatter_nd 'replace' wrote {got[index]} at {index}, not an update"
        expected[index] = chosen[0]
    return expected


@pytest.mark.parametrize("reduction", ["mean", "add", "", None])
def test_scatter_nd_unknown_reduction_raises_value_error(backend, reduction):
    idx = native(np.array([[0], [1]], np.int64), backend)
    updates = native(np.array([1.0, 2.0], np.float32), backend)
    for fn in api(backend, "scatter_nd"):
        with pytest.raises(ValueError):
            fn(idx, updates, (3,), reduction=reduction)


def _put_rows_reference(x, indices, updates):
    """``x`` with row ``indices[j]`` (negative from the end) replaced by ``updates[j]``, one row
    at a time, in a new array."""
    out = np.array(x, copy=True)
    for j, i in enumerate(indices):
        out[int(i) % x.shape[0]] = updates[j]
    return out


PUT_ROWS_CASES = {
    "matrix, negative index": ((5, 3), [4, -5, 2]),
    "vector": ((6,), [0, 5]),
    "3-D, one row": ((4, 2, 3), [1]),
    "every row, shuffled": ((3, 2), [2, 0, 1]),
    "no rows": ((4, 2), []),
}


@pytest.mark.parametrize("dtype", [*DTYPES, "bool"])
@pytest.mark.parametrize("case", list(PUT_ROWS_CASES.values()), ids=list(PUT_ROWS_CASES))
def test_put_rows(backend, dtype, case):
    shape, rows = case
    rng = np.random.default_rng(len(rows))
    x = _params(dtype, shape) if dtype != "bool" else rng.random(shape) > 0.5
    indices = np.array(rows, np.int64)
    updates = (rng.normal(size=(len(rows), *shape[1:])) * 9).astype(dtype)
    expected = _put_rows_reference(x, indices, updates)
    for fn in api(backend, "put_rows"):
        for idx in (indices, indices.astype(np.int32)):
            native_x = native(x, backend)
            out = fn(native_x, native(idx, backend), native(updates, backend))
            check(out, expected, backend)
            check(native_x, x, backend)  # x itself is left as it was


def test_put_rows_converts_updates_to_the_dtype_of_x(backend):
    x = _params("float32", (3, 2))
    updates = np.array([[1.5, -2.25]], np.float64)
    expected = _put_rows_reference(x, [1], updates.astype(np.float32))
    for fn in api(backend, "put_rows"):
        out = fn(native(x, backend), native(np.array([1]), backend), native(updates, backend))
        check(out, expected, backend)


def test_put_rows_gradients(diff_backend):
    """Gradients reach ``updates`` and the rows of ``x`` that are kept (none of the replaced
    rows' values survive, so their gradient is zero)."""
    indices = native(np.array([3, 0]), diff_backend)

    def fn(x, updates):
        return ivy.put_rows(x, indices, updates) ** 2

    rng = np.random.default_rng(11)
    x, updates = rng.normal(size=(4, 3)), rng.normal(size=(2, 3))
    check_gradients(diff_backend, fn, [x, updates], n_directions=3)
    v = {"x": native(x, diff_backend), "u": native(updates, diff_backend)}
    _, grads = ivy.execute_with_gradients(
        lambda v: ivy.sum(ivy.put_rows(v["x"], indices, v["u"])), v
    )
    kept = np.ones((4, 3))
    kept[[3, 0]] = 0.0
    check(grads["x"], kept, diff_backend)
    check(grads["u"], np.ones((2, 3)), diff_backend)


BAD_PUT_ROWS = {
    "updates rows differ from indices": ((4, 3), [0, 1], (1, 3), ivy.ShapeError),
    "updates row shape differs": ((4, 3), [0], (1, 2), ivy.ShapeError),
    "2-D indices": ((4, 3), [[0], [1]], (2, 3), ivy.ShapeError),
    "0-d x": ((), [0], (1,), ivy.ShapeError),
    "float indices": ((4, 3), [0.0], (1, 3), ivy.DtypeError),
    "index past the end": ((4, 3), [4], (1, 3), ivy.IndexOutOfBoundsError),
    "negative index past the start": ((4, 3), [-5], (1, 3), ivy.IndexOutOfBoundsError),
}


@pytest.mark.parametrize("case", list(BAD_PUT_ROWS.values()), ids=list(BAD_PUT_ROWS))
def test_put_rows_bad_input_raises_a_clear_error(backend, case):
    shape, rows, updates_shape, error = case
    x, updates = np.zeros(shape, np.float32), np.ones(updates_shape, np.float32)
    indices = np.array(rows)
    for fn in api(backend, "put_rows"):
        with pytest.raises(error, match="put_rows"):
            fn(native(x, backend), native(indices, backend), native(updates, backend))


def test_put_rows_compiled_with_x_donated(graph_backend):
    """Compiled, with ``x`` donated (on jax the rows are then written into ``x``'s buffer; see
    test_compilation.py), the result is the reference's, and the shape checks hold in tracing."""
    x = _params("float64", (6, 2))
    indices, updates = np.array([5, 1]), np.array([[1.0, 2.0], [3.0, 4.0]])
    write = ivy.compile_fn(lambda x, i, u: ivy.put_rows(x, i, u), donate_argnums=0)
    for _ in range(2):  # the second call runs the compiled function traced by the first
        i, u = native(indices, graph_backend), native(updates, graph_backend)
        out = write(native(x, graph_backend), i, u)
        check(out, _put_rows_reference(x, indices, updates), graph_backend)
    with pytest.raises(ivy.ShapeError, match="updates must have shape"):
        write(native(x, graph_backend), i, native(updates[:1], graph_backend))


def _one_hot_reference(indices, depth, dtype):
    out = np.zeros(indices.shape + (depth,), dtype=dtype)
    for index in np.ndindex(indices.shape):
        out[index + (indices[index],)] = 1
    return out


@pytest.mark.parametrize("indices", [[[0, 3, 1], [2, 2, 0]], [1, 0, 4], 2, []], ids=str)
def test_one_hot_is_float32_by_default(backend, indices):
    idx = np.array(indices, dtype=np.int64)
    expected = _one_hot_reference(idx, 5, np.float32)
    for fn in api(backend, "one_hot"):
        check(fn(native(idx, backend), 5), expected, backend)


@pytest.mark.parametrize("dtype", ["float64", "int32", "int64", "bool"])
def test_one_hot_with_dtype(backend, dtype):
    idx = np.array([[1, 0], [2, 1]], dtype=np.int32)
    expected = _one_hot_reference(idx, 3, dtype)
    for fn in api(backend, "one_hot"):
        check(fn(native(idx, backend), 3, dtype=dtype), expected, backend)
    xp_dtype = getattr(getattr(ivy, backend), dtype)  # the framework's own dtype object
    check(api(backend, "one_hot")[1](native(idx, backend), 3, dtype=xp_dtype), expected, backend)
