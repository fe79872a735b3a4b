"""tf.Tensor as the Array API's array object (``ivy/backends/tensorflow/_array_object.py``): the
attributes tf lacks are added when ``ivy.tensorflow`` loads, checked against numpy, and nothing of
tf's own is replaced."""

from __future__ import annotations

import types

import numpy as np
import pytest

import ivy

tf = pytest.importorskip("tensorflow")

from ivy.backends.tensorflow._array_object import add_array_methods  # noqa: E402

ADDED = ("__array_namespace__", "to_device", "T", "mT", "size", "__pos__")
SHIFTS = ("__lshift__", "__rlshift__", "__rshift__", "__rrshift__")


@pytest.fixture(autouse=True)
def _tensorflow_selected(request):
    if "tensorflow" not in request.config.ivy_backends:
        pytest.skip("the tensorflow backend is not selected")


@pytest.fixture
def ns():
    return ivy.tensorflow


def test_the_tensor_names_its_namespace(ns):
    x = ns.asarray([1.0, 2.0])
    assert x.__array_namespace__() is ns
    assert x.__array_namespace__(api_version="2023.12") is ns
    with pytest.raises(ValueError, match="2023.12"):
        x.__array_namespace__(api_version="2030.12")


def test_only_what_tf_lacks_is_added(ns):
    """Every attribute of tf.Tensor that comes from ivy is one of those tf does not define."""
    from_ivy = set()
    for name, value in vars(tf.Tensor).items():
        fn = value.fget if isinstance(value, property) else value
        if getattr(fn, "__module__", "").startswith("ivy."):
            from_ivy.add(name)
    assert from_ivy == set(ADDED + SHIFTS)
    for name in ("__neg__", "__abs__", "__pow__", "__floordiv__", "__dlpack__"):
        owner = next(c for c in type(ns.asarray(1)).__mro__ if name in vars(c))
        assert not getattr(vars(owner)[name], "__module__", "").startswith("ivy."), name


def test_an_existing_attribute_is_kept_and_the_switch_adds_nothing(ns, monkeypatch):
    class Tensor:
        T = "its own"

    added = add_array_methods(ns, Tensor)
    assert Tensor.T == "its own" and "T" not in added and "mT" in added

    class Untouched:
        pass

    monkeypatch.setenv("IVY_TF_ARRAY_METHODS", "0")
    assert add_array_methods(ns, Untouched) == []
    assert not hasattr(Untouched, "__array_namespace__")


@pytest.mark.parametrize("shape", [(2, 3), (0, 4)])
def test_T_is_the_transpose_of_a_matrix(ns, shape):
    a = np.arange(np.prod(shape), dtype=np.float64).reshape(shape)
    out = ns.asarray(a).T
    assert out.shape == a.T.shape and out.dtype == tf.float64
    np.testing.assert_array_equal(out.numpy(), a.T)


@pytest.mark.parametrize("shape", [(), (3,), (2, 3, 4)])
def test_T_of_other_ranks_raises(ns, shape):
    with pytest.raises(ValueError, match="2-D"):
        _ = ns.asarray(np.zeros(shape, np.float32)).T


@pytest.mark.parametrize("shape", [(2, 3), (4, 2, 3), (2, 1, 0, 5)])
def test_mT_swaps_the_last_two_axes(ns, shape):
    a = np.arange(np.prod(shape), dtype=np.int32).reshape(shape)
    np.testing.assert_array_equal(ns.asarray(a).mT.numpy(), np.swapaxes(a, -1, -2))


def test_mT_of_fewer_than_two_dimensions_raises(ns):
    with pytest.raises(ValueError, match="two or more"):
        _ = ns.asarray([1, 2, 3]).mT


@pytest.mark.parametrize("shape", [(), (0,), (3, 4), (2, 0, 5)])
def test_size_counts_the_elements(ns, shape):
    size = ns.asarray(np.zeros(shape, np.float32)).size
    assert type(size) is int and size == int(np.prod(shape))


def test_size_is_none_where_a_dimension_is_unknown():
    sizes = []

    @tf.function(input_signature=[tf.TensorSpec([None, 3], tf.float32)])
    def fn(x):
        sizes.append(x.size)
        return x.T

    out = fn(tf.ones((2, 3)))
    assert sizes == [None] and out.shape == (3, 2)


@pytest.mark.parametrize("dtype", ["int8", "uint8", "float32", "float64"])
def test_unary_plus_is_positive(ns, dtype):
    a = np.array([-2, 0, 3] if dtype != "uint8" else [2, 0, 3], dtype=dtype)
    out = +ns.asarray(a)
    assert out.dtype.name == dtype
    np.testing.assert_array_equal(out.numpy(), +a)


@pytest.mark.parametrize("dtype", ["int8", "uint8", "int32", "int64"])
def test_shift_operators_as_numpy(ns, dtype):
    a = np.array([0, 1, 5, 60], dtype=dtype)
    s = np.array([3, 0, 1, 2], dtype=dtype)
    x, y = ns.asarray(a), ns.asarray(s)
    cases = {
        "x << y": (x << y, a << s),
        "x >> y": (x >> y, a >> s),
        "x << 2": (x << 2, a << 2),
        "x >> 1": (x >> 1, a >> 1),
        "1 << y": (1 << y, 1 << s),
        "100 >> y": (100 >> y, np.asarray(100, dtype) >> s),
    }
    for what, (out, expected) in cases.items():
        assert out.dtype.name == dtype, what
        np.testing.assert_array_equal(out.numpy(), expected, err_msg=what)
    z = x
    z <<= 1  # (no in-place shift on an immutable tensor: Python rebinds z to x << 1)
    np.testing.assert_array_equal(z.numpy(), a << 1)
    np.testing.assert_array_equal(x.numpy(), a)


def test_shifts_leave_unknown_operands_to_python(ns):
    with pytest.raises(TypeError, match="unsupported operand"):
        ns.asarray([1, 2]) << "2"


def test_shift_of_floats_raises_ivys_dtype_error(ns):
    with pytest.raises(ivy.errors.DtypeError):
        ns.asarray([1.0]) << 1


def test_to_device_copies_onto_the_device(ns):
    x = ns.asarray([1.0, 2.0])
    for device in ("cpu", x.device):
        out = x.to_device(device)
        assert ns.dev(out) == "cpu"
        np.testing.assert_array_equal(out.numpy(), [1.0, 2.0])
    with pytest.raises(ValueError, match="streams"):
        x.to_device("cpu", stream=1)
    with pytest.raises(ValueError, match="tensorflow has no device .tpu:7."):
        x.to_device("tpu:7")


def test_methods_are_functions_of_the_namespace():
    assert isinstance(tf.Tensor.__array_namespace__, types.FunctionType)
    assert isinstance(tf.Tensor.__dict__["T"], property)
