"""Signed zeros are the same on every backend (``ivy/backends/_signed_zeros.py``).

The Array API leaves the sign open where ``minimum``, ``maximum``, ``min`` and ``max`` choose
between ``-0`` and ``+0``, and numpy's own answer depends on the order of the arguments and, for
the reductions, on the array's length; ivy takes IEEE 754-2019's order, ``-0 < +0``. A stable
descending ``sort`` keeps equal elements (``-0`` and ``+0``) in their order, as numpy's does; a
singular matrix's ``det`` is ``+0`` and ``slogdet``'s sign ``0``, as numpy's are. The expected
signs are written here, not read from any backend.
"""

from __future__ import annotations

import numpy as np
import pytest

import ivy
from tests.conftest import require
from tests.helpers import native, numpy_of

P, N = 0.0, -0.0  # +0, -0


def signs(x) -> list[bool]:
    return np.signbit(np.asarray(numpy_of(x), dtype=np.float64)).ravel().tolist()


@pytest.mark.parametrize("dtype", ["float32", "float64"])
def test_minimum_and_maximum_order_negative_zero_first(backend, xp, dtype):
    a = native(np.array([P, N, N, P], dtype), backend)
    b = native(np.array([N, P, N, P], dtype), backend)
    assert signs(xp.minimum(a, b)) == [True, True, True, False]
    assert signs(xp.maximum(a, b)) == [False, False, True, False]
    assert signs(xp.minimum(b, a)) == [True, True, True, False]  # whatever the order
    assert signs(xp.maximum(a, 0.0)) == [False, False, False, False]  # a Python zero
    assert signs(xp.minimum(0.0, a)) == [False, True, True, False]


@pytest.mark.parametrize("length", [2, 9, 40])
def test_min_and_max_of_zeros_follow_the_same_order(backend, xp, length):
    # numpy's own min of [0, -0, ...] depends on the length (its SIMD loops)
    for pattern in ([P, N], [N, P], [P, P], [N, N]):
        x = np.resize(np.array(pattern), length)
        got_min = signs(xp.min(native(x, backend)))
        got_max = signs(xp.max(native(x, backend)))
        assert got_min == [bool(np.signbit(x).any())], (pattern, length)
        assert got_max == [bool(np.signbit(x).all())], (pattern, length)
    rows = native(np.array([[P, N], [P, P], [N, N]]), backend)
    assert signs(xp.min(rows, axis=1)) == [True, False, True]
    assert signs(xp.max(rows, axis=1, keepdims=True)) == [False, False, True]


def test_relu_of_negative_zero_is_positive_zero(backend, xp):
    assert signs(xp.relu(native(np.array([N, P, -1.0]), backend))) == [False, False, False]


def test_descending_sort_keeps_equal_zeros_in_order(backend, xp):
    x = np.array([P, N, P, 1.0, N, P, N])
    got = xp.sort(native(x, backend), descending=True)
    assert numpy_of(got).tolist() == [1.0, 0, 0, 0, 0, 0, 0]
    assert signs(got) == [False, False, True, False, True, False, True]  # numpy's stable order


@pytest.mark.parametrize(
    "matrix",
    [[[0.0, 1.0], [0.0, 2.0]], [[1.0, 0.0], [2.0, 0.0]], [[-1.0, 0.0], [0.0, 0.0]]],
)
def test_det_and_slogdet_of_singular_matrices_are_positive_zero(backend, xp, matrix):
    a = native(np.array(matrix), backend)
    assert signs(xp.linalg.det(a)) == [False]
    sign, logabsdet = xp.linalg.slogdet(a)
    assert signs(sign) == [False] and numpy_of(logabsdet) == -np.inf


def test_det_of_a_singular_matrix_keeps_its_gradient(backend, xp):
    """The sign of the zero is set without losing the derivative, the adjugate."""
    require(backend, "autodiff")
    a = native(np.array([[-1.0, 0.0], [0.0, 0.0]]), backend)
    _, grad = ivy.execute_with_gradients(lambda m: xp.linalg.det(m), a)
    np.testing.assert_array_equal(numpy_of(grad), [[0.0, 0.0], [0.0, -1.0]])


def test_min_and_maximum_of_zeros_keep_their_gradients(diff_backend):
    """A tie of zeros shares the gradient, as a tie of other values does."""
    xp = getattr(ivy, diff_backend)
    x = native(np.array([N, P, 1.0]), diff_backend)
    _, grad = ivy.execute_with_gradients(lambda v: xp.min(v) + xp.maximum(v, 0.0)[0], x)
    assert numpy_of(grad).sum() == pytest.approx(1.5)
