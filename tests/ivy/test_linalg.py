"""Linear algebra against numpy float64 references, on every backend.

Matrices are well conditioned (orthogonal factors times singular values in [1, 3]) so that the
float32 tolerance of the table applies without scaling by a condition number.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from tests.helpers import (
    HYPOTHESIS,
    api,
    cast,
    check,
    check_meta,
    native,
    numpy_of,
    reference,
    tolerance,
)
from tests.ivy.strategies import FLOAT_DTYPES, arrays, axis_arguments, reals

RNG_SEED = 1234


def _random(shape, dtype, seed=0):
    return np.random.default_rng(RNG_SEED + seed).standard_normal(shape).astype(dtype)


def _well_conditioned(batch, n, dtype, seed=0):
    rng = np.random.default_rng(RNG_SEED + seed)
    q1, _ = np.linalg.qr(rng.standard_normal((*batch, n, n)))
    q2, _ = np.linalg.qr(rng.standard_normal((*batch, n, n)))
    s = rng.uniform(1, 3, (*batch, 1, n))
    return ((q1 * s) @ q2).astype(dtype)


# ----------------------------------------------------------------------------------------------
# matmul
# ----------------------------------------------------------------------------------------------

MATMUL_SHAPES = [
    ((3, 4), (4, 2)),
    ((2, 3, 4), (4, 5)),  # batch on the left only
    ((2, 1, 3, 4), (5, 4, 2)),  # batch broadcasting
    ((4,), (4, 3)),  # vector @ matrix
    ((2, 3, 4), (4,)),  # matrix @ vector
    ((4,), (4,)),  # dot product: 0-d
    ((3, 0), (0, 2)),  # empty inner dimension: zeros
]


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
@pytest.mark.parametrize("shapes", MATMUL_SHAPES, ids=str)
def test_matmul(backend, dtype, shapes):
    a, b = _random(shapes[0], dtype, 1), _random(shapes[1], dtype, 2)
    expected = cast(np.matmul(a.astype(np.float64), b.astype(np.float64)), dtype)
    for fn in api(backend, "matmul"):
        check(fn(native(a, backend), native(b, backend)), expected, backend, **tolerance(dtype, 10))


def test_matmul_of_integers(backend):
    a = np.arange(6, dtype=np.int64).reshape(2, 3)
    b = np.arange(12, dtype=np.int64).reshape(3, 4) - 5
    for fn in api(backend, "matmul"):
        check(fn(native(a, backend), native(b, backend)), a @ b, backend)


# ----------------------------------------------------------------------------------------------
# cross
# ----------------------------------------------------------------------------------------------


def _cross_reference(a, b, axis):
    a, b = np.moveaxis(a, axis, -1), np.moveaxis(b, axis, -1)
    a, b = np.broadcast_arrays(a, b)
    out = np.stack(
        [
            a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1],
            a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2],
            a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0],
        ],
        axis=-1,
    )
    return np.moveaxis(out, -1, axis)


@HYPOTHESIS
@given(data=st.data())
def test_cross(backend, data):
    dtype = data.draw(st.sampled_from(FLOAT_DTYPES), label="dtype")
    shape_a, shape_b, axis = data.draw(
        st.sampled_from(
            [((3,), (3,), -1), ((4, 3), (4, 3), -1), ((2, 1, 3), (5, 3), -1), ((3, 2), (3, 2), 0)]
        ),
        label="shapes, axis",
    )
    a = data.draw(arrays(dtype, reals(dtype, -10, 10, specials=False), shape_a), label="x1")
    b = data.draw(arrays(dtype, reals(dtype, -10, 10, specials=False), shape_b), label="x2")
    expected = cast(_cross_reference(a.astype(np.float64), b.astype(np.float64), axis), dtype)
    for fn in api(backend, "cross"):
        out = fn(native(a, backend), native(b, backend), axis=axis)
        check(out, expected, backend, **tolerance(dtype, 400))
    if axis == -1:
        out = api(backend, "cross")[0](native(a, backend), native(b, backend))
        check(out, expected, backend, **tolerance(dtype, 400))


def test_cross_of_the_basis(backend):
    e = np.eye(3)
    x = native(e, backend)
    for fn in api(backend, "cross"):
        check(fn(x, native(np.roll(e, -1, axis=0), backend)), np.roll(e, -2, axis=0), backend)


# ----------------------------------------------------------------------------------------------
# svd, inv, pinv
# ----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
@pytest.mark.parametrize("shape", [(3, 3), (4, 2), (2, 5), (2, 3, 4)], ids=str)
@pytest.mark.parametrize("full_matrices", [True, False])
def test_svd(backend, dtype, shape, full_matrices):
    a = _random(shape, dtype, 3)
    a64 = a.astype(np.float64)
    m, n = shape[-2:]
    k = min(m, n)
    s_expected = np.linalg.svd(a64, compute_uv=False)
    tol = tolerance(dtype, 10 * np.abs(a64).max())
    for fn in api(backend, "svd"):
        u, s, vh = fn(native(a, backend), full_matrices=full_matrices)
        rows, cols = (m, n) if full_matrices else (k, k)
        check(s, cast(s_expected, dtype), backend, **tol)
        check_meta(u, backend, dtype, (*shape[:-2], m, rows))
        check_meta(vh, backend, dtype, (*shape[:-2], cols, n))
        u, s, vh = (numpy_of(t).astype(np.float64) for t in (u, s, vh))
        assert np.all(np.diff(s, axis=-1) <= 0), "singular values are not descending"
        reconstructed = (u[..., :, :k] * s[..., None, :]) @ vh[..., :k, :]
        np.testing.assert_allclose(reconstructed, a64, **tol)
        for q in (np.swapaxes(u, -1, -2) @ u, vh @ np.swapaxes(vh, -1, -2)):  # orthonormal
            np.testing.assert_allclose(q, np.broadcast_to(np.eye(q.shape[-1]), q.shape), **tol)
    u, s, vh = api(backend, "svd")[0](native(a, backend))  # full_matrices=True by default
    assert numpy_of(u).shape[-1] == m and numpy_of(vh).shape[-2] == n


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
@pytest.mark.parametrize("batch", [(), (2,), (2, 3)], ids=str)
def test_inv(backend, dtype, batch):
    a = _well_conditioned(batch, 3, dtype, 4)
    expected = cast(np.linalg.inv(a.astype(np.float64)), dtype)
    for fn in api(backend, "inv"):
        check(fn(native(a, backend)), expected, backend, **tolerance(dtype, 10))


def _pinv_reference(a, rtol):
    """V diag(1/s) U^T over the singular values s > rtol * max(s)."""
    u, s, vh = np.linalg.svd(a, full_matrices=False)
    keep = s > rtol * s.max(axis=-1, keepdims=True)
    s_inv = np.where(keep, 1 / np.where(keep, s, 1), 0)
    return np.swapaxes(vh, -1, -2) @ (s_inv[..., :, None] * np.swapaxes(u, -1, -2))


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
@pytest.mark.parametrize("shape", [(3, 3), (4, 2), (2, 5), (2, 3, 4)], ids=str)
def test_pinv_of_full_rank_matrices(backend, dtype, shape):
    rng = np.random.default_rng(RNG_SEED + 5)
    m, n = shape[-2:]
    k = min(m, n)
    u, _ = np.linalg.qr(rng.standard_normal((*shape[:-2], m, k)))
    v, _ = np.linalg.qr(rng.standard_normal((*shape[:-2], n, k)))
    a = ((u * rng.uniform(1, 3, k)) @ np.swapaxes(v, -1, -2)).astype(dtype)
    expected = cast(_pinv_reference(a.astype(np.float64), 1e-6), dtype)
    for fn in api(backend, "pinv"):
        check(fn(native(a, backend)), expected, backend, **tolerance(dtype, 10))


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
def test_pinv_drops_singular_values_below_rtol_times_the_largest(backend, dtype):
    """Singular values 2, 1 and 1e-2: the last is dropped with rtol=1e-1, kept with 1e-3."""
    rng = np.random.default_rng(RNG_SEED + 6)
    u, _ = np.linalg.qr(rng.standard_normal((4, 3)))
    v, _ = np.linalg.qr(rng.standard_normal((3, 3)))
    a = ((u * np.array([2.0, 1.0, 1e-2])) @ v.T).astype(dtype)
    for rtol, scale in ((1e-1, 10), (1e-3, 1e4)):  # a kept 1/1e-2 amplifies rounding
        expected = cast(_pinv_reference(a.astype(np.float64), rtol), dtype)
        for fn in api(backend, "pinv"):
            check(fn(native(a, backend), rtol=rtol), expected, backend, **tolerance(dtype, scale))


# ----------------------------------------------------------------------------------------------
# vector_norm and its alias norm
# ----------------------------------------------------------------------------------------------


def _norm_reference(a, axis, keepdims, ord):
    a = np.abs(np.asarray(a, np.float64))
    if ord == np.inf:
        out = np.max(a, axis=axis, keepdims=keepdims)
    elif ord == -np.inf:
        out = np.min(a, axis=axis, keepdims=keepdims)
    else:
        out = np.sum(a**ord, axis=axis, keepdims=keepdims) ** (1 / ord)
    return out


@pytest.mark.parametrize("name", ["vector_norm", "norm"])
@HYPOTHESIS
@given(data=st.data())
def test_vector_norm(backend, name, data):
    dtype = data.draw(st.sampled_from(FLOAT_DTYPES), label="dtype")
    shape = data.draw(st.sampled_from([(5,), (2, 3), (2, 1, 3), (3, 4)]), label="shape")
    a = data.draw(arrays(dtype, reals(dtype, -10, 10, specials=False), shape), label="x")
    axis = data.draw(axis_arguments(a.ndim), label="axis")
    keepdims = data.draw(st.booleans(), label="keepdims")
    order = data.draw(st.sampled_from([2, 1, 3, 0.5, np.inf, -np.inf]), label="ord")
    expected = cast(reference(_norm_reference, a, axis, keepdims, order), dtype)
    for fn in api(backend, name):
        out = fn(native(a, backend), axis=axis, keepdims=keepdims, ord=order)
        check(out, expected, backend, **tolerance(dtype, 100))


@pytest.mark.parametrize("name", ["vector_norm", "norm"])
def test_vector_norm_defaults_to_the_2_norm_of_all_elements(backend, name):
    a = np.array([[3.0, 0.0], [0.0, -4.0]], dtype=np.float32)
    for fn in api(backend, name):
        check(fn(native(a, backend)), np.float32(5.0), backend)
        check(fn(native(a, backend), axis=1), np.array([3.0, 4.0], np.float32), backend)
