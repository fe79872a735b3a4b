"""Small dense algebra for the pipeline's kernels (private): 3x3 products written as
element-wise products and sums, which XLA and inductor fuse into the surrounding loops over the
batch (a ``matmul`` of 3x3 blocks would be one small library call each), and gathers by
constant indices. Every helper takes the backend namespace ``xp`` first.
"""

from __future__ import annotations

import numpy as np

from ivy_robot.physics.model import const, index


def mm(xp, a, b):
    """``a @ b`` for ``[..., 3, 3]`` blocks (broadcasting)."""
    return xp.sum(a[..., :, :, None] * b[..., None, :, :], axis=-2)


def mv(xp, a, v):
    """``a @ v`` for ``[..., 3, 3]`` and ``[..., 3]``."""
    return xp.sum(a * v[..., None, :], axis=-1)


def mtv(xp, a, v):
    """``a^T @ v`` for ``[..., 3, 3]`` and ``[..., 3]``."""
    return xp.sum(a * v[..., :, None], axis=-2)


def dot(xp, a, b):
    """``sum(a * b)`` over the last axis."""
    return xp.sum(a * b, axis=-1)


def cross(xp, a, b):
    """The cross product over the last axis (element-wise, fusable)."""
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return xp.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


def take(xp, x, indices, axis: int):
    """``x`` at the constant integer ``indices`` (numpy) along ``axis``: a slice where they are
    contiguous, else a gather."""
    indices = np.asarray(indices, dtype=np.int64)
    n = x.shape[axis]
    if len(indices) and np.array_equal(indices, np.arange(indices[0], indices[0] + len(indices))):
        if indices[0] == 0 and len(indices) == n:
            return x
        key = [slice(None)] * (len(x.shape))
        key[axis] = slice(int(indices[0]), int(indices[0]) + len(indices))
        return x[tuple(key)]
    return xp.take(x, index(xp, indices, x), axis=axis)


def quat_to_mat(xp, quat):
    """Rotation matrices ``[..., 3, 3]`` of quaternions ``[w, x, y, z]`` (normalised first;
    a zero quaternion is the identity, as MuJoCo's ``mju_normalize4``)."""
    norm = xp.safe_norm(quat, axis=-1, keepdims=True)
    unit = xp.constant(np.array([1.0, 0.0, 0.0, 0.0]), dtype=quat.dtype, device=xp.dev(quat))
    q = xp.where(norm < 1e-15, unit, quat / xp.where(norm < 1e-15, 1.0, norm))
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    rows = [
        [w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z],
    ]
    return xp.stack([xp.stack(row, axis=-1) for row in rows], axis=-2)


def eye3(xp, like):
    return const(xp, np.eye(3), like)


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
