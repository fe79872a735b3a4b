"""Tests of the core group ``pooling`` (``ivy/core/pooling.py``), on every backend.

Convolutions and pools (channel-last) against naive numpy float64 loops, on every backend.

The references below loop over output positions and kernel taps, and compute 'SAME' padding from
tf's documented rule; the tf backend passes 'SAME' to tf itself, so the rule is checked too.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ivy
from tests.helpers import HYPOTHESIS, check, native

FLOATS = ("float32", "float64")


def _random(shape, dtype, seed):
    return np.random.default_rng(100 + seed).standard_normal(shape).astype(dtype)


def _tuple(v, nd):
    return (v,) * nd if isinstance(v, int) else tuple(v)


def ref_pads(padding, sizes, windows, strides):
    """(low, high) per axis; 'SAME' by tf's rule: out = ceil(n / s), the odd pad at the end."""
    nd = len(sizes)
    if padding == "VALID":
        return [(0, 0)] * nd
    if padding == "SAME":
        pads = []
        for n, w, s in zip(sizes, windows, strides):
            total = max((math.ceil(n / s) - 1) * s + w - n, 0)
            pads.append((total // 2, total - total // 2))
        return pads
    if isinstance(padding, int):
        return [(padding, padding)] * nd
    return [(p, p) if isinstance(p, int) else tuple(p) for p in padding]


def ref_pool(x, kernel, strides, padding, average):
    """Max or mean over each window's real entries (padding never counts), float64."""
    x = x.astype(np.float64)
    nd = x.ndim - 2
    k, s = _tuple(kernel, nd), _tuple(strides, nd)
    pads = ref_pads(padding, x.shape[1:-1], k, s)
    sizes = x.shape[1:-1]
    out_sizes = [(n + lo + hi - ki) // si + 1 for n, (lo, hi), ki, si in zip(sizes, pads, k, s)]
    out = np.zeros((x.shape[0], *out_sizes, x.shape[-1]))
    for o in np.ndindex(*out_sizes):
        box = []
        for oi, si, ki, (lo, _), n in zip(o, s, k, pads, sizes):
            start = oi * si - lo
            box.append(slice(max(start, 0), min(start + ki, n)))
        window = x[(slice(None), *box)].reshape(x.shape[0], -1, x.shape[-1])
        out[(slice(None), *o)] = window.mean(1) if average else window.max(1)
    return out


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
    x = _random(x_shape, dtype, 12)
    flat = x.reshape(-1, *x_shape[-nd - 1 :])
    expected = ref_pool(flat, kernel, strides, padding, kind == "avg")
    expected = expected.reshape(x_shape[: -nd - 1] + expected.shape[1:])
    fn = getattr(ivy, f"{kind}_pool{nd}d")
    check(fn(native(x, backend), kernel, strides, padding), expected.astype(dtype), backend)


# Fewer examples than the shared profile: jax compiles every new shape.
GEOMETRY = settings(HYPOTHESIS, max_examples=15)


_PADDINGS = st.one_of(
    st.sampled_from(["SAME", "VALID"]),
    st.tuples(st.integers(0, 2), st.integers(0, 2)).map(lambda p: [p]),
)


@GEOMETRY
@given(n=st.integers(1, 7), k=st.integers(1, 3), s=st.integers(1, 3), padding=_PADDINGS)
def test_pool1d_geometry(backend, n, k, s, padding):
    x = _random((1, n, 2), "float64", 15)
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
