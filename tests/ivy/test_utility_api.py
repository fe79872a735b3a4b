"""all, any and diff on every backend, against references written as Python loops."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.helpers import HYPOTHESIS, api, check, native
from tests.ivy.strategies import arrays, axis_arguments, normalize_axis

pytestmark = pytest.mark.filterwarnings("ignore::RuntimeWarning")  # inf - inf in references

FEW = settings(HYPOTHESIS, max_examples=20)
SHAPES = st.sampled_from([(), (5,), (0,), (2, 3), (2, 1, 3), (3, 0)])


def _elements(dtype):
    if dtype == "bool":
        return st.booleans()
    if dtype == "int64":
        return st.integers(-2, 2)
    return st.sampled_from([0.0, -0.0, 1.5, -2.0, math.inf, math.nan])


@pytest.mark.parametrize("name", ["all", "any"])
@FEW
@given(data=st.data())
def test_all_any(backend, name, data):
    dtype = data.draw(st.sampled_from(["float32", "float64", "int64", "bool"]), label="dtype")
    a = data.draw(arrays(dtype, _elements(dtype), SHAPES), label="x")
    axis = data.draw(axis_arguments(a.ndim) | st.just(()), label="axis")
    keepdims = data.draw(st.booleans(), label="keepdims")
    reduced = normalize_axis(axis, a.ndim)
    shape = tuple(1 if ax in reduced else n for ax, n in enumerate(a.shape))
    start = name == "all"
    expected = np.full(shape, start)
    for index in np.ndindex(a.shape):
        target = tuple(0 if ax in reduced else i for ax, i in enumerate(index))
        truth = bool(a[index] != 0)  # NaN is true
        expected[target] = (expected[target] and truth) if start else (expected[target] or truth)
    if not keepdims:
        expected = expected.reshape([n for ax, n in enumerate(shape) if ax not in reduced])
    for fn in api(backend, name):
        check(fn(native(a, backend), axis=axis, keepdims=keepdims), expected, backend)


def _diff_reference(a, axis, n):
    out = np.moveaxis(a, axis, -1)
    for _ in range(n):
        new = np.empty(out.shape[:-1] + (max(out.shape[-1] - 1, 0),), a.dtype)
        for index in np.ndindex(out.shape[:-1]):
            r = [v.item() for v in out[index]]
            new[index] = [
                (r[i + 1] != r[i]) if a.dtype == bool else r[i + 1] - r[i]
                for i in range(len(r) - 1)
            ]
        out = new
    return np.moveaxis(out, -1, axis)


@FEW
@given(data=st.data())
def test_diff(backend, data):
    dtype = data.draw(st.sampled_from(["float32", "float64", "int64", "bool"]), label="dtype")
    elements = _elements(dtype) if dtype != "float32" else st.integers(-50, 50).map(float)
    a = data.draw(
        arrays(dtype, elements, st.sampled_from([(5,), (0,), (2, 4), (3, 1, 2)])), label="x"
    )
    axis = data.draw(st.integers(-a.ndim, a.ndim - 1), label="axis")
    n = data.draw(st.integers(0, 3), label="n")
    expected = _diff_reference(a, axis, n)
    for fn in api(backend, "diff"):
        check(fn(native(a, backend), axis=axis, n=n), expected, backend, rtol=0, atol=0)


def test_diff_prepend_and_append(backend):
    a = np.array([[1, 4, 9], [2, 3, 5]], np.int64)
    before, after = np.array([[0], [1]], np.int64), np.array([[16], [8]], np.int64)
    joined = np.concatenate([before, a, after], axis=1)
    for fn in api(backend, "diff"):
        check(
            fn(native(a, backend), prepend=native(before, backend), append=native(after, backend)),
            _diff_reference(joined, 1, 1),
            backend,
        )
        check(
            fn(native(a, backend), axis=0, prepend=0),
            _diff_reference(np.vstack([[0, 0, 0], a]), 0, 1),
            backend,
        )
        check(fn(native(a, backend)), _diff_reference(a, -1, 1), backend)
