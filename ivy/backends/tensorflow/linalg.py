"""tensorflow backend: linear algebra, the Array API ``linalg`` extension.

Shims over ``tf.linalg``: dtype promotion (tf requires equal dtypes), bool and integer inputs of
the floating-point functions computed in float32, namedtuple results, batch broadcasting where tf
requires equal batch shapes, and the matrix norms, powers and ranks tf does not have.
"""

from __future__ import annotations

import math

import numpy as np
import tensorflow as tf

from ivy.backends import _nonfinite, _signed_zeros
from ivy.backends.tensorflow._helpers import (
    FAST_TYPES,
    REFUSED,
    floating,
    native_dtype,
    promote,
    tensor,
)
from ivy.core.linalg import EighResult, QRResult, SlogdetResult, SVDResult
from ivy.errors import LinAlgError, ShapeError

matrix_transpose = tf.linalg.matrix_transpose


def matmul(x1, x2, /):
    """``tf.linalg.matmul``, plus 1-D operands and dtype promotion as in numpy."""
    if type(x1) in FAST_TYPES and type(x2) in FAST_TYPES:
        try:
            return _batched_matmul(x1, x2)
        except REFUSED:
            pass
    x1, x2 = promote(x1, x2)
    vec1, vec2 = x1.shape.rank == 1, x2.shape.rank == 1
    out = _integer_safe(_batched_matmul, x1[None] if vec1 else x1, x2[:, None] if vec2 else x2)
    if vec2:
        out = out[..., 0]  # drop the column of the vector made a matrix
    if vec1:
        out = out[..., 0] if vec2 else out[..., 0, :]
    return out


def _batched_matmul(x1, x2):
    """``tf.linalg.matmul`` with batch broadcasting made explicit.

    tensorflow 2.21's oneDNN kernel corrupts the heap (the process aborts) on some broadcast batch
    shapes, e.g. float32 ``[8, 1, 3, 3] @ [1, 3, 1]`` or ``[8, 1, 3, 3] @ [3, 1]``. Operands with
    equal batch shapes take the kernel's plain path; a matrix right operand folds the left
    operand's batch into its rows; other batch shapes are broadcast to their common shape first.
    """
    rank1, rank2 = x1.shape.rank, x2.shape.rank
    if rank1 is None or rank2 is None or rank1 < 2 or rank2 < 2 or rank1 + rank2 == 4:
        return tf.linalg.matmul(x1, x2)  # no batch to broadcast (or tf's own error)
    batch1, batch2 = x1.shape[:-2], x2.shape[:-2]
    if batch1 == batch2 and batch1.is_fully_defined():
        return tf.linalg.matmul(x1, x2)
    if rank2 == 2:
        rows = tf.linalg.matmul(tf.reshape(x1, [-1, tf.shape(x1)[-1]]), x2)
        return tf.reshape(rows, tf.concat([tf.shape(x1)[:-1], tf.shape(x2)[-1:]], 0))
    batch = tf.broadcast_dynamic_shape(tf.shape(x1)[:-2], tf.shape(x2)[:-2])
    x1 = tf.broadcast_to(x1, tf.concat([batch, tf.shape(x1)[-2:]], 0))
    x2 = tf.broadcast_to(x2, tf.concat([batch, tf.shape(x2)[-2:]], 0))
    return tf.linalg.matmul(x1, x2)


# Integer dtypes that tf's matmul has no kernel for: computed in int64 (uint64 as its bits),
# whose wrap-around modulo 2**64 is theirs.
_NO_MATMUL = frozenset({tf.int8, tf.int16, tf.uint8, tf.uint16, tf.uint32, tf.uint64})


