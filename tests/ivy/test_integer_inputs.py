"""Integer and boolean arrays given to functions defined on floating-point numbers.

The Array API leaves this open ("should have a floating-point data type"), and the frameworks
disagree: numpy computes in float64 (float16 for bool), torch in its default float, jax in
float64 for int64 under x64, tensorflow refuses. ivy makes one rule for every backend: such
inputs are computed in the default float dtype, float32, as a float32 array of the same values
would be. Reductions and products of integers (sum, prod, matmul, vecdot...) stay integer.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import special

import ivy
from tests.helpers import api, check, reference

# name, numpy float64 reference, integer inputs in the function's domain
UNARY = [
    ("acos", np.arccos, [-1, 0, 1]),
    ("acosh", np.arccosh, [1, 2, 7]),
    ("asin", np.arcsin, [-1, 0, 1]),
    ("asinh", np.arcsinh, [-3, 0, 7]),
    ("atan", np.arctan, [-3, 0, 7]),
    ("atanh", np.arctanh, [-1, 0, 1]),
    ("cos", np.cos, [-3, 0, 7]),
    ("cosh", np.cosh, [-3, 0, 7]),
    ("exp", np.exp, [-3, 0, 7]),
    ("expm1", np.expm1, [-3, 0, 7]),
    ("log", np.log, [0, 1, 7]),
    ("log10", np.log10, [0, 1, 100]),
    ("log1p", np.log1p, [-1, 0, 7]),
    ("log2", np.log2, [0, 1, 8]),
    ("reciprocal", np.reciprocal, [-3, 1, 7]),  # 1/x of integers is not an integer
    ("sin", np.sin, [-3, 0, 7]),
    ("sinh", np.sinh, [-3, 0, 7]),
    ("sqrt", np.sqrt, [0, 2, 9]),
    ("tan", np.tan, [-3, 0, 7]),
    ("tanh", np.tanh, [-3, 0, 7]),
    ("sigmoid", special.expit, [-3, 0, 7]),
    ("softplus", lambda x: np.logaddexp(0.0, x), [-3, 0, 7]),
    ("silu", lambda x: x * special.expit(x), [-3, 0, 7]),
    ("elu", lambda x: np.where(x > 0, x, np.expm1(x)), [-3, 0, 7]),
    ("gelu", lambda x: x * special.ndtr(x), [-3, 0, 7]),
    ("softmax", lambda x: special.softmax(x, axis=-1), [-3, 0, 7]),
    ("log_softmax", lambda x: special.log_softmax(x, axis=-1), [-3, 0, 7]),
    ("mean", np.mean, [-3, 0, 7]),
    ("var", np.var, [-3, 0, 7]),
    ("std", np.std, [-3, 0, 7]),
    ("logsumexp", special.logsumexp, [-3, 0, 7]),
    ("median", np.median, [-3, 0, 7]),
]
BINARY = [
    ("atan2", np.arctan2, [-3, 0, 7], [2, -1, 0]),
    ("copysign", np.copysign, [-3, 0, 7], [2, -1, -5]),
    ("divide", np.divide, [-3, 0, 7], [2, -1, 4]),
    ("hypot", np.hypot, [-3, 0, 7], [4, -1, 0]),
    ("logaddexp", np.logaddexp, [-3, 0, 7], [2, -1, 0]),
]
INT_DTYPES = ["int8", "int32", "int64", "uint8"]


def _native(a, backend):
    return getattr(ivy, backend).asarray(a)


def _inputs(values, dtype):
    if dtype == "uint8":
        values = [abs(v) for v in values]
    return np.asarray(values, dtype=dtype)


@pytest.mark.parametrize("dtype", INT_DTYPES)
@pytest.mark.parametrize("name, ref, values", UNARY, ids=[u[0] for u in UNARY])
def test_float_functions_of_integers_compute_in_float32(backend, name, ref, values, dtype):
    a = _inputs(values, dtype)
    expected = reference(ref, a.astype(np.float64))
    for fn in api(backend, name):
        check(fn(_native(a, backend)), expected, backend, dtype="float32")


@pytest.mark.parametrize("dtype", INT_DTYPES)
@pytest.mark.parametrize("name, ref, x1, x2", BINARY, ids=[b[0] for b in BINARY])
def test_binary_float_functions_of_integers_compute_in_float32(backend, name, ref, x1, x2, dtype):
    a, b = _inputs(x1, dtype), _inputs(x2, dtype)
    expected = reference(ref, a.astype(np.float64), b.astype(np.float64))
    for fn in api(backend, name):
        check(fn(_native(a, backend), _native(b, backend)), expected, backend, dtype="float32")
    # an integer next to a float array takes the float's dtype, as type promotion says
    f64 = b.astype(np.float64)
    out = getattr(ivy, name)(_native(a, backend), _native(f64, backend))
    check(out, reference(ref, a.astype(np.float64), f64), backend, dtype="float64")


@pytest.mark.parametrize("name", ["sqrt", "exp", "mean", "sigmoid", "divide"])
def test_booleans_count_as_zero_and_one(backend, name):
    a = np.array([True, False, True])
    expected = {
        "sqrt": np.sqrt,
        "exp": np.exp,
        "mean": np.mean,
        "sigmoid": special.expit,
        "divide": lambda x: x / x,
    }[name](a.astype(np.float64))
    args = (_native(a, backend),) * (2 if name == "divide" else 1)
    check(getattr(ivy, name)(*args), reference(lambda: expected), backend, dtype="float32")


@pytest.mark.parametrize("name", ["sum", "prod", "cumulative_sum"])
def test_integer_reductions_stay_integer(backend, name):
    a = np.array([[1, 2], [3, 5]], dtype=np.int32)
    ref = {"sum": np.sum, "prod": np.prod, "cumulative_sum": lambda x: np.cumsum(x, axis=0)}
    kwargs = {"axis": 0} if name == "cumulative_sum" else {}
    out = getattr(ivy, name)(_native(a, backend), **kwargs)
    # the Array API: sums and products of signed integers accumulate in the default int, int64
    check(out, ref[name](a).astype(np.int64), backend)


@pytest.mark.parametrize("dtype", ["int32", "int64"])
def test_integer_products_keep_their_dtype(backend, dtype):
    a = np.array([[1, 2], [3, 5]], dtype=dtype)
    x = _native(a, backend)
    check(ivy.vecdot(x[0], x[1]), np.array(a[0] @ a[1], dtype=dtype), backend)
    check(ivy.matmul(x, x), (a @ a).astype(dtype), backend)


def test_the_rule_is_declared_on_the_core_stubs_and_tested_here():
    """The functions of real numbers are declared once, on the core's stubs
    (``@dispatch(reals=True)``, read with ``ivy.function_info``); every one is tested above."""
    declared = {i.name: i.reals for i in ivy.list_functions() if i.reals}
    tested = {u[0] for u in UNARY} | {b[0] for b in BINARY} | {"nextafter"}  # (its own test)
    assert set(declared) <= tested, sorted(set(declared) - tested)
    for name, *_ in BINARY:
        assert declared[name] == "binary", name
    for name in ("sin", "sqrt", "reciprocal", "sigmoid"):
        assert declared[name] == "unary", name
    for name in ("mean", "var", "std", "softmax"):
        assert declared[name] == "options", name


def test_nextafter_of_integers_steps_in_float32(backend):
    a, b = np.array([-3, 0, 7], np.int8), np.array([2, -1, 0], np.int8)
    expected = np.nextafter(a.astype(np.float32), b.astype(np.float32))
    for fn in api(backend, "nextafter"):
        check(fn(_native(a, backend), _native(b, backend)), expected, backend, rtol=0, atol=0)


def test_boolean_products_are_any_of_the_ands(backend):
    """numpy's (and jax's) products of booleans, on every backend: torch and tensorflow have no
    boolean kernels, so ivy counts the true products and compares with 0."""
    a = np.array([[True, False, False], [True, True, False], [False, False, False]])
    v = np.array([True, False, True])

    def any_of_ands(p, q):  # written out: p @ q over (or, and)
        return np.array(
            [
                [any(p[i, k] and q[k, j] for k in range(p.shape[1])) for j in range(q.shape[1])]
                for i in range(p.shape[0])
            ]
        )

    x, y = _native(a, backend), _native(v, backend)
    for fn in api(backend, "matmul"):
        check(fn(x, x), any_of_ands(a, a), backend)
        check(fn(x, y), any_of_ands(a, v[:, None])[:, 0], backend)
    for fn in api(backend, "tensordot"):
        check(fn(x, x, axes=1), any_of_ands(a, a), backend)
    for fn in api(backend, "vecdot"):
        check(fn(x, x), np.array([any(r & r) for r in a]), backend)
    for fn in api(backend, "matrix_power"):
        check(fn(x, 3), any_of_ands(any_of_ands(a, a), a), backend)
        check(fn(x, 0), np.eye(3, dtype=bool), backend)


@pytest.mark.parametrize("dtype", ["int8", "uint8", "int16", "uint32", "bool"])
def test_einsum_of_small_integers_and_booleans(backend, dtype):
    """(tensorflow has einsum kernels for int32, int64 and floats only: it raised NotFoundError)"""
    a = np.array([[100, 3], [7, 200]]).astype(dtype)
    if dtype == "bool":
        expected = np.array(
            [[any(a[i, k] and a[k, j] for k in range(2)) for j in range(2)] for i in range(2)]
        )
    else:  # Python ints, wrapped into the dtype as the framework's integers wrap
        wide = a.astype(object)
        expected = np.array((wide @ wide).tolist(), dtype=object)
        expected = np.array(
            [[int(v) % 2 ** (8 * a.itemsize) for v in row] for row in expected], np.uint64
        )
        expected = expected.astype(dtype)
    x = _native(a, backend)
    for fn in (ivy.einsum, getattr(ivy, backend).einsum):
        check(fn("ij,jk->ik", x, x), expected, backend)
