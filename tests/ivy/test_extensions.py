"""Ivy's own functions beyond the Array API, on every backend, against references written here
with Python loops or plain numpy float64: gather_flat, scatter_flat, indices_where, cumsum,
cumprod, einsum, constant_pad, zero_pad, linear_resample, interp, vector_to_skew_symmetric_matrix,
cosine_similarity, clip_vector_norm, clip_by_global_norm, nan_to_num, isclose, allclose and
to_framework."""

from __future__ import annotations

import itertools
import math
import operator

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import ivy
from ivy import nest
from tests.helpers import (
    HYPOTHESIS,
    api,
    api_f,
    check,
    check_gradients,
    dtype_name,
    is_native,
    native,
    numpy_of,
    reference,
    tolerance,
)
from tests.ivy.strategies import BROADCAST_PAIRS, arrays, quarters

BACKENDS = ("numpy", "torch", "jax", "tensorflow")


# ----------------------------------------------------------------------------------------------
# gather_flat, scatter_flat
# ----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("dtype", ["float32", "float64", "int64"])
@pytest.mark.parametrize("indices", [[3, 0, 5], [[0, 11], [-1, 4]], 7, []], ids=str)
def test_gather_flat(backend, dtype, indices):
    params = (np.arange(12).reshape(3, 4) * 1.5 - 4).astype(dtype)
    flat = list(params.reshape(-1))
    idx = np.array(indices, np.int64)
    expected = np.array([flat[i] for i in idx.reshape(-1)], dtype).reshape(idx.shape)
    for fn in api(backend, "gather_flat"):
        check(fn(native(params, backend), native(idx, backend)), expected, backend)
        check(fn(native(params, backend), native(idx.astype(np.int32), backend)), expected, backend)


def _scatter_flat_reference(indices, updates, size, reduction):
    received: dict[int, list] = {}
    for i, u in zip(indices, updates):
        received.setdefault(int(i) % size, []).append(u)
    out = np.zeros(size, updates.dtype)
    combine = {"sum": sum, "min": min, "max": max}[reduction]
    for i, values in received.items():
        out[i] = combine(values)
    return out, received


@pytest.mark.parametrize("dtype", ["float32", "int64"])
@pytest.mark.parametrize("reduction", ["sum", "min", "max", "replace"])
def test_scatter_flat(backend, dtype, reduction):
    idx = np.array([4, 0, 4, 2, 4, 0], np.int64)  # duplicates, and places left untouched
    updates = np.array([3, -1, 7, 2, -5, 6], dtype) * (1.5 if dtype == "float32" else 1)
    updates = updates.astype(dtype)
    expected, received = _scatter_flat_reference(
        idx, updates, 6, "sum" if reduction == "replace" else reduction
    )
    for fn in api(backend, "scatter_flat"):
        out = fn(native(idx, backend), native(updates, backend), 6, reduction=reduction)
        if reduction == "replace":  # one of the updates, unspecified which
            got = numpy_of(out)
            for i, values in received.items():
                assert got[i] in values
                expected[i] = got[i]
        check(out, expected, backend)
    out = api(backend, "scatter_flat")[0](native(idx, backend), native(updates, backend), 6)
    check(out, _scatter_flat_reference(idx, updates, 6, "sum")[0], backend)  # sum by default


def test_scatter_flat_of_batched_indices(backend):
    idx = np.array([[0, 3], [3, 1]], np.int64)
    updates = np.array([[1.0, 2.0], [4.0, 8.0]], np.float32)
    expected = np.array([1.0, 8.0, 0.0, 6.0, 0.0], np.float32)
    for fn in api(backend, "scatter_flat"):
        check(fn(native(idx, backend), native(updates, backend), 5), expected, backend)


# ----------------------------------------------------------------------------------------------
# indices_where
# ----------------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "values",
    [[[True, False, True], [False, False, True]], [0.0, 2.5, 0.0, -1.0], [[0, 0]], True, False],
    ids=str,
)
def test_indices_where(backend, values):
    x = np.array(values)
    rows = [index for index in np.ndindex(x.shape) if x[index]]
    expected = np.array(rows, np.int64).reshape(len(rows), x.ndim)
    for fn in api(backend, "indices_where"):
        check(fn(native(x, backend)), expected, backend)


def test_indices_where_feeds_gather_nd(backend):
    x = np.array([[1.0, -2.0], [3.0, -4.0]], np.float32)
    xp = getattr(ivy, backend)
    where = ivy.indices_where(native(x > 0, backend))
    check(xp.gather_nd(native(x, backend), where), np.array([1.0, 3.0], np.float32), backend)


# ----------------------------------------------------------------------------------------------
# cumsum, cumprod
# ----------------------------------------------------------------------------------------------

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


