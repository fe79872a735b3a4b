"""torch backend: linear algebra, the Array API ``linalg`` extension (torch.linalg).

torch.linalg's defaults are the Array API's (``pinv``'s and ``matrix_rank``'s rtol defaults to
``max(M, N) * eps``), and its results are named (``eigh(x).eigenvalues``, ``svd(x).Vh``). The
shims compute bool and integer inputs of the floating-point functions in float32, promote mixed
dtypes where torch requires equal ones, and rename ``axis`` to ``dim``.
"""

from __future__ import annotations

import torch

from ivy.backends import _nonfinite, _signed_zeros
from ivy.backends.torch._helpers import as_inexact, native_dtype, reduction_args, values_known
from ivy.backends.torch._unsigned import promoted, unsigned_safe, work_dtype
from ivy.core.linalg import SlogdetResult
from ivy.errors import ShapeError

diagonal = torch.linalg.diagonal  # (x, *, offset=0) over the last two axes
_matmul = unsigned_safe(torch.matmul, "matmul", "arith")
_outer = unsigned_safe(torch.outer, "outer", "arith")
_tensordot = unsigned_safe(torch.tensordot, "tensordot", "arith")
_cross = unsigned_safe(torch.linalg.cross, "cross", "arith")


def _finite_only(compute, x):
    """``compute(x)``, NaN in the results of the matrices that hold NaN or infinity
    (``ivy/backends/_nonfinite.py``; torch would raise on NaN)."""
    x = as_inexact(x)
    ok = torch.isfinite(x).flatten(-2).all(-1)
    eye = torch.eye(x.shape[-2], x.shape[-1], dtype=x.dtype, device=x.device)
    return _nonfinite.nan_where_not_finite(
        compute, x, ok, eye, torch.where, lambda y: y.is_floating_point() or y.is_complex()
    )


def matmul(x1, x2, /):
    """``torch.matmul`` with mixed dtypes promoted (torch refuses them) and uint16+ computed
    through int64."""
    x1, x2 = _promoted(x1, x2)
    if x1.dtype is torch.bool:
        return _boolean(_matmul, x1, x2)
    return _matmul(x1, x2)


def _boolean(native, x1, x2, **kwargs):
    """A product of boolean matrices as numpy computes it (any of the ands), which torch has no
    kernel for: whether the count of true products is above 0 (in float32: no wrap-around)."""
    return native(x1.to(torch.float32), x2.to(torch.float32), **kwargs) > 0


def outer(x1, x2, /):
    return _outer(*_promoted(x1, x2))


_WIDE = {torch.bool: torch.int64, torch.uint8: torch.uint64, torch.uint16: torch.uint64}
_WIDE.update({torch.uint32: torch.uint64, torch.int8: torch.int64, torch.int16: torch.int64})
_WIDE[torch.int32] = torch.int64


def _promoted(x1, x2):
    """Both tensors in their dtype promoted by ivy's rules (torch's matmul, tensordot and vecdot
    require one dtype, and torch promotes none of uint16, uint32, uint64)."""
    if x1.dtype == x2.dtype:
        return x1, x2
    dtype = promoted((x1, x2))
    return x1.to(dtype), x2.to(dtype)


def cholesky(x, /, *, upper=False):
    return _finite_only(lambda x: torch.linalg.cholesky(x, upper=upper), x)


def cross(x1, x2, /, *, axis=-1):
    x1, x2 = _promoted(x1, x2)
    if x1.ndim != x2.ndim:  # torch.linalg.cross broadcasts only between equal ranks
        x1, x2 = torch.broadcast_tensors(x1, x2)
    return _cross(x1, x2, dim=axis)


def det(x, /):
    """A singular matrix's determinant is ``+0`` (``ivy/backends/_signed_zeros.py``)."""
    x = as_inexact(x)
    if x.is_complex():
        return torch.linalg.det(x)
    out = _Det.apply(x) if x.requires_grad else torch.linalg.det(x)
    return _signed_zeros.positive_zero(torch.where, torch.Tensor.detach, out)


class _Det(torch.autograd.Function):
    """det with the gradient that is right for singular matrices too, the transposed adjugate
    (torch's own gave zeros for a singular 2x2 matrix: d det/dA of [[1, 2], [2, 4]] is
    [[4, -2], [-2, 1]]). From the SVD A = U S V^T: adj(A)^T = det(U) det(V) U diag(c) V^T,
    c_i the product of the singular values but the i-th (no division, so no singularity)."""

    @staticmethod
    def forward(ctx, x):
        ctx.save_for_backward(x)
        return torch.linalg.det(x)

    @staticmethod
    def backward(ctx, g):
        (x,) = ctx.saved_tensors
        u, s, vh = torch.linalg.svd(x)
        ones = torch.ones_like(s[..., :1])
        before = torch.cumprod(torch.cat([ones, s[..., :-1]], -1), -1)
        after = torch.flip(
            torch.cumprod(torch.cat([ones, torch.flip(s, [-1])[..., :-1]], -1), -1), [-1]
        )
        sign = torch.linalg.det(u) * torch.linalg.det(vh)
        adjugate_t = (u * (before * after)[..., None, :]) @ vh
        return (g * sign)[..., None, None] * adjugate_t


