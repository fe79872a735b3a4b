"""Tests of the core group ``linalg`` (``ivy/core/linalg.py``), on every backend.

Linear algebra against numpy float64 references, on every backend.

Matrices are well conditioned (orthogonal factors times singular values in [1, 3]) so that the
float32 tolerance of the table applies without scaling by a condition number.

The Array API ``linalg`` extension (beyond matmul, cross, svd, inv, pinv and vector_norm, which
are in test_linalg.py) against numpy float64 references, on every backend; and the ``ivy.linalg``
and ``ivy.<backend>.linalg`` namespaces.

Matrices are well conditioned (orthogonal factors times singular values in [1, 3]) so that the
float32 tolerance of the table applies without scaling by a condition number.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import ivy
from ivy.core import linalg as core_linalg
from tests.conftest import require
from tests.helpers import (
    HYPOTHESIS,
    api,
    cast,
    check,
    check_meta,
    dtype_name,
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


MATMUL_SHAPES = [
    ((3, 4), (4, 2)),
    ((2, 3, 4), (4, 5)),  # batch on the left only
    ((2, 1, 3, 4), (5, 4, 2)),  # batch broadcasting
    ((4,), (4, 3)),  # vector @ matrix
    ((2, 3, 4), (4,)),  # matrix @ vector
    ((4,), (4,)),  # dot product: 0-d
    ((3, 0), (0, 2)),  # empty inner dimension: zeros
    # broadcast batches on which tensorflow 2.21's oneDNN kernel corrupts the heap (float32)
    ((8, 1, 3, 3), (1, 3, 1)),
    ((8, 1, 3, 3), (3, 1)),
    ((8, 1, 3, 3), (1, 1, 3, 3)),
    ((3, 3), (8, 1, 3, 1)),
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


RNG_SEED_linalg_ext = 4321


EXTENSION = [
    "cholesky", "cross", "det", "diagonal", "eigh", "eigvalsh", "inv", "matmul", "matrix_norm",
    "matrix_power", "matrix_rank", "matrix_transpose", "outer", "pinv", "qr", "slogdet", "solve",
    "svd", "svdvals", "tensordot", "trace", "vecdot", "vector_norm",
]  # fmt: skip


def _alternating(cases, dtypes=FLOAT_DTYPES):
    """``(dtype, case)`` pairs, the dtypes taking turns: every case and dtype, few compilations
    (jax compiles each function once per shape and dtype)."""
    return [(dtypes[i % len(dtypes)], case) for i, case in enumerate(cases)]


def _random(shape, dtype, seed=0):
    return np.random.default_rng(RNG_SEED_linalg_ext + seed).standard_normal(shape).astype(dtype)


def _orthogonal(batch, n, rng):
    q, _ = np.linalg.qr(rng.standard_normal((*batch, n, n)))
    return q


def _well_conditioned_linalg_ext(batch, n, dtype, seed=0):
    rng = np.random.default_rng(RNG_SEED_linalg_ext + seed)
    s = rng.uniform(1, 3, (*batch, 1, n)) * np.where(np.arange(n) == 0, -1, 1)  # det < 0 too
    return ((_orthogonal(batch, n, rng) * s) @ _orthogonal(batch, n, rng)).astype(dtype)


def _symmetric(batch, n, dtype, seed=0, positive=False):
    """Symmetric matrices with well separated eigenvalues (all in [1, 2n] when ``positive``)."""
    rng = np.random.default_rng(RNG_SEED_linalg_ext + seed)
    q = _orthogonal(batch, n, rng)
    values = np.arange(1, n + 1) * 2.0 - (0 if positive else n)
    return ((q * values) @ np.swapaxes(q, -1, -2)).astype(dtype)


def _f64(a):
    return np.asarray(a, np.float64)


def test_the_linalg_namespace_holds_the_agnostic_functions():
    assert sorted(EXTENSION) == sorted(n for n in core_linalg.__all__ if n != "norm")
    for name in EXTENSION:
        assert getattr(ivy.linalg, name) is getattr(ivy, name), name
    assert ivy.linalg.norm is ivy.vector_norm  # the paper's alias
    assert "linalg" in ivy.__all__ and set(dir(ivy.linalg)) == set(core_linalg.__all__)
    with pytest.raises(AttributeError):
        ivy.linalg.sin  # noqa: B018 - not of the extension


def test_each_backend_has_a_linalg_namespace_of_its_own_functions(backend, xp):
    assert "linalg" in xp.__all__
    for name in EXTENSION:
        assert getattr(xp.linalg, name) is getattr(xp, name), name
    assert xp.linalg.__name__ == f"ivy.{backend}.linalg"


def test_set_framework_binds_the_backend_linalg_namespace(backend, xp):
    with ivy.set_framework(backend):
        assert ivy.linalg is xp.linalg
        assert ivy.linalg.det is xp.det
    assert ivy.linalg.det is ivy.core.det


@pytest.mark.parametrize("dtype, batch", _alternating([(), (2,), (2, 3)]), ids=str)
def test_cholesky(backend, dtype, batch):
    a = _symmetric(batch, 4, dtype, 1, positive=True)
    lower = np.linalg.cholesky(_f64(a))
    tol = tolerance(dtype, 10)
    for fn in api(backend, "cholesky"):
        check(fn(native(a, backend)), cast(lower, dtype), backend, **tol)
        upper = fn(native(a, backend), upper=True)
        check(upper, cast(np.swapaxes(lower, -1, -2), dtype), backend, **tol)


@pytest.mark.parametrize("dtype, batch", _alternating([(), (3,)]), ids=str)
def test_eigh_and_eigvalsh(backend, dtype, batch):
    a = _symmetric(batch, 4, dtype, 2)
    values = np.linalg.eigvalsh(_f64(a))
    tol = tolerance(dtype, 40)
    for fn in api(backend, "eigvalsh"):
        check(fn(native(a, backend)), cast(values, dtype), backend, **tol)
    for fn in api(backend, "eigh"):
        out = fn(native(a, backend))
        w, v = out  # a namedtuple (eigenvalues, eigenvectors)
        assert out.eigenvalues is w and out.eigenvectors is v
        check(w, cast(values, dtype), backend, **tol)
        check_meta(v, backend, dtype, a.shape)
        v = _f64(numpy_of(v))
        np.testing.assert_allclose(
            np.swapaxes(v, -1, -2) @ v, np.broadcast_to(np.eye(4), a.shape), **tol
        )
        np.testing.assert_allclose(_f64(a) @ v, v * values[..., None, :], **tol)


QR_CASES = [(s, m) for s in [(3, 3), (5, 3), (3, 5), (2, 4, 2)] for m in ("reduced", "complete")]


@pytest.mark.parametrize("dtype, case", _alternating(QR_CASES[::-1]), ids=str)
def test_qr(backend, dtype, case):
    shape, mode = case
    a = _random(shape, dtype, 3)
    m, n = shape[-2:]
    k = min(m, n) if mode == "reduced" else m
    tol = tolerance(dtype, 10)
    for fn in api(backend, "qr"):
        out = fn(native(a, backend), mode=mode)
        q, r = out
        assert out.Q is q and out.R is r
        check_meta(q, backend, dtype, (*shape[:-2], m, k))
        check_meta(r, backend, dtype, (*shape[:-2], k, n))
        q, r = _f64(numpy_of(q)), _f64(numpy_of(r))
        np.testing.assert_allclose(q @ r, a, **tol)
        np.testing.assert_allclose(
            np.swapaxes(q, -1, -2) @ q, np.broadcast_to(np.eye(k), (*shape[:-2], k, k)), **tol
        )
        assert np.all(np.tril(r, -1) == 0), "R is not upper triangular"
    q, r = api(backend, "qr")[0](native(a, backend))  # reduced by default
    assert numpy_of(q).shape[-1] == min(m, n)


@pytest.mark.parametrize("dtype, batch", _alternating([(), (2,), (2, 3)]), ids=str)
def test_det_and_slogdet(backend, dtype, batch):
    a = _well_conditioned_linalg_ext(batch, 3, dtype, 4)
    det = np.linalg.det(_f64(a))
    tol = tolerance(dtype, 30)
    for fn in api(backend, "det"):
        check(fn(native(a, backend)), cast(det, dtype), backend, **tol)
    for fn in api(backend, "slogdet"):
        out = fn(native(a, backend))
        sign, logabsdet = out
        assert out.sign is sign and out.logabsdet is logabsdet
        check(sign, cast(np.sign(det), dtype), backend)
        check(logabsdet, cast(np.log(np.abs(det)), dtype), backend, **tol)


def test_slogdet_of_a_singular_matrix(backend):
    a = np.array([[1.0, 2.0], [2.0, 4.0]])
    for fn in api(backend, "slogdet"):
        sign, logabsdet = fn(native(a, backend))
        check(sign, np.float64(0.0), backend)  # (torch and tf give -0.0)
        check(logabsdet, np.float64(-np.inf), backend)


# (x1 shape, x2 shape): a vector, stacks of matrices with broadcast batch axes, and (..., M) that
# torch alone would read as a stack of vectors.
SOLVE_SHAPES = [
    ((3, 3), (3,)),
    ((2, 3, 3), (3,)),
    ((3, 3), (3, 2)),
    ((2, 3, 3), (3, 1)),
    ((3, 3), (2, 3, 2)),
    ((2, 1, 3, 3), (4, 3, 2)),
    ((3, 3, 3), (3, 3)),
]


@pytest.mark.parametrize("shapes", SOLVE_SHAPES, ids=str)
def test_solve(backend, shapes):
    dtype = "float32" if len(shapes[0]) == 2 else "float64"
    a = _well_conditioned_linalg_ext(shapes[0][:-2], 3, dtype, 5)
    b = _random(shapes[1], dtype, 6)
    if b.ndim == 1:
        expected = np.linalg.solve(_f64(a), _f64(b)[:, None])[..., 0]
    else:
        expected = np.linalg.solve(_f64(a), _f64(b))
    for fn in api(backend, "solve"):
        out = fn(native(a, backend), native(b, backend))
        check(out, cast(expected, dtype), backend, **tolerance(dtype, 30))


@pytest.mark.parametrize(
    "dtype, n", [("float64", n) for n in (0, 1, 2, 5, -1, -2)] + [("float32", 3), ("float32", -3)]
)
def test_matrix_power(backend, dtype, n):
    a = _well_conditioned_linalg_ext((2,), 3, dtype, 7) / 2
    expected = np.linalg.matrix_power(_f64(a), n)
    for fn in api(backend, "matrix_power"):
        check(fn(native(a, backend), n), cast(expected, dtype), backend, **tolerance(dtype, 100))


def test_matrix_power_of_integers_stays_integer(backend):
    a = np.array([[1, 1], [1, 0]], np.int64)  # Fibonacci
    for fn in api(backend, "matrix_power"):
        check(fn(native(a, backend), 10), np.array([[89, 55], [55, 34]], np.int64), backend)
        check(fn(native(a, backend), 0), np.eye(2, dtype=np.int64), backend)
        check(fn(native(a, backend), -1), np.array([[0, 1], [1, -1]], np.float32), backend)


@pytest.mark.parametrize("dtype, shape", _alternating([(3, 3), (4, 2), (2, 5), (2, 3, 4)]), ids=str)
def test_svdvals(backend, dtype, shape):
    a = _random(shape, dtype, 8)
    expected = np.linalg.svd(_f64(a), compute_uv=False)
    for fn in api(backend, "svdvals"):
        check(fn(native(a, backend)), cast(expected, dtype), backend, **tolerance(dtype, 10))


def _of_rank(rank, m, n, seed, scale=1.0):
    rng = np.random.default_rng(RNG_SEED_linalg_ext + seed)
    return rng.standard_normal((m, rank)) @ rng.standard_normal((rank, n)) * scale


@pytest.mark.parametrize("dtype", FLOAT_DTYPES)
def test_matrix_rank(backend, dtype):
    stack = np.stack([_of_rank(r, 4, 3, r) for r in (0, 1, 2, 3)]).astype(dtype)
    for fn in api(backend, "matrix_rank"):
        check(fn(native(stack, backend)), np.array([0, 1, 2, 3], np.int64), backend)
        check(fn(native(stack[2], backend)), np.int64(2), backend)


def test_matrix_rank_rtol_is_relative_to_the_largest_singular_value(backend):
    rng = np.random.default_rng(RNG_SEED_linalg_ext)
    q1, q2 = _orthogonal((), 3, rng), _orthogonal((), 3, rng)
    a = (q1 * np.array([100.0, 1.0, 1e-3])) @ q2  # relative 1, 1e-2, 1e-5
    for fn in api(backend, "matrix_rank"):
        for rtol, rank in ((1e-1, 1), (1e-3, 2), (1e-7, 3)):
            check(fn(native(a, backend), rtol=rtol), np.int64(rank), backend)
        check(fn(native(a, backend)), np.int64(3), backend)  # default max(M, N) * eps


ORDS = ["fro", "nuc", 1, -1, 2, -2, np.inf, -np.inf]


@HYPOTHESIS
@given(data=st.data())
def test_matrix_norm(backend, data):
    dtype = data.draw(st.sampled_from(FLOAT_DTYPES), label="dtype")
    shape = data.draw(st.sampled_from([(3, 3), (2, 4), (2, 3, 2), (1, 2, 1, 3)]), label="shape")
    a = data.draw(arrays(dtype, reals(dtype, -10, 10, specials=False), shape), label="x")
    order = data.draw(st.sampled_from(ORDS), label="ord")
    keepdims = data.draw(st.booleans(), label="keepdims")
    expected = np.linalg.matrix_norm(_f64(a), ord=order, keepdims=keepdims)
    for fn in api(backend, "matrix_norm"):
        out = fn(native(a, backend), ord=order, keepdims=keepdims)
        check(out, cast(expected, dtype), backend, **tolerance(dtype, 100))


def test_matrix_norm_defaults_to_frobenius(backend):
    a = np.array([[3.0, 0.0], [0.0, -4.0]], np.float32)
    for fn in api(backend, "matrix_norm"):
        check(fn(native(a, backend)), np.float32(5.0), backend)


@pytest.mark.parametrize(
    "dtype, shape", [("float32", (3, 4)), ("int64", (2, 4, 3)), ("bool", (3, 3))], ids=str
)
def test_diagonal(backend, dtype, shape):
    a = (np.arange(np.prod(shape)).reshape(shape) % 3).astype(dtype)
    for offset in range(-shape[-2] - 1, shape[-1] + 2):  # diagonals beyond the matrix are empty
        expected = np.diagonal(a, offset, -2, -1)
        for fn in api(backend, "diagonal"):
            check(fn(native(a, backend), offset=offset), expected, backend)
    check(api(backend, "diagonal")[0](native(a, backend)), np.diagonal(a, 0, -2, -1), backend)


# input dtype -> accumulated dtype
TRACE_DTYPES = {
    "float32": "float32",
    "float64": "float64",
    "int8": "int64",
    "int32": "int64",
    "int64": "int64",
    "uint8": "uint64",
    "bool": "int64",
}


@pytest.mark.parametrize("offset, dtype", _alternating(list(TRACE_DTYPES), (0, 1, -1)))
def test_trace(backend, dtype, offset):
    a = (np.arange(24).reshape(2, 3, 4) % 7).astype(dtype)
    expected = np.sum(np.diagonal(a, offset, -2, -1).astype(np.float64), axis=-1)
    want = TRACE_DTYPES[dtype]
    for fn in api(backend, "trace"):
        check(fn(native(a, backend), offset=offset), expected.astype(want), backend)
    out = api(backend, "trace")[0](native(a, backend), offset=offset, dtype="float64")
    check(out, expected, backend)


@pytest.mark.parametrize("shape", [(2, 3), (4, 2, 3), (2, 1, 1, 5)], ids=str)
def test_matrix_transpose(backend, shape):
    a = _random(shape, "float32", 9)
    for fn in api(backend, "matrix_transpose"):
        check(fn(native(a, backend)), np.swapaxes(a, -1, -2), backend)


@pytest.mark.parametrize("dtype", ["float32", "float64", "int64"])
def test_outer(backend, dtype):
    a, b = (np.arange(3) - 1).astype(dtype), (np.arange(4) * 1.5).astype(dtype)
    for fn in api(backend, "outer"):
        check(fn(native(a, backend), native(b, backend)), np.multiply.outer(a, b), backend)


def test_outer_promotes_mixed_float_dtypes(backend):
    a, b = np.ones(2, np.float32), np.arange(3, dtype=np.float64)
    for fn in api(backend, "outer"):
        check(fn(native(a, backend), native(b, backend)), np.multiply.outer(a, b), backend)


TENSORDOT_CASES = [
    ((3, 4), (4, 5), 1),
    ((2, 3, 4), (3, 4, 5), 2),
    ((2, 3), (4,), 0),
    ((2, 3, 4), (4, 3, 5), ([1, 2], [1, 0])),
    ((2, 3, 4), (5, 2), ([-3], [-1])),
    ((3, 4), (3, 4), 2),
]


@pytest.mark.parametrize("dtype, case", _alternating(TENSORDOT_CASES), ids=str)
def test_tensordot(backend, dtype, case):
    sa, sb, axes = case
    a, b = _random(sa, dtype, 10), _random(sb, dtype, 11)
    expected = np.tensordot(_f64(a), _f64(b), axes=axes)
    for fn in api(backend, "tensordot"):
        out = fn(native(a, backend), native(b, backend), axes=axes)
        check(out, cast(expected, dtype), backend, **tolerance(dtype, 10))
    if axes == 2:
        out = api(backend, "tensordot")[0](native(a, backend), native(b, backend))
        check(out, cast(expected, dtype), backend, **tolerance(dtype, 10))


def test_tensordot_promotes_mixed_float_dtypes(backend):
    a, b = _random((2, 3), "float32", 12), _random((3,), "float64", 13)
    expected = np.tensordot(_f64(a), b, axes=1)
    for fn in api(backend, "tensordot"):
        check(fn(native(a, backend), native(b, backend), axes=1), expected, backend, rtol=1e-6)


VECDOT_CASES = [
    ((5,), (5,), -1),
    ((2, 3), (2, 3), -1),
    ((2, 1, 3), (4, 3), -1),
    ((3, 2), (3, 2), 0),
]


VECDOT_DTYPES = ("float32", "float64", "int64", "complex64", "complex128")


@pytest.mark.parametrize(
    "dtype, case",
    _alternating(VECDOT_CASES * 2, VECDOT_DTYPES[:-1]) + [("complex128", VECDOT_CASES[2])],
    ids=str,
)
def test_vecdot(backend, dtype, case):
    sa, sb, axis = case
    a, b = _random(sa, "float64", 14), _random(sb, "float64", 15)
    if dtype.startswith("complex"):
        a, b = a + 1j * _random(sa, "float64", 16), b - 2j * _random(sb, "float64", 17)
    a, b = (
        (np.round(a * 4) if dtype == "int64" else a),
        (np.round(b * 4) if dtype == "int64" else b),
    )
    a, b = a.astype(dtype), b.astype(dtype)
    ab = np.broadcast_arrays(a.astype(np.complex128), b.astype(np.complex128))
    expected = np.sum(np.conj(ab[0]) * ab[1], axis=axis)  # x1 conjugated
    expected = expected.real if not dtype.startswith("complex") else expected
    tol = tolerance(dtype, 10) if dtype != "int64" else {}
    for fn in api(backend, "vecdot"):
        out = fn(native(a, backend), native(b, backend), axis=axis)
        check(out, expected.astype(dtype), backend, **tol)


INTEGER_MATRIX = np.array([[4, 2, 0], [2, 5, 1], [0, 1, 3]], np.int64)  # symmetric, SPD


FLOAT_RESULTS = {
    "cholesky": lambda a: np.linalg.cholesky(a),
    "det": lambda a: np.linalg.det(a),
    "eigvalsh": lambda a: np.linalg.eigvalsh(a),
    "inv": lambda a: np.linalg.inv(a),
    "matrix_norm": lambda a: np.linalg.matrix_norm(a),
    "pinv": lambda a: np.linalg.pinv(a),
    "svdvals": lambda a: np.linalg.svd(a, compute_uv=False),
    "vector_norm": lambda a: np.linalg.vector_norm(a),
    "solve": lambda a: np.linalg.solve(a, np.ones(3)),
}


@pytest.mark.parametrize("name", list(FLOAT_RESULTS))
def test_integer_inputs_are_computed_in_float32(backend, name):
    a = INTEGER_MATRIX
    expected = cast(FLOAT_RESULTS[name](a.astype(np.float64)), "float32")
    args = [native(a, backend)] + (
        [native(np.ones(3, np.int64), backend)] if name == "solve" else []
    )
    for fn in api(backend, name):
        check(fn(*args), expected, backend, **tolerance("float32", 10))


def test_integer_inputs_of_decompositions_are_computed_in_float32(backend):
    a = native(INTEGER_MATRIX, backend)
    for name in ("eigh", "qr", "slogdet", "svd"):
        for part in getattr(ivy, name)(a):
            assert dtype_name(part) == "float32", name
    assert dtype_name(ivy.matrix_rank(a)) == "int64"


@pytest.mark.parametrize(
    "a",
    [[[2.0, 1.0], [1.0, 3.0]], [[1.0, 2.0], [2.0, 4.0]], np.zeros((3, 3))],
    ids=["regular", "rank 1", "zero"],
)
def test_gradient_of_det_is_the_adjugate(backend, a):
    """d det(A) / dA is the transposed adjugate, finite for singular matrices too (torch's own
    gradient gave zeros for a rank-1 2x2 matrix)."""
    require(backend, "autodiff")
    a = np.asarray(a, np.float64)
    n = a.shape[0]
    cofactors = np.array(
        [
            [
                (-1) ** (i + j) * np.linalg.det(np.delete(np.delete(a, i, 0), j, 1))
                if n > 1
                else 1.0
                for j in range(n)
            ]
            for i in range(n)
        ]
    )
    grad = ivy.grad(lambda x: ivy.det(x))(native(a, backend))
    np.testing.assert_allclose(numpy_of(grad), cofactors, atol=1e-9)
