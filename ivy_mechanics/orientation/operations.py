"""Operations on rotations: applying them to points, interpolation and distances."""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework
from ivy_mechanics._checks import takes
from ivy_mechanics.orientation import _kernels as K

__all__ = [
    "rotate_points",
    "quaternion_rotate_points",
    "slerp",
    "geodesic_distance",
    "quaternion_geodesic_distance",
]


@takes("rot_mat", "points")
def rotate_points(rot_mat: Array, points: Array, *, f: Framework = None) -> Array:
    """Rotate points: ``R @ p``. Batch dimensions broadcast, so a cloud ``[B, N, 3]`` is rotated
    by ``[B, 1, 3, 3]`` matrices.

    Args:
        rot_mat: rotation matrices *[batch_shape, 3, 3]*.
        points: points *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotated points *[batch_shape, 3]*.

    Example:
        >>> rz90 = np.array([[0., -1., 0.], [1., 0., 0.], [0., 0., 1.]])
        >>> rotate_points(rz90, np.array([1., 2., 3.]))
        array([-2.,  1.,  3.])
    """
    xp = ivy.get_framework(rot_mat, points, f=f)
    return xp.matvec(rot_mat, points)


@takes("quaternion", "points")
def quaternion_rotate_points(quaternion: Array, points: Array, *, f: Framework = None) -> Array:
    """Rotate points by unit quaternions without forming the matrix:
    ``p + w t + v x t`` with ``t = 2 v x p``. Batch dimensions broadcast.

    Args:
        quaternion: unit quaternions *[batch_shape, 4]*, scalar-last.
        points: points *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotated points *[batch_shape, 3]*.

    Example:
        >>> q = np.array([0., 0., np.sqrt(0.5), np.sqrt(0.5)])
        >>> quaternion_rotate_points(q, np.array([1., 2., 3.])).round(6) + 0.
        array([-2.,  1.,  3.])
    """
    xp = ivy.get_framework(quaternion, points, f=f)
    v, w = quaternion[..., :3], quaternion[..., 3:]
    t = 2.0 * xp.cross(v, points)
    return points + w * t + xp.cross(v, t)


@takes("quaternion0", "quaternion1")
def slerp(
    quaternion0: Array, quaternion1: Array, t: Array | float, *, f: Framework = None
) -> Array:
    """Spherical linear interpolation on the shortest arc: ``q0 * (q0^-1 * q1) ** t``.

    Exact (series) when the two rotations are close, finite gradients when they are equal.

    Args:
        quaternion0: unit quaternions at ``t = 0`` *[batch_shape, 4]*, scalar-last.
        quaternion1: unit quaternions at ``t = 1`` *[batch_shape, 4]*.
        t: interpolation parameter, a float or an array *[batch_shape, 1]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Interpolated unit quaternions *[batch_shape, 4]*.

    Example:
        >>> q1 = np.array([0., 0., 1., 0.])
        >>> slerp(np.array([0., 0., 0., 1.]), q1, 0.5).round(6)
        array([0.      , 0.      , 0.707107, 0.707107])
    """
    xp = ivy.get_framework(quaternion0, quaternion1, t, f=f)
    conj0 = xp.concat([-quaternion0[..., :3], quaternion0[..., 3:]], axis=-1)
    relative = K.quat_to_rotvec(xp, K.hamilton_product(xp, conj0, quaternion1))
    return K.hamilton_product(xp, quaternion0, K.rotvec_to_quat(xp, relative * t))


@takes("rot_mat1", "rot_mat2")
def geodesic_distance(rot_mat1: Array, rot_mat2: Array, *, f: Framework = None) -> Array:
    """Angle in [0, pi] of the rotation between two orientations, ``|log(R1^T R2)|``.

    Computed as ``atan2(sin, cos)`` of the relative rotation (not ``acos``), so it is accurate
    near 0 and pi, with finite gradients at both.

    Args:
        rot_mat1: rotation matrices *[batch_shape, 3, 3]*.
        rot_mat2: rotation matrices *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Angles *[batch_shape]* in radians.

    Example:
        >>> rz90 = np.array([[0., -1., 0.], [1., 0., 0.], [0., 0., 1.]])
        >>> float(geodesic_distance(np.eye(3), rz90).round(6))
        1.570796
    """
    xp = ivy.get_framework(rot_mat1, rot_mat2, f=f)
    rel = xp.matmul(xp.swapaxes(rot_mat1, -1, -2), rot_mat2)
    skew = xp.stack(
        [
            rel[..., 2, 1] - rel[..., 1, 2],
            rel[..., 0, 2] - rel[..., 2, 0],
            rel[..., 1, 0] - rel[..., 0, 1],
        ],
        axis=-1,
    )
    sin = 0.5 * xp.safe_norm(skew)
    cos = 0.5 * (rel[..., 0, 0] + rel[..., 1, 1] + rel[..., 2, 2] - 1.0)
    return xp.atan2(sin, cos)


@takes("quaternion1", "quaternion2")
def quaternion_geodesic_distance(
    quaternion1: Array, quaternion2: Array, *, f: Framework = None
) -> Array:
    """Angle in [0, pi] of the rotation between two orientations given as quaternions
    (``q`` and ``-q`` are the same orientation): ``2 atan2(|v|, |w|)`` of ``conj(q1) * q2``.

    Args:
        quaternion1: quaternions *[batch_shape, 4]*, scalar-last.
        quaternion2: quaternions *[batch_shape, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Angles *[batch_shape]* in radians.

    Example:
        >>> float(quaternion_geodesic_distance(np.array([0., 0., 0., 1.]),
        ...                                    np.array([0., 0., 0., -1.])))
        0.0
    """
    xp = ivy.get_framework(quaternion1, quaternion2, f=f)
    conj1 = xp.concat([-quaternion1[..., :3], quaternion1[..., 3:]], axis=-1)
    rel = K.hamilton_product(xp, conj1, quaternion2)
    return 2.0 * xp.atan2(xp.safe_norm(rel[..., :3]), xp.abs(rel[..., 3]))
