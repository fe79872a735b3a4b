"""Tests of the core group ``pooling`` (``ivy/core/pooling.py``), on every backend.

Pools (channel-last) against naive numpy float64 loops (``_nn_reference.py``), on every backend.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import ivy
from tests.helpers import check, native
from tests.ivy.core._nn_reference import (
    FLOATS,
    GEOMETRY,
    PADDINGS,
    random_array,
    ref_pads,
    ref_pool,
)

# (x shape, kernel, strides, padding)
POOL_CASES = {
    1: [((2, 7, 3), 2, 2, "SAME"), ((2, 7, 3), 3, 2, "VALID"), ((2, 7, 3), 3, 1, [(2, 1)])],
    2: [
        ((2, 5, 6, 3), 2, 2, "SAME"),
        ((2, 5, 6, 3), (3, 2), (2, 1), "VALID"),
        ((2, 5, 6, 3), 3, 2, "SAME"),
        ((2, 5, 6, 3), (3, 3), 1, [(0, 2), 1]),
        ((2, 2, 5, 6, 3), 2, 2, "VALID"),  # extra leading batch axis
    ],
    3: [
        ((1, 5, 4, 5, 2), 2, 2, "SAME"),
        ((2, 4, 5, 4, 2), (3, 2, 2), (1, 2, 1), [(1, 1), 0, (0, 1)]),
    ],
}


def _pool_case_ids():
    return [
        pytest.param(nd, case, id=f"{nd}d-{i}")
        for nd, cases in POOL_CASES.items()
        for i, case in enumerate(cases)
    ]


@pytest.mark.parametrize("kind", ["max", "avg"])
@pytest.mark.parametrize("dtype", FLOATS)
@pytest.mark.parametrize(("nd", "case"), _pool_case_ids())
def test_pool(backend, dtype, kind, nd, case):
    x_shape, kernel, strides, padding = case
    x = random_array(x_shape, dtype, 12)
    flat = x.reshape(-1, *x_shape[-nd - 1 :])
    expected = ref_pool(flat, kernel, strides, padding, kind == "avg")
    expected = expected.reshape(x_shape[: -nd - 1] + expected.shape[1:])
    fn = getattr(ivy, f"{kind}_pool{nd}d")
    check(fn(native(x, backend), kernel, strides, padding), expected.astype(dtype), backend)


@GEOMETRY
@given(n=st.integers(1, 7), k=st.integers(1, 3), s=st.integers(1, 3), padding=PADDINGS)
def test_pool1d_geometry(backend, n, k, s, padding):
    x = random_array((1, n, 2), "float64", 15)
    pads = ref_pads(padding, (n,), (k,), (s,))
    if any(p >= k for p in pads[0]) or n + sum(pads[0]) < k:
        with pytest.raises(ValueError):
            ivy.max_pool1d(native(x, backend), k, s, padding)
        return
    for kind in ("max", "avg"):
        fn = getattr(ivy, f"{kind}_pool1d")
        check(
            fn(native(x, backend), k, s, padding),
            ref_pool(x, k, s, padding, kind == "avg"),
            backend,
        )


def test_pool_errors(backend):
    x = native(np.ones((1, 5, 5, 2)), backend)
    with pytest.raises(ValueError, match=r"rank >= 4, channel-last \[N, H, W, C\]"):
        ivy.max_pool2d(native(np.ones((5, 5, 2)), backend), 2, 2, "SAME")
    with pytest.raises(ValueError, match="unknown padding 'full'"):
        ivy.avg_pool2d(x, 2, 2, "full")
    with pytest.raises(ValueError, match="smaller than the window"):
        ivy.avg_pool2d(x, 2, 1, [(2, 0), 0])
    with pytest.raises(ValueError, match="kernel must be"):
        ivy.max_pool2d(x, (2, 2, 2), 1, "VALID")


@pytest.mark.parametrize("reduction", ["max", "mean"])
def test_pool_general(backend, reduction):
    """The backends' one pool, called with resolved arguments."""
    x = random_array((2, 5, 6, 3), "float64", 16)
    pads = ((0, 1), (1, 0))
    expected = ref_pool(x, (2, 3), (2, 1), pads, reduction == "mean")
    out = ivy.pool_general(native(x, backend), (2, 3), (2, 1), pads, reduction=reduction)
    check(out, expected, backend)
    with pytest.raises(ValueError, match="reduction must be 'max' or 'mean'"):
        ivy.pool_general(native(x, backend), (2, 3), (2, 1), pads, reduction="avg")


@pytest.mark.parametrize("dtype", ["int8", "uint8", "int32", "uint32"])
@pytest.mark.parametrize("nd", [1, 2])
def test_pools_of_integers(backend, dtype, nd):
    """Max pools keep the integer dtype, average pools are float32, on every backend (torch had
    no integer kernels, jax's max refused them, numpy's average was float64)."""
    for x_shape, kernel, strides, padding in POOL_CASES[nd]:  # (explicit padding included)
        a = (np.random.default_rng(5).integers(0, 100, x_shape)).astype(dtype)
        flat = a.reshape(-1, *x_shape[-nd - 1 :])
        for kind, average, want in (("max", False, dtype), ("avg", True, "float32")):
            fn = getattr(ivy, f"{kind}_pool{nd}d")
            expected = ref_pool(flat, kernel, strides, padding, average).astype(want)
            expected = expected.reshape(x_shape[: -nd - 1] + expected.shape[1:])
            check(fn(native(a, backend), kernel, strides, padding), expected, backend)
