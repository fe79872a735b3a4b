"""argmax, argmin and where against numpy references, on every backend."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import ivy
from tests.helpers import HYPOTHESIS, api, check, native
from tests.ivy.strategies import (
    BROADCAST_PAIRS,
    FLOAT_DTYPES,
    NONEMPTY_SHAPES,
    arrays,
    axis_arguments,
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
