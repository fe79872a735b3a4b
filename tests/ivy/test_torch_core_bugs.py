"""Bugs that the applied libraries found in the torch backend (issue 17, item 4): converting a
numpy constant inside ``torch.compile`` without a graph break, ``asarray`` of a tensor that
requires grad without torch's warning, and ``take`` through ``index_select``."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import ivy

torch = pytest.importorskip("torch")


@pytest.fixture(autouse=True)
def _torch_selected(request):
    if "torch" not in request.config.ivy_backends:
        pytest.skip("the torch backend is not selected")


def test_asarray_of_numpy_constants_compiles_in_one_graph():
    constant = np.array([1.0, 2.0, 3.0], dtype="float32")
    frozen = constant.copy()
    frozen.flags.writeable = False

    def fn(x):
        return ivy.torch.add(ivy.torch.asarray(constant), x) * ivy.torch.asarray(frozen)

    torch._dynamo.reset()
    compiled = torch.compile(fn, fullgraph=True, backend="eager")  # a graph break raises
    x = torch.ones(3)
    np.testing.assert_array_equal(compiled(x).numpy(), (constant + 1.0) * frozen)


def test_asarray_of_a_tensor_that_requires_grad_does_not_warn():
    t = torch.ones(2, requires_grad=True)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        same = ivy.torch.asarray(t, dtype=t.dtype)
        wider = ivy.torch.asarray(t, dtype=torch.float64)
    assert same is t
    assert wider.dtype is torch.float64 and wider.requires_grad


@pytest.mark.parametrize("dtype", ["int64", "int32"])
def test_take_with_1d_indices_is_index_select(dtype):
    x = torch.arange(12.0).reshape(3, 4)
    idx = torch.as_tensor(np.array([3, -1, 0], dtype=dtype))
    with torch.profiler.profile(activities=[torch.profiler.ProfilerActivity.CPU]) as prof:
        out = ivy.torch.take(x, idx, axis=1)
    ops = {e.name for e in prof.events()}
    assert "aten::index_select" in ops and "aten::index" not in ops
    np.testing.assert_array_equal(out.numpy(), np.take(x.numpy(), [3, -1, 0], axis=1))
    with pytest.raises(IndexError, match="out of bounds"):
        ivy.take(x, torch.as_tensor([4]), axis=1)


def test_max_pool_of_64_bit_integers_raises_unsupported():
    """torch has no integer max pool: integers of up to 32 bits go through float64, which holds
    them exactly (tests/ivy/core/test_pooling.py); 64-bit ones cannot, and raise a clear error."""
    x = torch.arange(12, dtype=torch.int64).reshape(1, 4, 3)
    with pytest.raises(ivy.errors.UnsupportedError, match="64-bit"):
        ivy.max_pool1d(x, 2, 2, "VALID")
    with pytest.raises(ivy.errors.UnsupportedError, match="64-bit"):
        ivy.torch.max_pool1d(x, 2, 2, "VALID")
