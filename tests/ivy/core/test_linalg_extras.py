"""Tests of the core group ``linalg_extras`` (``ivy/core/linalg_extras.py``), on every backend.

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

import ivy
from ivy import nest
from tests.helpers import (
    api,
    check,
    check_gradients,
    native,
    numpy_of,
    tolerance,
)

A, B, V = np.arange(6.0).reshape(2, 3) - 2, np.arange(12.0).reshape(3, 4) / 4, np.arange(3.0) + 1


S = np.arange(9.0).reshape(3, 3)


BATCH1, BATCH2 = np.arange(24.0).reshape(2, 3, 4) / 5, np.arange(16.0).reshape(2, 4, 2) - 8


EINSUM_CASES = {
    "matmul": ("ij,jk->ik", (A, B), A @ B),
    "matrix-vector": ("ij,j->i", (A, V), A @ V),
    "outer": ("i,j->ij", (V, V), V[:, None] * V[None, :]),
    "trace": ("ii->", (S,), np.float64(S[0, 0] + S[1, 1] + S[2, 2])),
    "transpose": ("ij->ji", (A,), A.T),
    "sum": ("ij->", (A,), np.float64(A.sum())),
    "batched matmul": ("bij,bjk->bik", (BATCH1, BATCH2), BATCH1 @ BATCH2),
    "ellipsis": ("...ij->...ji", (BATCH1,), np.swapaxes(BATCH1, -1, -2)),
    "three operands": ("ij,jk,k->i", (A, B, np.ones(4)), (A @ B).sum(-1)),
}


@pytest.mark.parametrize("dtype", ["float32", "float64"])
@pytest.mark.parametrize("case", list(EINSUM_CASES.values()), ids=list(EINSUM_CASES))
def test_einsum(backend, dtype, case):
    equation, operands, expected = case
    args = [native(o.astype(dtype), backend) for o in operands]
    for fn in api(backend, "einsum"):
        check(
            fn(equation, *args),
            np.asarray(expected).astype(dtype),
            backend,
            **tolerance(dtype, 100),
        )


def test_einsum_promotes_mixed_dtypes_and_takes_f(backend):
    a, v = A.astype(np.float32), V.astype(np.float64)
    for fn in api(backend, "einsum"):
        check(fn("ij,j->i", native(a, backend), native(v, backend)), A @ V, backend)
    out = ivy.einsum("ij,j->i", native(a, backend), native(v, backend), f=backend)
    check(out, A @ V, backend)


def test_einsum_without_operands_needs_a_framework():
    with pytest.raises(ivy.NoFrameworkError):
        ivy.einsum("->")


@pytest.mark.parametrize("dtype", ["float32", "float64"])
@pytest.mark.parametrize("batch", [(), (4,), (2, 3)], ids=str)
def test_vector_to_skew_symmetric_matrix(backend, dtype, batch):
    rng = np.random.default_rng(5)
    v, u = rng.standard_normal((*batch, 3)), rng.standard_normal((*batch, 3))
    x, y, z = v[..., 0], v[..., 1], v[..., 2]
    zero = np.zeros_like(x)
    expected = np.stack(
        [np.stack(r, -1) for r in [[zero, -z, y], [z, zero, -x], [-y, x, zero]]], -2
    )
    for fn in api(backend, "vector_to_skew_symmetric_matrix"):
        out = fn(native(v.astype(dtype), backend))
        check(out, expected.astype(dtype), backend)
        np.testing.assert_allclose(
            numpy_of(out) @ u[..., None], np.cross(v, u)[..., None], rtol=1e-5, atol=1e-5
        )


def test_vector_to_skew_symmetric_matrix_wants_3_vectors(backend):
    for fn in api(backend, "vector_to_skew_symmetric_matrix"):
        with pytest.raises(ValueError, match=r"\[\.\.\., 3\]"):
            fn(native(np.ones((2, 4)), backend))


def _cosine_reference(a, b, axis, eps=1e-8):
    a, b = np.broadcast_arrays(a.astype(np.float64), b.astype(np.float64))
    dot = np.sum(a * b, axis=axis)
    norm_a = np.maximum(np.sqrt(np.sum(a * a, axis=axis)), eps)
    norm_b = np.maximum(np.sqrt(np.sum(b * b, axis=axis)), eps)
    return dot / (norm_a * norm_b)


COSINE_CASES = [
    ((4,), (4,), -1),
    ((3, 4), (3, 4), 1),
    ((3, 4), (3, 4), 0),
    ((2, 1, 4), (3, 4), -1),
    ((5, 3), (1, 3), -1),
    ((2, 0), (2, 0), 0),
]


@pytest.mark.parametrize("dtype", ["float32", "float64"])
@pytest.mark.parametrize("shape1, shape2, axis", COSINE_CASES, ids=str)
def test_cosine_similarity(backend, dtype, shape1, shape2, axis):
    rng = np.random.default_rng(11)
    a = rng.standard_normal(shape1).astype(dtype)
    b = rng.standard_normal(shape2).astype(dtype)
    expected = _cosine_reference(a, b, axis).astype(dtype)
    for fn in api(backend, "cosine_similarity"):
        check(fn(native(a, backend), native(b, backend), axis=axis), expected, backend)


def test_cosine_similarity_of_zero_and_tiny_vectors(backend):
    a = np.array([[0.0, 0.0], [1e-9, 0.0], [3.0, 4.0]])
    b = np.array([[1.0, 2.0], [1e-9, 0.0], [-3.0, -4.0]])
    expected = _cosine_reference(a, b, -1)  # 0, a tiny number (eps clamps each norm), -1
    for fn in api(backend, "cosine_similarity"):
        check(fn(native(a, backend), native(b, backend)), expected, backend)
    if backend == "torch":  # the very definition of torch's own function
        import torch

        torch_own = torch.nn.functional.cosine_similarity(torch.tensor(a), torch.tensor(b), dim=-1)
        check(torch_own, expected, backend)


def test_cosine_similarity_gradients(diff_backend):
    rng = np.random.default_rng(12)

    def fn(a, b):
        return ivy.cosine_similarity(a, b, axis=0)

    check_gradients(diff_backend, fn, [rng.standard_normal((3, 4)), rng.standard_normal((3, 4))])


@pytest.mark.parametrize("dtype", ["float32", "float64"])
@pytest.mark.parametrize("axis", [None, 1, -2, (0, 1)], ids=str)
@pytest.mark.parametrize("p", [2.0, 1.0, math.inf], ids=str)
def test_clip_vector_norm(backend, dtype, axis, p):
    a = (np.random.default_rng(13).standard_normal((3, 4)) * 2).astype(dtype)
    max_norm = 2.5
    norm = np.linalg.vector_norm(a.astype(np.float64), axis=axis, ord=p, keepdims=True)
    expected = a * np.where(norm > max_norm, max_norm / norm, 1.0)
    for fn in api(backend, "clip_vector_norm"):
        out = fn(native(a, backend), max_norm, axis=axis, p=p)
        check(out, expected.astype(dtype), backend)
        within = fn(native(a, backend), 1e3, axis=axis, p=p)  # every norm is within: unchanged
        check(within, a, backend, rtol=0, atol=0)


def test_clip_vector_norm_refuses_a_max_norm_that_is_not_positive(backend):
    for fn in api(backend, "clip_vector_norm"):
        with pytest.raises(ValueError, match="positive"):
            fn(native(np.ones(3), backend), 0.0)


def _grads(dtype_w="float64", dtype_b="float64"):
    rng = np.random.default_rng(14)
    return {
        "w": rng.standard_normal((3, 2)).astype(dtype_w),
        "layers": [rng.standard_normal(2).astype(dtype_b), np.array(1.5, dtype_b)],
    }


@pytest.mark.parametrize("scale", [0.5, 2.0], ids=["clipped", "within"])
def test_clip_by_global_norm(backend, scale):
    grads = _grads()
    leaves = [grads["w"], *grads["layers"]]
    norm = np.sqrt(sum(np.sum(g**2) for g in leaves))
    max_norm = scale * norm
    factor = min(1.0, max_norm / norm)
    for fn in api(backend, "clip_by_global_norm"):
        clipped, global_norm = fn(nest.map_nest(lambda g: native(g, backend), grads), max_norm)
        check(global_norm, np.array(norm), backend)
        assert isinstance(clipped, dict) and isinstance(clipped["layers"], list)
        check(clipped["w"], grads["w"] * factor, backend)
        check(clipped["layers"][0], grads["layers"][0] * factor, backend)
        check(clipped["layers"][1], grads["layers"][1] * factor, backend)


def test_clip_by_global_norm_keeps_each_dtype_and_takes_empty_nests(backend):
    grads = _grads("float32", "float64")
    leaves = [grads["w"], *grads["layers"]]
    norm = np.sqrt(sum(np.sum(g.astype(np.float64) ** 2) for g in leaves))
    clipped, global_norm = ivy.clip_by_global_norm(
        nest.map_nest(lambda g: native(g, backend), grads), 1.0
    )
    check(global_norm, np.array(norm), backend, rtol=1e-6)  # float32 squares, promoted
    check(clipped["w"], (grads["w"] / norm).astype("float32"), backend)
    check(clipped["layers"][0], grads["layers"][0] / norm, backend, rtol=1e-6)
    empty, zero = ivy.clip_by_global_norm({"a": []}, 1.0, f=backend)
    assert empty == {"a": []}
    check(zero, np.array(0.0, np.float32), backend)


def test_clip_gradients(diff_backend):
    rng = np.random.default_rng(15)
    a, b = rng.standard_normal((2, 3)), rng.standard_normal(4)

    def by_vector(x):
        return ivy.clip_vector_norm(x, 1.0, axis=1)  # both rows are longer than 1

    def by_global(a, b):
        clipped, norm = ivy.clip_by_global_norm({"a": a, "b": b}, 1.0)
        return ivy.concat([ivy.reshape(clipped["a"], (-1,)), clipped["b"], norm[None]])

    check_gradients(diff_backend, by_vector, [a * 3])
    check_gradients(diff_backend, by_global, [a, b])
