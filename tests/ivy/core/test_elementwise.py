"""Tests of the core group ``elementwise`` (``ivy/core/elementwise.py``), on every backend.

Elementwise functions against numpy float64 references, on every backend.

Each function is tried on hypothesis arrays (0-d and empty included) mixed with edge values
(±0, ±inf, nan, halves), on a fixed grid of edge values, and through both ``ivy.<name>`` (the
framework inferred from the inputs) and the backend namespace ``xp.<name>``.

The Array API's elementwise functions added to the core (bitwise, complex parts, copysign,
hypot, logaddexp, signbit, and 2024.12's nextafter and reciprocal), on every backend.

References are numpy in float64 (rounded to the dtype under test) for floating functions, Python
integers for bitwise ones. Hypothesis mixes edge values (±0, ±inf, NaN of both signs) into arrays
of the shapes that matter (0-d, empty), and a fixed grid tries every pair of edge values.

Ivy's own functions beyond the Array API, on every backend, against references written here
with Python loops or plain numpy float64: gather_flat, scatter_flat, indices_where, cumsum,
cumprod, einsum, constant_pad, zero_pad, linear_resample, interp, vector_to_skew_symmetric_matrix,
cosine_similarity, clip_vector_norm, clip_by_global_norm, nan_to_num, isclose, allclose and
to_framework.
"""

from __future__ import annotations

import itertools
import math
import operator

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ivy
from tests.conftest import require
from tests.helpers import (
    HYPOTHESIS,
    api,
    cast,
    check,
    check_gradients,
    dtype_name,
    native,
    numpy_of,
    reference,
)
from tests.ivy.strategies import (
    FLOAT_DTYPES,
    INT_DTYPES,
    SPECIALS,
    arrays,
    quarters,
    reals,
)

# Few shapes: jax compiles each function once per shape and dtype. 0-d and empty arrays are among
# them, and the edge-value arrays have 16 elements.
SHAPES = st.sampled_from([(), (0,), (2, 3), (16,)])


BROADCAST_PAIRS = st.sampled_from(
    [((), ()), ((2, 3), ()), ((), (2, 3)), ((2, 3), (2, 3)), ((2, 1), (1, 3)), ((0,), (1,))]
)


# name, numpy reference, interesting domain [lo, hi] (the edge values are always mixed in).
# Domains stay where float32 libm implementations are accurate (no huge trig arguments, no
# arguments within a hair of the float32 overflow threshold); inputs outside the mathematical
# domain (log of a negative, acos(2)) are included: the result is nan.
UNARY = [
    ("abs", np.abs, (-1e3, 1e3)),
    ("acos", np.arccos, (-1.5, 1.5)),
    ("acosh", np.arccosh, (0.5, 1e3)),
    ("asin", np.arcsin, (-1.5, 1.5)),
    ("asinh", np.arcsinh, (-1e3, 1e3)),
    ("atan", np.arctan, (-1e3, 1e3)),
    ("atanh", np.arctanh, (-1.5, 1.5)),
    ("ceil", np.ceil, (-1e3, 1e3)),
    ("cos", np.cos, (-100, 100)),
    ("cosh", np.cosh, (-80, 80)),
    ("exp", np.exp, (-80, 80)),
    ("expm1", np.expm1, (-80, 80)),
    ("floor", np.floor, (-1e3, 1e3)),
    ("isfinite", np.isfinite, (-1e3, 1e3)),
    ("isinf", np.isinf, (-1e3, 1e3)),
    ("isnan", np.isnan, (-1e3, 1e3)),
    ("log", np.log, (-1, 1e3)),
    ("log10", np.log10, (-1, 1e3)),
    ("log1p", np.log1p, (-2, 1e3)),
    ("log2", np.log2, (-1, 1e3)),
    ("negative", np.negative, (-1e3, 1e3)),
    ("positive", np.positive, (-1e3, 1e3)),
    ("round", np.round, (-1e3, 1e3)),  # numpy rounds halves to even, as the contract says
    ("sign", np.sign, (-1e3, 1e3)),
    ("sin", np.sin, (-100, 100)),
    ("sinh", np.sinh, (-80, 80)),
    ("sqrt", np.sqrt, (-1, 1e3)),
    ("square", np.square, (-1e3, 1e3)),
    ("tan", np.tan, (-10, 10)),
    ("tanh", np.tanh, (-1e3, 1e3)),
    ("trunc", np.trunc, (-1e3, 1e3)),
]


UNARY_REFERENCE = {name: ref for name, ref, _ in UNARY}


# The Array API leaves the sign of sign(±0) open; every other zero result must keep its sign
# (sin(-0) = -0, ceil(-0.5) = -0, abs(-0) = +0, ...).
UNSIGNED_ZERO = {"sign"}


