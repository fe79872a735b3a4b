"""Tests of the core group ``searching`` (``ivy/core/searching.py``), on every backend.

argmax, argmin and where against numpy references, on every backend.

nonzero, searchsorted and count_nonzero on every backend, against references written in
Python loops; jax's compiled code cannot give data-dependent shapes (UnsupportedError).
"""

from __future__ import annotations

import bisect
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ivy
from tests.helpers import HYPOTHESIS, api, check, native
from tests.ivy.strategies import (
    BROADCAST_PAIRS,
    FLOAT_DTYPES,
    NONEMPTY_SHAPES,
    arrays,
    axis_arguments,
    normalize_axis,
    quarters,
    reals,
)

ARG_REDUCTIONS = {"argmax": np.argmax, "argmin": np.argmin}


@pytest.mark.parametrize("name", sorted(ARG_REDUCTIONS))
@HYPOTHESIS
@given(data=st.data())
def test_arg_reduction(backend, name, data):
    """Index of the first extreme (values are multiples of 1/4 in [-2, 2]: many ties), int64."""
    dtype = data.draw(st.sampled_from([*FLOAT_DTYPES, "int32", "int64"]), label="dtype")
    elements = st.integers(-2, 2) if dtype.startswith("int") else quarters(-2, 2) | st.just(-np.inf)
    a = data.draw(arrays(dtype, elements, NONEMPTY_SHAPES), label="x")
    axis = data.draw(axis_arguments(a.ndim, tuples=False), label="axis")
    keepdims = data.draw(st.booleans(), label="keepdims")
    expected = np.asarray(ARG_REDUCTIONS[name](a, axis=axis, keepdims=keepdims), dtype=np.int64)
    x = native(a, backend)
    for fn in api(backend, name):
        check(fn(x, axis=axis, keepdims=keepdims), expected, backend)
    check(getattr(ivy, name)(x), np.int64(ARG_REDUCTIONS[name](a)), backend)


@pytest.mark.parametrize("name", sorted(ARG_REDUCTIONS))
def test_arg_reduction_first_occurrence_of_ties(backend, name):
    a = np.array([[1.0, 5.0, 5.0, -3.0, -3.0], [0.0, 0.0, 0.0, 0.0, 0.0]], dtype=np.float32)
    expected = {"argmax": [1, 0], "argmin": [3, 0]}[name]
    for fn in api(backend, name):
        check(fn(native(a, backend), axis=1), np.array(expected, np.int64), backend)
        check(fn(native(a, backend)), np.int64(expected[0] if name == "argmax" else 3), backend)


@HYPOTHESIS
@given(data=st.data())
def test_where_broadcasts_all_three(backend, data):
    dtype = data.draw(st.sampled_from(FLOAT_DTYPES), label="dtype")
    shape1, shape2 = data.draw(BROADCAST_PAIRS, label="shapes")
    cond_shape = data.draw(st.sampled_from([(), shape1, shape2]), label="condition shape")
    condition = data.draw(arrays("bool", st.booleans(), cond_shape), label="condition")
    a = data.draw(arrays(dtype, reals(dtype, -10, 10), shape1), label="x1")
    b = data.draw(arrays(dtype, reals(dtype, -10, 10), shape2), label="x2")
    expected = np.where(condition, a, b)
    args = [native(v, backend) for v in (condition, a, b)]
    for fn in api(backend, "where"):
        check(fn(*args), expected, backend, rtol=0, atol=0)


def test_where_with_python_scalars_and_mixed_dtypes(backend):
    condition = np.array([True, False, True])
    a = np.array([1.5, 2.5, 3.5], dtype=np.float32)
    b = np.array([-1.0, -2.0, -3.0], dtype=np.float64)
    c, x, y = native(condition, backend), native(a, backend), native(b, backend)
    for fn in api(backend, "where"):
        check(fn(c, x, 0.0), np.array([1.5, 0.0, 3.5], np.float32), backend)
        check(fn(c, 7.0, x), np.array([7.0, 2.5, 7.0], np.float32), backend)
        check(fn(c, x, y), np.array([1.5, -2.0, 3.5], np.float64), backend)


FEW = settings(HYPOTHESIS, max_examples=20)


SHAPES = st.sampled_from([(5,), (0,), (2, 3), (2, 1, 3), (3, 0)])


DTYPES = ["float32", "float64", "int64", "bool"]


def _elements(dtype):
    if dtype == "bool":
        return st.booleans()
    if dtype == "int64":
        return st.integers(-2, 2)
    return st.sampled_from([0.0, -0.0, 1.5, -2.0, math.inf, math.nan])


@FEW
@given(data=st.data())
def test_nonzero(backend, data):
    dtype = data.draw(st.sampled_from(DTYPES), label="dtype")
    a = data.draw(arrays(dtype, _elements(dtype), SHAPES), label="x")
    found = [index for index in np.ndindex(a.shape) if a[index] != 0]  # NaN is nonzero
    expected = [np.array([f[k] for f in found], np.int64) for k in range(a.ndim)]
    for fn in api(backend, "nonzero"):
        out = fn(native(a, backend))
        assert isinstance(out, tuple) and len(out) == a.ndim
        for o, e in zip(out, expected):
            check(o, e, backend)


def test_nonzero_refuses_0d_arrays(backend):
    for fn in api(backend, "nonzero"):
        with pytest.raises(ValueError):
            fn(native(np.float32(1.0), backend))


