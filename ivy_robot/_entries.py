"""Rotations and positions held entry by entry (private): a 3x3 matrix is three rows of three
entries, a vector three entries, and each entry is either a Python float (a model constant) or
an array of the batch shape. Every helper takes the backend namespace ``xp`` where it needs one;
nothing here dispatches.

Why: a chain of 3x3 products on ``[..., 3, 3]`` arrays becomes, under ``torch.compile``, one
small ``bmm`` call per joint plus loops over 3-element axes; entry by entry, the whole forward
kinematics is element-wise arithmetic on batch-shaped arrays, which inductor and XLA fuse into
one loop over the batch. Constant entries fold at build time: products with a constant 0 vanish,
products with a constant 1 pass the array through, sums of constants are constants. Model
constants within ``SNAP`` of 0 or +-1 (e.g. ``cos(pi / 2)``) are snapped to it when a model is
built (:func:`snap`), which changes results by at most ``SNAP`` relative.
"""

from __future__ import annotations

import numpy as np

from ivy_robot._arrays import broadcast_leading

SNAP = 1e-15


def snap(values: np.ndarray) -> np.ndarray:
    """Model constants with entries within :data:`SNAP` of 0, 1 or -1 set to them exactly."""
    values = np.array(values, dtype=np.float64)
    for target in (0.0, 1.0, -1.0):
        values[np.abs(values - target) <= SNAP] = target
    return values


def is_const(entry) -> bool:
    return type(entry) is float  # not numpy scalars (np.float64 subclasses float): values


def affine(const: float, terms) -> object:
    """``const + sum(coef * array)`` over ``terms`` ``[(coef, array)]``, skipping zero
    coefficients and multiplications by +-1."""
    acc = None
    for coef, array in terms:
        if coef == 0.0:
            continue
        if acc is None:
            acc = array if coef == 1.0 else (-array if coef == -1.0 else array * coef)
        elif coef == 1.0:
            acc = acc + array
        elif coef == -1.0:
            acc = acc - array
        else:
            acc = acc + array * coef
    if acc is None:
        return float(const)
    return acc + const if const != 0.0 else acc


def dot(pairs) -> object:
    """``sum(a * b)`` over entry pairs, folding constants."""
    const, terms, products = 0.0, [], None
    for a, b in pairs:
        if is_const(a) and is_const(b):
            const += a * b
        elif is_const(a):
            terms.append((a, b))
        elif is_const(b):
            terms.append((b, a))
        else:
            products = a * b if products is None else products + a * b
    result = affine(const, terms)
    if products is None:
        return result
    if is_const(result):
        return products + result if result != 0.0 else products
    return products + result


def add(a, b) -> object:
    if is_const(a) and is_const(b):
        return a + b
    if is_const(a):
        return b + a if a != 0.0 else b
    if is_const(b):
        return a + b if b != 0.0 else a
    return a + b


def matmul(r1, r2):
    """The product of two 3x3 entry matrices."""
    return [[dot([(r1[i][k], r2[k][j]) for k in range(3)]) for j in range(3)] for i in range(3)]


def matvec(r, v):
    """A 3x3 entry matrix times an entry vector."""
    return [dot([(r[i][k], v[k]) for k in range(3)]) for i in range(3)]


def compose(rot1, pos1, rot2, pos2):
    """The pose ``(rot1, pos1)`` followed by ``(rot2, pos2)`` (in the frame of the first)."""
    return matmul(rot1, rot2), [add(pos1[i], p) for i, p in enumerate(matvec(rot1, pos2))]


def constant_matrix(values: np.ndarray):
    """A numpy 3x3 (snapped) as entries."""
    return [[float(x) for x in row] for row in snap(values)]


def constant_vector(values: np.ndarray):
    return [float(x) for x in snap(values)]


def from_array(matrix):
    """``[..., 3, 3]`` array -> entries."""
    return [[matrix[..., i, j] for j in range(3)] for i in range(3)]


def vector_from_array(vector):
    return [vector[..., i] for i in range(3)]


def any_array(entries):
    for entry in entries:
        if not is_const(entry):
            return entry
    return None


class Broadcaster:
    """Constants as arrays of the batch shape, each value made once per call."""

    def __init__(self, xp, like):
        self._xp, self._zero, self._made = xp, xp.zeros_like(like), {}

    def __call__(self, entry):
        if not is_const(entry):
            return entry
        if entry not in self._made:
            self._made[entry] = self._zero if entry == 0.0 else self._zero + entry
        return self._made[entry]


def to_array(xp, entries, qpos, trailing_shape):
    """Flat entries -> an array ``[batch_shape, *trailing_shape]``, ``batch_shape`` that of
    ``qpos`` ``[batch_shape, n]`` (whose dtype and device constants take)."""
    first = any_array(entries)
    if first is None:
        values = np.asarray(entries, dtype=np.float64).reshape(trailing_shape).tolist()
        const = xp.asarray(values, dtype=qpos.dtype, device=xp.dev(qpos))
        return broadcast_leading(xp, const, qpos, 1)
    fill = Broadcaster(xp, first)
    arrays = [fill(e) for e in entries]
    # nested stacks (rows, then matrices, then the leading trailing axis): one stack of all
    # entries is a concatenation of many operands into which XLA duplicates the computation
    # (the joint sines 17 times over for a 7-DOF arm, 10x slower); nested, jax.jit and
    # torch.compile each emit one fused loop over the batch
    for level, size in enumerate(reversed(trailing_shape)):
        arrays = [
            xp.stack(arrays[k : k + size], axis=-1 - level) for k in range(0, len(arrays), size)
        ]
    return arrays[0]


def pose_entries(rot, pos):
    """The top three rows of a homogeneous pose, as 12 flat entries."""
    return [*rot[0], pos[0], *rot[1], pos[1], *rot[2], pos[2]]


def poses_to_array(xp, entries, qpos, count):
    """:func:`pose_entries` of ``count`` poses -> homogeneous poses
    ``[batch_shape, count, 4, 4]``: the top rows from the entries, then one constant
    ``[0, 0, 0, 1]`` row for all."""
    top = to_array(xp, entries, qpos, (count, 3, 4))
    bottom = xp.asarray([[[0.0, 0.0, 0.0, 1.0]]] * count, dtype=qpos.dtype, device=xp.dev(qpos))
    return xp.concat([top, broadcast_leading(xp, bottom, qpos, 1)], axis=-2)
