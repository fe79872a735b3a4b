"""Linear algebra: the Array API (2023.12) ``linalg`` extension.

Every function here is reachable flat (``ivy.svd``, ``ivy.torch.svd``) and in the extension
namespace (``ivy.linalg.svd``, ``ivy.torch.linalg.svd``), the very same object. ``matmul``,
``matrix_transpose``, ``tensordot`` and ``vecdot`` are also main-namespace functions of the
standard. ``norm`` is the paper's spelling of ``vector_norm``.

Matrix functions act on the last two axes and broadcast over any leading batch axes. The
floating-point functions (all but ``diagonal``, ``matmul``, ``matrix_power`` with ``n >= 0``,
``matrix_transpose``, ``outer``, ``tensordot``, ``trace``, ``vecdot``, ``cross``) compute bool and
integer inputs in float32, the default float dtype, on every backend.

Matrices holding NaN or infinity: the decompositions (``cholesky``, ``eigh``, ``eigvalsh``,
``pinv``, ``qr``, ``slogdet``, ``svd``, ``svdvals``) answer NaN in every floating result for such
a matrix and the usual result for the finite matrices of the same batch, on every backend (numpy
and torch would raise, jax and tensorflow answer NaN in part); ``det``, ``inv`` and ``solve``
propagate them as IEEE arithmetic does; ``matrix_rank`` refuses them
(``ivy/backends/_nonfinite.py``).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Literal, NamedTuple

from ivy.core._dispatch import alias, dispatch
from ivy.typing import Array, Dtype, Framework

__extension__ = "linalg"

__all__ = [
    "cholesky",
    "cross",
    "det",
    "diagonal",
    "eigh",
    "eigvalsh",
    "inv",
    "matmul",
    "matrix_norm",
    "matrix_power",
    "matrix_rank",
    "matrix_transpose",
    "outer",
    "pinv",
    "qr",
    "slogdet",
    "solve",
    "svd",
    "svdvals",
    "tensordot",
    "trace",
    "vecdot",
    "vector_norm",
    "norm",
]


# Results with named fields (the backends whose framework returns plain tuples use these; numpy,
# torch and jax return their own named results, with the same field names).
class EighResult(NamedTuple):
    eigenvalues: Array
    eigenvectors: Array


class QRResult(NamedTuple):
    Q: Array
    R: Array


class SlogdetResult(NamedTuple):
    sign: Array
    logabsdet: Array


class SVDResult(NamedTuple):
    U: Array
    S: Array
    Vh: Array


@dispatch
def cholesky(x: Array, /, *, upper: bool = False, f: Framework = None) -> Array:
    """Cholesky factor of symmetric (Hermitian) positive-definite matrices.

    Args:
        x: matrices ``[..., M, M]``.
        upper: return the upper factor ``U`` (``x = U^H U``) instead of the lower ``L``
            (``x = L L^H``).

    Returns:
        The triangular factors, ``[..., M, M]``.

    Example: ``ivy.cholesky(np.array([[4., 2.], [2., 2.]]))`` -> ``[[2., 0.], [1., 1.]]``.
    """


@dispatch("x1", "x2")
def cross(x1: Array, x2: Array, /, *, axis: int = -1, f: Framework = None) -> Array:
    """Cross product of 3-vectors along ``axis`` (the other axes broadcast)."""


@dispatch
def det(x: Array, /, *, f: Framework = None) -> Array:
    """Determinants of the matrices ``x`` (``[..., M, M]`` -> ``[...]``)."""


@dispatch
def diagonal(x: Array, /, *, offset: int = 0, f: Framework = None) -> Array:
    """Diagonal of the last two axes: ``offset > 0`` above the main diagonal, ``< 0`` below.

    Args:
        x: ``[..., M, N]``, any dtype.
        offset: which diagonal; one beyond the matrix gives an empty result.

    Returns:
        ``[..., K]`` with ``K`` the length of that diagonal.

    Example: ``ivy.diagonal(np.arange(6).reshape(2, 3), offset=1)`` -> ``[1, 5]``.
    """


@dispatch
def eigh(x: Array, /, *, f: Framework = None) -> EighResult:
    """Eigen-decomposition of symmetric (Hermitian) matrices, read from their lower triangle on
    every backend (the upper one is ignored).

    Returns:
        A namedtuple ``(eigenvalues, eigenvectors)``: eigenvalues ``[..., M]`` ascending, and
        the orthonormal eigenvectors as the columns of ``[..., M, M]``.
    """


@dispatch
def eigvalsh(x: Array, /, *, f: Framework = None) -> Array:
    """Eigenvalues of symmetric (Hermitian) matrices, ascending (``[..., M]``)."""


@dispatch
def inv(x: Array, /, *, f: Framework = None) -> Array:
    """Inverse of square matrices (batched)."""


@dispatch("x1", "x2")
def matmul(x1: Array, x2: Array, /, *, f: Framework = None) -> Array:
    """Matrix product with batch broadcasting (1-D operands as in numpy)."""


@dispatch
def matrix_norm(
    x: Array,
    /,
    *,
    keepdims: bool = False,
    ord: int | float | Literal["fro", "nuc"] = "fro",
    f: Framework = None,
) -> Array:
    """Matrix norm over the last two axes.

    Args:
        x: ``[..., M, N]``.
        keepdims: keep the two reduced axes with size 1.
        ord: ``'fro'`` (Frobenius), ``'nuc'`` (sum of singular values), ``2`` / ``-2`` (largest
            / smallest singular value), ``1`` / ``-1`` (max / min absolute column sum), ``inf``
            / ``-inf`` (max / min absolute row sum).

    Returns:
        Real norms ``[...]``.
    """


@dispatch
def matrix_power(x: Array, n: int, /, *, f: Framework = None) -> Array:
    """``x`` raised to the integer power ``n`` (``n = 0``: identity; ``n < 0``: powers of the
    inverse). Integer matrices stay integer for ``n >= 0``."""


@dispatch
def matrix_rank(x: Array, /, *, rtol: float | Array | None = None, f: Framework = None) -> Array:
    """Rank: the number of singular values above ``rtol`` times the largest one.

    Args:
        x: ``[..., M, N]``.
        rtol: relative tolerance, a float or one per matrix; default ``max(M, N) * eps``.

    Returns:
        int64 ranks ``[...]``.

    Raises:
        LinAlgError: ``x`` holds NaN or infinity (its rank is undefined), where the values are
            known; inside a compiled program, where they are not, such a matrix counts 0.
    """


@dispatch
def matrix_transpose(x: Array, /, *, f: Framework = None) -> Array:
    """Swap the last two axes (``[..., M, N]`` -> ``[..., N, M]``), not conjugating."""


@dispatch("x1", "x2")
def outer(x1: Array, x2: Array, /, *, f: Framework = None) -> Array:
    """Outer product of two 1-D arrays: ``out[i, j] = x1[i] * x2[j]``."""


@dispatch
def pinv(x: Array, /, *, rtol: float | Array | None = None, f: Framework = None) -> Array:
    """Moore-Penrose pseudo-inverse; singular values below ``rtol * max(S)`` are dropped."""


@dispatch
def qr(
    x: Array, /, *, mode: Literal["reduced", "complete"] = "reduced", f: Framework = None
) -> QRResult:
    """QR decomposition ``x = Q @ R``.

    Args:
        x: ``[..., M, N]``.
        mode: ``'reduced'`` (``Q`` is ``[..., M, K]``, ``R`` ``[..., K, N]``, ``K = min(M, N)``) or
            ``'complete'`` (``Q`` is ``[..., M, M]``, ``R`` ``[..., M, N]``).

    Returns:
        A namedtuple ``(Q, R)``: orthonormal columns and upper-triangular ``R``.
    """


@dispatch
def slogdet(x: Array, /, *, f: Framework = None) -> SlogdetResult:
    """Sign and log of the absolute value of determinants, a namedtuple ``(sign, logabsdet)``.

    A singular matrix gives ``sign = 0`` and ``logabsdet = -inf``.
    """


@dispatch("x1", "x2")
def solve(x1: Array, x2: Array, /, *, f: Framework = None) -> Array:
    """Solution ``X`` of ``x1 @ X = x2`` for square, non-singular ``x1``.

    Args:
        x1: coefficients ``[..., M, M]``.
        x2: a vector ``[M]`` (solved against every matrix of ``x1``), else a stack of matrices
            ``[..., M, K]`` whose batch axes broadcast with those of ``x1``.

    Returns:
        ``[..., M]`` for a vector ``x2``, else ``[..., M, K]``.
    """


@dispatch
def svd(x: Array, /, *, full_matrices: bool = True, f: Framework = None) -> SVDResult:
    """Singular value decomposition, a namedtuple ``(U, S, Vh)`` with
    ``x = U @ diag(S) @ Vh``; S descending."""


@dispatch
def svdvals(x: Array, /, *, f: Framework = None) -> Array:
    """Singular values, descending (``[..., M, N]`` -> ``[..., min(M, N)]``)."""


@dispatch("x1", "x2")
def tensordot(
    x1: Array,
    x2: Array,
    /,
    *,
    axes: int | tuple[Sequence[int], Sequence[int]] = 2,
    f: Framework = None,
) -> Array:
    """Tensor contraction.

    Args:
        x1, x2: arrays.
        axes: an int ``N`` (the last ``N`` axes of ``x1`` with the first ``N`` of ``x2``) or a
            pair of sequences of axes to contract, of equal lengths.

    Returns:
        The non-contracted axes of ``x1`` followed by those of ``x2``.

    Example: ``ivy.tensordot(a, b, axes=([1], [0]))`` is ``a @ b`` for matrices.
    """


@dispatch
def trace(
    x: Array, /, *, offset: int = 0, dtype: Dtype | None = None, f: Framework = None
) -> Array:
    """Sum along a diagonal of the last two axes (``offset`` as in :func:`diagonal`).

    With ``dtype=None``, floating inputs keep their dtype, bool and integers narrower than 64
    bits accumulate in int64 (unsigned ones in uint64).
    """


@dispatch("x1", "x2")
def vecdot(x1: Array, x2: Array, /, *, axis: int = -1, f: Framework = None) -> Array:
    """Dot product of vectors along ``axis``, ``sum(conj(x1) * x2, axis)``; other axes
    broadcast."""


@dispatch
def vector_norm(
    x: Array,
    /,
    *,
    axis: int | tuple[int, ...] | None = None,
    keepdims: bool = False,
    ord: int | float = 2,
    f: Framework = None,
) -> Array:
    """Vector p-norm over ``axis`` (None: all elements; a tuple: those axes together).

    ``ord`` is any real p, ``inf`` or ``-inf``.
    """


norm = alias("norm", vector_norm)
