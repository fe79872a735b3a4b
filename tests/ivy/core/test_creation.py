"""Tests of the core group ``creation`` (``ivy/core/creation.py``), on every backend.

Array creation on every backend: values, shapes, and the default dtypes (float32 for Python
floats and floating results, int64 for Python ints and integer ranges).

meshgrid, tril, triu and from_dlpack on every backend, against numpy references written out
with indexing (values are copied, never computed: results must be exact).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ivy
from tests.conftest import device_for
from tests.helpers import HYPOTHESIS, api, api_f, cast, check, check_meta, native, numpy_of
from tests.ivy.strategies import arrays, reals

# object, expected numpy array (its dtype is the expected default dtype)
FROM_PYTHON = {
    "nested floats": ([[1.5, -2.0], [0.25, 3.0]], np.array([[1.5, -2.0], [0.25, 3.0]], np.float32)),
    "nested ints": ([[1, -2, 3]], np.array([[1, -2, 3]], np.int64)),
    "bools": ([True, False], np.array([True, False])),
    "float scalar": (2.5, np.float32(2.5)),
    "int scalar": (7, np.int64(7)),
    "bool scalar": (True, np.bool_(True)),
    "ints and floats": ([1, 2.5], np.array([1.0, 2.5], np.float32)),
    "tuple": ((0.5, 1.0), np.array([0.5, 1.0], np.float32)),
}


@pytest.mark.parametrize("name", ["asarray", "array"])
@pytest.mark.parametrize("obj, expected", list(FROM_PYTHON.values()), ids=list(FROM_PYTHON))
def test_asarray_from_python_objects_uses_default_dtypes(backend, name, obj, expected):
    for fn in api_f(backend, name):
        check(fn(obj), expected, backend, rtol=0, atol=0)


@pytest.mark.parametrize("name", ["asarray", "array"])
@pytest.mark.parametrize("dtype", ["float64", "float32", "int32", "int64", "bool", "uint8"])
def test_asarray_keeps_the_dtype_of_numpy_arrays(backend, name, dtype):
    a = np.array([[0, 1, 2], [3, 4, 5]]).astype(dtype)
    for fn in api_f(backend, name):
        check(fn(a), a, backend)
        check(fn(a[0, 1]), a[0, 1], backend)  # a numpy scalar keeps its dtype too


@pytest.mark.parametrize("dtype", ["float64", "float32", "int32"])
def test_asarray_of_a_native_array_keeps_it(backend, dtype):
    a = np.array([1.0, 2.0, 3.0], dtype=dtype)
    for fn in api(backend, "asarray"):
        check(fn(native(a, backend)), a, backend)


@pytest.mark.parametrize("dtype", ["float64", "float32", "int32", "int64", "bool"])
def test_asarray_with_dtype(backend, dtype):
    values = [[0.0, 1.0], [2.0, 3.0]]
    expected = np.array(values).astype(dtype)
    xp = getattr(ivy, backend)
    for fn in api_f(backend, "asarray"):
        check(fn(values, dtype=dtype), expected, backend)
        check(fn(values, dtype=getattr(xp, dtype)), expected, backend)
        check(fn(np.array(values, np.float64), dtype=dtype), expected, backend)


def test_array_is_the_same_function_as_asarray(backend):
    assert ivy.array is ivy.asarray
    xp = getattr(ivy, backend)
    assert xp.array is xp.asarray


SHAPES = [3, (2, 3), (), (0, 2), [4, 1]]


FILLED = {"zeros": 0, "ones": 1}


@pytest.mark.parametrize("name", ["zeros", "ones", "empty"])
@pytest.mark.parametrize("shape", SHAPES, ids=str)
def test_filled_arrays_are_float32_by_default(backend, name, shape):
    full_shape = (shape,) if isinstance(shape, int) else tuple(shape)
    for fn in api_f(backend, name):
        out = fn(shape)
        check_meta(out, backend, "float32", full_shape)
        if name in FILLED:
            check(out, np.full(full_shape, FILLED[name], np.float32), backend)


@pytest.mark.parametrize("name", ["zeros", "ones", "empty"])
@pytest.mark.parametrize("dtype", ["float64", "int32", "int64", "bool"])
def test_filled_arrays_with_dtype(backend, name, dtype):
    xp = getattr(ivy, backend)
    for fn in api_f(backend, name):
        for dt in (dtype, getattr(xp, dtype)):
            out = fn((2, 2), dtype=dt)
            check_meta(out, backend, dtype, (2, 2))
            if name in FILLED:
                check(out, np.full((2, 2), FILLED[name], dtype), backend)
        check_meta(fn(shape=(1, 3), dtype=dtype, device="cpu"), backend, dtype, (1, 3))


# fill value, default dtype that the value implies
FULL_DEFAULTS = {
    "bool": (True, "bool"),
    "int": (7, "int64"),
    "negative int": (-3, "int64"),
    "float": (2.5, "float32"),
    "complex": (1 + 2j, "complex64"),
    "inf": (float("inf"), "float32"),
}


@pytest.mark.parametrize("value, dtype", list(FULL_DEFAULTS.values()), ids=list(FULL_DEFAULTS))
def test_full_dtype_follows_the_value(backend, value, dtype):
    for fn in api_f(backend, "full"):
        check(fn((2, 3), value), np.full((2, 3), value, dtype), backend)
        check(fn(4, value), np.full(4, value, dtype), backend)


@pytest.mark.parametrize("dtype", ["float64", "float32", "int32"])
def test_full_with_dtype(backend, dtype):
    for fn in api_f(backend, "full"):
        check(fn((3,), 5, dtype=dtype), np.full(3, 5, dtype), backend)
        check(fn(shape=(1, 2), fill_value=-1.0, dtype=dtype), np.full((1, 2), -1, dtype), backend)


# arguments, keyword arguments, default dtype
ARANGE = [
    ((5,), {}, "int64"),
    ((2, 7), {}, "int64"),
    ((1, 10, 3), {}, "int64"),
    ((10, 0, -2), {}, "int64"),
    ((3, 3), {}, "int64"),  # empty
    ((0.5, 3.0, 0.5), {}, "float32"),
    ((5.0,), {}, "float32"),
    ((0, 1, 0.25), {}, "float32"),  # a float step makes it float
    ((-1.5, 2), {}, "float32"),
    ((4,), {"dtype": "float64"}, "float64"),
    ((0, 6, 2), {"dtype": "int32"}, "int32"),
    ((1,), {"stop": 4, "step": 1}, "int64"),
]


@pytest.mark.parametrize("args, kwargs, dtype", ARANGE, ids=[f"{a}-{k}" for a, k, _ in ARANGE])
def test_arange(backend, args, kwargs, dtype):
    np_args = args + tuple(kwargs[k] for k in ("stop", "step") if k in kwargs)
    expected = cast(np.arange(*(float(v) for v in np_args)), dtype)
    for fn in api_f(backend, "arange"):
        check(fn(*args, **kwargs), expected, backend)


LINSPACE = [
    ((0.0, 1.0, 5), {}),
    ((-2.5, 7.5, 9), {}),
    ((1, 3, 4), {}),  # int bounds: still float32
    ((0.0, 1.0, 4), {"endpoint": False}),
    ((2.0, 3.0, 1), {}),
    ((5.0, -5.0, 6), {"dtype": "float64"}),
    ((0.0, 1.0, 0), {}),
    ((0j, 2 + 4j, 5), {}),  # complex bounds (the Array API allows them): complex64
    ((1.0, -1 + 1j, 4), {"endpoint": False, "dtype": "complex128"}),
]


@pytest.mark.parametrize("args, kwargs", LINSPACE, ids=[f"{a}-{k}" for a, k in LINSPACE])
def test_linspace(backend, args, kwargs):
    is_complex = any(isinstance(v, complex) for v in args[:2])
    dtype = kwargs.get("dtype", "complex64" if is_complex else "float32")
    np_kwargs = {k: v for k, v in kwargs.items() if k != "dtype"}
    expected = cast(np.linspace(*args, **np_kwargs), dtype)
    for fn in api_f(backend, "linspace"):
        check(fn(*args, **kwargs), expected, backend)
    check(api_f(backend, "linspace")[0](args[0], args[1], num=args[2], **kwargs), expected, backend)


def test_linspace_with_complex_bounds_and_a_real_dtype_raises(backend):
    with pytest.raises(ivy.errors.DtypeError, match="complex dtype"):
        ivy.linspace(0j, 1 + 1j, 3, dtype="float32", f=backend)


LOGSPACE = [
    ((0.0, 3.0, 4), {}),
    ((-2.0, 2.5, 10), {}),
    ((1, 3, 3), {"base": 2.0}),
    ((0.0, 1.0, 4), {"endpoint": False, "base": 3.0}),
    ((5.0, -5.0, 6), {"dtype": "float64"}),
    ((0.0, 3.0, 4), {"dtype": "int64"}),  # computed in float64, then truncated as numpy does
    ((2.0, 3.0, 1), {}),
    ((0.0, 1.0, 0), {}),
]


@pytest.mark.parametrize("args, kwargs", LOGSPACE, ids=[f"{a}-{k}" for a, k in LOGSPACE])
def test_logspace(backend, args, kwargs):
    is_complex = any(isinstance(v, complex) for v in args[:2])
    dtype = kwargs.get("dtype", "complex64" if is_complex else "float32")
    np_kwargs = {k: v for k, v in kwargs.items() if k != "dtype"}
    expected = np.logspace(*(float(a) for a in args[:2]), args[2], **np_kwargs).astype(dtype)
    for fn in api_f(backend, "logspace"):
        check(fn(*args, **kwargs), expected, backend)
    check(ivy.logspace(args[0], args[1], num=args[2], f=backend, **kwargs), expected, backend)


def test_logspace_takes_the_global_framework(backend):
    with ivy.set_framework(backend):
        check(ivy.logspace(0.0, 2.0, 3), np.array([1.0, 10.0, 100.0], np.float32), backend)


EYE = [
    ((3,), {}),
    ((2, 4), {}),
    ((4, 2), {"k": 1}),
    ((3,), {"k": -1}),
    ((3, 3), {"k": 5}),
    ((0,), {}),
    ((2, 3), {"dtype": "int64"}),
    ((3,), {"dtype": "bool", "k": 1}),
]


@pytest.mark.parametrize("args, kwargs", EYE, ids=[f"{a}-{k}" for a, k in EYE])
def test_eye(backend, args, kwargs):
    n_rows = args[0]
    n_cols = args[1] if len(args) > 1 else n_rows
    k = kwargs.get("k", 0)
    expected = np.array(
        [[1 if j - i == k else 0 for j in range(n_cols)] for i in range(n_rows)], dtype=np.float64
    ).reshape(n_rows, n_cols)
    expected = expected.astype(kwargs.get("dtype", "float32"))
    for fn in api_f(backend, "eye"):
        check(fn(*args, **kwargs), expected, backend)


@pytest.mark.parametrize("name", ["zeros_like", "ones_like", "empty_like", "full_like"])
@pytest.mark.parametrize("dtype", ["float64", "float32", "int32", "bool"])
@pytest.mark.parametrize("shape", [(2, 3), (), (0, 4)], ids=str)
def test_like_functions_keep_shape_and_dtype(backend, name, dtype, shape):
    a = np.ones(shape, dtype=dtype)
    value = {"zeros_like": 0, "ones_like": 1, "empty_like": None, "full_like": 1}[name]
    args = (1,) if name == "full_like" else ()
    for fn in api(backend, name):
        out = fn(native(a, backend), *args)
        check_meta(out, backend, dtype, shape)
        if value is not None:
            check(out, np.full(shape, value, dtype), backend)


@pytest.mark.parametrize("name", ["zeros_like", "ones_like", "empty_like", "full_like"])
@pytest.mark.parametrize("dtype", ["float64", "int64", "float32"])
def test_like_functions_with_dtype(backend, name, dtype):
    a = np.ones((3, 1), dtype=np.float32 if dtype != "float32" else np.int32)
    value = {"zeros_like": 0, "ones_like": 1, "empty_like": None, "full_like": 4}[name]
    args = (4,) if name == "full_like" else ()
    xp = getattr(ivy, backend)
    for fn in api(backend, name):
        for dt in (dtype, getattr(xp, dtype)):
            out = fn(native(a, backend), *args, dtype=dt, device="cpu")
            check_meta(out, backend, dtype, (3, 1))
            if value is not None:
                check(out, np.full((3, 1), value, dtype), backend)


def test_full_like_keeps_the_dtype_of_x_over_the_value(backend):
    a = np.zeros((2, 2), np.float32)
    ints = np.zeros(3, np.int32)
    for fn in api(backend, "full_like"):
        check(fn(native(a, backend), 3), np.full((2, 2), 3, np.float32), backend)
        check(fn(native(a, backend), fill_value=-0.5), np.full((2, 2), -0.5, np.float32), backend)
        check(fn(native(ints, backend), 7), np.full(3, 7, np.int32), backend)


FEW = settings(HYPOTHESIS, max_examples=20)


BACKENDS = ("numpy", "torch", "jax", "tensorflow")


def _exact(out, expected, backend):
    check(out, expected, backend, rtol=0, atol=0, signed_zeros=True)


def _meshgrid_reference(vectors, indexing):
    """out[k][i0, i1, ...] = vectors[k][i_k] ('ij'); 'xy' swaps the first two output axes."""
    shape = tuple(len(v) for v in vectors)
    outs = []
    for k, v in enumerate(vectors):
        out = np.empty(shape, v.dtype)
        for index in np.ndindex(shape):
            out[index] = v[index[k]]
        outs.append(np.swapaxes(out, 0, 1) if indexing == "xy" and len(shape) > 1 else out)
    return outs


@FEW
@given(data=st.data())
def test_meshgrid(backend, data):
    dtype = data.draw(st.sampled_from(["float32", "float64", "int64"]), label="dtype")
    count = data.draw(st.integers(1, 3), label="number of arrays")
    elements = st.integers(-9, 9) if dtype == "int64" else reals(dtype, -10, 10)
    vectors = [
        data.draw(arrays(dtype, elements, st.sampled_from([(0,), (1,), (3,), (4,)])), label="x")
        for _ in range(count)
    ]
    indexing = data.draw(st.sampled_from(["xy", "ij"]), label="indexing")
    expected = _meshgrid_reference(vectors, indexing)
    xs = [native(v, backend) for v in vectors]
    for fn in api(backend, "meshgrid"):
        out = fn(*xs, indexing=indexing)
        assert isinstance(out, list) and len(out) == count
        for o, e in zip(out, expected):
            _exact(o, e, backend)
    for o, e in zip(ivy.meshgrid(*xs), _meshgrid_reference(vectors, "xy")):  # the default
        _exact(o, e, backend)


def test_meshgrid_with_f_and_no_arrays(backend):
    assert ivy.meshgrid(f=backend) == []
    out = ivy.meshgrid(np.arange(3.0), np.arange(2.0), f=backend)
    _exact(out[0], np.array([[0.0, 1.0, 2.0]] * 2), backend)


def _triangle_reference(a, k, lower):
    out = a.copy()
    for index in np.ndindex(a.shape):
        i, j = index[-2:]
        if (j - i > k) if lower else (j - i < k):
            out[index] = 0
    return out


@pytest.mark.parametrize("name", ["tril", "triu"])
@FEW
@given(data=st.data())
def test_tril_triu(backend, name, data):
    dtype = data.draw(st.sampled_from(["float32", "float64", "int64", "bool"]), label="dtype")
    shape = data.draw(st.sampled_from([(3, 3), (2, 4), (4, 2), (2, 3, 3), (0, 3), (2, 1, 0)]))
    special = {"int64": st.integers(-9, 9), "bool": st.booleans()}
    elements = special[dtype] if dtype in special else reals(dtype, -10, 10)
    a = data.draw(arrays(dtype, elements, st.just(shape)), label="x")
    k = data.draw(st.integers(-4, 4), label="k")
    expected = _triangle_reference(a, k, name == "tril")
    for fn in api(backend, name):
        _exact(fn(native(a, backend), k=k), expected, backend)
    _exact(
        api(backend, name)[0](native(a, backend)),
        _triangle_reference(a, 0, name == "tril"),
        backend,
    )


def _source(producer, a):
    if producer not in ivy.installed_frameworks():
        pytest.skip(f"the producer {producer} is not installed")
    if producer == "numpy":
        return a.copy()
    return native(a, producer)


@pytest.mark.parametrize("producer", BACKENDS)
@pytest.mark.parametrize("dtype", ["float32", "float64", "int32", "uint8", "bool"])
def test_from_dlpack_from_every_framework(backend, producer, dtype):
    a = np.arange(6).reshape(2, 3).astype(dtype)
    src = _source(producer, a)
    for fn in api(backend, "from_dlpack")[1:]:
        for copy in (None, True):
            _exact(fn(src, copy=copy), a, backend)
        _exact(fn(src, device="cpu"), a, backend)
    _exact(ivy.from_dlpack(src, f=backend), a, backend)


# The frameworks whose arrays live on host or accelerator memory and convert by DLPack both ways
# (issue 24: numpy's host arrays, torch's and jax's on either).
INTERCHANGE = ("numpy", "torch", "jax")


@pytest.mark.parametrize("producer", INTERCHANGE)
@pytest.mark.parametrize("consumer", INTERCHANGE)
def test_from_dlpack_between_the_host_and_the_target_device(request, consumer, producer):
    """Host arrays to the device the test run targets, and back to the host and to the
    producer's framework (jax <-> torch where the run targets a GPU)."""
    for name in (consumer, producer):
        if name not in request.config.ivy_backends:
            pytest.skip(f"{name} is not among the backends of this run")
    xp, back = getattr(ivy, consumer), getattr(ivy, producer)
    device = device_for(consumer)
    a = np.arange(6.0, dtype=np.float32).reshape(2, 3)
    out = xp.from_dlpack(_source(producer, a), device=device)  # host -> target
    _exact(out, a, consumer)
    assert xp.dev(out) == device
    np.testing.assert_array_equal(ivy.numpy.from_dlpack(out), a)  # target -> host
    np.testing.assert_array_equal(ivy.to_numpy(ivy.to_framework(out, "numpy")), a)
    home = back.from_dlpack(out)  # -> the producer's framework, where ``out`` is
    _exact(home, a, producer)
    # where ``out`` is, if the producer's framework has such a device; else on the host (numpy)
    assert back.dev(home) == (device if device_for(producer) == device else "cpu")
    for copy in (None, True):
        _exact(xp.from_dlpack(out, device=device, copy=copy), a, consumer)


