"""Conversions to rotation vectors ``angle * axis`` ``[..., 3]`` (the SO(3) logarithm).

Rotation vectors returned by these functions have angles in [0, pi]; at exactly pi, ``v`` and
``-v`` are the same rotation and either may be returned.
"""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework
from ivy_mechanics._checks import takes
from ivy_mechanics.orientation import _kernels as K

__all__ = [
    "rot_mat_to_rot_vec",
    "quaternion_to_rot_vec",
    "axis_angle_to_rot_vec",
    "polar_axis_angle_to_rot_vec",
    "euler_to_rot_vec",
    "rot_6d_to_rot_vec",
    "get_random_rot_vec",
]


@takes("rot_mat")
def rot_mat_to_rot_vec(rot_mat: Array, *, f: Framework = None) -> Array:
    """Rotation vector of a rotation matrix (via the quaternion: exact near 0 and near pi).

    Args:
        rot_mat: rotation matrices *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotation vectors *[batch_shape, 3]*, angles in [0, pi].

    Example:
        >>> rot_mat_to_rot_vec(np.eye(3))
        array([0., 0., 0.])
    """
    xp = ivy.get_framework(rot_mat, f=f)
    return K.mat_to_rotvec(xp, rot_mat)


@takes("quaternion")
def quaternion_to_rot_vec(quaternion: Array, *, f: Framework = None) -> Array:
    """Rotation vector ``2 atan2(|v|, w) v / |v|`` of a quaternion ``[v, w]`` (any non-zero norm;
    a series of atan near the identity).

    Args:
        quaternion: quaternions *[batch_shape, 4]*, scalar-last.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotation vectors *[batch_shape, 3]*, angles in [0, pi].

    Example:
        >>> quaternion_to_rot_vec(np.array([0., 0., 1., 0.])).round(6)
        array([0.      , 0.      , 3.141593])
    """
    xp = ivy.get_framework(quaternion, f=f)
    return K.quat_to_rotvec(xp, quaternion)


@takes("axis_angle")
def axis_angle_to_rot_vec(axis_angle: Array, *, f: Framework = None) -> Array:
    """Rotation vector ``angle * axis`` of ``[ax, ay, az, angle]``.

    Args:
        axis_angle: unit axes and angles *[batch_shape, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotation vectors *[batch_shape, 3]* (the angle is kept as given).

    Example:
        >>> axis_angle_to_rot_vec(np.array([0., 1., 0., 2.]))
        array([0., 2., 0.])
    """
    xp = ivy.get_framework(axis_angle, f=f)
    return K.axis_angle_to_rotvec(xp, axis_angle)


@takes("polar_axis_angle")
def polar_axis_angle_to_rot_vec(polar_axis_angle: Array, *, f: Framework = None) -> Array:
    """Rotation vector of ``[inclination, azimuth, angle]``.

    Args:
        polar_axis_angle: polar axis-angles *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotation vectors *[batch_shape, 3]* (the angle is kept as given).

    Example:
        >>> polar_axis_angle_to_rot_vec(np.array([0., 0., 2.]))
        array([0., 0., 2.])
    """
    xp = ivy.get_framework(polar_axis_angle, f=f)
    return K.axis_angle_to_rotvec(xp, K.polar_to_axis_angle(xp, polar_axis_angle))


@takes("euler_angles")
def euler_to_rot_vec(euler_angles: Array, convention: str = "zyx", *, f: Framework = None) -> Array:
    """Rotation vector of Euler angles (scipy's spelling; see :func:`euler_to_rot_mat`).

    Args:
        euler_angles: angles *[batch_shape, 3]* in radians, in the order of ``convention``.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotation vectors *[batch_shape, 3]*, angles in [0, pi].

    Example:
        >>> euler_to_rot_vec(np.array([0.5, 0., 0.]), 'xyz')
        array([0.5, 0. , 0. ])
    """
    xp = ivy.get_framework(euler_angles, f=f)
    return K.quat_to_rotvec(xp, K.euler_to_quat(xp, euler_angles, convention))


@takes("rot_6d")
def rot_6d_to_rot_vec(rot_6d: Array, *, f: Framework = None) -> Array:
    """Rotation vector of the 6D representation (see :func:`rot_6d_to_rot_mat`).

    Args:
        rot_6d: 6D representations *[batch_shape, 6]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotation vectors *[batch_shape, 3]*, angles in [0, pi].

    Example:
        >>> rot_6d_to_rot_vec(np.array([1., 0., 0., 0., 1., 0.]))
        array([0., 0., 0.])
    """
    xp = ivy.get_framework(rot_6d, f=f)
    return K.mat_to_rotvec(xp, K.rot6d_to_mat(xp, rot_6d))


@takes()
def get_random_rot_vec(batch_shape=(), dtype=None, *, f: Framework = None) -> Array:
    """Rotation vectors of rotations drawn uniformly (Haar measure) from SO(3).

    Args:
        batch_shape: leading shape of the result.
        dtype: float dtype (name or native); float32 by default.
        f: framework name or namespace; the global framework if None.

    Returns:
        Random rotation vectors *[batch_shape, 3]*, angles in [0, pi].

    Example:
        >>> get_random_rot_vec((4,), f='numpy').shape
        (4, 3)
    """
    xp = ivy.get_framework(f=f)
    quat = xp.random_normal(0.0, 1.0, (*tuple(batch_shape), 4), dtype=dtype)
    return K.quat_to_rotvec(xp, quat)