def eigh(x, /):
    return _finite_only(torch.linalg.eigh, x)


def eigvalsh(x, /):
    return _finite_only(torch.linalg.eigvalsh, x)


def inv(x, /):
    return torch.linalg.inv(as_inexact(x))


def matrix_norm(x, /, *, keepdims=False, ord="fro"):
    return torch.linalg.matrix_norm(as_inexact(x), ord=ord, dim=(-2, -1), keepdim=keepdims)


_matrix_power = unsigned_safe(torch.linalg.matrix_power, "matrix_power", "arith", (0,))


def matrix_power(x, n, /):
    """Integer matrices stay integer for ``n >= 0``; a negative ``n`` inverts in float32."""
    if x.dtype is torch.bool and n >= 0:  # (as matmul: whether the count is above 0)
        return _matrix_power(x.to(torch.float32), n) > 0
    return _matrix_power(x if n >= 0 else as_inexact(x), n)


def matrix_rank(x, /, *, rtol=None):
    x = as_inexact(x)
    if values_known(x):
        _nonfinite.refuse_not_finite(bool(torch.isfinite(x).all()), "torch")
    return torch.linalg.matrix_rank(x, rtol=rtol)


def matrix_transpose(x, /):
    return x.mT


def pinv(x, /, *, rtol=None):
    return _finite_only(lambda x: torch.linalg.pinv(x, rtol=rtol), x)


def qr(x, /, *, mode="reduced"):
    return _finite_only(lambda x: torch.linalg.qr(x, mode=mode), x)


def slogdet(x, /):
    """The sign of a singular matrix's determinant is ``0``, not ``-0``."""
    sign, logabsdet = _finite_only(torch.linalg.slogdet, x)
    if not sign.is_complex():
        sign = _signed_zeros.positive_zero(torch.where, torch.Tensor.detach, sign)
    return SlogdetResult(sign, logabsdet)


def solve(x1, x2, /):
    """``x2`` is a vector only when 1-D (torch would also read ``(..., M)`` as vectors)."""
    x1, x2 = _promoted(as_inexact(x1), as_inexact(x2))
    if x2.ndim == 1:
        return torch.linalg.solve(x1, x2)
    batch = torch.broadcast_shapes(x1.shape[:-2], x2.shape[:-2])
    x1 = x1.expand(*batch, *x1.shape[-2:])
    x2 = x2.expand(*batch, *x2.shape[-2:])
    return torch.linalg.solve(x1, x2)


def svd(x, /, *, full_matrices=True):
    return _finite_only(lambda x: torch.linalg.svd(x, full_matrices=full_matrices), x)


def svdvals(x, /):
    return _finite_only(torch.linalg.svdvals, x)


def tensordot(x1, x2, /, *, axes=2):
    x1, x2 = _promoted(x1, x2)
    if x1.dtype is torch.bool:
        return _boolean(_tensordot, x1, x2, dims=axes)
    return _tensordot(x1, x2, dims=axes)


def trace(x, /, *, offset=0, dtype=None):
    """Bool and small integers accumulate in int64 (unsigned ones in uint64, computed in int64:
    the bits are the same modulo 2**64)."""
    diag = torch.diagonal(x, offset, -2, -1)
    dtype = native_dtype(dtype) or _WIDE.get(diag.dtype, diag.dtype)
    if dtype in (torch.uint64, torch.uint32, torch.uint16):
        return diag.sum(-1, dtype=torch.int64).to(dtype)
    return diag.sum(-1, dtype=dtype)


def vecdot(x1, x2, /, *, axis=-1):
    x1, x2 = _promoted(x1, x2)
    if x1.shape[axis] != x2.shape[axis]:  # (broadcasting would hide it)
        raise ShapeError(
            f"the axis {axis} of x1 (shape {tuple(x1.shape)}) and of x2 (shape "
            f"{tuple(x2.shape)}) must have the same size.",
            function="vecdot",
            argument="x1, x2",
            backend="torch",
        )
    if not (x1.is_floating_point() or x1.is_complex()):  # torch.linalg.vecdot refuses integers
        work = work_dtype(x1.dtype)
        out = torch.sum(x1.to(work) * x2.to(work), dim=axis, dtype=work)  # torch: int64 sums
        return out if out.dtype is x1.dtype else out.to(x1.dtype)
    return torch.linalg.vecdot(x1, x2, dim=axis)


def vector_norm(x, /, *, axis=None, keepdims=False, ord=2):
    x, dim, keepdim = reduction_args(as_inexact(x), axis, keepdims)
    return torch.linalg.vector_norm(x, ord=ord, dim=dim, keepdim=keepdim)