def _integer_safe(native, a, b, **kwargs):
    dtype = a.dtype
    if dtype is tf.bool:  # numpy's product of booleans (any of the ands): the count above 0
        return native(tf.cast(a, tf.float32), tf.cast(b, tf.float32), **kwargs) > 0
    if dtype not in _NO_MATMUL:
        return native(a, b, **kwargs)
    if dtype is tf.uint64:
        return tf.bitcast(
            native(tf.bitcast(a, tf.int64), tf.bitcast(b, tf.int64), **kwargs), tf.uint64
        )
    return tf.cast(native(tf.cast(a, tf.int64), tf.cast(b, tf.int64), **kwargs), dtype)


def _is_finite(x):
    """tf.math.is_finite, also of complex values (it has no complex kernel: their parts)."""
    if x.dtype.is_complex:
        return tf.math.is_finite(tf.math.real(x)) & tf.math.is_finite(tf.math.imag(x))
    return tf.math.is_finite(x)


def _finite_only(compute, x):
    """``compute(x)``, NaN in the results of the matrices that hold NaN or infinity
    (``ivy/backends/_nonfinite.py``; tf's ``eigh`` would raise, its QR answer in part)."""
    x = floating(x)
    ok = tf.reduce_all(_is_finite(x), axis=[-2, -1])
    shape = tf.shape(x)
    eye = tf.eye(shape[-2], shape[-1], dtype=x.dtype)
    return _nonfinite.nan_where_not_finite(
        compute,
        x,
        ok,
        eye,
        lambda c, a, b: tf.where(c, a, tf.cast(b, a.dtype)),
        lambda y: y.dtype.is_floating or y.dtype.is_complex,
    )


def cholesky(x, /, *, upper=False):
    x = floating(x)
    lower = _finite_only(tf.linalg.cholesky, x)
    if tf.executing_eagerly() and not bool(tf.reduce_all(tf.math.is_finite(lower))):
        if bool(tf.reduce_all(tf.math.is_finite(x))):  # tf answers with NaN where numpy raises
            raise LinAlgError(
                "the matrix is not positive definite.",
                function="cholesky",
                argument="x",
                backend="tensorflow",
            )
    return tf.linalg.adjoint(lower) if upper else lower


def cross(x1, x2, /, *, axis=-1):
    x1, x2 = promote(x1, x2)
    a0, a1, a2 = tf.unstack(x1, 3, axis=axis)
    b0, b1, b2 = tf.unstack(x2, 3, axis=axis)
    return tf.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=axis)


def det(x, /):
    """A singular matrix's determinant is ``+0`` (``ivy/backends/_signed_zeros.py``)."""
    out = tf.linalg.det(floating(x))
    if out.dtype.is_complex:
        return out
    return _signed_zeros.positive_zero(tf.where, tf.stop_gradient, out)


def diagonal(x, /, *, offset=0):
    x = tensor(x)
    rows, cols = x.shape[-2], x.shape[-1]
    if rows is not None and cols is not None and not -rows < offset < cols:
        return tf.zeros(tf.concat([tf.shape(x)[:-2], [0]], 0), x.dtype)  # beyond the matrix
    return tf.linalg.diag_part(x, k=offset)


def eigh(x, /):
    return _finite_only(lambda x: EighResult(*tf.linalg.eigh(x)), x)


def eigvalsh(x, /):
    return _finite_only(tf.linalg.eigvalsh, x)


def inv(x, /):
    return tf.linalg.inv(floating(x))


def matrix_norm(x, /, *, keepdims=False, ord="fro"):
    x = floating(x)
    if ord == "fro":
        out = tf.math.sqrt(tf.math.reduce_sum(tf.math.square(tf.math.abs(x)), axis=[-2, -1]))
    elif ord == "nuc":
        out = tf.math.reduce_sum(svdvals(x), axis=-1)
    elif ord in (2, -2):
        extreme = tf.math.reduce_max if ord == 2 else tf.math.reduce_min
        out = extreme(svdvals(x), axis=-1)
    elif ord in (1, -1, math.inf, -math.inf):
        summed = -2 if ord in (1, -1) else -1  # column sums for 1, row sums for inf
        extreme = tf.math.reduce_max if ord > 0 else tf.math.reduce_min
        out = extreme(tf.math.reduce_sum(tf.math.abs(x), axis=summed), axis=-1)
    else:
        raise ValueError(
            f"matrix_norm: unknown ord {ord!r}; use 'fro', 'nuc', 1, -1, 2, -2, inf or -inf."
        )
    return out[..., None, None] if keepdims else out


