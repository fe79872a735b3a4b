"""Matrices holding NaN or infinity in the linear algebra, the same on every backend
(``ivy/backends/_nonfinite.py``): the decompositions answer NaN for such a matrix and the usual
result for the finite matrices of the same batch (numpy and torch raised, jax and tensorflow
answered NaN, in part or in whole, tensorflow's ``eigh`` raised); ``matrix_rank`` refuses them
where the values are known; ``eigh`` reads the lower triangle on every backend."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
from ivy.errors import LinAlgError
from tests.helpers import check_gradients, native, native_value_and_grads, numpy_of

_M = np.array([[1.0, 0.5, -0.3], [0.2, 1.5, 0.4], [-0.1, 0.3, 0.8]])
SPD = _M @ _M.T + 0.5 * np.eye(3)  # symmetric positive definite: every decomposition applies


def _batch() -> np.ndarray:
    """A finite matrix, one with a NaN and one with an infinity."""
    with_nan, with_inf = SPD.copy(), SPD.copy()
    with_nan[0, 1] = np.nan
    with_inf[2, 2] = np.inf
    return np.stack([SPD, with_nan, with_inf])


def _leaves(out) -> list[np.ndarray]:
    return [numpy_of(y) for y in out] if isinstance(out, tuple) else [numpy_of(out)]


# each function, and what its result for SPD must satisfy (numpy float64 written here)
CHECKS = {
    "cholesky": lambda out: np.testing.assert_allclose(out[0], np.linalg.cholesky(SPD)),
    "eigvalsh": lambda out: np.testing.assert_allclose(out[0], np.linalg.eigvalsh(SPD)),
    "eigh": lambda out: (
        np.testing.assert_allclose(out[0], np.linalg.eigvalsh(SPD)),
        np.testing.assert_allclose(SPD @ out[1], out[1] * out[0], atol=1e-12),
    ),
    "pinv": lambda out: np.testing.assert_allclose(out[0], np.linalg.inv(SPD)),
    "qr": lambda out: np.testing.assert_allclose(out[0] @ out[1], SPD, atol=1e-12),
    "slogdet": lambda out: np.testing.assert_allclose([out[0], out[1]], np.linalg.slogdet(SPD)),
    "svd": lambda out: np.testing.assert_allclose(out[0] * out[1] @ out[2], SPD, atol=1e-12),
    "svdvals": lambda out: np.testing.assert_allclose(out[0], np.linalg.svd(SPD, compute_uv=False)),
}


@pytest.mark.parametrize("name", sorted(CHECKS))
def test_not_finite_matrices_give_nan_the_others_their_result(backend, name):
    out = _leaves(getattr(ivy, name)(native(_batch(), backend)))
    CHECKS[name]([y[0] for y in out])
    for y in out:
        assert np.isnan(y[1:]).all(), (name, y)


def test_matrix_rank_refuses_a_matrix_that_is_not_finite(backend):
    assert numpy_of(ivy.matrix_rank(native(_batch()[:1], backend))).tolist() == [3]
    for bad in _batch()[1:]:
        with pytest.raises(LinAlgError, match="NaN or infinity.*ivy.nan_to_num"):
            ivy.matrix_rank(native(bad, backend))


def test_matrix_rank_inside_a_compiled_program_counts_no_nan(graph_backend):
    """Where the values are not known, the count of a non-finite matrix is 0."""
    xp = getattr(ivy, graph_backend)
    rank = ivy.compile_fn(xp.matrix_rank, f=xp)
    assert numpy_of(rank(native(_batch(), graph_backend))).tolist() == [3, 0, 0]


def test_eigh_reads_the_lower_triangle(backend):
    lower_only = np.tril(SPD) + np.triu(np.full((3, 3), 7.0), 1)  # the upper triangle ignored
    values, vectors = ivy.eigh(native(lower_only, backend))
    np.testing.assert_allclose(numpy_of(values), np.linalg.eigvalsh(SPD))
    np.testing.assert_allclose(numpy_of(ivy.eigvalsh(native(lower_only, backend))),
                               np.linalg.eigvalsh(SPD))  # fmt: skip


def test_gradients_of_the_finite_matrices_are_unchanged(diff_backend):
    """The NaN of one matrix does not reach the gradient of the others."""
    xp = getattr(ivy, diff_backend)
    check_gradients(diff_backend, xp.svdvals, [SPD[None] + 0.1 * _M[None]])

    def finite_part(a):
        s = xp.svdvals(a)
        return xp.where(xp.isnan(s), 0.0, s)

    _, (grad,) = native_value_and_grads(diff_backend, finite_part, [_batch()], np.ones((3, 3)))
    np.testing.assert_allclose(grad[0], native_value_and_grads(
        diff_backend, xp.svdvals, [SPD[None]], np.ones((1, 3)))[1][0][0])  # fmt: skip
    assert (grad[1:] == 0).all()