# Integer inputs keep their dtype (rounding functions return them unchanged).
INT_UNARY = ["abs", "ceil", "floor", "negative", "positive", "round", "sign", "square", "trunc"]


def _unary_expected(name, a):
    return cast(reference(UNARY_REFERENCE[name], a.astype(np.float64)), _out_dtype(name, a))


def _out_dtype(name, a):
    return "bool" if name in ("isfinite", "isinf", "isnan") else a.dtype.name


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
@pytest.mark.parametrize("name, ref, domain", UNARY, ids=[u[0] for u in UNARY])
@HYPOTHESIS
@given(data=st.data())
def test_unary_float(backend, name, ref, domain, dtype, data):
    a = data.draw(arrays(dtype, reals(dtype, *domain), SHAPES), label="x")
    expected = _unary_expected(name, a)
    for fn in api(backend, name):
        check(fn(native(a, backend)), expected, backend, signed_zeros=name not in UNSIGNED_ZERO)


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
@pytest.mark.parametrize("name", [u[0] for u in UNARY])
def test_unary_edge_values(backend, name, dtype):
    a = np.array(SPECIALS + (-1e-3, 3.0, -7.25, 1e3), dtype=dtype)
    expected = _unary_expected(name, a)
    for fn in api(backend, name):
        check(fn(native(a, backend)), expected, backend, signed_zeros=name not in UNSIGNED_ZERO)


@pytest.mark.parametrize("name", INT_UNARY)
@HYPOTHESIS
@given(data=st.data())
def test_unary_integer(backend, name, data):
    a = data.draw(arrays("int64", st.integers(-1000, 1000), SHAPES), label="x")
    expected = UNARY_REFERENCE[name](a)
    for fn in api(backend, name):
        check(fn(native(a, backend)), expected, backend)


@pytest.mark.parametrize("name", INT_UNARY)
def test_unary_int32_stays_int32(backend, name):
    a = np.array([-7, -1, 0, 3, 1000], dtype=np.int32)
    for fn in api(backend, name):
        check(fn(native(a, backend)), UNARY_REFERENCE[name](a), backend)


@HYPOTHESIS
@given(a=arrays("bool", st.booleans(), SHAPES))
def test_logical_not(backend, a):
    for fn in api(backend, "logical_not"):
        check(fn(native(a, backend)), np.logical_not(a), backend)


@pytest.mark.parametrize("name", ["isfinite", "isinf", "isnan"])
def test_classification_of_integers_is_all_finite(backend, name):
    a = np.array([-3, 0, 7], dtype=np.int64)
    expected = np.array([name == "isfinite"] * 3)
    for fn in api(backend, name):
        check(fn(native(a, backend)), expected, backend)


def _wide(dtype):
    return reals(dtype, -1e3, 1e3)


def _ties(dtype):
    return quarters(-2, 2) | st.sampled_from(SPECIALS)


def _exact(dtype):  # finite multiples of 1/4: floor division and remainder are exact
    return quarters(-10, 10)


def _base(dtype):
    return reals(dtype, -4, 10)


def _exponent(dtype):
    return reals(dtype, -5, 5)


COMPARISONS = ["equal", "greater", "greater_equal", "less", "less_equal", "not_equal"]


# name, numpy reference, strategy of x1, strategy of x2, whether zero results keep their sign
BINARY = [
    ("add", np.add, _wide, _wide, True),
    ("atan2", np.arctan2, _wide, _wide, True),
    ("divide", np.divide, _wide, _wide, True),
    ("floor_divide", np.floor_divide, _exact, _exact, False),
    ("maximum", np.maximum, _ties, _ties, False),
    ("minimum", np.minimum, _ties, _ties, False),
    ("multiply", np.multiply, _wide, _wide, True),
    ("pow", np.power, _base, _exponent, False),
    ("remainder", np.remainder, _exact, _exact, False),
    ("subtract", np.subtract, _wide, _wide, True),
] + [(name, getattr(np, name), _ties, _ties, False) for name in COMPARISONS]


BINARY_REFERENCE = {b[0]: b[1] for b in BINARY}


SIGNED_ZERO = {b[0] for b in BINARY if b[4]}


# Integer inputs: name -> (strategy of x1, strategy of x2); results keep the integer dtype.
INT_BINARY = {
    **{
        name: (st.integers(-20, 20), st.integers(-20, 20))
        for name in ["add", "maximum", "minimum", "multiply", "subtract", *COMPARISONS]
    },
    "floor_divide": (st.integers(-20, 20), st.integers(-20, 20).filter(bool)),
    "remainder": (st.integers(-20, 20), st.integers(-20, 20).filter(bool)),
    "pow": (st.integers(-5, 5), st.integers(0, 5)),
}