def matrix_power(x, n, /):
    """Repeated squaring; integer matrices stay integer for ``n >= 0``, a negative ``n`` inverts
    (in float32 for integers)."""
    x = tensor(x)
    if n < 0:
        x, n = inv(x), -n
    if n == 0:
        shape = tf.shape(x)
        return tf.eye(shape[-1], batch_shape=shape[:-2], dtype=x.dtype)
    result = None
    while True:
        if n & 1:
            result = x if result is None else matmul(result, x)
        n >>= 1
        if not n:
            return result
        x = matmul(x, x)


def matrix_rank(x, /, *, rtol=None):
    x = floating(x)
    if tf.executing_eagerly():
        _nonfinite.refuse_not_finite(bool(tf.reduce_all(_is_finite(x))), "tensorflow")
    s = svdvals(x)
    if rtol is None:
        rows, cols = x.shape[-2:]
        rtol = max(rows, cols) * np.finfo(s.dtype.as_numpy_dtype).eps
    else:
        rtol = tf.cast(rtol, s.dtype)[..., None]  # a scalar, or one per matrix of the stack
    tol = rtol * tf.math.reduce_max(s, axis=-1, keepdims=True)
    return tf.math.count_nonzero(s > tol, axis=-1, dtype=tf.int64)


def outer(x1, x2, /):
    x1, x2 = promote(x1, x2)
    return x1[:, None] * x2[None, :]


def pinv(x, /, *, rtol=None):
    return _finite_only(lambda x: _pinv(x, rtol), x)


def _pinv(x, rtol):
    real = x.dtype.real_dtype
    if x.shape.num_elements() == 0:  # tf's SVD refuses empty stacks and matrices
        *batch, rows, cols = x.shape
        return tf.zeros((*batch, cols, rows), x.dtype)
    if rtol is not None:  # a Python float, or an array of any real dtype (one per matrix)
        rtol = tf.cast(rtol, real)
    if rtol is None:  # numpy 2's default
        rows, cols = x.shape[-2:]
        if rows is None or cols is None:
            size = tf.cast(tf.reduce_max(tf.shape(x)[-2:]), x.dtype.real_dtype)
        else:
            size = max(rows, cols)
        rtol = size * np.finfo(x.dtype.real_dtype.as_numpy_dtype).eps
    if x.dtype.is_complex:  # tf.linalg.pinv takes real matrices only: through the SVD
        s, u, v = tf.linalg.svd(x)
        cutoff = tf.cast(rtol, s.dtype)[..., None] * tf.math.reduce_max(s, axis=-1, keepdims=True)
        inverse = tf.where(s > cutoff, 1 / s, tf.zeros_like(s))
        return tf.linalg.matmul(v * tf.cast(inverse, x.dtype)[..., None, :], u, adjoint_b=True)
    return tf.linalg.pinv(x, rcond=rtol)


def qr(x, /, *, mode="reduced"):
    if mode not in ("reduced", "complete"):
        raise ValueError(f"qr: unknown mode {mode!r}; use 'reduced' or 'complete'.")
    return _finite_only(lambda x: QRResult(*tf.linalg.qr(x, full_matrices=mode == "complete")), x)


def slogdet(x, /):
    """The log of the absolute determinant is real, also for complex matrices (tf gives it the
    input's complex dtype)."""
    sign, logabsdet = _finite_only(tf.linalg.slogdet, x)
    if logabsdet.dtype.is_complex:
        logabsdet = tf.math.real(logabsdet)
    else:  # a singular matrix's sign is 0, not -0
        sign = _signed_zeros.positive_zero(tf.where, tf.stop_gradient, sign)
    return SlogdetResult(sign, logabsdet)


