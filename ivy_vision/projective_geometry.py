"""General projective geometry: transforming coordinate images by matrices, inverting projection
matrices, and the homogeneous DLT.

Example:
    >>> transform(np.ones((2, 2, 3)), 2 * np.eye(3))[0, 0]
    array([2., 2., 2.])
"""

from __future__ import annotations

import numpy as np

import ivy
from ivy.typing import Array, Framework
from ivy_vision import _common as C
from ivy_vision._checks import InputError, checked

__all__ = [
    "transform",
    "projection_matrix_inverse",
    "projection_matrix_pseudo_inverse",
    "solve_homogeneous_dlt",
]

#: A matrix whose condition number exceeds this is treated as singular by the eager checks.
MAX_CONDITION = 1e12


def check_invertible(xp, m, what: str, hint: str) -> None:
    """Raise a ValueError when the square matrices ``m`` are singular (eager mode only; under
    compilation the values are unknown and the inverse of a singular matrix is inf or nan)."""
    values = C.concrete(xp, m)
    if values is None:
        return
    with np.errstate(all="ignore"):
        cond = np.linalg.cond(values.astype(np.float64).reshape(-1, *values.shape[-2:]))
    bad = ~np.isfinite(cond) | (cond > MAX_CONDITION)
    if np.any(bad):
        raise InputError(
            f"{what} is singular (condition number {np.max(cond):.3g} for "
            f"{int(np.sum(bad))} of {bad.size} matrices); {hint}"
        )


@checked
def transform(coords: Array, trans: Array, *, f: Framework = None) -> Array:
    """Transform every ``n``-vector of a coordinate image by an ``m x n`` matrix.

    The matrix's leading dimensions are the batch dimensions; the same leading dimensions (or
    ones that broadcast with them) come first in ``coords``, then any image dimensions.

    Args:
        coords: coordinates *[batch_shape, image_shape, n]*.
        trans: transformation matrices *[batch_shape, m, n]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Transformed coordinates *[batch_shape, image_shape, m]*.

    Example:
        >>> transform(np.array([[1., 2., 3.]]), np.eye(2, 3))
        array([[1., 2.]])
    """
    xp = ivy.get_framework(coords, trans, f=f)
    if len(C.shape_of(xp, trans)) < 2:
        raise InputError(f"trans must be [..., m, n]; got shape {C.shape_of(xp, trans)}.")
    return C.transform(xp, coords, trans, "coords", "trans")


@checked
def projection_matrix_inverse(proj_mat: Array, *, f: Framework = None) -> Array:
    """Inverse ``[M^-1 | -M^-1 t]`` of a projection (or extrinsic) matrix ``[M | t]``: the top
    three rows of the inverse of the homogeneous ``4 x 4`` matrix.

    Args:
        proj_mat: matrices *[batch_shape, 3, 4]*; ``M`` must be invertible (a clear error is
            raised for singular ones in eager mode).
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Inverse matrices *[batch_shape, 3, 4]*.

    Example:
        >>> projection_matrix_inverse(np.array([[2., 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0]]))
        array([[ 0.5,  0. ,  0. , -1. ],
               [ 0. ,  1. ,  0. , -0. ],
               [ 0. ,  0. ,  1. , -0. ]])
    """
    xp = ivy.get_framework(proj_mat, f=f)
    C.check_matrix(xp, proj_mat, 3, 4, "proj_mat")
    check_invertible(
        xp,
        proj_mat[..., 0:3],
        "the left 3x3 block of proj_mat",
        "a calibration matrix needs non-zero focal lengths and a rotation must be orthonormal.",
    )
    return invert_affine(xp, proj_mat)


def invert_affine(xp, mat):
    """``[M^-1 | -M^-1 t]`` of ``[M | t]`` (unchecked)."""
    inv = xp.inv(mat[..., 0:3])
    return xp.concat([inv, -xp.matmul(inv, mat[..., 3:4])], axis=-1)


@checked
def projection_matrix_pseudo_inverse(proj_mat: Array, *, f: Framework = None) -> Array:
    """Right pseudo-inverse ``P^T (P P^T)^-1`` of full-rank projection matrices.

    Args:
        proj_mat: projection matrices *[batch_shape, 3, 4]* of rank 3.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Pseudo-inverses *[batch_shape, 4, 3]* with ``P @ P^+ = I``.

    Example:
        >>> projection_matrix_pseudo_inverse(np.eye(3, 4)).shape
        (4, 3)
    """
    xp = ivy.get_framework(proj_mat, f=f)
    C.check_matrix(xp, proj_mat, 3, 4, "proj_mat")
    gram = xp.matmul(proj_mat, xp.swapaxes(proj_mat, -1, -2))
    check_invertible(xp, gram, "P P^T", "proj_mat must have rank 3.")
    return xp.matmul(xp.swapaxes(proj_mat, -1, -2), xp.inv(gram))


@checked
def solve_homogeneous_dlt(A: Array, *, f: Framework = None) -> Array:
    """Solve ``A x = 0`` for a unit vector ``x`` by the homogeneous DLT: the right singular
    vector of the smallest singular value.

    Args:
        A: systems of equations *[batch_shape, k, d]* with ``k >= d - 1``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Unit solutions *[batch_shape, d]*, with the sign that makes the largest component (the
        first of those equal to it within 1e-6) positive: the same on every backend (each
        SVD picks its own sign). NaN for a system holding NaN or inf.

    Example:
        >>> solve_homogeneous_dlt(np.array([[1., 0, 0], [0, 1, 0], [0, 0, 0]]))
        array([0., 0., 1.])
    """
    xp = ivy.get_framework(A, f=f)
    shape = C.shape_of(xp, A)
    if len(shape) < 2:
        raise InputError(f"A must be [..., k, d]; got shape {shape}.")
    # a system with NaN or inf has no solution: NaN on every backend (numpy's and torch's SVD
    # raise, jax's and tensorflow's return NaN)
    finite = xp.all(xp.isfinite(A), axis=(-2, -1))
    A = xp.where(finite[..., None, None], A, xp.zeros_like(A))
    x = xp.svd(A, full_matrices=True)[2][..., -1, :]
    x = xp.where(finite[..., None], x, xp.full_like(x, float("nan")))
    # the first component within rounding of the largest magnitude (exact ties differ by
    # backend in their last bits)
    size = xp.abs(x)
    near = size >= xp.max(size, axis=-1, keepdims=True) * (1.0 - 1e-6)
    first = xp.argmax(xp.astype(near, "int8"), axis=-1, keepdims=True)
    pivot = xp.take_along_axis(x, first, axis=-1)
    return x * xp.stop_gradient(xp.where(pivot < 0, -xp.ones_like(pivot), xp.ones_like(pivot)))