LOGICAL = {
    "logical_and": np.logical_and,
    "logical_or": np.logical_or,
    "logical_xor": np.logical_xor,
}


def _binary_expected(name, a, b, dtype):
    out = reference(BINARY_REFERENCE[name], np.asarray(a, np.float64), np.asarray(b, np.float64))
    return cast(out, "bool" if name in COMPARISONS else dtype)


def _broadcastable_pair(data, dtype, elements1, elements2):
    shape1, shape2 = data.draw(BROADCAST_PAIRS, label="shapes")
    a = data.draw(arrays(dtype, elements1, shape1), label="x1")
    b = data.draw(arrays(dtype, elements2, shape2), label="x2")
    return a, b


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
@pytest.mark.parametrize(
    "name, ref, elements1, elements2, signed", BINARY, ids=[b[0] for b in BINARY]
)
@HYPOTHESIS
@given(data=st.data())
def test_binary_float(backend, name, ref, elements1, elements2, signed, dtype, data):
    a, b = _broadcastable_pair(data, dtype, elements1(dtype), elements2(dtype))
    expected = _binary_expected(name, a, b, dtype)
    for fn in api(backend, name):
        check(fn(native(a, backend), native(b, backend)), expected, backend, signed_zeros=signed)


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
@pytest.mark.parametrize("name", [b[0] for b in BINARY])
def test_binary_edge_values(backend, name, dtype):
    """Every pair of edge values (finite ones for floor_divide and remainder, whose infinite
    cases the Array API and numpy do not agree on)."""
    values = SPECIALS + (3.0, -4.0)
    if name in ("floor_divide", "remainder"):
        values = [v for v in values if np.isfinite(v)]
    pairs = np.array(list(itertools.product(values, repeat=2)), dtype=dtype)
    a, b = pairs[:, 0], pairs[:, 1]
    expected = _binary_expected(name, a, b, dtype)
    for fn in api(backend, name):
        check(
            fn(native(a, backend), native(b, backend)),
            expected,
            backend,
            signed_zeros=name in SIGNED_ZERO,
        )


@pytest.mark.parametrize("name", sorted(INT_BINARY))
@HYPOTHESIS
@given(data=st.data())
def test_binary_integer(backend, name, data):
    """int64 here; int32 (which must stay int32) in the tests with Python scalars below."""
    a, b = _broadcastable_pair(data, "int64", *INT_BINARY[name])
    expected = BINARY_REFERENCE[name](a, b)
    for fn in api(backend, name):
        check(fn(native(a, backend), native(b, backend)), expected, backend)


@pytest.mark.parametrize("name", sorted(LOGICAL))
@HYPOTHESIS
@given(data=st.data())
def test_logical_binary(backend, name, data):
    a, b = _broadcastable_pair(data, "bool", st.booleans(), st.booleans())
    for fn in api(backend, name):
        check(fn(native(a, backend), native(b, backend)), LOGICAL[name](a, b), backend)


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
@pytest.mark.parametrize("name", [b[0] for b in BINARY])
def test_binary_python_float_on_either_side_keeps_array_dtype(backend, name, dtype):
    a = np.array([[0.5, 1.5], [2.0, 3.25]], dtype=dtype)
    for fn in api(backend, name):
        check(fn(native(a, backend), 2.0), _binary_expected(name, a, 2.0, dtype), backend)
        check(fn(2.0, native(a, backend)), _binary_expected(name, 2.0, a, dtype), backend)


@pytest.mark.parametrize("dtype", INT_DTYPES)
@pytest.mark.parametrize("name", sorted(INT_BINARY))
def test_binary_python_int_on_either_side_keeps_array_dtype(backend, name, dtype):
    a = np.array([1, 2, 3, 4], dtype=dtype)
    ref = BINARY_REFERENCE[name]
    out_dtype = "bool" if name in COMPARISONS else dtype
    for fn in api(backend, name):
        check(fn(native(a, backend), 3), ref(a.astype(np.int64), 3).astype(out_dtype), backend)
        check(fn(3, native(a, backend)), ref(3, a.astype(np.int64)).astype(out_dtype), backend)


@pytest.mark.parametrize("name", ["add", "subtract", "multiply", "divide", "maximum", "pow"])
def test_float32_with_float64_promotes_to_float64(backend, name):
    a = np.array([1.5, 2.25, 3.0], dtype=np.float32)
    b = np.array([0.5, 4.0, 1.0], dtype=np.float64)
    expected = _binary_expected(name, a, b, "float64")
    for fn in api(backend, name):
        check(fn(native(a, backend), native(b, backend)), expected, backend)
        check(
            fn(native(b, backend), native(a, backend)),
            _binary_expected(name, b, a, "float64"),
            backend,
        )


