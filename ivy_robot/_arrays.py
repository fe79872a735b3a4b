"""Array helpers shared by ivy_robot's kernels (private). Every helper takes the backend
namespace ``xp`` first; nothing here dispatches.

Model constants are float64 numpy arrays computed once; :func:`constants` converts them, per
call, to the dtype and device of the input (under ``jax.jit``, ``tf.function`` and
``torch.compile`` they become constants of the compiled program, so the conversion costs nothing
there).
"""

from __future__ import annotations

import numpy as np


def constants(xp, like, arrays: dict) -> dict:
    """``{name: numpy array}`` -> ``{name: backend array}`` of ``like``'s dtype and device."""
    dtype, device = like.dtype, xp.dev(like)
    return {k: xp.asarray(v, dtype=dtype, device=device) for k, v in arrays.items()}


def check_floating(xp, x, name: str, owner: str) -> None:
    """Raise a TypeError unless ``x`` has a real floating dtype."""
    if not xp.isdtype(x.dtype, "real floating"):
        raise TypeError(
            f"{owner}: {name} has dtype {x.dtype}; give a floating-point array "
            "(float32 or float64)"
        )


def batch_shape_of(x, trailing: int) -> tuple | None:
    """The leading shape of ``x`` before its last ``trailing`` axes; None if unknown (a
    ``tf.function`` traced with a None dimension)."""
    shape = tuple(x.shape)
    lead = shape[: len(shape) - trailing]
    return None if any(d is None for d in lead) else lead


def broadcast_leading(xp, const, like, like_trailing: int):
    """``const`` (unbatched) broadcast to the batch shape of ``like``."""
    lead = batch_shape_of(like, like_trailing)
    if lead is not None:
        return xp.broadcast_to(const, lead + tuple(const.shape))
    # unknown batch shape: broadcast by adding zeros of the right leading shape
    zeros = xp.zeros_like(like[(Ellipsis,) + (0,) * like_trailing])
    return const + zeros[(Ellipsis,) + (None,) * len(const.shape)]


def select_last(xp, x, indices: np.ndarray, size: int):
    """``x[..., indices]`` for a static index list: a slice when the indices are contiguous,
    else one matrix product with a 0/1 selection matrix (exact: sums of ``x * 1`` and zeros;
    no fancy indexing, which tensorflow lacks)."""
    indices = np.asarray(indices, dtype=np.int64)
    if indices.size == 0:
        return x[..., 0:0]
    start = int(indices[0])
    if np.array_equal(indices, np.arange(start, start + indices.size)):
        return x[..., start : start + indices.size]
    selection = np.zeros((size, indices.size))
    selection[indices, np.arange(indices.size)] = 1.0
    selection = xp.asarray(selection, dtype=x.dtype, device=xp.dev(x))
    return xp.matmul(x[..., None, :], selection)[..., 0, :]


def matvec(xp, m, v):
    """``m @ v`` for matrices ``[..., n, k]`` and vectors ``[..., k]``."""
    return xp.matmul(m, v[..., None])[..., 0]


def cross(xp, a, b):
    """Cross product over the last axis, broadcasting on every backend."""
    ax, ay, az = a[..., 0], a[..., 1], a[..., 2]
    bx, by, bz = b[..., 0], b[..., 1], b[..., 2]
    return xp.stack([ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx], axis=-1)


def assemble_poses(xp, rot, pos):
    """``[[R, t], [0, 0, 0, 1]]`` ``[..., 4, 4]`` from ``R`` ``[..., 3, 3]`` and ``t``
    ``[..., 3]``."""
    top = xp.concat([rot, pos[..., None]], axis=-1)
    bottom = xp.concat([xp.zeros_like(top[..., 0:1, 0:3]), xp.ones_like(top[..., 0:1, 0:1])], axis=-1)
    return xp.concat([top, bottom], axis=-2)


def skew(axis: np.ndarray) -> np.ndarray:
    """The cross-product matrix of a numpy 3-vector."""
    x, y, z = axis
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])
