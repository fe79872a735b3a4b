"""Tests of the core group ``sets`` (``ivy/core/sets.py``), on every backend.

unique_all, unique_counts, unique_inverse and unique_values on every backend, against a
reference written with Python dicts: values sorted, each NaN its own value, -0.0 equal to 0.0.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ivy
from tests.helpers import HYPOTHESIS, api, check, native
from tests.ivy.strategies import arrays

FEW = settings(HYPOTHESIS, max_examples=20)


SHAPES = st.sampled_from([(), (7,), (0,), (3, 4), (2, 0, 3)])


FIELDS = {
    "unique_all": ("values", "indices", "inverse_indices", "counts"),
    "unique_counts": ("values", "counts"),
    "unique_inverse": ("values", "inverse_indices"),
}


def _elements(dtype):
    if dtype == "bool":
        return st.booleans()
    if dtype.startswith(("int", "uint")):
        return st.integers(0, 4)
    return st.sampled_from([0.0, -0.0, 1.0, -1.0, 2.5, math.inf, math.nan])


def _reference(a):
    flat = [v.item() for v in a.reshape(-1)]
    nan = [i for i, v in enumerate(flat) if isinstance(v, float) and math.isnan(v)]
    first: dict = {}
    for i, v in enumerate(flat):
        if i not in nan:
            first.setdefault(v, i)  # -0.0 == 0.0: one key (the first one met)
    keys = sorted(first)
    position = {k: j for j, k in enumerate(keys)}
    values = [flat[first[k]] for k in keys] + [math.nan] * len(nan)
    indices = [first[k] for k in keys] + nan
    inverse = [
        position[v] if i not in nan else len(keys) + nan.index(i) for i, v in enumerate(flat)
    ]
    counts = [sum(1 for i, v in enumerate(flat) if i not in nan and v == k) for k in keys]
    counts += [1] * len(nan)
    return {
        "values": np.array(values, a.dtype).reshape(-1),
        "indices": np.array(indices, np.int64),
        "inverse_indices": np.array(inverse, np.int64).reshape(a.shape),
        "counts": np.array(counts, np.int64),
    }


@FEW
@given(data=st.data())
def test_unique(backend, data):
    dtype = data.draw(
        st.sampled_from(["float32", "float64", "int64", "uint8", "bool"]), label="dtype"
    )
    a = data.draw(arrays(dtype, _elements(dtype), SHAPES), label="x")
    expected = _reference(a)
    x = native(a, backend)
    for name, fields in FIELDS.items():
        for fn in api(backend, name):
            out = fn(x)
            assert isinstance(out, tuple) and out._fields == fields, name
            for field in fields:
                # -0.0 and 0.0 are one value; which of them is kept is left open
                check(getattr(out, field), expected[field], backend, rtol=0, atol=0)
    for fn in api(backend, "unique_values"):
        check(fn(x), expected["values"], backend, rtol=0, atol=0)


def test_unique_of_a_matrix(backend):
    a = np.array([[3, 1, 3], [2, 1, 1]], np.int32)
    out = ivy.unique_all(native(a, backend))
    check(out.values, np.array([1, 2, 3], np.int32), backend)
    check(out.indices, np.array([1, 3, 0]), backend)
    check(out.inverse_indices, np.array([[2, 0, 2], [1, 0, 0]]), backend)
    check(out.counts, np.array([3, 1, 2]), backend)


def test_unique_inside_jax_jit_is_unsupported():
    jax = pytest.importorskip("jax")
    for name in ["unique_all", "unique_counts", "unique_inverse", "unique_values"]:
        with pytest.raises(ivy.UnsupportedError, match="size"):
            jax.jit(getattr(ivy.jax, name))(jax.numpy.ones(3))


def test_unique_inside_tf_function():
    tf = pytest.importorskip("tensorflow")
    fn = tf.function(ivy.tensorflow.unique_all, input_signature=[tf.TensorSpec([None], tf.float32)])
    out = fn(tf.constant([2.0, -0.0, 2.0, 0.0, float("nan")]))
    check(out.values, np.array([0.0, 2.0, np.nan], np.float32), "tensorflow")
    check(out.indices, np.array([1, 0, 4]), "tensorflow")
    check(out.inverse_indices, np.array([1, 0, 1, 0, 2]), "tensorflow")
    check(out.counts, np.array([2, 2, 1]), "tensorflow")


@pytest.mark.parametrize("invert", [False, True])
@pytest.mark.parametrize("dtype", ["int64", "float32"])
def test_isin(backend, invert, dtype):
    x1 = np.array([[1, 2, 3], [4, 5, 1]], dtype)
    x2 = np.array([3, 1, 7], dtype)
    expected = np.isin(x1, x2, invert=invert)
    for fn in api(backend, "isin"):
        check(fn(native(x1, backend), native(x2, backend), invert=invert), expected, backend)
    nan = np.array([np.nan, 1.0], np.float32)  # NaN is in no array, itself included
    check(ivy.isin(native(nan, backend), native(nan, backend)), [False, True], backend)
