"""Tests of the core group ``interpolation`` (``ivy/core/interpolation.py``), on every backend.

Ivy's own functions beyond the Array API, on every backend, against references written here
with Python loops or plain numpy float64: gather_flat, scatter_flat, indices_where, cumsum,
cumprod, einsum, constant_pad, zero_pad, linear_resample, interp, vector_to_skew_symmetric_matrix,
cosine_similarity, clip_vector_norm, clip_by_global_norm, nan_to_num, isclose, allclose and
to_framework.
"""

from __future__ import annotations

import numpy as np
import pytest

import ivy
from tests.helpers import (
    api,
    check,
    check_gradients,
    native,
    tolerance,
)


def _resample_reference(x, num_samples, axis):
    moved = np.moveaxis(x.astype(np.float64), axis, -1)
    n = moved.shape[-1]
    positions = np.linspace(0, n - 1, num_samples) if num_samples > 1 else np.zeros(1)
    out = np.empty((*moved.shape[:-1], num_samples))
    for index in np.ndindex(moved.shape[:-1]):
        out[index] = np.interp(positions, np.arange(n), moved[index])
    return np.moveaxis(out, -1, axis)


@pytest.mark.parametrize("dtype", ["float32", "float64"])
@pytest.mark.parametrize(
    "shape, num_samples, axis",
    [((5,), 9, -1), ((5,), 3, 0), ((2, 4), 7, 1), ((3, 2, 4), 5, 0), ((2, 1), 4, -1), ((4,), 1, 0)],
    ids=str,
)
def test_linear_resample(backend, dtype, shape, num_samples, axis):
    x = (np.random.default_rng(3).standard_normal(shape) * 4).astype(dtype)
    expected = _resample_reference(x, num_samples, axis)
    for fn in api(backend, "linear_resample"):
        out = fn(native(x, backend), num_samples, axis=axis)
        check(out, expected.astype(dtype), backend, **tolerance(dtype, 10))


def test_linear_resample_keeps_the_end_points_and_computes_integers_in_float32(backend):
    x = np.array([0, 10], np.int64)
    for fn in api(backend, "linear_resample"):
        check(fn(native(x, backend), 5), np.array([0, 2.5, 5, 7.5, 10], np.float32), backend)


KNOTS = np.array([-1.0, 0.0, 0.5, 2.0, 3.5])


VALUES = np.array([2.0, -1.0, 0.0, 4.0, 1.0])


INTERP_X = {
    "inside": 1.25,
    "knots and ends": [-1.0, 0.0, 0.5, 2.0, 3.5],
    "outside and nan": [-3.0, 4.0, np.nan, 3.49],
    "2-D": np.random.default_rng(8).uniform(-2.0, 5.0, (3, 4)),
    "empty": np.zeros((2, 0)),
}


@pytest.mark.parametrize("dtype", ["float32", "float64"])
@pytest.mark.parametrize("x", list(INTERP_X.values()), ids=list(INTERP_X))
@pytest.mark.parametrize("bounds", [{}, {"left": -7.0, "right": 9.0}], ids=["default", "given"])
def test_interp(backend, dtype, x, bounds):
    x = np.asarray(x, dtype)
    expected = np.interp(x.astype(np.float64), KNOTS, VALUES, **bounds).astype(dtype)
    args = [native(v.astype(dtype), backend) for v in (x, KNOTS, VALUES)]
    for fn in api(backend, "interp"):
        check(fn(*args, **bounds), expected, backend)


def test_interp_of_one_point_integers_and_a_python_scalar(backend):
    x = native(np.array([-1.0, 2.0, 3.0, np.nan]), backend)
    for fn in api(backend, "interp"):
        one = fn(x, native(np.array([2.0]), backend), native(np.array([5.0]), backend), right=0.0)
        check(one, np.array([5.0, 5.0, 0.0, np.nan]), backend)
        ints = fn(
            native(np.array([1, 3]), backend),
            native(np.array([0, 2, 4]), backend),
            native(np.array([0, 10, 0]), backend),
        )
        check(ints, np.array([5.0, 5.0], np.float32), backend)
        scalar = fn(0.25, native(KNOTS, backend), native(VALUES, backend))
        check(scalar, np.array(np.interp(0.25, KNOTS, VALUES)), backend)
        with pytest.raises(ValueError, match="same length"):
            fn(x, native(KNOTS, backend), native(VALUES[:3], backend))


def test_interp_gradients(diff_backend):
    knots = native(KNOTS, diff_backend)

    def fn(x, values):
        return ivy.interp(x, knots, values)

    x = np.array([[-0.7, 0.2, 1.1], [2.9, 3.3, 0.3]])  # inside segments, away from the knots
    check_gradients(diff_backend, fn, [x, VALUES], n_directions=2)
