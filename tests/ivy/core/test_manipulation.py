"""Tests of the core group ``manipulation`` (``ivy/core/manipulation.py``), on every backend.

Shape manipulation against numpy references, on every backend.

Hypothesis draws arrays (0-d and empty ones included) and valid arguments for them; results must
equal numpy's exactly (values are moved, never computed).

moveaxis and broadcast_arrays on every backend, against references written with numpy indexing
(values are moved, never computed: results must be exact).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ivy
from tests.helpers import HYPOTHESIS, api, check, native
from tests.ivy.strategies import arrays, axis_arguments, reals

DTYPES = ("float32", "float64", "int64")


SHAPES = [(), (4,), (0,), (2, 3), (3, 1), (2, 1, 3), (1, 2, 0), (2, 3, 1, 2)]


SHAPES_1D_PLUS = [s for s in SHAPES if s]


def _array(data, shapes=SHAPES):
    """An array of a drawn dtype and shape. The dtype is drawn rather than parametrized: jax
    compiles an operation for each dtype, shape and arguments, so examples are what costs."""
    dtype = data.draw(st.sampled_from(DTYPES), label="dtype")
    elements = st.integers(-100, 100) if dtype == "int64" else reals(dtype, -100, 100)
    return data.draw(arrays(dtype, elements, st.sampled_from(shapes)), label="x")


def _exact(out, expected, backend):
    check(out, expected, backend, rtol=0, atol=0)


@HYPOTHESIS
@given(data=st.data())
def test_reshape(backend, data):
    a = _array(data)
    options = [(a.size,), a.shape[::-1], (1, *a.shape), (*a.shape, 1)]
    if a.size:  # -1 is ambiguous for an empty array
        options += [(-1,), (-1, *a.shape[1:])]
    shape = data.draw(st.sampled_from(options), label="shape")
    for fn in api(backend, "reshape"):
        _exact(fn(native(a, backend), shape), a.reshape(shape), backend)
    _exact(api(backend, "reshape")[0](native(a, backend), shape=shape), a.reshape(shape), backend)


@HYPOTHESIS
@given(data=st.data())
def test_permute_dims(backend, data):
    a = _array(data)
    axes = tuple(data.draw(st.permutations(range(a.ndim)), label="axes"))
    for fn in api(backend, "permute_dims"):
        _exact(fn(native(a, backend), axes), np.transpose(a, axes), backend)


@HYPOTHESIS
@given(data=st.data())
def test_transpose(backend, data):
    """The paper's spelling: axes=None reverses the axes."""
    a = _array(data)
    axes = tuple(data.draw(st.permutations(range(a.ndim)), label="axes"))
    for fn in api(backend, "transpose"):
        _exact(fn(native(a, backend)), a.T, backend)
        _exact(fn(native(a, backend), axes), np.transpose(a, axes), backend)


@pytest.mark.parametrize("name", ["concat", "concatenate"])
@HYPOTHESIS
@given(data=st.data())
def test_concat(backend, name, data):
    base = _array(data, SHAPES_1D_PLUS)
    axis = data.draw(st.integers(-base.ndim, base.ndim - 1), label="axis")
    sizes = data.draw(st.lists(st.integers(0, 3), min_size=1, max_size=3), label="sizes")
    pieces = []
    for size in sizes:
        shape = list(base.shape)
        shape[axis] = size
        piece = np.arange(math.prod(shape), dtype=base.dtype).reshape(shape) + len(pieces)
        pieces.append(piece)
    expected = np.concatenate(pieces, axis=axis)
    for fn in api(backend, name):
        _exact(fn([native(p, backend) for p in pieces], axis=axis), expected, backend)
        _exact(fn(tuple(native(p, backend) for p in pieces), axis=axis), expected, backend)


@pytest.mark.parametrize("name", ["concat", "concatenate"])
def test_concat_default_axis_and_axis_none(backend, name):
    a = np.arange(6, dtype=np.float32).reshape(2, 3)
    b = np.arange(3, dtype=np.float32).reshape(1, 3) - 10
    c = np.array([[[7.5]]], dtype=np.float32)
    for fn in api(backend, name):
        x, y, z = native(a, backend), native(b, backend), native(c, backend)
        _exact(fn([x, y]), np.concatenate([a, b]), backend)
        _exact(fn([x, y, z], axis=None), np.concatenate([a, b, c], axis=None), backend)


@HYPOTHESIS
@given(data=st.data())
def test_stack(backend, data):
    a = _array(data)
    count = data.draw(st.integers(1, 3), label="count")
    axis = data.draw(st.integers(-a.ndim - 1, a.ndim), label="axis")
    pieces = [a + i for i in range(count)]
    for fn in api(backend, "stack"):
        _exact(fn([native(p, backend) for p in pieces], axis=axis), np.stack(pieces, axis), backend)
    _exact(api(backend, "stack")[0]([native(a, backend)] * 2), np.stack([a, a]), backend)


