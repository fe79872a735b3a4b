"""The Array API's elementwise functions added to the core (bitwise, complex parts, copysign,
hypot, logaddexp, signbit, and 2024.12's nextafter and reciprocal), on every backend.

References are numpy in float64 (rounded to the dtype under test) for floating functions, Python
integers for bitwise ones. Hypothesis mixes edge values (±0, ±inf, NaN of both signs) into arrays
of the shapes that matter (0-d, empty), and a fixed grid tries every pair of edge values.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ivy
from tests.conftest import require
from tests.helpers import HYPOTHESIS, api, cast, check, native, reference
from tests.ivy.strategies import FLOAT_DTYPES, SPECIALS, arrays, reals

pytestmark = pytest.mark.filterwarnings("ignore::RuntimeWarning")  # numpy on edge values

FEW = settings(HYPOTHESIS, max_examples=20)
NEG_NAN = -math.nan  # a NaN with its sign bit set
EDGES = SPECIALS + (NEG_NAN, 3.0, -4.0, 1e-3)
SHAPES = st.sampled_from([(), (0,), (2, 3), (16,)])
BROADCAST_PAIRS = st.sampled_from(
    [((), ()), ((2, 3), ()), ((), (2, 3)), ((2, 3), (2, 3)), ((2, 1), (1, 3)), ((0,), (1,))]
)


def _floats(dtype, lo=-1e3, hi=1e3):
    return reals(dtype, lo, hi) | st.just(NEG_NAN)


def _pair(data, dtype, elements):
    shape1, shape2 = data.draw(BROADCAST_PAIRS, label="shapes")
    a = data.draw(arrays(dtype, elements, shape1), label="x1")
    b = data.draw(arrays(dtype, elements, shape2), label="x2")
    return a, b


# ----------------------------------------------------------------------------------------------
# Floating functions
# ----------------------------------------------------------------------------------------------

# name, float64 reference, whether exact (values, signed zeros and all)
UNARY = {
    "reciprocal": (lambda a: 1.0 / a, False),
    "signbit": (np.signbit, True),
    "conj": (np.conj, True),
    "real": (np.real, True),
}
BINARY = {
    "copysign": (np.copysign, True),
    "hypot": (np.hypot, False),
    "logaddexp": (np.logaddexp, False),
}


def _unary_expected(name, a):
    ref, exact = UNARY[name]
    if exact:  # computed in the input's own dtype: these only move bits
        return reference(ref, a)
    return cast(reference(ref, a.astype(np.float64)), a.dtype.name)


def _binary_expected(name, a, b, dtype):
    ref, exact = BINARY[name]
    if exact:
        return reference(ref, np.asarray(a, dtype), np.asarray(b, dtype))
    return cast(reference(ref, np.asarray(a, np.float64), np.asarray(b, np.float64)), dtype)


@pytest.mark.parametrize("name", sorted(UNARY))
@FEW
@given(data=st.data())
def test_unary_float(backend, name, data):
    dtype = data.draw(st.sampled_from(FLOAT_DTYPES), label="dtype")
    a = data.draw(arrays(dtype, _floats(dtype), SHAPES), label="x")
    expected = _unary_expected(name, a)
    for fn in api(backend, name):
        check(fn(native(a, backend)), expected, backend, signed_zeros=True)


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
@pytest.mark.parametrize("name", sorted(UNARY))
def test_unary_edge_values(backend, name, dtype):
    a = np.array(EDGES, dtype=dtype)
    expected = _unary_expected(name, a)
    for fn in api(backend, name):
        check(fn(native(a, backend)), expected, backend, signed_zeros=True)


def test_signbit_reads_the_sign_of_zeros_and_nans(backend):
    a = np.array([0.0, -0.0, math.nan, NEG_NAN, -math.inf, 1e-30, -1e-30], np.float32)
    expected = np.array([False, True, False, True, True, False, True])
    for fn in api(backend, "signbit"):
        check(fn(native(a, backend)), expected, backend)


@pytest.mark.parametrize("name", sorted(BINARY))
@FEW
@given(data=st.data())
def test_binary_float(backend, name, data):
    dtype = data.draw(st.sampled_from(FLOAT_DTYPES), label="dtype")
    a, b = _pair(data, dtype, _floats(dtype))
    expected = _binary_expected(name, a, b, dtype)
    for fn in api(backend, name):
        check(fn(native(a, backend), native(b, backend)), expected, backend, signed_zeros=True)


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
@pytest.mark.parametrize("name", sorted(BINARY) + ["nextafter"])
def test_binary_edge_values(backend, name, dtype):
    """Every pair of edge values: hypot(inf, nan) = inf, logaddexp(inf, inf) = inf, ..."""
    pairs = np.array(list(itertools.product(EDGES, repeat=2)), dtype=dtype)
    a, b = pairs[:, 0], pairs[:, 1]
    if name == "nextafter":
        expected = _nextafter_reference(a, b, dtype)
    else:
        expected = _binary_expected(name, a, b, dtype)
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


@pytest.mark.parametrize("name", sorted(BINARY) + ["nextafter"])
def test_binary_python_scalars_keep_the_array_dtype(backend, name):
    a = np.array([[0.5, -1.5], [2.0, 3.25]], dtype=np.float32)
    ref = {**{k: v[0] for k, v in BINARY.items()}, "nextafter": np.nextafter}[name]
    for fn in api(backend, name):
        check(fn(native(a, backend), -2.0), ref(a, np.float32(-2.0)), backend)
        check(fn(-2.0, native(a, backend)), ref(np.float32(-2.0), a), backend)


@pytest.mark.parametrize("name", sorted(BINARY) + ["nextafter"])
def test_float32_with_float64_gives_float64(backend, name):
    a = np.array([1.5, -2.25, 3.0], dtype=np.float32)
    b = np.array([0.5, 4.0, -1.0], dtype=np.float64)
    ref = {**{k: v[0] for k, v in BINARY.items()}, "nextafter": np.nextafter}[name]
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


# ----------------------------------------------------------------------------------------------
# Complex numbers
# ----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", ["conj", "real", "imag"])
@FEW
@given(data=st.data())
def test_complex_parts(backend, name, data):
    dtype = data.draw(st.sampled_from(["complex64", "complex128"]), label="dtype")
    part = "float32" if dtype == "complex64" else "float64"
    shape = data.draw(SHAPES, label="shape")
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


# ----------------------------------------------------------------------------------------------
# Bitwise functions, against Python integers
# ----------------------------------------------------------------------------------------------

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
    a = data.draw(arrays(dtype, st.integers(int(info.min), int(info.max)), SHAPES), label="x")
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