@pytest.mark.parametrize("name", ["add", "subtract", "multiply", "maximum"])
def test_int32_with_int64_promotes_to_int64(backend, name):
    a = np.array([1, -2, 3], dtype=np.int32)
    b = np.array([5, 6, -7], dtype=np.int64)
    expected = BINARY_REFERENCE[name](a.astype(np.int64), b)
    for fn in api(backend, name):
        check(fn(native(a, backend), native(b, backend)), expected, backend)


def test_floor_divide_and_remainder_follow_the_sign_of_the_divisor(backend):
    a = np.array([7.0, -7.0, 7.0, -7.0])
    b = np.array([2.0, 2.0, -2.0, -2.0])
    check(ivy.floor_divide(native(a, backend), native(b, backend)), [3.0, -4.0, -4.0, 3.0], backend)
    check(ivy.remainder(native(a, backend), native(b, backend)), [1.0, 1.0, -1.0, -1.0], backend)


def _clip_reference(a, lo, hi):
    out = np.asarray(a, np.float64)
    if lo is not None:
        out = np.maximum(out, lo)
    if hi is not None:
        out = np.minimum(out, hi)
    return out


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
@HYPOTHESIS
@given(data=st.data())
def test_clip_scalar_bounds(backend, dtype, data):
    a = data.draw(arrays(dtype, reals(dtype, -10, 10), SHAPES), label="x")
    lo = data.draw(st.none() | quarters(-5, 0), label="min")
    hi = data.draw(st.none() | quarters(0, 5), label="max")
    expected = cast(_clip_reference(a, lo, hi), dtype)
    for fn in api(backend, "clip"):
        check(fn(native(a, backend), lo, hi), expected, backend)
        check(fn(native(a, backend), min=lo, max=hi), expected, backend)


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
def test_clip_array_bounds_broadcast(backend, dtype):
    a = np.linspace(-3, 3, 12).reshape(3, 4).astype(dtype)
    lo = np.array([-1.0, -2.0, 0.0, -0.5], dtype=dtype)
    hi = np.array([[0.5], [1.0], [2.0]], dtype=dtype)
    expected = cast(_clip_reference(a, lo, hi), dtype)
    for fn in api(backend, "clip"):
        check(fn(native(a, backend), native(lo, backend), native(hi, backend)), expected, backend)
        check(
            fn(native(a, backend), None, native(hi, backend)),
            cast(_clip_reference(a, None, hi), dtype),
            backend,
        )


def test_clip_integers_keep_their_dtype(backend):
    a = np.array([-5, 0, 3, 9], dtype=np.int64)
    for fn in api(backend, "clip"):
        check(fn(native(a, backend), 0, 4), np.array([0, 0, 3, 4]), backend)


def test_clip_propagates_nan_and_handles_infinities(backend):
    a = np.array([np.nan, np.inf, -np.inf, 0.25], dtype=np.float32)
    check(
        ivy.clip(native(a, backend), -1.0, 1.0),
        np.array([np.nan, 1.0, -1.0, 0.25], np.float32),
        backend,
    )


FEW = settings(HYPOTHESIS, max_examples=20)


NEG_NAN = -math.nan  # a NaN with its sign bit set


EDGES = SPECIALS + (NEG_NAN, 3.0, -4.0, 1e-3)


SHAPES_elementwise_api = st.sampled_from([(), (0,), (2, 3), (16,)])


def _floats(dtype, lo=-1e3, hi=1e3):
    return reals(dtype, lo, hi) | st.just(NEG_NAN)


def _pair(data, dtype, elements):
    shape1, shape2 = data.draw(BROADCAST_PAIRS, label="shapes")
    a = data.draw(arrays(dtype, elements, shape1), label="x1")
    b = data.draw(arrays(dtype, elements, shape2), label="x2")
    return a, b


# name, float64 reference, whether exact (values, signed zeros and all)
UNARY_elementwise_api = {
    "reciprocal": (lambda a: 1.0 / a, False),
    "signbit": (np.signbit, True),
    "conj": (np.conj, True),
    "real": (np.real, True),
}


BINARY_elementwise_api = {
    "copysign": (np.copysign, True),
    "hypot": (np.hypot, False),
    "logaddexp": (np.logaddexp, False),
}


def _unary_expected_elementwise_api(name, a):
    ref, exact = UNARY_elementwise_api[name]
    if exact:  # computed in the input's own dtype: these only move bits
        return reference(ref, a)
    return cast(reference(ref, a.astype(np.float64)), a.dtype.name)


def _binary_expected_elementwise_api(name, a, b, dtype):
    ref, exact = BINARY_elementwise_api[name]
    if exact:
        return reference(ref, np.asarray(a, dtype), np.asarray(b, dtype))
    return cast(reference(ref, np.asarray(a, np.float64), np.asarray(b, np.float64)), dtype)


