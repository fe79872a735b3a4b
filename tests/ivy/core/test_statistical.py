"""Tests of the core group ``statistical`` (``ivy/core/statistical.py``), on every backend.

Reductions against numpy (and scipy) float64 references, on every backend.

Hypothesis draws the array (0-d and empty included), the ``axis`` (None, an int, a tuple, negative
axes) and ``keepdims``. Float32 results are compared with a tolerance scaled to the magnitude of
the reduced values, since a float32 sum carries rounding errors relative to sum(|x|). The dtype
(float32 or float64) is drawn with the rest: jax compiles per dtype, shape and axis.

cumulative_sum and cumulative_prod on every backend, against running sums and products
written as Python loops in float64 (or exact Python integers).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ivy
from tests.helpers import (
    HYPOTHESIS,
    api,
    cast,
    check,
    check_gradients,
    native,
    reference,
    tolerance,
)
from tests.ivy.strategies import (
    FLOAT_DTYPES,
    NONEMPTY_SHAPES,
    SHAPES,
    arrays,
    axis_arguments,
    quarters,
    reals,
)


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


@HYPOTHESIS
@given(data=st.data())
def test_logsumexp(backend, data):
    """Against numpy's ``logaddexp`` reduction (another algorithm: pairwise), with infinities
    and NaN among the values; float32 errors scale with the largest value (the shift)."""
    dtype = data.draw(st.sampled_from(FLOAT_DTYPES), label="dtype")
    a = data.draw(arrays(dtype, reals(dtype, -50, 50)), label="x")
    axis = data.draw(axis_arguments(a.ndim), label="axis")
    keepdims = data.draw(st.booleans(), label="keepdims")
    expected = reference(np.logaddexp.reduce, a.astype(np.float64), axis=axis, keepdims=keepdims)
    tol = tolerance(dtype, _magnitude(a))
    x = native(a, backend)
    for fn in api(backend, "logsumexp"):
        check(fn(x, axis=axis, keepdims=keepdims), cast(expected, dtype), backend, **tol)


LOGSUMEXP_CASES = [
    ([-math.inf, -math.inf], {}, -math.inf),
    ([math.inf, 1.0], {}, math.inf),
    ([math.inf, -math.inf], {}, math.inf),
    ([-math.inf, 0.0], {}, 0.0),
    ([math.nan, 1.0], {}, math.nan),
    ([1000.0, 1000.0], {}, 1000.0 + math.log(2.0)),  # exp(1000) overflows: the shift avoids it
    (np.zeros((2, 0)), {"axis": 1}, [-math.inf, -math.inf]),
    (2.5, {}, 2.5),
]


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
@pytest.mark.parametrize("values, kwargs, expected", LOGSUMEXP_CASES, ids=str)
def test_logsumexp_edge_values(backend, dtype, values, kwargs, expected):
    a = np.asarray(values, dtype=dtype)
    for fn in api(backend, "logsumexp"):
        check(fn(native(a, backend), **kwargs), np.asarray(expected, dtype=dtype), backend)


def test_logsumexp_of_integers_is_float32(backend):
    a = np.array([[1, 2, 3], [0, 0, 0]], np.int64)
    for fn in api(backend, "logsumexp"):
        expected = np.logaddexp.reduce(a.astype(np.float64), axis=1).astype("float32")
        check(fn(native(a, backend), axis=1), expected, backend)


@pytest.mark.parametrize("kwargs", [{"axis": 1}, {}, {"axis": (0, 2), "keepdims": True}], ids=str)
def test_logsumexp_gradients(diff_backend, kwargs):
    def fn(x):
        return ivy.logsumexp(x, **kwargs)

    check_gradients(diff_backend, fn, [np.random.default_rng(1).normal(size=(2, 3, 4))])


@HYPOTHESIS
@given(data=st.data())
def test_median(backend, data):
    """Against numpy, with infinities, NaN and empty reductions (NaN) among the cases."""
    dtype = data.draw(st.sampled_from(FLOAT_DTYPES), label="dtype")
    a = data.draw(arrays(dtype, reals(dtype, -100, 100)), label="x")
    axis = data.draw(axis_arguments(a.ndim), label="axis")
    keepdims = data.draw(st.booleans(), label="keepdims")
    expected = reference(np.median, a.astype(np.float64), axis=axis, keepdims=keepdims)
    x = native(a, backend)
    for fn in api(backend, "median"):
        check(fn(x, axis=axis, keepdims=keepdims), cast(expected, dtype), backend)


METHODS = ["linear", "lower", "higher", "nearest", "midpoint"]


EIGHTHS = st.integers(0, 8).map(lambda i: i / 8)  # exact in float32 too, as are their positions


@HYPOTHESIS
@given(data=st.data())
def test_quantile(backend, data):
    """Against numpy, for each method, with ``q`` a float, a list or a 1-D array of the backend,
    and NaN among the values (no infinities: numpy interpolates ``inf * 0`` to NaN there)."""
    dtype = data.draw(st.sampled_from(FLOAT_DTYPES), label="dtype")
    elements = quarters(-2, 2) | st.just(math.nan)
    a = data.draw(arrays(dtype, elements, NONEMPTY_SHAPES), label="x")
    axis = data.draw(axis_arguments(a.ndim), label="axis")
    keepdims = data.draw(st.booleans(), label="keepdims")
    method = data.draw(st.sampled_from(METHODS), label="method")
    kind = data.draw(st.sampled_from(["float", "list", "array"]), label="q kind")
    if kind == "float":
        q = data.draw(st.floats(0, 1), label="q")
    elif kind == "list":
        q = data.draw(st.lists(st.floats(0, 1), min_size=1, max_size=3), label="q")
    else:
        q = np.array(data.draw(st.lists(EIGHTHS, min_size=1, max_size=3), label="q"), dtype)
    expected = reference(
        np.quantile, a.astype(np.float64), q, axis=axis, keepdims=keepdims, method=method
    )
    x = native(a, backend)
    q_arg = native(q, backend) if kind == "array" else q
    for fn in api(backend, "quantile"):
        out = fn(x, q_arg, axis=axis, keepdims=keepdims, method=method)
        check(out, cast(expected, dtype), backend)


def test_median_and_quantile_of_integers_are_float32(backend):
    a = np.array([[4, 1, 3, 2], [7, 7, 0, 1]], np.int64)
    x = native(a, backend)
    check(ivy.median(x, axis=1), np.median(a, axis=1).astype("float32"), backend)
    check(ivy.quantile(x, 0.3), np.float32(np.quantile(a, 0.3)), backend)


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
def test_median_and_quantile_of_nothing_are_nan(backend, dtype):
    x = native(np.zeros((2, 0), dtype), backend)
    for fn in api(backend, "median"):
        check(fn(x, axis=1), np.full(2, np.nan, dtype), backend)
        check(fn(x), np.array(np.nan, dtype), backend)
    for fn in api(backend, "quantile"):
        check(fn(x, [0.5, 1.0], axis=1), np.full((2, 2), np.nan, dtype), backend)


def test_quantile_next_to_infinities(backend):
    """Exact positions take the value there; numpy gives NaN (from ``inf * 0``) in these cases."""
    a = np.array([0.0, 1.0, np.inf])
    for fn in api(backend, "quantile"):
        check(fn(native(a, backend), [0.5, 1.0]), np.array([1.0, np.inf]), backend)
        check(fn(native(-a, backend), 0.0), np.array(-np.inf), backend)


def test_quantile_shapes_with_keepdims_and_a_list_of_q(backend):
    a = np.arange(24.0).reshape(2, 3, 4)
    x = native(a, backend)
    for fn in api(backend, "quantile"):
        out = fn(x, [0.1, 0.9], axis=(0, 2), keepdims=True)
        check(out, np.quantile(a, [0.1, 0.9], axis=(0, 2), keepdims=True), backend)
        check(fn(x, 0.5, axis=-1), np.quantile(a, 0.5, axis=-1), backend)


@pytest.mark.parametrize(
    "q, kwargs, message",
    [
        (1.5, {}, "q must be in"),
        ([0.5, -0.1], {}, "q must be in"),
        (0.5, {"method": "inverted_cdf"}, "unknown method"),
        (0.5, {"axis": 2}, "out of bounds"),
        (0.5, {"axis": (0, 0)}, "repeated axis"),
    ],
)
def test_quantile_refuses_bad_arguments(backend, q, kwargs, message):
    x = native(np.ones((2, 2)), backend)
    for fn in api(backend, "quantile"):
        with pytest.raises(ValueError, match=message):
            fn(x, q, **kwargs)
    with pytest.raises(ValueError, match="1-D"):
        ivy.quantile(x, native(np.ones((1, 2)) / 2, backend))


@pytest.mark.parametrize("shape", [(3, 5), (3, 4)], ids=["odd", "even"])
def test_median_gradients(diff_backend, shape):
    a = np.random.default_rng(4).permutation(15)[: math.prod(shape)].reshape(shape) * 0.3

    def fn(x):
        return ivy.median(x, axis=1)

    check_gradients(diff_backend, fn, [a])


@pytest.mark.parametrize("method", ["linear", "midpoint", "nearest"])
def test_quantile_gradients(diff_backend, method):
    a = np.random.default_rng(5).permutation(12).reshape(3, 4) * 0.7  # distinct values

    def fn(x):
        return ivy.quantile(x, [0.1, 0.5, 0.8], axis=0, method=method)

    check_gradients(diff_backend, fn, [a])


FEW = settings(HYPOTHESIS, max_examples=20)


NAMES = {"cumulative_sum": (0, lambda acc, v: acc + v), "cumulative_prod": (1, lambda a, v: a * v)}


def _running(a, axis, name, include_initial, out_dtype):
    """Running sums or products along ``axis``, element by element in Python numbers."""
    initial, op = NAMES[name]
    moved = np.moveaxis(a, axis, -1)
    n = moved.shape[-1] + include_initial
    out = np.zeros(moved.shape[:-1] + (n,), dtype=object)
    for index in np.ndindex(moved.shape[:-1]):
        acc = initial
        values = [acc] if include_initial else []
        for v in moved[index]:
            acc = op(acc, float(v) if out_dtype.startswith("float") else int(v))
            values.append(acc)
        out[index] = values
    if out_dtype.startswith("float"):
        return cast(np.moveaxis(out, -1, axis).astype(np.float64), out_dtype)
    info = np.iinfo(out_dtype)  # integers wrap around as fixed-width integers do
    wrapped = np.vectorize(lambda v: (v - info.min) % (1 << info.bits) + info.min, otypes=[object])
    return np.moveaxis(wrapped(out), -1, axis).astype(out_dtype)


@pytest.mark.parametrize("name", sorted(NAMES))
@FEW
@given(data=st.data())
def test_cumulative_floats(backend, name, data):
    dtype = data.draw(st.sampled_from(["float32", "float64"]), label="dtype")
    bound = 100 if name == "cumulative_sum" else 2
    a = data.draw(
        arrays(
            dtype,
            reals(dtype, -bound, bound, specials=False),
            st.sampled_from([(6,), (0,), (2, 4), (3, 1, 2), (2, 0)]),
        ),
        label="x",
    )
    axis = data.draw(st.integers(-a.ndim, a.ndim - 1), label="axis")
    include_initial = data.draw(st.booleans(), label="include_initial")
    expected = _running(a, axis, name, include_initial, dtype)
    tol = tolerance(
        dtype, float(np.abs(a.astype(np.float64)).sum()) if name == "cumulative_sum" else 64.0
    )
    for fn in api(backend, name):
        check(
            fn(native(a, backend), axis=axis, include_initial=include_initial),
            expected,
            backend,
            **tol,
        )
        if a.ndim == 1:  # axis may be left out for 1-D arrays only
            check(fn(native(a, backend), include_initial=include_initial), expected, backend, **tol)


@pytest.mark.parametrize("name", sorted(NAMES))
@pytest.mark.parametrize(
    "dtype, out_dtype",
    [
        ("int8", "int64"),
        ("int32", "int64"),
        ("int64", "int64"),
        ("bool", "int64"),
        ("uint8", "uint64"),
    ],
)
def test_cumulative_integers_accumulate_in_64_bits(backend, name, dtype, out_dtype):
    """Signed integers and bools accumulate in int64, unsigned ones in uint64 (the standard's
    default integer, and the unsigned one of its size)."""
    if dtype == "bool":
        a = np.array([[True, False, True], [True, True, False]])
    elif name == "cumulative_sum":
        a = np.array([[100, 100, 100], [120, 7, 1]], dtype)  # int8 running sums overflow int8
    else:
        a = np.array([[3, 5, 7], [11, 13, 2]], dtype)
    for fn in api(backend, name):
        for include_initial in (False, True):
            check(
                fn(native(a, backend), axis=1, include_initial=include_initial),
                _running(a, 1, name, include_initial, out_dtype),
                backend,
            )


@pytest.mark.parametrize("name", sorted(NAMES))
def test_cumulative_with_dtype(backend, name):
    a = np.array([1, 2, 3, 4], np.int32)
    for fn in api(backend, name):
        check(
            fn(native(a, backend), dtype="float64"), _running(a, 0, name, False, "float64"), backend
        )


@pytest.mark.parametrize("name", sorted(NAMES))
def test_cumulative_needs_an_axis_beyond_one_dimension(backend, name):
    for fn in api(backend, name):
        with pytest.raises(ValueError):
            fn(native(np.ones((2, 2)), backend))


def _spread_reference(a: np.ndarray, axis, correction: float, keepdims: bool, root: bool):
    """var (or std) written from the standard: sum of squared deviations / (N - correction), NaN
    where N - correction <= 0."""
    a = a.astype(np.float64)
    axes = tuple(range(a.ndim)) if axis is None else (axis if isinstance(axis, tuple) else (axis,))
    n = int(np.prod([a.shape[i] for i in axes]))
    squares = ((a - a.mean(axis=axes, keepdims=True)) ** 2).sum(axis=axes, keepdims=keepdims)
    out = squares / (n - correction) if n - correction > 0 else np.full_like(squares, np.nan)
    return np.sqrt(out) if root else out


@pytest.mark.parametrize("name", ["var", "std"])
@pytest.mark.parametrize(
    "axis, correction, keepdims",
    [
        (None, 3, False),
        (None, 4, False),
        (None, 5.5, True),
        (1, 2, False),
        ((0, 1), 6, True),
        (0, 1, False),
    ],
)
def test_var_and_std_are_nan_where_too_few_elements_remain(
    backend, name, axis, correction, keepdims
):
    """N - correction <= 0 gives NaN, as the standard says (numpy and torch gave inf,
    tensorflow a negative variance)."""
    a = np.array([[1.0, 2.0], [3.0, 5.0]], np.float32)
    expected = _spread_reference(a, axis, correction, keepdims, root=name == "std")
    for fn in api(backend, name):
        out = fn(ivy.asarray(a, f=backend), axis=axis, correction=correction, keepdims=keepdims)
        check(out, expected.astype(np.float32), backend)


@pytest.mark.parametrize("name", ["cumulative_sum", "cumulative_prod"])
def test_cumulative_of_a_0d_array_needs_an_axis(backend, name):
    """(numpy accumulated a 0-d array into shape (1,), the others raised)"""
    for fn in api(backend, name):
        with pytest.raises(ValueError):
            fn(ivy.asarray(np.array(3.0, np.float32), f=backend))
