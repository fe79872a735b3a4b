"""Tests of the core group ``padding`` (``ivy/core/padding.py``), on every backend.

Ivy's own functions beyond the Array API, on every backend, against references written here
with Python loops or plain numpy float64: gather_flat, scatter_flat, indices_where, cumsum,
cumprod, einsum, constant_pad, zero_pad, linear_resample, interp, vector_to_skew_symmetric_matrix,
cosine_similarity, clip_vector_norm, clip_by_global_norm, nan_to_num, isclose, allclose and
to_framework.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from tests.helpers import (
    api,
    check,
    native,
)


def _pad_reference(x, pad_width, value):
    shape = tuple(n + b + a for n, (b, a) in zip(x.shape, pad_width))
    out = np.full(shape, value, x.dtype)
    out[tuple(slice(b, b + n) for n, (b, _) in zip(x.shape, pad_width))] = x
    return out


PAD_CASES = [
    ((3,), [(1, 2)]),
    ((2, 3), [(0, 1), (2, 0)]),
    ((2, 1, 3), [(1, 1), (0, 0), (3, 2)]),
    ((0, 2), [(1, 0), (1, 1)]),
    ((), []),
]


@pytest.mark.parametrize("dtype", ["float32", "int64", "bool"])
@pytest.mark.parametrize("case", PAD_CASES, ids=str)
def test_constant_pad_and_zero_pad(backend, dtype, case):
    shape, pad_width = case
    x = (np.arange(math.prod(shape)).reshape(shape) % 3 + 1).astype(dtype)
    value = {"float32": -1.5, "int64": 7, "bool": True}[dtype]
    for fn in api(backend, "constant_pad"):
        out = fn(native(x, backend), pad_width, value=value)
        check(out, _pad_reference(x, pad_width, value), backend)
    for fn in api(backend, "zero_pad"):
        check(fn(native(x, backend), pad_width), _pad_reference(x, pad_width, 0), backend)


@pytest.mark.parametrize(
    "pad_width", [[(1, 1)], [(1, 1), (0, 0), (0, 0)], [(-1, 0), (0, 0)]], ids=str
)
def test_constant_pad_refuses_bad_widths(backend, pad_width):
    x = native(np.ones((2, 2), np.float32), backend)
    for fn in api(backend, "constant_pad"):
        with pytest.raises(ValueError, match="pad"):
            fn(x, pad_width)
