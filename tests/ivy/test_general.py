"""to_numpy, to_list, shape, dtype and dev on every backend."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
from tests.helpers import api, native

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


def test_dev_is_cpu(backend):
    arrays = [
        native(np.ones((2, 2), np.float32), backend),
        native(np.int64(3), backend),
        _trainable(np.ones(2, np.float32), backend),
        ivy.zeros((2,), f=backend),
        ivy.zeros((2,), device="cpu", f=backend),
    ]
    for x in arrays:
        for fn in api(backend, "dev"):
            assert fn(x) == "cpu"


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
    (as a string or an attribute call) in tests/ivy/test_<group>.py or another test file here."""
    import importlib
    import pathlib

    names = importlib.import_module(f"ivy.core.{group}").__all__
    here = pathlib.Path(__file__).parent
    source = "\n".join(p.read_text() for p in sorted(here.glob("test_*.py")))
    missing = [n for n in names if f'"{n}"' not in source and f".{n}(" not in source]
    assert not missing, f"no test in tests/ivy names these {group} functions: {missing}"