@HYPOTHESIS
@given(data=st.data())
def test_unstack(backend, data):
    a = _array(data, SHAPES_1D_PLUS)
    axis = data.draw(st.integers(-a.ndim, a.ndim - 1), label="axis")
    expected = [np.take(a, i, axis=axis) for i in range(a.shape[axis])]
    for fn in api(backend, "unstack"):
        out = fn(native(a, backend), axis=axis)
        assert isinstance(out, tuple), f"unstack returned {type(out).__name__}, not a tuple"
        assert len(out) == len(expected)
        for piece, want in zip(out, expected):
            _exact(piece, want, backend)


@HYPOTHESIS
@given(data=st.data())
def test_split(backend, data):
    a = _array(data, SHAPES_1D_PLUS)
    axis = data.draw(st.integers(-a.ndim, a.ndim - 1), label="axis")
    n = a.shape[axis]
    equal_pieces = [d for d in range(1, n + 1) if n % d == 0]
    mode = data.draw(st.sampled_from(["count", "sizes", "none"] if n else ["sizes"]))
    if mode == "count":
        arg = data.draw(st.sampled_from(equal_pieces), label="num")
        bounds = [n // arg * i for i in range(1, arg)]
    elif mode == "sizes":
        cuts = sorted(data.draw(st.lists(st.integers(0, n), max_size=3), label="cuts"))
        arg = [hi - lo for lo, hi in zip([0, *cuts], [*cuts, n])]
        bounds = cuts
    else:
        arg, bounds = None, list(range(1, n))
    expected = np.split(a, bounds, axis=axis)
    for fn in api(backend, "split"):
        out = fn(native(a, backend), arg, axis=axis)
        assert isinstance(out, list), f"split returned {type(out).__name__}, not a list"
        assert len(out) == len(expected)
        for piece, want in zip(out, expected):
            _exact(piece, want, backend)


def test_split_default_is_pieces_of_size_one(backend):
    a = np.arange(6.0).reshape(3, 2)
    for fn in api(backend, "split"):
        out = fn(native(a, backend))
        assert len(out) == 3
        for i, piece in enumerate(out):
            _exact(piece, a[i : i + 1], backend)
        out = fn(native(a, backend), num_or_size_splits=[1, 1], axis=1)
        _exact(out[1], a[:, 1:], backend)


@pytest.mark.parametrize("shape, num, axis", [((5,), 2, 0), ((2, 3), 2, 1), ((7, 2), 3, -2)])
def test_split_into_unequal_pieces_raises_value_error(backend, shape, num, axis):
    x = native(np.zeros(shape, np.float32), backend)
    for fn in api(backend, "split"):
        with pytest.raises(ValueError):
            fn(x, num, axis=axis)


SQUEEZABLE = [(1,), (1, 3), (2, 1, 3), (1, 1), (3, 1, 1, 2), (1, 0)]


@HYPOTHESIS
@given(data=st.data())
def test_squeeze(backend, data):
    a = _array(data, SQUEEZABLE)
    ones = [i for i, s in enumerate(a.shape) if s == 1]
    one = st.sampled_from(ones).flatmap(lambda i: st.sampled_from([i, i - a.ndim]))
    axis = data.draw(one | st.lists(st.sampled_from(ones), min_size=1, unique=True).map(tuple))
    for fn in api(backend, "squeeze"):
        _exact(fn(native(a, backend), axis), np.squeeze(a, axis), backend)
        _exact(fn(native(a, backend), axis=axis), np.squeeze(a, axis), backend)
    _exact(api(backend, "squeeze")[0](native(a, backend)), np.squeeze(a), backend)


@HYPOTHESIS
@given(data=st.data())
def test_expand_dims(backend, data):
    a = _array(data)
    axis = data.draw(st.integers(-a.ndim - 1, a.ndim), label="axis")
    for fn in api(backend, "expand_dims"):
        _exact(fn(native(a, backend), axis=axis), np.expand_dims(a, axis), backend)
    _exact(api(backend, "expand_dims")[0](native(a, backend)), a[None], backend)


@HYPOTHESIS
@given(data=st.data())
def test_flip(backend, data):
    a = _array(data)
    axis = data.draw(axis_arguments(a.ndim), label="axis")
    for fn in api(backend, "flip"):
        _exact(fn(native(a, backend), axis=axis), np.flip(a, axis), backend)
    _exact(api(backend, "flip")[0](native(a, backend)), np.flip(a), backend)


@HYPOTHESIS
@given(data=st.data())
def test_tile(backend, data):
    a = _array(data)
    length = data.draw(st.sampled_from([a.ndim, a.ndim + 1]).filter(bool), label="length")
    reps = tuple(data.draw(st.lists(st.integers(0, 3), min_size=length, max_size=length)))
    for fn in api(backend, "tile"):
        _exact(fn(native(a, backend), reps), np.tile(a, reps), backend)


@HYPOTHESIS
@given(data=st.data())
def test_repeat(backend, data):
    a = _array(data)
    repeats = data.draw(st.integers(0, 3), label="repeats")
    axis = data.draw(axis_arguments(a.ndim, tuples=False), label="axis")
    for fn in api(backend, "repeat"):
        _exact(fn(native(a, backend), repeats, axis=axis), np.repeat(a, repeats, axis), backend)
    _exact(api(backend, "repeat")[0](native(a, backend), 2), np.repeat(a, 2), backend)


@HYPOTHESIS
@given(data=st.data())
def test_roll(backend, data):
    a = _array(data)
    axis = data.draw(axis_arguments(a.ndim), label="axis")
    if isinstance(axis, tuple):
        shift = tuple(data.draw(st.integers(-7, 7)) for _ in axis)
    else:
        shift = data.draw(st.integers(-7, 7), label="shift")
    for fn in api(backend, "roll"):
        _exact(fn(native(a, backend), shift, axis=axis), np.roll(a, shift, axis), backend)
    _exact(api(backend, "roll")[0](native(a, backend), shift=3), np.roll(a, 3), backend)


@HYPOTHESIS
@given(data=st.data())
def test_swapaxes(backend, data):
    a = _array(data, SHAPES_1D_PLUS)
    axis0, axis1 = (data.draw(st.integers(-a.ndim, a.ndim - 1)) for _ in range(2))
    for fn in api(backend, "swapaxes"):
        _exact(fn(native(a, backend), axis0, axis1), np.swapaxes(a, axis0, axis1), backend)


@HYPOTHESIS
@given(data=st.data())
def test_broadcast_to(backend, data):
    a = _array(data)
    leading = data.draw(st.lists(st.integers(1, 3), max_size=2), label="leading")
    grown = [data.draw(st.integers(0, 3)) if s == 1 else s for s in a.shape]
    shape = (*leading, *grown)
    for fn in api(backend, "broadcast_to"):
        _exact(fn(native(a, backend), shape), np.broadcast_to(a, shape), backend)
        _exact(fn(native(a, backend), shape=shape), np.broadcast_to(a, shape), backend)


FEW = settings(HYPOTHESIS, max_examples=20)


SHAPES_manipulation_api = [(4,), (0,), (2, 3), (2, 1, 3), (1, 2, 0), (2, 3, 1, 2)]


def _exact_manipulation_api(out, expected, backend):
    check(out, expected, backend, rtol=0, atol=0, signed_zeros=True)


def _array_manipulation_api(data, shapes):
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
    a = _array_manipulation_api(data, SHAPES_manipulation_api)
    n = a.ndim
    count = data.draw(st.integers(1, n), label="number of axes")
    source = data.draw(st.permutations(range(n)), label="source")[:count]
    destination = data.draw(st.permutations(range(n)), label="destination")[:count]
    source = [s - n if data.draw(st.booleans(), label="negative") else s for s in source]
    expected = _moveaxis_reference(a, source, destination)
    for fn in api(backend, "moveaxis"):
        _exact_manipulation_api(
            fn(native(a, backend), tuple(source), tuple(destination)), expected, backend
        )
        if count == 1:
            _exact_manipulation_api(
                fn(native(a, backend), source[0], destination[0]), expected, backend
            )


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
            _exact_manipulation_api(o, expected, backend)


def test_broadcast_arrays_refuses_incompatible_shapes(backend):
    x, y = native(np.zeros(2), backend), native(np.zeros(3), backend)
    for fn in api(backend, "broadcast_arrays"):
        with pytest.raises(Exception):  # noqa: B017 - each framework raises its own error
            fn(x, y)


def test_broadcast_arrays_with_f(backend):
    out = ivy.broadcast_arrays(np.zeros((2, 1)), np.ones(3), f=backend)
    _exact_manipulation_api(out[1], np.ones((2, 3)), backend)


@pytest.mark.parametrize("name", ["stack", "concat"])
def test_nothing_to_join_raises(backend, name):
    """(tensorflow stacked no arrays into an empty float32 array)"""
    with pytest.raises(ValueError):
        getattr(ivy, name)([], f=backend)
    with pytest.raises(ValueError):
        getattr(getattr(ivy, backend), name)([])


@pytest.mark.parametrize("axis", [2, -3, 5])
def test_expand_dims_of_an_axis_out_of_range_raises_index_error(backend, axis):
    """As the standard's tests ask (jax's own raised ValueError): ivy's AxisError is both."""
    for fn in api(backend, "expand_dims"):
        with pytest.raises(IndexError):
            fn(native(np.zeros((3,), np.float32), backend), axis=axis)