def test_nonzero_inside_jax_jit_is_unsupported():
    jax = pytest.importorskip("jax")
    with pytest.raises(ivy.UnsupportedError, match="size"):
        jax.jit(ivy.jax.nonzero)(jax.numpy.ones(3))


def test_nonzero_inside_tf_function():
    tf = pytest.importorskip("tensorflow")
    fn = tf.function(ivy.tensorflow.nonzero)
    out = fn(tf.constant([[0.0, 2.0], [3.0, 0.0]]))
    check(out[0], np.array([0, 1]), "tensorflow")
    check(out[1], np.array([1, 0]), "tensorflow")


@FEW
@given(data=st.data())
def test_searchsorted(backend, data):
    dtype = data.draw(st.sampled_from(["float32", "float64", "int64"]), label="dtype")
    values = (
        st.integers(-5, 5)
        if dtype == "int64"
        else st.sampled_from([-2.5, -1.0, 0.0, 1.0, 3.0, math.inf, -math.inf])
    )
    seq = data.draw(arrays(dtype, values, st.sampled_from([(0,), (1,), (6,)])), label="x1")
    v = data.draw(arrays(dtype, values, st.sampled_from([(), (4,), (2, 3), (0,)])), label="x2")
    side = data.draw(st.sampled_from(["left", "right"]), label="side")
    use_sorter = data.draw(st.booleans(), label="sorter")
    if use_sorter:  # x1 unsorted, with the permutation that sorts it
        sorter = np.array(sorted(range(len(seq)), key=lambda i: seq[i]), np.int64)
        ordered = [seq[i] for i in sorter]
    else:
        seq = np.sort(seq)
        sorter, ordered = None, list(seq)
    search = bisect.bisect_left if side == "left" else bisect.bisect_right
    expected = np.array([search(ordered, x) for x in v.ravel()], np.int64).reshape(v.shape)
    kwargs = {"side": side}
    for fn in api(backend, "searchsorted"):
        if use_sorter:
            kwargs["sorter"] = native(sorter, backend)
        check(fn(native(seq, backend), native(v, backend), **kwargs), expected, backend)


def test_searchsorted_with_a_python_scalar_and_mixed_dtypes(backend):
    seq = np.array([1.0, 2.0, 3.0], np.float32)
    for fn in api(backend, "searchsorted"):
        check(fn(native(seq, backend), 2.5), np.int64(2), backend)
        v = native(np.array([2, 3], np.int64), backend)
        check(fn(native(seq, backend), v, side="right"), np.array([2, 3]), backend)


@FEW
@given(data=st.data())
def test_count_nonzero(backend, data):
    dtype = data.draw(st.sampled_from(DTYPES), label="dtype")
    a = data.draw(arrays(dtype, _elements(dtype), SHAPES), label="x")
    axis = data.draw(axis_arguments(a.ndim) | st.just(()), label="axis")
    keepdims = data.draw(st.booleans(), label="keepdims")
    reduced = normalize_axis(axis, a.ndim)
    out_shape = tuple(
        1 if ax in reduced else n for ax, n in enumerate(a.shape) if keepdims or ax not in reduced
    )
    expected = np.zeros(out_shape, np.int64)
    for index in np.ndindex(a.shape):
        if a[index] != 0:
            target = tuple(0 if ax in reduced else i for ax, i in enumerate(index))
            if not keepdims:
                target = tuple(i for ax, i in enumerate(target) if ax not in reduced)
            expected[target] += 1
    for fn in api(backend, "count_nonzero"):
        check(fn(native(a, backend), axis=axis, keepdims=keepdims), expected, backend)


@pytest.mark.parametrize(
    "x1, x2, dtype",
    [
        (1.5, 2, "float32"),
        (1, 2, "int64"),
        (True, False, "bool"),
        (1j, 2, "complex64"),
        (0.5, 2.5, "float32"),
    ],
)
def test_where_of_two_python_scalars_is_of_the_default_dtype(backend, x1, x2, dtype):
    """(numpy and jax made ``where(c, 1.5, 2)`` float64)"""
    c = np.array([True, False])
    for fn in api(backend, "where"):
        check(fn(native(c, backend), x1, x2), np.where(c, x1, x2).astype(dtype), backend)


def _nan_last_key(v: float) -> tuple:
    """The order ivy sorts floats in: numbers by value, NaN after every number."""
    return (1, 0.0) if math.isnan(v) else (0, v)


@pytest.mark.parametrize("side", ["left", "right"])
def test_searchsorted_with_nan_in_the_sorted_array(backend, xp, side):
    """NaN sorts last (the standard leaves its order open; ivy.sort puts it last everywhere)."""
    x1 = [1.0, math.inf, math.nan, math.nan]
    x2 = [0.5, 1.0, 2.0, math.inf, math.nan, -math.inf]
    search = bisect.bisect_left if side == "left" else bisect.bisect_right
    keys = [_nan_last_key(v) for v in x1]
    expected = np.array([search(keys, _nan_last_key(v)) for v in x2], np.int64)
    for dtype in ("float32", "float64"):
        a = native(np.array(x1, dtype), backend)
        check(
            xp.searchsorted(a, native(np.array(x2, dtype), backend), side=side), expected, backend
        )
    # through a sorter: x1 given out of order
    shuffled = [math.nan, 1.0, math.nan, math.inf]
    sorter = native(np.array([1, 3, 0, 2], np.int64), backend)
    out = ivy.searchsorted(
        native(np.array(shuffled, np.float32), backend),
        native(np.array(x2, np.float32), backend),
        side=side,
        sorter=sorter,
    )
    check(out, expected, backend)
