"""Small dense algebra for the pipeline's kernels (private). Every helper takes the backend
namespace ``xp`` first.

Products over small, static dimensions (3x3 blocks, 6-vectors, the tree's masks) are written as
sums of broadcast products, one term per index of the contracted dimension: element-wise code
that XLA and inductor fuse into one loop over the batch. Measured on the CPU at batch 1,000
(float64), a 3x3 product of ``[1000, 14, 3, 3]`` blocks took 78 us (jax) and 99 us (torch) this
way, against 162 us and 785 us as ``matmul`` and 855 us and 107 us as a broadcast product reduced
by ``sum``; a constant ``[14, 14]`` matrix times ``[1000, 14, 10]`` took 150 us and 221 us against
482 us and 499 us as ``matmul``.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ivy_robot.physics.model import const


class Gather(NamedTuple):
    """Constant integer indices along an axis, made once when a model is read: a slice where
    they are contiguous (``start``, ``stop``), else a gather of ``indices`` (:func:`gather`)."""

    indices: np.ndarray  # int64
    indices32: np.ndarray  # the same, int32 (gathers take these: jax without 64-bit types)
    start: int  # -1 when not contiguous
    stop: int
    whole: bool  # all of an axis of length ``size``, in order


def gather(indices, size: int) -> Gather:
    """A :class:`Gather` of ``indices`` along an axis of length ``size`` (made once, outside
    traced code).

    Example:
        >>> gather([2, 3], 5).start, gather([3, 1], 5).start      # a slice; a gather
        (2, -1)
    """
    values = [int(i) for i in np.asarray(indices, dtype=np.int64).reshape(-1)]
    contiguous = bool(values) and values == list(range(values[0], values[0] + len(values)))
    return Gather(
        indices=np.asarray(values, dtype=np.int64),
        indices32=np.asarray(values, dtype=np.int32),
        start=values[0] if contiguous else -1,
        stop=values[-1] + 1 if contiguous else -1,
        whole=contiguous and values[0] == 0 and len(values) == size,
    )


def contract(xp, a, b):
    """``a @ b`` for ``a`` *[..., m, K]* and ``b`` *[..., K, n]* with a small static ``K``:
    the sum over ``k`` of the outer products of ``a``'s columns and ``b``'s rows."""
    total = a[..., :, 0:1] * b[..., 0:1, :]
    for k in range(1, a.shape[-1]):
        total = total + a[..., :, k : k + 1] * b[..., k : k + 1, :]
    return total


def matvec(xp, a, v):
    """``a @ v`` for ``a`` *[..., m, K]* and ``v`` *[..., K]* with a small static ``K``: the
    sum over ``k`` of ``a``'s columns times ``v``'s entries."""
    total = a[..., :, 0] * v[..., 0:1]
    for k in range(1, a.shape[-1]):
        total = total + a[..., :, k] * v[..., k : k + 1]
    return total


def rmatvec(xp, a, v):
    """``a^T @ v`` for ``a`` *[..., K, m]* and ``v`` *[..., K]* (an ``einsum``, not a product with
    a transposed view: inside a loop's body, torch.compile lifts a transposed view of a captured
    array as a second input, which its loop operators refuse as aliasing the first)."""
    return xp.einsum("...km,...k->...m", a, v)


def gram(xp, a, weights):
    """``a^T diag(weights) a`` *[..., m, m]* for ``a`` *[..., K, m]* and ``weights`` *[..., K]*.

    An ``einsum`` (a dot on XLA, which keeps its result in memory): written as a sum of outer
    products, XLA fused it into each element of an ``L D L'`` factorisation that read it, and
    recomputed it there (a Newton step of the Hopper at batch 1,000: 3.2 ms against 1.0 ms)."""
    return xp.einsum("...ki,...kj->...ij", a * weights[..., :, None], a)


def mm(xp, a, b):
    """``a @ b`` for ``[..., 3, 3]`` blocks (broadcasting)."""
    return contract(xp, a, b)


def mv(xp, a, v):
    """``a @ v`` for ``[..., 3, 3]`` and ``[..., 3]``."""
    return a[..., :, 0] * v[..., 0:1] + a[..., :, 1] * v[..., 1:2] + a[..., :, 2] * v[..., 2:3]


def mtv(xp, a, v):
    """``a^T @ v`` for ``[..., 3, 3]`` and ``[..., 3]``."""
    return a[..., 0, :] * v[..., 0:1] + a[..., 1, :] * v[..., 1:2] + a[..., 2, :] * v[..., 2:3]


def dot(xp, a, b):
    """``sum(a * b)`` over a last axis of static size."""
    return sum_last(xp, a * b)


def sum_last(xp, x):
    """The sum over a last axis of static size, as a sum of slices."""
    total = x[..., 0]
    for k in range(1, x.shape[-1]):
        total = total + x[..., k]
    return total


class ConstMatrix(NamedTuple):
    """A constant matrix *[m, K]* to multiply arrays *[..., K, n]* with (:func:`cmatmul`), made
    once: its non-zero columns as *[m, 1]* numpy arrays."""

    rows: int
    columns: tuple  # (k, column [m, 1]) for every non-zero column


def const_matrix(matrix) -> ConstMatrix:
    matrix = np.asarray(matrix, dtype=np.float64)
    return ConstMatrix(
        rows=matrix.shape[0],
        columns=tuple(
            (k, matrix[:, k : k + 1].copy()) for k in range(matrix.shape[1]) if matrix[:, k].any()
        ),
    )


def cmatmul(xp, matrix: ConstMatrix, x):
    """``matrix @ x`` for a :class:`ConstMatrix` *[m, K]* and ``x`` *[..., K, n]*: one term
    per non-zero column."""
    if not matrix.columns:
        return _zeros_rows(xp, x, matrix.rows)
    total = None
    for k, column in matrix.columns:
        term = const(xp, column, x) * x[..., k : k + 1, :]
        total = term if total is None else total + term
    return total


def _zeros_rows(xp, x, rows: int):
    zero = x[..., :1, :] * 0.0
    return xp.concat([zero] * rows, axis=-2) if rows else x[..., :0, :]


def cross(xp, a, b):
    """The cross product over the last axis (element-wise, fusable)."""
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return xp.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


def take(xp, x, where: Gather, axis: int):
    """``x`` at the constant indices ``where`` (:func:`gather`) along ``axis`` (negative)."""
    if where.whole:
        return x
    if where.start >= 0:
        key = (Ellipsis, slice(where.start, where.stop)) + (slice(None),) * (-axis - 1)
        return x[key]
    indices = xp.constant(where.indices32, dtype="int32", device=xp.dev(x))
    return xp.take(x, indices, axis=axis)


def quat_to_mat(xp, quat):
    """Rotation matrices ``[..., 3, 3]`` of quaternions ``[w, x, y, z]`` (normalised first;
    a zero quaternion is the identity, as MuJoCo's ``mju_normalize4``)."""
    norm = xp.safe_norm(quat, axis=-1, keepdims=True)
    tiny = norm < 1e-15
    q = xp.where(tiny, const(xp, _UNIT_QUATERNION, quat), quat / xp.where(tiny, 1.0, norm))
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    rows = [
        [w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z],
    ]
    return xp.stack([xp.stack(row, axis=-1) for row in rows], axis=-2)


_UNIT_QUATERNION = np.array([1.0, 0.0, 0.0, 0.0])
EYE3 = np.eye(3)


def eye3(xp, like):
    return const(xp, EYE3, like)


def cross_motion(xp, v, u):
    """MuJoCo's ``mju_crossMotion``: ``v x u`` for motion vectors ``[..., 6]`` (angular,
    linear)."""
    vw, vv, uw, uv = v[..., :3], v[..., 3:], u[..., :3], u[..., 3:]
    return xp.concat([cross(xp, vw, uw), cross(xp, vw, uv) + cross(xp, vv, uw)], axis=-1)


def cross_force(xp, v, f):
    """MuJoCo's ``mju_crossForce``: ``v x* f`` for a motion ``v`` and a force ``f`` [..., 6]
    (torque, force)."""
    vw, vv, ft, ff = v[..., :3], v[..., 3:], f[..., :3], f[..., 3:]
    return xp.concat([cross(xp, vw, ft) + cross(xp, vv, ff), cross(xp, vw, ff)], axis=-1)


def inertia_parts(xp, cinert):
    """MuJoCo's ``cinert`` ``[..., 10]`` -> (rotational inertia ``[..., 3, 3]`` about the
    frame's origin, first moment ``h = m c`` ``[..., 3]``, mass ``[...]``)."""
    xx, yy, zz, xy, xz, yz = (cinert[..., k] for k in range(6))
    rot = xp.stack(
        [xp.stack(r, axis=-1) for r in ((xx, xy, xz), (xy, yy, yz), (xz, yz, zz))],
        axis=-2,
    )
    return rot, cinert[..., 6:9], cinert[..., 9]


def apply_inertia(xp, cinert, v):
    """MuJoCo's ``mju_mulInertVec``: the momentum ``[..., 6]`` (angular, linear) of a body with
    the inertia ``cinert`` ``[..., 10]`` moving with ``v`` ``[..., 6]``."""
    rot, h, mass = inertia_parts(xp, cinert)
    w, lin = v[..., :3], v[..., 3:]
    return xp.concat(
        [mv(xp, rot, w) + cross(xp, h, lin), mass[..., None] * lin - cross(xp, h, w)], axis=-1
    )
