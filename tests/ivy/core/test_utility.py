"""Tests of the core group ``utility`` (``ivy/core/utility.py``), on every backend.

Ivy's own functions beyond the Array API, on every backend, against references written here
with Python loops or plain numpy float64: gather_flat, scatter_flat, indices_where, cumsum,
cumprod, einsum, constant_pad, zero_pad, linear_resample, interp, vector_to_skew_symmetric_matrix,
cosine_similarity, clip_vector_norm, clip_by_global_norm, nan_to_num, isclose, allclose and
to_framework.

to_numpy, to_list, shape, dtype and dev on every backend.

all, any and diff on every backend, against references written as Python loops.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ivy
from tests.conftest import device_for
from tests.helpers import (
    HYPOTHESIS,
    api,
    api_f,
    check,
    dtype_name,
    is_native,
    native,
    numpy_of,
)
from tests.ivy.strategies import BROADCAST_PAIRS, arrays, axis_arguments, normalize_axis


@pytest.mark.parametrize("name", ["cumsum", "cumprod"])
def test_cumulative_defaults_and_dtype(backend, name):
    x = np.array([[1, 2, 3], [4, 5, 6]], np.int32)
    op = np.cumsum if name == "cumsum" else np.cumprod
    for fn in api(backend, name):
        check(fn(native(x, backend)), op(x.astype(np.int64), axis=0), backend)  # axis 0
        check(fn(native(x, backend), 1, dtype="float64"), op(x.astype(np.float64), axis=1), backend)


@pytest.mark.parametrize("dtype", ["float32", "float64", "int64", "uint8", "bool", "complex64"])
def test_to_framework_to_every_backend(request, backend, dtype):
    a = (np.arange(6).reshape(2, 3) % 4).astype(dtype)
    x = native(a, backend)
    for target in request.config.ivy_backends:
        for fn in api(backend, "to_framework"):
            for spelling in (target, getattr(ivy, target)):
                out = fn(x, spelling)
                assert is_native(out, target), (backend, target, type(out))
                assert dtype_name(out) == dtype
                np.testing.assert_array_equal(numpy_of(out), a)
    assert ivy.to_framework(x, backend) is x  # already of that framework


def _pointer(x):
    if isinstance(x, np.ndarray):
        return x.ctypes.data
    if type(x).__module__.startswith("torch"):
        return x.data_ptr()
    return x.unsafe_buffer_pointer()  # jax


# Conversions that DLPack makes without a copy, observable through the buffer's address.
ZERO_COPY = [
    ("numpy", "torch"),
    ("torch", "numpy"),
    ("torch", "jax"),
    ("jax", "torch"),
    ("jax", "numpy"),
]


@pytest.mark.parametrize("source, target", ZERO_COPY, ids=str)
def test_to_framework_shares_memory(request, source, target):
    if not {source, target} <= set(request.config.ivy_backends):
        pytest.skip(f"needs {source} and {target}")
    if source == "torch":
        import torch

        x = torch.arange(8.0)  # torch's allocator aligns buffers as jax requires
    else:
        x = native(np.arange(8.0), source)
    out = ivy.to_framework(x, target)
    assert _pointer(out) == _pointer(x)
    np.testing.assert_array_equal(numpy_of(out), np.arange(8.0))


def test_numpy_and_torch_see_each_others_writes(request):
    if "torch" not in request.config.ivy_backends:
        pytest.skip("needs torch")
    a = np.zeros(3)
    t = ivy.to_framework(a, "torch")
    t[0] = 5.0
    a[2] = 7.0
    assert a[0] == 5.0 and t[2].item() == 7.0


def test_to_framework_copies_what_dlpack_cannot_carry(request):
    """A read-only numpy array and a torch tensor that requires gradients still convert."""
    readonly = np.arange(3.0)
    readonly.flags.writeable = False
    for target in request.config.ivy_backends:
        out = ivy.to_framework(readonly, target)
        np.testing.assert_array_equal(numpy_of(out), readonly)
    if "torch" in request.config.ivy_backends:
        import torch

        leaf = torch.ones(2, requires_grad=True)
        for target in request.config.ivy_backends:
            out = ivy.to_framework(leaf, target)
            assert is_native(out, target)
            np.testing.assert_array_equal(numpy_of(out), np.ones(2, np.float32))


def test_to_framework_reads_the_source_from_the_type_under_a_global_framework(request, backend):
    a = np.arange(3.0)
    with ivy.set_framework(backend):
        for target in request.config.ivy_backends:
            out = ivy.to_framework(a, target)
            assert is_native(out, target)
            np.testing.assert_array_equal(numpy_of(out), a)
        out = ivy.to_framework([1.5, 2.5], backend)  # Python data: the target's asarray
        check(out, np.array([1.5, 2.5], np.float32), backend)


def test_to_framework_refuses_an_unknown_framework(backend):
    with pytest.raises(ivy.UnknownFrameworkError):
        ivy.to_framework(native(np.ones(2), backend), "mxnet")


NEAR_ONE = [0.0, -0.0, 1.0, 1.0 + 1e-6, 1.0 + 3e-5, 1.001, 1e-9, -1e-9, math.inf, -math.inf]


TOLERANCE_ARGS = [(1e-5, 1e-8), (0.0, 0.0), (1e-3, 0.0), (0.0, 1e-6)]


@HYPOTHESIS
@given(data=st.data())
def test_isclose_and_allclose(backend, data):
    """Against numpy (which computes in the inputs' dtype too), broadcasting, with infinities
    and NaNs."""
    dtype = data.draw(st.sampled_from(["float32", "float64"]), label="dtype")
    shape1, shape2 = data.draw(BROADCAST_PAIRS, label="shapes")
    elements = st.sampled_from([float(np.dtype(dtype).type(v)) for v in [*NEAR_ONE, math.nan]])
    a = data.draw(arrays(dtype, elements, shape1), label="x1")
    b = data.draw(arrays(dtype, elements, shape2), label="x2")
    rtol, atol = data.draw(st.sampled_from(TOLERANCE_ARGS), label="rtol, atol")
    equal_nan = data.draw(st.booleans(), label="equal_nan")
    kwargs = dict(rtol=rtol, atol=atol, equal_nan=equal_nan)
    x1, x2 = native(a, backend), native(b, backend)
    for fn in api(backend, "isclose"):
        check(fn(x1, x2, **kwargs), np.isclose(a, b, **kwargs), backend)
    for fn in api(backend, "allclose"):
        check(fn(x1, x2, **kwargs), np.array(np.allclose(a, b, **kwargs)), backend)


def test_isclose_of_mixed_dtypes_and_python_scalars(backend):
    ints = np.array([1, 2, 3], np.int64)
    floats = np.array([1.0 + 1e-7, 2.1, np.inf], np.float32)
    for fn in api(backend, "isclose"):
        out = fn(native(ints, backend), native(floats, backend))
        check(out, np.isclose(ints.astype(np.float32), floats), backend)
        check(fn(native(floats, backend), 2.1), np.isclose(floats, np.float32(2.1)), backend)
    for fn in api_f(backend, "isclose"):
        check(fn(1.0, 1.0 + 1e-9), np.array(True), backend)
    for fn in api(backend, "allclose"):
        check(fn(native(floats[:2], backend), native(floats[:2], backend)), np.array(True), backend)
        check(
            fn(native(np.zeros(0), backend), native(np.ones(0), backend)), np.array(True), backend
        )


DTYPES = ["float16", "float32", "float64", "int32", "int64", "uint8", "bool"]


SHAPES = [(2, 3), (), (0, 3), (4,)]


def _values(shape, dtype):
    return (np.arange(np.prod(shape, dtype=int)).reshape(shape) % 3).astype(dtype)


def _trainable(a, backend):
    """A native array that records gradients (torch) or a variable (tensorflow)."""
    if backend == "torch":
        import torch

        return torch.tensor(a, requires_grad=True)
    if backend == "tensorflow":
        import tensorflow as tf

        return tf.Variable(a)
    return native(a, backend)


@pytest.mark.parametrize("dtype", DTYPES)
@pytest.mark.parametrize("shape", SHAPES, ids=str)
def test_to_numpy(backend, dtype, shape):
    a = _values(shape, dtype)
    for fn in api(backend, "to_numpy"):
        out = fn(native(a, backend))
        assert isinstance(out, np.ndarray), type(out)
        assert out.dtype == a.dtype and out.shape == a.shape
        np.testing.assert_array_equal(out, a)


def test_to_numpy_of_trainable_arrays(backend):
    a = np.array([[1.5, -2.0]], np.float32)
    for fn in api(backend, "to_numpy"):
        out = fn(_trainable(a, backend))
        assert isinstance(out, np.ndarray)
        assert out.dtype == np.float32
        np.testing.assert_array_equal(out, a)


@pytest.mark.parametrize("dtype, python_type", [("float32", float), ("int64", int), ("bool", bool)])
def test_to_list(backend, dtype, python_type):
    a = _values((2, 3), dtype)
    for fn in api(backend, "to_list"):
        out = fn(native(a, backend))
        assert out == a.tolist()
        assert type(out) is list and type(out[0]) is list
        assert type(out[1][2]) is python_type
        scalar = fn(native(a[1, 1], backend))  # a 0-d array gives a scalar
        assert type(scalar) is python_type and scalar == a[1, 1].item()
        assert fn(native(a[:0], backend)) == []


def test_to_list_of_floats_is_exact(backend):
    a = np.array([0.1, 1 / 3, -2.5], np.float64)
    for fn in api(backend, "to_list"):
        assert fn(native(a, backend)) == a.tolist()


@pytest.mark.parametrize("shape", SHAPES, ids=str)
def test_shape_is_a_tuple_of_int(backend, shape):
    for fn in api(backend, "shape"):
        out = fn(native(np.zeros(shape, np.float32), backend))
        assert type(out) is tuple, type(out)
        assert out == shape
        assert all(type(d) is int for d in out), [type(d) for d in out]


@pytest.mark.parametrize("dtype", DTYPES)
def test_dtype(backend, dtype):
    xp = getattr(ivy, backend)
    x = native(np.zeros(3, dtype), backend)
    for fn in api(backend, "dtype"):
        assert fn(x) == getattr(xp, dtype)
        assert fn(x, as_str=True) == dtype
        assert type(fn(x, as_str=True)) is str


def test_dtype_of_trainable_arrays(backend):
    x = _trainable(np.zeros(2, np.float64), backend)
    for fn in api(backend, "dtype"):
        assert fn(x, as_str=True) == "float64"
    assert ivy.shape(x) == (2,)


def test_dev_is_the_target_device(backend):
    """Arrays made without a device are on the device the test run targets; ``device='cpu'``
    puts them on the CPU."""
    target = device_for(backend)
    arrays = [
        native(np.ones((2, 2), np.float32), backend),
        native(np.int64(3), backend),
        _trainable(np.ones(2, np.float32), backend),
        ivy.zeros((2,), f=backend),
    ]
    for x in arrays:
        for fn in api(backend, "dev"):
            assert fn(x) == target
    for fn in api(backend, "dev"):
        assert fn(ivy.zeros((2,), device="cpu", f=backend)) == "cpu"


GROUPS = [
    "creation",
    "data_type",
    "elementwise",
    "utility",
    "indexing",
    "linalg",
    "manipulation",
    "random",
    "searching",
    "statistical",
]


@pytest.mark.parametrize("group", GROUPS)
def test_every_function_of_a_group_is_named_in_a_test_file(group):
    """Guards the rule that every public function is tested: each name of a group must appear
    (as a string or an attribute call) in tests/ivy/core/test_<group>.py or another test file
    under tests/ivy."""
    import importlib
    import pathlib

    names = importlib.import_module(f"ivy.core.{group}").__all__
    here = pathlib.Path(__file__).parent.parent
    source = "\n".join(p.read_text() for p in sorted(here.rglob("test_*.py")))
    missing = [n for n in names if f'"{n}"' not in source and f".{n}(" not in source]
    assert not missing, f"no test in tests/ivy names these {group} functions: {missing}"


FEW = settings(HYPOTHESIS, max_examples=20)


SHAPES_utility_api = st.sampled_from([(), (5,), (0,), (2, 3), (2, 1, 3), (3, 0)])


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
    a = data.draw(arrays(dtype, _elements(dtype), SHAPES_utility_api), label="x")
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


def test_every_group_has_its_test_file():
    """The layout: the tests of core group ``g`` are in ``tests/ivy/core/test_g.py``."""
    import pathlib

    here = pathlib.Path(__file__).parent
    missing = [g for g in ivy.core.GROUP_NAMES if not (here / f"test_{g}.py").exists()]
    assert not missing, f"no tests/ivy/core/test_<group>.py for {missing}"