@pytest.mark.parametrize("name", sorted(UNARY_elementwise_api))
@FEW
@given(data=st.data())
def test_unary_float_elementwise_api(backend, name, data):
    dtype = data.draw(st.sampled_from(FLOAT_DTYPES), label="dtype")
    a = data.draw(arrays(dtype, _floats(dtype), SHAPES_elementwise_api), label="x")
    expected = _unary_expected_elementwise_api(name, a)
    for fn in api(backend, name):
        check(fn(native(a, backend)), expected, backend, signed_zeros=True)


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
@pytest.mark.parametrize("name", sorted(UNARY_elementwise_api))
def test_unary_edge_values_elementwise_api(backend, name, dtype):
    a = np.array(EDGES, dtype=dtype)
    expected = _unary_expected_elementwise_api(name, a)
    for fn in api(backend, name):
        check(fn(native(a, backend)), expected, backend, signed_zeros=True)


def test_signbit_reads_the_sign_of_zeros_and_nans(backend):
    a = np.array([0.0, -0.0, math.nan, NEG_NAN, -math.inf, 1e-30, -1e-30], np.float32)
    expected = np.array([False, True, False, True, True, False, True])
    for fn in api(backend, "signbit"):
        check(fn(native(a, backend)), expected, backend)


@pytest.mark.parametrize("name", sorted(BINARY_elementwise_api))
@FEW
@given(data=st.data())
def test_binary_float_elementwise_api(backend, name, data):
    dtype = data.draw(st.sampled_from(FLOAT_DTYPES), label="dtype")
    a, b = _pair(data, dtype, _floats(dtype))
    expected = _binary_expected_elementwise_api(name, a, b, dtype)
    for fn in api(backend, name):
        check(fn(native(a, backend), native(b, backend)), expected, backend, signed_zeros=True)


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
@pytest.mark.parametrize("name", sorted(BINARY_elementwise_api) + ["nextafter"])
def test_binary_edge_values_elementwise_api(backend, name, dtype):
    """Every pair of edge values: hypot(inf, nan) = inf, logaddexp(inf, inf) = inf, ..."""
    pairs = np.array(list(itertools.product(EDGES, repeat=2)), dtype=dtype)
    a, b = pairs[:, 0], pairs[:, 1]
    if name == "nextafter":
        expected = _nextafter_reference(a, b, dtype)
    else:
        expected = _binary_expected_elementwise_api(name, a, b, dtype)
    for fn in api(backend, name):
        check(fn(native(a, backend), native(b, backend)), expected, backend, signed_zeros=True)


def _nextafter_reference(a, b, dtype):
    """float64: Python's math.nextafter; float32: one step of the integer that holds the bits."""
    a, b = np.broadcast_arrays(np.asarray(a, dtype), np.asarray(b, dtype))
    if dtype == "float64":
        out = [math.nextafter(float(x), float(y)) for x, y in zip(a.ravel(), b.ravel())]
        return np.array(out, dtype).reshape(a.shape)
    out = []
    for x, y in zip(a.ravel(), b.ravel()):
        if math.isnan(x) or math.isnan(y) or x == y:
            out.append(y if not math.isnan(x) else x)
            continue
        if x == 0:
            bits = 1 | (0x80000000 if y < 0 else 0)
        else:
            bits = int(np.array(x, np.float32).view(np.uint32))
            bits += 1 if (y > x) == (x > 0) else -1
        out.append(np.array(bits, np.uint32).view(np.float32))
    return np.array(out, dtype).reshape(a.shape)


@FEW
@given(data=st.data())
def test_nextafter(backend, data):
    dtype = data.draw(st.sampled_from(FLOAT_DTYPES), label="dtype")
    a, b = _pair(data, dtype, _floats(dtype))
    expected = _nextafter_reference(a, b, dtype)
    for fn in api(backend, "nextafter"):
        out = fn(native(a, backend), native(b, backend))
        check(out, expected, backend, signed_zeros=True, rtol=0, atol=0)


@pytest.mark.parametrize("name", sorted(BINARY_elementwise_api) + ["nextafter"])
def test_binary_python_scalars_keep_the_array_dtype(backend, name):
    a = np.array([[0.5, -1.5], [2.0, 3.25]], dtype=np.float32)
    ref = {**{k: v[0] for k, v in BINARY_elementwise_api.items()}, "nextafter": np.nextafter}[name]
    for fn in api(backend, name):
        check(fn(native(a, backend), -2.0), ref(a, np.float32(-2.0)), backend)
        check(fn(-2.0, native(a, backend)), ref(np.float32(-2.0), a), backend)


