"""Linear algebra, the Array API ``linalg`` extension, written once: ``xp.linalg`` where it agrees
with ivy, and shims that compute bool and integer inputs of the floating-point functions in
float32, the default float dtype (numpy, and jax with 64-bit types, would use float64)."""

from __future__ import annotations

from ivy.backends.array_api._unbound import as_inexact, backend_name, concrete, xp
from ivy.errors import LinAlgError


def _checked(out, x, name: str, what: str):
    """``out``, or LinAlgError where a finite ``x`` gave non-finite values: jax answers a
    singular or indefinite matrix with inf or NaN where numpy raises (checked only where the
    values are known: not inside ``jax.jit``)."""
    if concrete(out) and not bool(xp.all(xp.isfinite(out))) and bool(xp.all(xp.isfinite(x))):
        raise LinAlgError(
            f"the matrix is {what}.", function=name, argument="x", backend=backend_name
        )
    return out


NATIVE = {
    "matmul": "matmul",
    "cross": "linalg.cross",
    "diagonal": "linalg.diagonal",
    "matrix_transpose": "linalg.matrix_transpose",
    "outer": "linalg.outer",
    "tensordot": "tensordot",
    "trace": "linalg.trace",  # bool and small integers accumulate in int64 (unsigned: uint64)
    "vecdot": "vecdot",
}


def cholesky(x, /, *, upper=False):
    x = as_inexact(x)
    return _checked(xp.linalg.cholesky(x, upper=upper), x, "cholesky", "not positive definite")


def det(x, /):
    return xp.linalg.det(as_inexact(x))


def eigh(x, /):
    return xp.linalg.eigh(as_inexact(x))


def eigvalsh(x, /):
    return xp.linalg.eigvalsh(as_inexact(x))


def inv(x, /):
    x = as_inexact(x)
    return _checked(xp.linalg.inv(x), x, "inv", "singular")


def matrix_norm(x, /, *, keepdims=False, ord="fro"):
    return xp.linalg.matrix_norm(as_inexact(x), keepdims=keepdims, ord=ord)


def matrix_power(x, n, /):
    """Integer matrices stay integer for ``n >= 0``; a negative ``n`` inverts in float32."""
    return xp.linalg.matrix_power(x if n >= 0 else as_inexact(x), n)


def matrix_rank(x, /, *, rtol=None):
    return xp.linalg.matrix_rank(as_inexact(x), rtol=rtol)


def pinv(x, /, *, rtol=None):
    return xp.linalg.pinv(as_inexact(x), rtol=rtol)


def qr(x, /, *, mode="reduced"):
    return xp.linalg.qr(as_inexact(x), mode=mode)


def slogdet(x, /):
    return xp.linalg.slogdet(as_inexact(x))


def solve(x1, x2, /):
    x1 = as_inexact(x1)
    return _checked(xp.linalg.solve(x1, as_inexact(x2)), x1, "solve", "singular")


def svd(x, /, *, full_matrices=True):
    return xp.linalg.svd(as_inexact(x), full_matrices=full_matrices)


def svdvals(x, /):
    return xp.linalg.svdvals(as_inexact(x))


def vector_norm(x, /, *, axis=None, keepdims=False, ord=2):
    return xp.linalg.vector_norm(as_inexact(x), axis=axis, keepdims=keepdims, ord=ord)
