"""meshgrid, tril, triu and from_dlpack on every backend, against numpy references written out
with indexing (values are copied, never computed: results must be exact)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ivy
from tests.helpers import HYPOTHESIS, api, check, native, numpy_of
from tests.ivy.strategies import arrays, reals

FEW = settings(HYPOTHESIS, max_examples=20)
BACKENDS = ("numpy", "torch", "jax", "tensorflow")


def _exact(out, expected, backend):
    check(out, expected, backend, rtol=0, atol=0, signed_zeros=True)


# ----------------------------------------------------------------------------------------------
# meshgrid
# ----------------------------------------------------------------------------------------------


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


# ----------------------------------------------------------------------------------------------
# tril and triu
# ----------------------------------------------------------------------------------------------


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


# ----------------------------------------------------------------------------------------------
# from_dlpack
# ----------------------------------------------------------------------------------------------


def _source(producer, a):
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


@pytest.mark.parametrize("producer", ["numpy", "torch"])
def test_from_dlpack_copy_true_never_shares_memory(backend, producer):
    a = np.zeros(64, np.float64)
    src = _source(producer, a)
    out = getattr(ivy, backend).from_dlpack(src, copy=True)
    src[0] = 5.0  # numpy arrays and torch tensors are mutable
    assert numpy_of(out)[0] == 0.0


def test_from_dlpack_shares_memory_by_default(mutable_backend):
    """numpy and torch consumers share the producer's memory (tf and jax may copy: immutable)."""
    import torch

    src = torch.zeros(8)
    out = getattr(ivy, mutable_backend).from_dlpack(src)
    src[0] = 3.0
    assert numpy_of(out)[0] == 3.0


def test_from_dlpack_infers_the_producer_without_f(backend):
    a = np.array([1.5, 2.5], np.float32)
    _exact(ivy.from_dlpack(native(a, backend)), a, backend)