@pytest.mark.parametrize("producer", ["numpy", "torch"])
def test_from_dlpack_copy_true_never_shares_memory(backend, producer):
    a = np.zeros(64, np.float64)
    src = _source(producer, a)
    out = getattr(ivy, backend).from_dlpack(src, copy=True)
    src[0] = 5.0  # numpy arrays and torch tensors are mutable
    assert numpy_of(out)[0] == 0.0


def test_from_dlpack_shares_memory_by_default(request, mutable_backend):
    """numpy and torch consumers share the producer's memory (tf and jax may copy: immutable)."""
    if "torch" not in request.config.ivy_backends:
        pytest.skip("the producer here is a torch tensor; torch is not among this run's backends")
    import torch

    src = torch.zeros(8)
    out = getattr(ivy, mutable_backend).from_dlpack(src)
    src[0] = 3.0
    assert numpy_of(out)[0] == 3.0


def test_from_dlpack_infers_the_producer_without_f(backend):
    a = np.array([1.5, 2.5], np.float32)
    _exact(ivy.from_dlpack(native(a, backend)), a, backend)


@pytest.mark.parametrize(
    "obj", [[2**63], 2**64, [[2**63], [2**64 - 1]], [2**70], [-(2**63) - 1]], ids=repr
)
def test_python_ints_beyond_int64_raise_without_a_dtype(backend, obj):
    """int64 is the default integer dtype: numpy made such ints uint64 (or objects), torch and
    jax refused them, each with its own error. (numpy reads ``[1, 2**63]``, whose ints are not
    all beyond int64 and not all below it, as float64: left so, ``docs/conformance.md``.)"""
    for fn in api_f(backend, "asarray"):
        with pytest.raises(OverflowError, match="uint64"):
            fn(obj)


def test_python_ints_beyond_int64_with_dtype_uint64(backend):
    for fn in api_f(backend, "asarray"):
        check(
            fn([2**63, 2**64 - 1], dtype="uint64"), np.array([2**63, 2**64 - 1], np.uint64), backend
        )
