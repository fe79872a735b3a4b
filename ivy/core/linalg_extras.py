"""Linear algebra beyond the Array API ``linalg`` extension (which is ``ivy.core.linalg``):
Einstein summation and the skew-symmetric (cross-product) matrix of 3-vectors."""

from __future__ import annotations

from ivy import framework_handler as _fh
from ivy.core._by_hand import by_hand
from ivy.core._dispatch import composition

__all__ = ["einsum", "vector_to_skew_symmetric_matrix"]


@by_hand  # ``@dispatch`` stubs take no ``*operands``; every backend implements einsum
def einsum(equation: str, *operands, f=None):
    """Einstein summation over ``operands`` as described by ``equation`` (numpy's notation,
    ``'...'`` for broadcast axes); mixed dtypes promote.

    Args:
        equation: subscripts, e.g. ``'ij,jk->ik'``.
        *operands: the arrays.
        f: framework (name or namespace); by default inferred from the operands.

    Returns:
        The contraction.

    Example: ``ivy.einsum('ij,j->i', a, v)`` is ``a @ v``.
    """
    return _fh.get_framework(*operands, f=f).einsum(equation, *operands)


@composition
def vector_to_skew_symmetric_matrix(vector, /, *, f=None):
    """The skew-symmetric matrix ``[v]x`` of 3-vectors, with ``[v]x @ u == cross(v, u)``.

    Args:
        vector: ``[..., 3]``.

    Returns:
        ``[..., 3, 3]``: ``[[0, -z, y], [z, 0, -x], [-y, x, 0]]``.

    Example: ``ivy.vector_to_skew_symmetric_matrix(np.array([1., 2., 3.]))`` ->
    ``[[0., -3., 2.], [3., 0., -1.], [-2., 1., 0.]]``.
    """
    xp = _fh.get_framework(vector, f=f)
    if xp.shape(vector)[-1:] != (3,):
        raise ValueError(
            f"vector_to_skew_symmetric_matrix: vector must be [..., 3]; got shape "
            f"{tuple(xp.shape(vector))}."
        )
    x, y, z = vector[..., 0], vector[..., 1], vector[..., 2]
    zero = xp.zeros_like(x)
    rows = [[zero, -z, y], [z, zero, -x], [-y, x, zero]]
    return xp.stack([xp.stack(row, axis=-1) for row in rows], axis=-2)
