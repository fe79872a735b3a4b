"""Tests of the core group ``cumulative`` (``ivy/core/cumulative.py``), on every backend.

Ivy's own functions beyond the Array API, on every backend, against references written here
with Python loops or plain numpy float64: gather_flat, scatter_flat, indices_where, cumsum,
cumprod, einsum, constant_pad, zero_pad, linear_resample, interp, vector_to_skew_symmetric_matrix,
cosine_similarity, clip_vector_norm, clip_by_global_norm, nan_to_num, isclose, allclose and
to_framework.
"""

from __future__ import annotations

import itertools
import operator

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import ivy
from tests.helpers import (
    HYPOTHESIS,
    api,
    check,
    check_gradients,
    native,
    tolerance,
)
from tests.ivy.strategies import arrays, quarters

# input dtype -> accumulated dtype (dtype=None)
ACCUMULATED = {
    "float32": "float32",
    "float64": "float64",
    "int32": "int64",
    "int64": "int64",
    "int8": "int64",
    "uint8": "uint64",
    "bool": "int64",
}


def _cumulative_reference(x, axis, exclusive, reverse, op, identity):
    """Along ``axis``, with Python's itertools.accumulate on float64 values."""
    moved = np.moveaxis(x.astype(np.float64), axis, -1)
    out = np.empty(moved.shape, np.float64)
    for index in np.ndindex(moved.shape[:-1]):
        line = list(moved[index])
        if reverse:
            line = line[::-1]
        acc = list(itertools.accumulate(line, op))
        if exclusive:
            acc = [identity] + acc[:-1]
        out[index] = acc[::-1] if reverse else acc
    return np.moveaxis(out, -1, axis)


@pytest.mark.parametrize("name", ["cumsum", "cumprod"])
@HYPOTHESIS
@given(data=st.data())
def test_cumsum_and_cumprod(backend, name, data):
    dtype = data.draw(st.sampled_from(list(ACCUMULATED)), label="dtype")
    shape = data.draw(st.sampled_from([(5,), (2, 3), (3, 1, 4), (0, 3)]), label="shape")
    if dtype == "bool":
        elements = st.booleans()
    elif dtype.startswith("float"):
        elements = quarters(-2, 2)
    else:
        elements = st.integers(0 if dtype.startswith("u") else -3, 3)
    x = data.draw(arrays(dtype, elements, st.just(shape)), label="x")
    axis = data.draw(st.integers(-len(shape), len(shape) - 1), label="axis")
    exclusive = data.draw(st.booleans(), label="exclusive")
    reverse = data.draw(st.booleans(), label="reverse")
    op, identity = (operator.add, 0) if name == "cumsum" else (operator.mul, 1)
    expected = _cumulative_reference(x, axis, exclusive, reverse, op, identity)
    want = ACCUMULATED[dtype]
    for fn in api(backend, name):
        out = fn(native(x, backend), axis=axis, exclusive=exclusive, reverse=reverse)
        check(
            out,
            expected.astype(want),
            backend,
            **tolerance(want, 10) if want.startswith("f") else {},
        )


def test_the_docstring_examples(backend):
    x = native(np.array([1, 2, 3], np.int64), backend)
    check(ivy.cumsum(x, exclusive=True), np.array([0, 1, 3], np.int64), backend)
    check(ivy.cumprod(x, reverse=True), np.array([6, 6, 3], np.int64), backend)
    check(ivy.cumsum(x, exclusive=True, reverse=True), np.array([5, 3, 0], np.int64), backend)


@pytest.mark.parametrize(
    "a",
    [
        [2.0, 0.0, 3.0],
        [0.0, 0.0, 2.0],
        [1.0, 2.0, 0.0],
        [[2.0, 0.0, 3.0, 4.0], [0.0, 1.5, 0.0, 2.0]],
    ],
    ids=["one zero", "two zeros", "last zero", "2-d"],
)
@pytest.mark.parametrize(
    "call",
    [
        lambda x: ivy.cumulative_prod(x, axis=-1),
        lambda x: ivy.cumulative_prod(x, axis=-1, include_initial=True),
        lambda x: ivy.cumprod(x, axis=-1, exclusive=True),
        lambda x: ivy.cumprod(x, axis=-1, reverse=True),
        lambda x: ivy.cumprod(x, axis=-1, exclusive=True, reverse=True),
    ],
    ids=["cumulative_prod", "include_initial", "exclusive", "reverse", "exclusive reverse"],
)
def test_gradients_of_products_through_zeros(diff_backend, a, call):
    """A product is a polynomial: its gradient at a zero is finite (d/dx1 of
    sum(cumprod([2, x1, 3])) at 0 is 8). tensorflow's own divides by x there and gave 0."""
    check_gradients(diff_backend, call, [np.array(a)], n_directions=3)
