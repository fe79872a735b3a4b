"""astype and its paper spelling cast, and the handling of dtype names, on every backend."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
from tests.helpers import api, api_f, check, native

SIGNED = [-2.7, -1.0, -0.0, 0.0, 0.4, 1.5, 2.7, 100.25]
UNSIGNED = [0.0, 0.4, 1.5, 2.7, 100.25]
TARGETS = [
    "float16",
    "float32",
    "float64",
    "int8",
    "int16",
    "int32",
    "int64",
    "uint8",
    "bool",
]


def _source(source_dtype, target):
    values = UNSIGNED if target.startswith("uint") else SIGNED
    return np.array(values, dtype=source_dtype)


def _expected(a, target):
    """Floats to integers truncate toward zero; nonzero is True."""
    a64 = a.astype(np.float64)
    if target == "bool":
        return a64 != 0
    if target.startswith(("int", "uint")):
        return np.trunc(a64).astype(target)
    return a64.astype(target)


@pytest.mark.parametrize("name", ["astype", "cast"])
@pytest.mark.parametrize("source", ["float32", "float64"])
@pytest.mark.parametrize("target", TARGETS)
def test_astype_from_floats(backend, name, source, target):
    a = _source(source, target)
    expected = _expected(a, target)
    native_target = getattr(getattr(ivy, backend), target)
    for fn in api(backend, name):
        check(fn(native(a, backend), target), expected, backend, dtype=target)
        check(fn(native(a, backend), native_target), expected, backend, dtype=target)


@pytest.mark.parametrize("name", ["astype", "cast"])
@pytest.mark.parametrize("source", ["int32", "int64", "bool", "uint8"])
@pytest.mark.parametrize("target", ["float32", "float64", "int64", "int32", "bool"])
def test_astype_from_integers_and_bools(backend, name, source, target):
    a = np.array([0, 1, 7, 100], dtype=source)
    expected = (a != 0) if target == "bool" else a.astype(target)
    for fn in api(backend, name):
        check(fn(native(a, backend), target), expected, backend)


def test_astype_keeps_the_shape_of_0d_and_empty_arrays(backend):
    for a in (np.float32(2.5), np.zeros((0, 3), np.float32)):
        for fn in api(backend, "astype"):
            check(fn(native(a, backend), "float64"), np.asarray(a, np.float64), backend)


def test_astype_with_copy_false(backend):
    a = np.array([1.0, 2.0], np.float32)
    for fn in api(backend, "astype"):
        check(fn(native(a, backend), "float32", copy=False), a, backend)
        check(fn(native(a, backend), "float64", copy=False), a.astype(np.float64), backend)


def test_cast_is_the_same_function_as_astype(backend):
    assert ivy.cast is ivy.astype
    xp = getattr(ivy, backend)
    assert xp.cast is xp.astype


# Every function that takes a dtype refuses a name it does not know (clearly bogus names: whether
# aliases such as 'double' are accepted is left to the backends).
UNKNOWN_DTYPE_CALLS = {
    "astype": lambda b: ivy.astype(native(np.ones(2, np.float32), b), "float31"),
    "cast": lambda b: ivy.cast(native(np.ones(2, np.float32), b), "flaot32"),
    "asarray": lambda b: ivy.asarray([1.0, 2.0], dtype="int65", f=b),
    "zeros": lambda b: ivy.zeros((2,), dtype="float32x", f=b),
    "ones": lambda b: ivy.ones(3, dtype="doubble", f=b),
    "full": lambda b: ivy.full((2,), 1.0, dtype="float33", f=b),
    "arange": lambda b: ivy.arange(4, dtype="int63", f=b),
    "linspace": lambda b: ivy.linspace(0.0, 1.0, 3, dtype="floatt", f=b),
    "eye": lambda b: ivy.eye(2, dtype="float31", f=b),
    "zeros_like": lambda b: ivy.zeros_like(native(np.ones(2), b), dtype="zeros32"),
    "one_hot": lambda b: ivy.one_hot(native(np.array([0, 1]), b), 2, dtype="onehot"),
    "sum": lambda b: ivy.sum(native(np.ones(2), b), dtype="float65"),
    "random_uniform": lambda b: ivy.random_uniform(shape=(2,), dtype="uniform", f=b),
    "randint": lambda b: ivy.randint(0, 3, (2,), dtype="int63", f=b),
}


@pytest.mark.parametrize("name", sorted(UNKNOWN_DTYPE_CALLS))
def test_unknown_dtype_name_raises_type_error(backend, name):
    with pytest.raises(TypeError):
        UNKNOWN_DTYPE_CALLS[name](backend)


def test_unknown_dtype_name_raises_type_error_in_namespace(backend):
    xp = getattr(ivy, backend)
    with pytest.raises(TypeError):
        xp.astype(native(np.ones(2, np.float32), backend), "float31")
    for fn in api_f(backend, "zeros"):
        with pytest.raises(TypeError):
            fn((2,), dtype="float31")