@pytest.mark.parametrize("name", sorted(BINARY_elementwise_api) + ["nextafter"])
def test_float32_with_float64_gives_float64(backend, name):
    a = np.array([1.5, -2.25, 3.0], dtype=np.float32)
    b = np.array([0.5, 4.0, -1.0], dtype=np.float64)
    ref = {**{k: v[0] for k, v in BINARY_elementwise_api.items()}, "nextafter": np.nextafter}[name]
    for fn in api(backend, name):
        check(fn(native(a, backend), native(b, backend)), ref(a.astype(np.float64), b), backend)


@pytest.mark.parametrize("name", ["copysign", "hypot", "logaddexp", "nextafter", "signbit"])
def test_float16(backend, name):
    """float16 too: tensorflow's nextafter has no float16 kernel, ivy steps the bits itself."""
    require(backend, "float16")
    a = np.array([0.0, -0.0, 1.0, -2.5, 65504.0, math.inf, math.nan], np.float16)
    b = np.array([-1.0, 1.0, 2.0, -3.0, math.inf, 0.0, 1.0], np.float16)
    if name == "signbit":
        expected, args = np.signbit(a), (a,)
    elif name in ("copysign", "nextafter"):
        expected, args = getattr(np, name)(a, b), (a, b)
    else:
        expected, args = (
            cast(reference(getattr(np, name), a.astype(np.float64), b), "float16"),
            (a, b),
        )
    for fn in api(backend, name):
        check(fn(*(native(v, backend) for v in args)), expected, backend, signed_zeros=True)


@pytest.mark.parametrize("name", ["conj", "real", "imag"])
@FEW
@given(data=st.data())
def test_complex_parts(backend, name, data):
    dtype = data.draw(st.sampled_from(["complex64", "complex128"]), label="dtype")
    part = "float32" if dtype == "complex64" else "float64"
    shape = data.draw(SHAPES_elementwise_api, label="shape")
    re = data.draw(arrays(part, reals(part, -1e3, 1e3), st.just(shape)), label="real")
    im = data.draw(arrays(part, reals(part, -1e3, 1e3), st.just(shape)), label="imag")
    z = np.empty(shape, dtype)
    z.real, z.imag = re, im  # exactly these parts: -0.0, inf and nan included
    conj = np.empty(shape, dtype)
    conj.real, conj.imag = re, -im
    expected = {"conj": conj, "real": re, "imag": im}[name]
    for fn in api(backend, name):
        out = fn(native(z, backend))
        check(out, expected, backend, signed_zeros=name != "conj")
        if name == "conj":  # the sign of an imaginary zero flips too
            got = np.asarray(ivy.to_numpy(out)).imag
            numbers = ~np.isnan(im)
            np.testing.assert_array_equal(np.signbit(got[numbers]), np.signbit(-im[numbers]))


INT_DTYPES = ["int8", "int16", "int32", "int64", "uint8"]


BITWISE = {
    "bitwise_and": lambda a, b: a & b,
    "bitwise_or": lambda a, b: a | b,
    "bitwise_xor": lambda a, b: a ^ b,
    "bitwise_left_shift": lambda a, b: a << b,
    "bitwise_right_shift": lambda a, b: a >> b,  # Python's >> is arithmetic, as the standard
}


def _wrap(value: int, dtype: str) -> int:
    """``value`` reduced to ``dtype`` by two's complement, as fixed-width integers wrap."""
    info = np.iinfo(dtype)
    value %= 1 << info.bits
    return value - (1 << info.bits) if value > info.max else value


def _python_reference(op, a, b, dtype):
    a, b = np.broadcast_arrays(a, b)
    out = [_wrap(op(int(x), int(y)), dtype) for x, y in zip(a.ravel(), b.ravel())]
    return np.array(out, dtype=dtype).reshape(a.shape)


@pytest.mark.parametrize("name", sorted(BITWISE))
@FEW
@given(data=st.data())
def test_bitwise_integers(backend, name, data):
    dtype = data.draw(st.sampled_from(INT_DTYPES), label="dtype")
    info = np.iinfo(dtype)
    shape1, shape2 = data.draw(BROADCAST_PAIRS, label="shapes")
    a = data.draw(arrays(dtype, st.integers(int(info.min), int(info.max)), shape1), label="x1")
    if "shift" in name:  # shifts by 0 to bits - 1 (wider shifts are left undefined)
        b = data.draw(arrays(dtype, st.integers(0, info.bits - 1), shape2), label="x2")
    else:
        b = data.draw(arrays(dtype, st.integers(int(info.min), int(info.max)), shape2), label="x2")
    expected = _python_reference(BITWISE[name], a, b, dtype)
    for fn in api(backend, name):
        check(fn(native(a, backend), native(b, backend)), expected, backend)


