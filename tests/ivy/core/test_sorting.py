"""Tests of the core group ``sorting`` (``ivy/core/sorting.py``), on every backend.

argsort, sort and top_k on every backend, against a stable sort written with Python's
``sorted``: NaN is the largest value (last ascending, first descending), -0.0 equals 0.0, and
equal elements keep their order in both directions (top_k: the lower index first).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ivy
from tests.helpers import HYPOTHESIS, api, check, check_gradients, native, numpy_of
from tests.ivy.strategies import arrays

FEW = settings(HYPOTHESIS, max_examples=20)


SHAPES = st.sampled_from([(6,), (0,), (2, 5), (3, 1, 4), (2, 0)])


TIES = [0.0, -0.0, 1.0, -1.0, 2.5, math.inf, -math.inf, math.nan]


def _elements(dtype):
    if dtype == "bool":
        return st.booleans()
    if dtype.startswith(("int", "uint")):
        info = np.iinfo(dtype)
        return st.sampled_from([int(info.min), int(info.max), 0, 1, 2])
    return st.sampled_from(TIES)


def _argsort_reference(a, axis, descending):
    moved = np.moveaxis(a, axis, -1)
    out = np.empty(moved.shape, np.int64)
    for index in np.ndindex(moved.shape[:-1]):
        row = [x.item() for x in moved[index]]

        def key(i, row=row):
            v = row[i]
            nan = isinstance(v, float) and math.isnan(v)
            if descending:  # sorted() is stable: negating keeps ties in their order
                return (not nan, -v if not nan else 0)
            return (nan, v if not nan else 0)

        out[index] = sorted(range(len(row)), key=key)
    return np.moveaxis(out, -1, axis)


@FEW
@given(data=st.data())
def test_argsort_and_sort(backend, data):
    dtype = data.draw(
        st.sampled_from(["float32", "float64", "int8", "int64", "uint8", "bool"]), label="dtype"
    )
    a = data.draw(arrays(dtype, _elements(dtype), SHAPES), label="x")
    axis = data.draw(st.integers(-a.ndim, a.ndim - 1), label="axis")
    descending = data.draw(st.booleans(), label="descending")
    order = _argsort_reference(a, axis, descending)
    x = native(a, backend)
    for fn in api(backend, "argsort"):
        check(fn(x, axis=axis, descending=descending), order, backend)
        check(fn(x, axis=axis, descending=descending, stable=True), order, backend)
    values = np.take_along_axis(a, order, axis)
    for fn in api(backend, "sort"):
        check(fn(x, axis=axis, descending=descending), values, backend, rtol=0, atol=0)
        # unstable: any order of equal elements, so only the values are compared
        unstable = fn(x, axis=axis, descending=descending, stable=False)
        check(unstable, values, backend, rtol=0, atol=0)


def test_defaults_sort_the_last_axis_ascending(backend):
    a = np.array([[3.0, 1.0, 2.0], [0.0, -5.0, 5.0]], np.float32)
    for fn in api(backend, "sort"):
        check(
            fn(native(a, backend)),
            np.array([[1.0, 2.0, 3.0], [-5.0, 0.0, 5.0]], np.float32),
            backend,
        )
    for fn in api(backend, "argsort"):
        check(fn(native(a, backend)), np.array([[1, 2, 0], [1, 0, 2]]), backend)


def test_stable_descending_keeps_equal_elements_in_order(backend):
    a = np.array([1, 2, 1, 2, 0, 2], np.int64)
    for fn in api(backend, "argsort"):
        check(fn(native(a, backend), descending=True), np.array([1, 3, 5, 0, 2, 4]), backend)


@pytest.mark.parametrize("dtype", ["uint16", "uint32", "uint64", "int16", "float16"])
def test_other_dtypes(backend, dtype):
    a = np.array([5, 0, 3, 3, 1], dtype)
    for fn in api(backend, "argsort"):
        check(fn(native(a, backend)), np.array([1, 4, 2, 3, 0]), backend)
        check(fn(native(a, backend), descending=True), np.array([0, 2, 3, 4, 1]), backend)
    for fn in api(backend, "sort"):
        check(fn(native(a, backend)), np.array([0, 1, 3, 3, 5], dtype), backend)


@FEW
@given(data=st.data())
def test_top_k(backend, data):
    """The first ``k`` of the stable sort: ties (many here) in index order, NaN the largest."""
    dtype = data.draw(
        st.sampled_from(["float32", "float64", "int8", "int64", "uint8", "bool"]), label="dtype"
    )
    a = data.draw(arrays(dtype, _elements(dtype), SHAPES), label="x")
    axis = data.draw(st.integers(-a.ndim, a.ndim - 1), label="axis")
    k = data.draw(st.integers(0, a.shape[axis]), label="k")
    largest = data.draw(st.booleans(), label="largest")
    order = np.take(_argsort_reference(a, axis, descending=largest), np.arange(k), axis=axis)
    values = np.take_along_axis(a, order, axis)
    x = native(a, backend)
    for fn in api(backend, "top_k"):
        out = fn(x, k, axis=axis, largest=largest)
        assert isinstance(out, tuple) and out._fields == ("values", "indices")
        check(out.values, values, backend, rtol=0, atol=0)
        check(out.indices, order, backend)
        # unsorted: the same elements, in any order
        loose = fn(x, k, axis=axis, largest=largest, sorted=False)
        np.testing.assert_array_equal(np.sort(numpy_of(loose.indices), axis), np.sort(order, axis))
        np.testing.assert_array_equal(
            np.take_along_axis(a, numpy_of(loose.indices), axis), numpy_of(loose.values)
        )


def test_top_k_defaults_and_ties_in_index_order(backend):
    a = np.array([[1.0, 3.0, 2.0, 3.0, 3.0], [0.0, -0.0, 0.0, -1.0, 5.0]], np.float32)
    for fn in api(backend, "top_k"):
        values, indices = fn(native(a, backend), 3)
        check(values, np.array([[3.0, 3.0, 3.0], [5.0, 0.0, -0.0]], np.float32), backend)
        check(indices, np.array([[1, 3, 4], [4, 0, 1]]), backend)
        values, indices = fn(native(a, backend), 2, largest=False)
        check(values, np.array([[1.0, 2.0], [-1.0, 0.0]], np.float32), backend)
        check(indices, np.array([[0, 2], [3, 0]]), backend)
    # a long row of few distinct values: torch's own topk takes ties in no fixed order there
    long = np.random.default_rng(0).integers(0, 3, 500).astype(np.float64)
    for largest in (True, False):
        expected = np.argsort(-long if largest else long, kind="stable")[:40]
        _, indices = ivy.top_k(native(long, backend), 40, largest=largest)
        check(indices, expected, backend)


def test_top_k_refuses_bad_k_and_0d_arrays(backend):
    x = native(np.arange(4.0), backend)
    for fn in api(backend, "top_k"):
        for k in (-1, 5):
            with pytest.raises(ValueError, match="k must be between 0"):
                fn(x, k)
        with pytest.raises(ivy.errors.AxisError, match="0-d array has no axis"):
            fn(native(np.array(1.0), backend), 1)


def test_top_k_gradients(diff_backend):
    a = np.random.default_rng(2).permutation(12).reshape(3, 4) * 0.5  # distinct values

    def fn(x):
        return ivy.top_k(x, 2, axis=0, largest=False).values

    check_gradients(diff_backend, fn, [a])


@pytest.mark.parametrize("name", ["sort", "argsort"])
def test_sorting_a_0d_array_raises_axis_error(backend, name):
    """axis -1 does not exist in a 0-d array (torch sorted it; numpy's argsort gave [0]): ivy's
    AxisError from ``ivy.<name>``, a ValueError (the framework's own) from the namespace."""
    x = native(np.array(3.0, np.float32), backend)
    with pytest.raises(ivy.errors.AxisError):
        getattr(ivy, name)(x)
    with pytest.raises(ValueError):
        getattr(getattr(ivy, backend), name)(x)
