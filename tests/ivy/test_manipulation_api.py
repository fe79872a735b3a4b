"""moveaxis and broadcast_arrays on every backend, against references written with numpy indexing
(values are moved, never computed: results must be exact)."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ivy
from tests.helpers import HYPOTHESIS, api, check, native
from tests.ivy.strategies import arrays, reals

FEW = settings(HYPOTHESIS, max_examples=20)
SHAPES = [(4,), (0,), (2, 3), (2, 1, 3), (1, 2, 0), (2, 3, 1, 2)]


def _exact(out, expected, backend):
    check(out, expected, backend, rtol=0, atol=0, signed_zeros=True)


def _array(data, shapes):
    dtype = data.draw(st.sampled_from(["float32", "float64", "int64"]), label="dtype")
    elements = st.integers(-100, 100) if dtype == "int64" else reals(dtype, -100, 100)
    return data.draw(arrays(dtype, elements, st.sampled_from(shapes)), label="x")


def _moveaxis_reference(a, source, destination):
    """Element by element: output index ``j`` reads input index ``j`` permuted back."""
    n = a.ndim
    source = [s % n for s in source]
    destination = [d % n for d in destination]
    order = [ax for ax in range(n) if ax not in source]
    for d, s in sorted(zip(destination, source)):
        order.insert(d, s)
    out = np.empty(tuple(a.shape[ax] for ax in order), a.dtype)
    for index in np.ndindex(out.shape):
        src = [0] * n
        for j, ax in enumerate(order):
            src[ax] = index[j]
        out[index] = a[tuple(src)]
    return out


@FEW
@given(data=st.data())
def test_moveaxis(backend, data):
    a = _array(data, SHAPES)
    n = a.ndim
    count = data.draw(st.integers(1, n), label="number of axes")
    source = data.draw(st.permutations(range(n)), label="source")[:count]
    destination = data.draw(st.permutations(range(n)), label="destination")[:count]
    source = [s - n if data.draw(st.booleans(), label="negative") else s for s in source]
    expected = _moveaxis_reference(a, source, destination)
    for fn in api(backend, "moveaxis"):
        _exact(fn(native(a, backend), tuple(source), tuple(destination)), expected, backend)
        if count == 1:
            _exact(fn(native(a, backend), source[0], destination[0]), expected, backend)


def test_moveaxis_refuses_mismatched_axes(backend):
    x = native(np.zeros((2, 3, 4)), backend)
    for fn in api(backend, "moveaxis"):
        with pytest.raises((ValueError, IndexError, RuntimeError)):
            fn(x, (0, 1), (2,))


BROADCAST_GROUPS = [
    [(), ()],
    [(2, 3), ()],
    [(2, 1), (1, 3)],
    [(3,), (2, 1, 3), (1, 1)],
    [(0,), (1,)],
    [(2, 0), (1, 1), ()],
    [(4,)],
]


def _broadcast_reference(shapes):
    """The broadcast shape by the rules: right-aligned, sizes equal or 1."""
    ndim = max(len(s) for s in shapes)
    out = []
    for axis in range(ndim):
        sizes = {s[axis - ndim + len(s)] for s in shapes if axis - ndim + len(s) >= 0} - {1}
        assert len(sizes) <= 1
        out.append(sizes.pop() if sizes else 1)
    return tuple(out)


@pytest.mark.parametrize("shapes", BROADCAST_GROUPS, ids=str)
def test_broadcast_arrays(backend, shapes):
    rng = np.random.default_rng(0)
    inputs = [rng.normal(size=s).astype(np.float32) for s in shapes]
    target = _broadcast_reference(shapes)
    for fn in api(backend, "broadcast_arrays"):
        out = fn(*(native(a, backend) for a in inputs))
        assert isinstance(out, list) and len(out) == len(inputs)
        for o, a in zip(out, inputs):
            expected = np.empty(target, np.float32)
            pad = (1,) * (len(target) - a.ndim) + a.shape
            for index in itertools.product(*map(range, target)):
                expected[index] = a.reshape(pad)[
                    tuple(0 if p == 1 else i for i, p in zip(index, pad))
                ]
            _exact(o, expected, backend)


def test_broadcast_arrays_refuses_incompatible_shapes(backend):
    x, y = native(np.zeros(2), backend), native(np.zeros(3), backend)
    for fn in api(backend, "broadcast_arrays"):
        with pytest.raises(Exception):  # noqa: B017 - each framework raises its own error
            fn(x, y)


def test_broadcast_arrays_with_f(backend):
    out = ivy.broadcast_arrays(np.zeros((2, 1)), np.ones(3), f=backend)
    _exact(out[1], np.ones((2, 3)), backend)