@pytest.mark.parametrize("name", ["cumsum", "cumprod"])
def test_cumulative_defaults_and_dtype(backend, name):
    x = np.array([[1, 2, 3], [4, 5, 6]], np.int32)
    op = np.cumsum if name == "cumsum" else np.cumprod
    for fn in api(backend, name):
        check(fn(native(x, backend)), op(x.astype(np.int64), axis=0), backend)  # axis 0
        check(fn(native(x, backend), 1, dtype="float64"), op(x.astype(np.float64), axis=1), backend)


def test_the_docstring_examples(backend):
    x = native(np.array([1, 2, 3], np.int64), backend)
    check(ivy.cumsum(x, exclusive=True), np.array([0, 1, 3], np.int64), backend)
    check(ivy.cumprod(x, reverse=True), np.array([6, 6, 3], np.int64), backend)
    check(ivy.cumsum(x, exclusive=True, reverse=True), np.array([5, 3, 0], np.int64), backend)


# ----------------------------------------------------------------------------------------------
# einsum
# ----------------------------------------------------------------------------------------------

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


# ----------------------------------------------------------------------------------------------
# constant_pad, zero_pad
# ----------------------------------------------------------------------------------------------


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


# ----------------------------------------------------------------------------------------------
# linear_resample
# ----------------------------------------------------------------------------------------------


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


# ----------------------------------------------------------------------------------------------
# vector_to_skew_symmetric_matrix
# ----------------------------------------------------------------------------------------------


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


# ----------------------------------------------------------------------------------------------
# to_framework
# ----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("dtype", ["float32", "float64", "int64", "uint8", "bool", "complex64"])
def test_to_framework_to_every_backend(request, backend, dtype):
    a = (np.arange(6).reshape(2, 3) % 4).astype(dtype)
    x = native(a, backend)
    for target in request.config.ivy_backends:
        for fn in api(backend, "to_framework"):
            for spelling in (target, getattr(ivy, target)):
                out = fn(x, spelling)
                assert is_native(out, target), (backend, target, type(out))
                assert dtype_name(out) == dtype
                np.testing.assert_array_equal(numpy_of(out), a)
    assert ivy.to_framework(x, backend) is x  # already of that framework


def _pointer(x):
    if isinstance(x, np.ndarray):
        return x.ctypes.data
    if type(x).__module__.startswith("torch"):
        return x.data_ptr()
    return x.unsafe_buffer_pointer()  # jax


# Conversions that DLPack makes without a copy, observable through the buffer's address.
ZERO_COPY = [
    ("numpy", "torch"),
    ("torch", "numpy"),
    ("torch", "jax"),
    ("jax", "torch"),
    ("jax", "numpy"),
]


@pytest.mark.parametrize("source, target", ZERO_COPY, ids=str)
def test_to_framework_shares_memory(request, source, target):
    if not {source, target} <= set(request.config.ivy_backends):
        pytest.skip(f"needs {source} and {target}")
    if source == "torch":
        import torch

        x = torch.arange(8.0)  # torch's allocator aligns buffers as jax requires
    else:
        x = native(np.arange(8.0), source)
    out = ivy.to_framework(x, target)
    assert _pointer(out) == _pointer(x)
    np.testing.assert_array_equal(numpy_of(out), np.arange(8.0))


def test_numpy_and_torch_see_each_others_writes(request):
    if "torch" not in request.config.ivy_backends:
        pytest.skip("needs torch")
    a = np.zeros(3)
    t = ivy.to_framework(a, "torch")
    t[0] = 5.0
    a[2] = 7.0
    assert a[0] == 5.0 and t[2].item() == 7.0


def test_to_framework_copies_what_dlpack_cannot_carry(request):
    """A read-only numpy array and a torch tensor that requires gradients still convert."""
    readonly = np.arange(3.0)
    readonly.flags.writeable = False
    for target in request.config.ivy_backends:
        out = ivy.to_framework(readonly, target)
        np.testing.assert_array_equal(numpy_of(out), readonly)
    if "torch" in request.config.ivy_backends:
        import torch

        leaf = torch.ones(2, requires_grad=True)
        for target in request.config.ivy_backends:
            out = ivy.to_framework(leaf, target)
            assert is_native(out, target)
            np.testing.assert_array_equal(numpy_of(out), np.ones(2, np.float32))


def test_to_framework_reads_the_source_from_the_type_under_a_global_framework(request, backend):
    a = np.arange(3.0)
    with ivy.set_framework(backend):
        for target in request.config.ivy_backends:
            out = ivy.to_framework(a, target)
            assert is_native(out, target)
            np.testing.assert_array_equal(numpy_of(out), a)
        out = ivy.to_framework([1.5, 2.5], backend)  # Python data: the target's asarray
        check(out, np.array([1.5, 2.5], np.float32), backend)


def test_to_framework_refuses_an_unknown_framework(backend):
    with pytest.raises(ivy.UnknownFrameworkError):
        ivy.to_framework(native(np.ones(2), backend), "mxnet")