def solve(x1, x2, /):
    """``x2`` is a vector when 1-D, else a stack of matrices; batch shapes broadcast."""
    x1, x2 = promote(floating(x1), floating(x2))
    vector = x2.shape.rank == 1
    if vector:
        x2 = x2[:, None]
    s1, s2 = tf.shape(x1), tf.shape(x2)
    batch = tf.broadcast_dynamic_shape(s1[:-2], s2[:-2])
    x1 = tf.broadcast_to(x1, tf.concat([batch, s1[-2:]], 0))
    x2 = tf.broadcast_to(x2, tf.concat([batch, s2[-2:]], 0))
    out = tf.linalg.solve(x1, x2)
    return out[..., 0] if vector else out


def svd(x, /, *, full_matrices=True):
    def native(x):
        s, u, v = tf.linalg.svd(x, full_matrices=full_matrices)
        return SVDResult(u, s, tf.linalg.adjoint(v))

    return _finite_only(native, x)


def svdvals(x, /):
    return _finite_only(lambda x: tf.linalg.svd(x, compute_uv=False), x)


def tensordot(x1, x2, /, *, axes=2):
    x1, x2 = promote(x1, x2)
    if not isinstance(axes, int):  # tf.tensordot wants non-negative axes
        a1, a2 = axes
        r1, r2 = x1.shape.rank, x2.shape.rank
        axes = ([a % r1 for a in a1], [a % r2 for a in a2])
    return _integer_safe(tf.tensordot, x1, x2, axes=axes)


def trace(x, /, *, offset=0, dtype=None):
    """Bool and small integers accumulate in int64 (unsigned ones in uint64)."""
    diag = diagonal(x, offset=offset)
    dt = native_dtype(dtype)
    if dt is None:
        dt = diag.dtype
        if dt == tf.bool or (dt.is_integer and dt.size < 8):
            dt = tf.uint64 if dt.is_unsigned else tf.int64
    return tf.math.reduce_sum(tf.cast(diag, dt), axis=-1)


def vecdot(x1, x2, /, *, axis=-1):
    x1, x2 = promote(x1, x2)
    n1, n2 = x1.shape[axis], x2.shape[axis]
    if n1 is not None and n2 is not None and n1 != n2:  # (broadcasting would hide it)
        raise ShapeError(
            f"the axis {axis} of x1 (shape {tuple(x1.shape)}) and of x2 (shape {tuple(x2.shape)}) "
            f"must have the same size.",
            function="vecdot",
            argument="x1, x2",
            backend="tensorflow",
        )
    if x1.dtype.is_complex:
        x1 = tf.math.conj(x1)
    if x1.dtype is tf.bool:  # (numpy's: any of the ands)
        return tf.math.reduce_any(tf.math.logical_and(x1, x2), axis=axis)
    return tf.math.reduce_sum(x1 * x2, axis=axis)


def vector_norm(x, /, *, axis=None, keepdims=False, ord=2):
    x = tf.math.abs(floating(x))
    if ord == 2:
        return tf.math.sqrt(tf.math.reduce_sum(tf.math.square(x), axis=axis, keepdims=keepdims))
    if ord == 1:
        return tf.math.reduce_sum(x, axis=axis, keepdims=keepdims)
    if ord == math.inf:
        return tf.math.reduce_max(x, axis=axis, keepdims=keepdims)
    if ord == -math.inf:
        return tf.math.reduce_min(x, axis=axis, keepdims=keepdims)
    if ord == 0:
        return tf.math.reduce_sum(tf.cast(x != 0, x.dtype), axis=axis, keepdims=keepdims)
    return tf.math.reduce_sum(x**ord, axis=axis, keepdims=keepdims) ** (1.0 / ord)
