"""Reductions against numpy float64 references, on every backend.

Hypothesis draws the array (0-d and empty included), the ``axis`` (None, an int, a tuple, negative
axes) and ``keepdims``. Float32 results are compared with a tolerance scaled to the magnitude of
the reduced values, since a float32 sum carries rounding errors relative to sum(|x|). The dtype
(float32 or float64) is drawn with the rest: jax compiles per dtype, shape and axis.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from tests.helpers import HYPOTHESIS, api, cast, check, native, reference, tolerance
from tests.ivy.strategies import (
    FLOAT_DTYPES,
    NONEMPTY_SHAPES,
    SHAPES,
    arrays,
    axis_arguments,
    reals,
)

pytestmark = pytest.mark.filterwarnings("ignore::RuntimeWarning")  # numpy on empty slices


def _finite_abs(a):
    a = np.abs(np.asarray(a, np.float64))
    return a[np.isfinite(a)]


def _magnitude_of_sum(a):
    return float(_finite_abs(a).sum())


def _magnitude(a):
    m = _finite_abs(a)
    return float(m.max()) if m.size else 1.0


# name, reference(x64, axis, keepdims), element bound, whether empty reductions are defined,
# scale of the float32 rounding error for an input a.
REDUCTIONS = [
    ("sum", np.sum, 100, True, _magnitude_of_sum),
    ("prod", np.prod, 2, True, lambda a: 1.0),
    ("mean", np.mean, 100, True, _magnitude),
    ("min", np.min, 100, False, lambda a: 1.0),
    ("max", np.max, 100, False, lambda a: 1.0),
]


@pytest.mark.parametrize(
    "name, ref, bound, empty_ok, scale", REDUCTIONS, ids=[r[0] for r in REDUCTIONS]
)
@HYPOTHESIS
@given(data=st.data())
def test_reduction(backend, name, ref, bound, empty_ok, scale, data):
    dtype = data.draw(st.sampled_from(FLOAT_DTYPES), label="dtype")
    shapes = SHAPES if empty_ok else NONEMPTY_SHAPES
    a = data.draw(arrays(dtype, reals(dtype, -bound, bound, specials=False), shapes), label="x")
    axis = data.draw(axis_arguments(a.ndim), label="axis")
    keepdims = data.draw(st.booleans(), label="keepdims")
    expected = cast(reference(ref, a.astype(np.float64), axis=axis, keepdims=keepdims), dtype)
    tol = tolerance(dtype, scale(a))
    x = native(a, backend)
    for fn in api(backend, name):
        check(fn(x, axis=axis, keepdims=keepdims), expected, backend, **tol)
    check(
        api(backend, name)[0](x), cast(reference(ref, a.astype(np.float64)), dtype), backend, **tol
    )


@pytest.mark.parametrize("name, ref", [("var", np.var), ("std", np.std)])
@HYPOTHESIS
@given(data=st.data())
def test_var_std(backend, name, ref, data):
    """Dividing by N - correction; N - correction <= 0 (a single or no element) gives nan."""
    dtype = data.draw(st.sampled_from(FLOAT_DTYPES), label="dtype")
    a = data.draw(arrays(dtype, reals(dtype, -100, 100, specials=False)), label="x")
    axis = data.draw(axis_arguments(a.ndim), label="axis")
    keepdims = data.draw(st.booleans(), label="keepdims")
    correction = data.draw(st.sampled_from([0.0, 1.0]), label="correction")
    expected = reference(ref, a.astype(np.float64), axis=axis, ddof=correction, keepdims=keepdims)
    m = _magnitude(a)
    tol = tolerance(dtype, m * m if name == "var" else m)
    x = native(a, backend)
    for fn in api(backend, name):
        out = fn(x, axis=axis, correction=correction, keepdims=keepdims)
        check(out, cast(expected, dtype), backend, **tol)


# name, input, keyword arguments: special values, and empty inputs where the result is defined.
EDGE_CASES = [
    ("sum", [1.0, np.inf], {}),
    ("sum", [np.inf, -np.inf], {}),
    ("sum", [1.0, np.nan], {}),
    ("sum", np.zeros((0, 3)), {"axis": 0}),
    ("sum", np.zeros((0, 3)), {}),
    ("prod", [0.0, np.inf], {}),
    ("prod", [-2.0, np.inf], {}),
    ("prod", np.zeros((2, 0)), {"axis": 1}),
    ("mean", [1.0, np.inf], {}),
    ("mean", [np.inf, -np.inf], {}),
    ("mean", np.zeros(0), {}),
    ("min", [1.0, np.nan, -1.0], {}),
    ("min", [np.inf, -np.inf], {}),
    ("min", [[np.nan, 1.0], [2.0, 3.0]], {"axis": 1}),
    ("max", [1.0, np.nan, -1.0], {}),
    ("max", [-np.inf, -1.0], {}),
    ("max", [[np.nan, 1.0], [2.0, 3.0]], {"axis": 0}),
    ("var", [1.0, np.inf], {}),
    ("var", [3.0], {"correction": 1.0}),
    ("var", np.zeros((0, 2)), {"axis": 0}),
    ("std", [1.0, np.nan], {}),
    ("std", [2.0, 2.0, 2.0], {}),
]
NUMPY_NAMES = {"var": np.var, "std": np.std}


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
@pytest.mark.parametrize(
    "name, values, kwargs", EDGE_CASES, ids=[f"{c[0]}-{i}" for i, c in enumerate(EDGE_CASES)]
)
def test_reduction_edge_values(backend, name, values, kwargs, dtype):
    a = np.asarray(values, dtype=dtype)
    np_kwargs = {("ddof" if k == "correction" else k): v for k, v in kwargs.items()}
    ref = NUMPY_NAMES.get(name, getattr(np, name))
    expected = cast(reference(ref, a.astype(np.float64), **np_kwargs), dtype)
    for fn in api(backend, name):
        check(fn(native(a, backend), **kwargs), expected, backend)


@pytest.mark.parametrize("name", ["sum", "prod"])
@pytest.mark.parametrize("dtype", ["int32", "int64", "bool"])
def test_integer_sum_and_prod_accumulate_in_int64(backend, name, dtype):
    if dtype == "bool":
        a = np.array([[True, False, True], [True, True, True]])
    else:  # int32 results that overflow int32
        a = np.array([[2**31 - 1, 1, 1], [65536, 65536, 1]], dtype=dtype)
    ref = getattr(np, name)
    for fn in api(backend, name):
        check(fn(native(a, backend)), ref(a.astype(np.int64)), backend)
        check(fn(native(a, backend), axis=1), ref(a.astype(np.int64), axis=1), backend)


@pytest.mark.parametrize("name", ["sum", "prod"])
def test_sum_and_prod_with_dtype(backend, name):
    a = np.array([[1.5, 2.25], [3.0, 1e-3]], dtype=np.float32)
    ref = getattr(np, name)
    for fn in api(backend, name):
        check(fn(native(a, backend), dtype="float64"), ref(a.astype(np.float64)), backend)
        out = fn(native(a, backend), axis=0, dtype="float64")
        check(out, ref(a.astype(np.float64), axis=0), backend)
        ints = np.array([1, 2, 3], dtype=np.int64)
        check(fn(native(ints, backend), dtype="float32"), ref(ints).astype(np.float32), backend)


@pytest.mark.parametrize("name", ["min", "max"])
@pytest.mark.parametrize("dtype", ["int32", "int64"])
def test_min_max_integers_keep_their_dtype(backend, name, dtype):
    a = np.array([[3, -7, 2], [9, 0, -1]], dtype=dtype)
    ref = getattr(np, name)
    for fn in api(backend, name):
        check(fn(native(a, backend)), ref(a), backend)
        check(
            fn(native(a, backend), axis=-1, keepdims=True), ref(a, axis=-1, keepdims=True), backend
        )


def test_sum_over_a_tuple_of_axes_with_negative_entries(backend):
    a = np.arange(24, dtype=np.float64).reshape(2, 3, 4)
    for fn in api(backend, "sum"):
        check(fn(native(a, backend), axis=(0, -1)), a.sum(axis=(0, 2)), backend)
        check(
            fn(native(a, backend), axis=(0, -1), keepdims=True),
            a.sum(axis=(0, 2), keepdims=True),
            backend,
        )