@FEW
@given(data=st.data())
def test_bitwise_invert_integers(backend, data):
    dtype = data.draw(st.sampled_from(INT_DTYPES), label="dtype")
    info = np.iinfo(dtype)
    a = data.draw(
        arrays(dtype, st.integers(int(info.min), int(info.max)), SHAPES_elementwise_api), label="x"
    )
    expected = np.array([_wrap(~int(v), dtype) for v in a.ravel()], dtype).reshape(a.shape)
    for fn in api(backend, "bitwise_invert"):
        check(fn(native(a, backend)), expected, backend)


@pytest.mark.parametrize("name", ["bitwise_and", "bitwise_or", "bitwise_xor", "bitwise_invert"])
def test_bitwise_of_bools_is_logical(backend, name):
    a = np.array([True, True, False, False])
    b = np.array([True, False, True, False])
    logical = {
        "bitwise_and": a & b,
        "bitwise_or": a | b,
        "bitwise_xor": a ^ b,
        "bitwise_invert": ~a,
    }[name]
    args = (a,) if name == "bitwise_invert" else (a, b)
    for fn in api(backend, name):
        check(fn(*(native(v, backend) for v in args)), logical, backend)


@pytest.mark.parametrize("name", sorted(BITWISE))
def test_bitwise_promotion_and_python_ints(backend, name):
    """int8 with int64 gives int64, uint8 with int8 gives int16; a Python int keeps the array's
    dtype, on either side."""
    a = np.array([1, -7, 100], np.int8)
    b = np.array([3, 1, 2], np.int64)
    u = np.array([3, 1, 200], np.uint8)
    s = np.array([1, 2, 0], np.int8)  # nonnegative: shift amounts
    op = BITWISE[name]
    for fn in api(backend, name):
        x1, x2 = native(a, backend), native(b, backend)
        check(fn(x1, x2), _python_reference(op, a, b, "int64"), backend)
        check(
            fn(native(u, backend), native(s, backend)),
            _python_reference(op, u, s, "int16"),
            backend,
        )
        check(fn(x1, 2), _python_reference(op, a, 2, "int8"), backend)
        check(
            fn(5, native(s.astype(np.uint8), backend)),
            _python_reference(op, 5, s, "uint8"),
            backend,
        )


NAN_TO_NUM_ARGS = [{}, {"nan": -1.0, "posinf": 9.0, "neginf": -9.0}, {"posinf": 1e300}]


@pytest.mark.filterwarnings("ignore:overflow encountered in cast:RuntimeWarning")  # numpy's own
@pytest.mark.parametrize("dtype", ["float32", "float64"])
@pytest.mark.parametrize("kwargs", NAN_TO_NUM_ARGS, ids=str)
def test_nan_to_num(backend, dtype, kwargs):
    a = np.array([[np.nan, np.inf, -np.inf], [1.5, -0.0, -2.0]], dtype)
    expected = reference(np.nan_to_num, a, **kwargs)  # in dtype: its largest finite values
    for fn in api(backend, "nan_to_num"):
        check(fn(native(a, backend), **kwargs), expected, backend, signed_zeros=True)
        check(fn(native(a[0, 0], backend), **kwargs), expected[0, 0], backend)  # 0-d


@pytest.mark.parametrize("dtype", ["int64", "uint8", "bool", "complex64", "complex128"])
def test_nan_to_num_of_integers_and_complex_numbers(backend, dtype):
    if dtype.startswith("complex"):
        a = np.array([complex(np.nan, np.inf), complex(-np.inf, 1.0), 2 - 1j], dtype)
    else:
        a = np.array([1, 0, 1], dtype)
    for fn in api(backend, "nan_to_num"):
        check(fn(native(a, backend), nan=4.0), np.nan_to_num(a, nan=4.0), backend)


def test_nan_to_num_gradients(diff_backend):
    def fn(x):
        return ivy.nan_to_num(x) * x

    check_gradients(diff_backend, fn, [np.random.default_rng(16).standard_normal((2, 3))])