# ----------------------------------------------------------------------------------------------
# interp
# ----------------------------------------------------------------------------------------------

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


# ----------------------------------------------------------------------------------------------
# cosine_similarity
# ----------------------------------------------------------------------------------------------


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


# ----------------------------------------------------------------------------------------------
# clip_vector_norm, clip_by_global_norm
# ----------------------------------------------------------------------------------------------


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


# ----------------------------------------------------------------------------------------------
# nan_to_num
# ----------------------------------------------------------------------------------------------

NAN_TO_NUM_ARGS = [{}, {"nan": -1.0, "posinf": 9.0, "neginf": -9.0}, {"posinf": 1e300}]


@pytest.mark.filterwarnings("ignore:overflow encountered in cast:RuntimeWarning")  # numpy's own
@pytest.mark.parametrize("dtype", ["float32", "float64"])
@pytest.mark.parametrize("kwargs", NAN_TO_NUM_ARGS, ids=str)
def test_nan_to_num(backend, dtype, kwargs):
    a = np.array([[np.nan, np.inf, -np.inf], [1.5, -0.0, -2.0]], dtype)
    expected = reference(np.nan_to_num, a, **kwargs)  # in dtype: its largest finite values
    for fn in api(backend, "nan_to_num"):
        check(fn(native(a, backend), **kwargs), expected, backend, signed_zeros=True)
        check(fn(native(a[0, 0], backend), **kwargs), expected[0, 0], backend)  # 0-d


@pytest.mark.parametrize("dtype", ["int64", "uint8", "bool", "complex64", "complex128"])
def test_nan_to_num_of_integers_and_complex_numbers(backend, dtype):
    if dtype.startswith("complex"):
        a = np.array([complex(np.nan, np.inf), complex(-np.inf, 1.0), 2 - 1j], dtype)
    else:
        a = np.array([1, 0, 1], dtype)
    for fn in api(backend, "nan_to_num"):
        check(fn(native(a, backend), nan=4.0), np.nan_to_num(a, nan=4.0), backend)


def test_nan_to_num_gradients(diff_backend):
    def fn(x):
        return ivy.nan_to_num(x) * x

    check_gradients(diff_backend, fn, [np.random.default_rng(16).standard_normal((2, 3))])


# ----------------------------------------------------------------------------------------------
# isclose, allclose
# ----------------------------------------------------------------------------------------------

NEAR_ONE = [0.0, -0.0, 1.0, 1.0 + 1e-6, 1.0 + 3e-5, 1.001, 1e-9, -1e-9, math.inf, -math.inf]
TOLERANCE_ARGS = [(1e-5, 1e-8), (0.0, 0.0), (1e-3, 0.0), (0.0, 1e-6)]


@HYPOTHESIS
@given(data=st.data())
def test_isclose_and_allclose(backend, data):
    """Against numpy (which computes in the inputs' dtype too), broadcasting, with infinities
    and NaNs."""
    dtype = data.draw(st.sampled_from(["float32", "float64"]), label="dtype")
    shape1, shape2 = data.draw(BROADCAST_PAIRS, label="shapes")
    elements = st.sampled_from([float(np.dtype(dtype).type(v)) for v in [*NEAR_ONE, math.nan]])
    a = data.draw(arrays(dtype, elements, shape1), label="x1")
    b = data.draw(arrays(dtype, elements, shape2), label="x2")
    rtol, atol = data.draw(st.sampled_from(TOLERANCE_ARGS), label="rtol, atol")
    equal_nan = data.draw(st.booleans(), label="equal_nan")
    kwargs = dict(rtol=rtol, atol=atol, equal_nan=equal_nan)
    x1, x2 = native(a, backend), native(b, backend)
    for fn in api(backend, "isclose"):
        check(fn(x1, x2, **kwargs), np.isclose(a, b, **kwargs), backend)
    for fn in api(backend, "allclose"):
        check(fn(x1, x2, **kwargs), np.array(np.allclose(a, b, **kwargs)), backend)


def test_isclose_of_mixed_dtypes_and_python_scalars(backend):
    ints = np.array([1, 2, 3], np.int64)
    floats = np.array([1.0 + 1e-7, 2.1, np.inf], np.float32)
    for fn in api(backend, "isclose"):
        out = fn(native(ints, backend), native(floats, backend))
        check(out, np.isclose(ints.astype(np.float32), floats), backend)
        check(fn(native(floats, backend), 2.1), np.isclose(floats, np.float32(2.1)), backend)
    for fn in api_f(backend, "isclose"):
        check(fn(1.0, 1.0 + 1e-9), np.array(True), backend)
    for fn in api(backend, "allclose"):
        check(fn(native(floats[:2], backend), native(floats[:2], backend)), np.array(True), backend)
        check(
            fn(native(np.zeros(0), backend), native(np.ones(0), backend)), np.array(True), backend
        )
