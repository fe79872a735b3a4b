"""Linear algebra beyond the Array API ``linalg`` extension (which is ``ivy.core.linalg``):
Einstein summation, the skew-symmetric (cross-product) matrix of 3-vectors, cosine similarity,
and clipping by norm (of one array, or of a whole nest such as gradients)."""

from __future__ import annotations

import numbers

from ivy import framework_handler as _fh
from ivy import nest as _nest
from ivy.core._by_hand import by_hand
from ivy.core._dispatch import composition
from ivy.core._floats import common_floating, floating
from ivy.typing import Array, Framework, Nest

__all__ = [
    "einsum",
    "vector_to_skew_symmetric_matrix",
    "cosine_similarity",
    "clip_vector_norm",
    "clip_by_global_norm",
]


@by_hand  # ``@dispatch`` stubs take no ``*operands``; every backend implements einsum
def einsum(equation: str, *operands: Array, f: Framework = None) -> Array:
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
    ns = _fh.get_framework(*operands, f=f)
    if f is not None:
        operands = _fh.to_namespace(ns, operands)
    return ns.einsum(equation, *operands)


@composition
def vector_to_skew_symmetric_matrix(vector: Array, /, *, f: Framework = None) -> Array:
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


@composition
def cosine_similarity(
    x1: Array, x2: Array, /, *, axis: int = -1, eps: float = 1e-8, f: Framework = None
) -> Array:
    """Cosine of the angle between the vectors of ``x1`` and ``x2`` along ``axis``.

    Computed as torch (2.x) defines it, each norm clamped separately:
    ``sum(x1 * x2) / (max(|x1|, eps) * max(|x2|, eps))`` with Euclidean norms ``|.|``; so a zero
    vector gives 0, not NaN.

    Args:
        x1: array; integers are computed in float32.
        x2: array broadcastable with ``x1``.
        axis: the axis of the vectors, in the broadcast shape.
        eps: the smallest norm used in the division.

    Returns:
        The broadcast shape without ``axis``, of the promoted floating dtype.

    Example: ``ivy.cosine_similarity(np.array([1., 0.]), np.array([1., 1.]))`` -> ``0.7071...``.
    """
    xp = _fh.get_framework(x1, x2, f=f)
    a, b = common_floating(xp, x1, x2)
    if tuple(xp.shape(a)) != tuple(xp.shape(b)):
        a, b = xp.broadcast_arrays(a, b)
    dot = xp.sum(xp.multiply(a, b), axis=axis)
    norm_a = xp.maximum(xp.vector_norm(a, axis=axis), eps)
    norm_b = xp.maximum(xp.vector_norm(b, axis=axis), eps)
    return xp.divide(dot, xp.multiply(norm_a, norm_b))


def _check_max_norm(max_norm, name):
    if isinstance(max_norm, numbers.Real) and not max_norm > 0:
        raise ValueError(f"{name}: max_norm must be positive; got {max_norm!r}.")


@composition
def clip_vector_norm(
    x: Array,
    max_norm: float | Array,
    /,
    *,
    axis: int | tuple[int, ...] | None = None,
    p: float = 2.0,
    f: Framework = None,
) -> Array:
    """``x`` scaled down so that its ``p``-norm over ``axis`` is at most ``max_norm``.

    Where the norm is already within ``max_norm``, ``x`` is unchanged; elsewhere it is multiplied
    by ``max_norm / norm`` (no epsilon, as ``optax.clip_by_global_norm``).

    Args:
        x: array; integers are computed in float32.
        max_norm: the largest norm, positive (a number or an array broadcastable with the norms).
        axis: None (the norm of all elements), an int or a tuple of ints: each vector along
            ``axis`` is clipped on its own.
        p: the order of the norm, as ``ord`` of :func:`vector_norm` (``2.0``, ``1.0``,
            ``inf`` ...).

    Returns:
        ``x``'s shape and floating dtype.

    Example: ``ivy.clip_vector_norm(np.array([3., 4.]), 1.)`` -> ``[0.6, 0.8]``.
    """
    _check_max_norm(max_norm, "clip_vector_norm")
    xp = _fh.get_framework(x, f=f)
    x = floating(xp, x)
    norm = xp.vector_norm(x, axis=axis, keepdims=True, ord=p)
    return xp.multiply(x, xp.divide(max_norm, xp.maximum(norm, max_norm)))


@composition
def clip_by_global_norm(
    xs: Nest, max_norm: float | Array, /, *, f: Framework = None
) -> tuple[Nest, Array]:
    """Scale every array of the nest ``xs`` by one factor so that their global norm (the
    Euclidean norm of all their elements together) is at most ``max_norm``.

    The functional form of ``torch.nn.utils.clip_grad_norm_`` and ``optax.clip_by_global_norm``:
    the arrays are multiplied by ``max_norm / global_norm`` when the global norm exceeds
    ``max_norm`` (no epsilon), and returned unchanged otherwise.

    Args:
        xs: a nest (dicts, lists, tuples) of floating arrays, e.g. gradients.
        max_norm: the largest global norm, positive.

    Returns:
        ``(clipped, global_norm)``: a nest of ``xs``' structure whose arrays keep their dtypes,
        and the global norm before clipping (a 0-d array of the promoted dtype of the arrays).

    Example:
        >>> grads = {"w": np.array([3., 0.]), "b": np.array([4.])}
        >>> clipped, norm = ivy.clip_by_global_norm(grads, 1.0)  # norm 5.0
        >>> clipped["w"], clipped["b"]
        (array([0.6, 0. ]), array([0.8]))
    """
    _check_max_norm(max_norm, "clip_by_global_norm")
    leaves = _nest.nest_leaves(xs)
    xp = _fh.get_framework(*leaves, f=f)
    if not leaves:
        return xs, xp.asarray(0.0)
    total = None
    for leaf in leaves:
        leaf = floating(xp, leaf)
        if "complex" in xp.dtype(leaf, as_str=True):
            leaf = xp.abs(leaf)
        squares = xp.sum(xp.square(leaf))
        total = squares if total is None else xp.add(total, squares)
    global_norm = xp.sqrt(total)
    scale = xp.divide(max_norm, xp.maximum(global_norm, max_norm))

    def clip(leaf):
        leaf = floating(xp, leaf)
        return xp.multiply(leaf, xp.astype(scale, xp.dtype(leaf)))

    return _nest.map_nest(clip, xs), global_norm
