"""Linear algebra, the Array API ``linalg`` extension, written once: ``xp.linalg`` where it agrees
with ivy, and shims that compute bool and integer inputs of the floating-point functions in
float32, the default float dtype (numpy, and jax with 64-bit types, would use float64)."""

from __future__ import annotations

from ivy.backends._nonfinite import nan_where_not_finite, refuse_not_finite
from ivy.backends.array_api._unbound import as_inexact, backend_name, concrete, xp
from ivy.errors import LinAlgError


def _finite_only(compute, x):
    """``compute(x)``, NaN in the results of the matrices that hold NaN or infinity
    (``ivy/backends/_nonfinite.py``)."""
    x = as_inexact(x)
    ok = xp.all(xp.isfinite(x), axis=(-2, -1))
    eye = xp.eye(x.shape[-2], x.shape[-1], dtype=x.dtype)
    return nan_where_not_finite(
        compute,
        x,
        ok,
        eye,
        lambda c, a, b: xp.where(c, a, xp.asarray(b, dtype=a.dtype)),
        lambda y: xp.isdtype(y.dtype, ("real floating", "complex floating")),
    )


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
    out = _finite_only(lambda x: xp.linalg.cholesky(x, upper=upper), x)
    return _checked(out, x, "cholesky", "not positive definite")


def det(x, /):
    return xp.linalg.det(as_inexact(x))


def eigh(x, /):
    return _finite_only(xp.linalg.eigh, x)


def eigvalsh(x, /):
    return _finite_only(xp.linalg.eigvalsh, x)


def inv(x, /):
    x = as_inexact(x)
    return _checked(xp.linalg.inv(x), x, "inv", "singular")


def matrix_norm(x, /, *, keepdims=False, ord="fro"):
    return xp.linalg.matrix_norm(as_inexact(x), keepdims=keepdims, ord=ord)


def matrix_power(x, n, /):
    """Integer matrices stay integer for ``n >= 0``; a negative ``n`` inverts in float32."""
    return xp.linalg.matrix_power(x if n >= 0 else as_inexact(x), n)


def matrix_rank(x, /, *, rtol=None):
    x = as_inexact(x)
    if concrete(x):
        refuse_not_finite(bool(xp.all(xp.isfinite(x))), backend_name)
    return xp.linalg.matrix_rank(x, rtol=rtol)


def pinv(x, /, *, rtol=None):
    return _finite_only(lambda x: xp.linalg.pinv(x, rtol=rtol), x)


def qr(x, /, *, mode="reduced"):
    return _finite_only(lambda x: xp.linalg.qr(x, mode=mode), x)


def slogdet(x, /):
    return _finite_only(xp.linalg.slogdet, x)


def solve(x1, x2, /):
    x1 = as_inexact(x1)
    return _checked(xp.linalg.solve(x1, as_inexact(x2)), x1, "solve", "singular")


def svd(x, /, *, full_matrices=True):
    return _finite_only(lambda x: xp.linalg.svd(x, full_matrices=full_matrices), x)


def svdvals(x, /):
    return _finite_only(xp.linalg.svdvals, x)


def vector_norm(x, /, *, axis=None, keepdims=False, ord=2):
    return xp.linalg.vector_norm(as_inexact(x), axis=axis, keepdims=keepdims, ord=ord)