# ----------------------------------------------------------------------------------------------
# Zeros given as Python or numpy scalars keep their sign
# ----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("met_first", [0.0, -0.0], ids=["+0 met first", "-0 met first"])
def test_scalar_zeros_keep_their_sign(backend, met_first):
    """Whichever zero the framework made first: tensorflow caches the tensors it makes of Python
    scalars by value, and -0.0 == 0.0, so ``x * -0.0`` once computed ``x * 0.0``."""
    zero = -met_first  # the other zero
    a = np.array([1.0, 2.0], np.float32)
    neg = -a
    for fn in api(backend, "multiply") + api(backend, "add") + api(backend, "maximum"):
        fn(ivy.asarray(a, f=backend), met_first)  # the framework meets ``met_first`` first
    ivy.asarray(np.float64(met_first), f=backend)
    ivy.asarray(np.complex128(complex(met_first, met_first)), f=backend)
    x, m = ivy.asarray(a, f=backend), ivy.asarray(neg, f=backend)
    for multiply, add, maximum, where in zip(
        api(backend, "multiply"),
        api(backend, "add"),
        api(backend, "maximum"),
        api(backend, "where"),
    ):
        product = multiply(x, zero)
        check(product, a * zero, backend, signed_zeros=True)
        check(add(zero, product), zero + a * zero, backend, signed_zeros=True)
        check(maximum(m, zero), np.maximum(neg, np.float32(zero)), backend, signed_zeros=True)
        yes = ivy.asarray(np.array([True, True]), f=backend)
        check(where(yes, zero, x), np.where(True, np.float32(zero), a), backend, signed_zeros=True)
    check(ivy.asarray(np.float64(zero), f=backend), np.float64(zero), backend, signed_zeros=True)
    c = numpy_of(ivy.asarray(np.complex128(complex(zero, zero)), f=backend))
    assert c.dtype == np.complex128
    assert np.signbit(c.real) == np.signbit(c.imag) == np.signbit(zero)


# ----------------------------------------------------------------------------------------------
# Python ints beyond the integer array's dtype (ivy/backends/_int_scalars.py), as numpy 2 answers
# ----------------------------------------------------------------------------------------------

_BEYOND = [("int8", 300), ("int8", -129), ("uint8", -1), ("int16", 40000), ("uint32", -5)]
_RAISING = (
    "add subtract multiply floor_divide remainder pow maximum minimum bitwise_and bitwise_or "
    "bitwise_xor bitwise_left_shift bitwise_right_shift"
).split()
_COMPARING = {  # (written from Python's operators, not from ivy's table)
    name: getattr(operator, op)
    for name, op in zip(
        ["equal", "not_equal", "less", "less_equal", "greater", "greater_equal"],
        ["eq", "ne", "lt", "le", "gt", "ge"],
    )
}
_REALS = {
    "divide": np.divide,
    "atan2": np.arctan2,
    "copysign": np.copysign,
    "hypot": np.hypot,
    "logaddexp": np.logaddexp,
}


@pytest.mark.parametrize("dtype, value", _BEYOND)
@pytest.mark.parametrize("left", [False, True], ids=["array op int", "int op array"])
def test_python_ints_beyond_the_dtype(backend, dtype, value, left):
    """Arithmetic raises OverflowError (torch, jax and tensorflow would wrap the int around:
    int8 + 300 added 44); comparisons answer exactly; functions of real numbers take the int as
    a float."""
    a = np.array([1, 2, 5], dtype=dtype)
    x = ivy.asarray(a, f=backend)

    def call(fn):
        return fn(value, x) if left else fn(x, value)

    for name in _RAISING:
        for fn in api(backend, name):
            with pytest.raises(OverflowError):
                call(fn)
    for name, op in _COMPARING.items():
        expected = np.array([op(value, int(v)) if left else op(int(v), value) for v in a])
        for fn in api(backend, name):
            check(call(fn), expected, backend)
    for name, ref in _REALS.items():
        wide = a.astype(np.float64)
        expected = (ref(float(value), wide) if left else ref(wide, float(value))).astype("float32")
        for fn in api(backend, name):
            check(call(fn), expected, backend, rtol=1e-6)


@pytest.mark.parametrize("dtype, value", [("int8", 127), ("int8", -128), ("uint8", 255)])
def test_python_ints_at_the_dtypes_bounds_compute(backend, dtype, value):
    a = np.array([0, 1], dtype=dtype)
    for fn in api(backend, "add"):
        check(
            fn(ivy.asarray(a, f=backend), value),
            (a.astype(np.int64) + value).astype(dtype),
            backend,
        )
    for fn in api(backend, "less"):
        check(fn(value, ivy.asarray(a, f=backend)), value < a.astype(np.int64), backend)


@pytest.mark.parametrize("name", ["add", "multiply", "maximum", "divide"])
def test_a_python_float_on_the_left_promotes_as_on_the_right(backend, name):
    """``ivy.add(2.5, int8_array)`` is float32 as ``ivy.add(int8_array, 2.5)`` (on numpy the
    left-hand float went to numpy's own function, which gives float64). array_api_strict
    refuses a float next to an integer array on either side."""
    a = np.array([1, 2], dtype="int8")
    fn = getattr(ivy, name)
    expected = getattr(np, name)(np.float32(2.5), a.astype(np.float32))
    try:
        right = fn(ivy.asarray(a, f=backend), 2.5)
    except TypeError:
        with pytest.raises(TypeError):
            fn(2.5, ivy.asarray(a, f=backend))
        return
    assert dtype_name(right) == "float32"
    check(fn(2.5, ivy.asarray(a, f=backend)), expected, backend)
    check(fn(2.5, ivy.asarray(a, f=backend), f=backend), expected, backend)
