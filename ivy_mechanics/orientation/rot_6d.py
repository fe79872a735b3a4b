"""Conversions to the 6D representation ``[..., 6]`` of Zhou et al. (2019): the first two
columns of the rotation matrix, ``[R[:, 0], R[:, 1]]``. Continuous, hence suited to learning."""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework
from ivy_mechanics._checks import takes
from ivy_mechanics.orientation import _kernels as K

__all__ = [
    "rot_mat_to_rot_6d",
    "quaternion_to_rot_6d",
    "rot_vec_to_rot_6d",
    "axis_angle_to_rot_6d",
    "polar_axis_angle_to_rot_6d",
    "euler_to_rot_6d",
]


@takes("rot_mat")
def rot_mat_to_rot_6d(rot_mat: Array, *, f: Framework = None) -> Array:
    """The first two columns of a rotation matrix.

    Args:
        rot_mat: rotation matrices *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        6D representations *[batch_shape, 6]*.

    Example:
        >>> rot_mat_to_rot_6d(np.eye(3))
        array([1., 0., 0., 0., 1., 0.])
    """
    xp = ivy.get_framework(rot_mat, f=f)
    return K.mat_to_rot6d(xp, rot_mat)


@takes("quaternion")
def quaternion_to_rot_6d(quaternion: Array, *, f: Framework = None) -> Array:
    """6D representation of a quaternion (any non-zero norm).

    Args:
        quaternion: quaternions *[batch_shape, 4]*, scalar-last.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        6D representations *[batch_shape, 6]*.

    Example:
        >>> quaternion_to_rot_6d(np.array([0., 0., 0., 1.]))
        array([1., 0., 0., 0., 1., 0.])
    """
    xp = ivy.get_framework(quaternion, f=f)
    return K.mat_to_rot6d(xp, K.quat_to_mat(xp, quaternion))


@takes("rot_vec")
def rot_vec_to_rot_6d(rot_vec: Array, *, f: Framework = None) -> Array:
    """6D representation of a rotation vector.

    Args:
        rot_vec: rotation vectors *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        6D representations *[batch_shape, 6]*.

    Example:
        >>> rot_vec_to_rot_6d(np.zeros(3))
        array([1., 0., 0., 0., 1., 0.])
    """
    xp = ivy.get_framework(rot_vec, f=f)
    return K.mat_to_rot6d(xp, K.rotvec_to_mat(xp, rot_vec))


@takes("axis_angle")
def axis_angle_to_rot_6d(axis_angle: Array, *, f: Framework = None) -> Array:
    """6D representation of ``[ax, ay, az, angle]`` (unit axis).

    Args:
        axis_angle: unit axes and angles *[batch_shape, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        6D representations *[batch_shape, 6]*.

    Example:
        >>> axis_angle_to_rot_6d(np.array([0., 0., 1., 0.]))
        array([1., 0., 0., 0., 1., 0.])
    """
    xp = ivy.get_framework(axis_angle, f=f)
    quat = K.axis_angle_to_quat(xp, axis_angle)
    return K.mat_to_rot6d(xp, K.quat_to_mat(xp, quat, normalize=False))


@takes("polar_axis_angle")
def polar_axis_angle_to_rot_6d(polar_axis_angle: Array, *, f: Framework = None) -> Array:
    """6D representation of ``[inclination, azimuth, angle]``.

    Args:
        polar_axis_angle: polar axis-angles *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        6D representations *[batch_shape, 6]*.

    Example:
        >>> polar_axis_angle_to_rot_6d(np.zeros(3))
        array([1., 0., 0., 0., 1., 0.])
    """
    xp = ivy.get_framework(polar_axis_angle, f=f)
    quat = K.axis_angle_to_quat(xp, K.polar_to_axis_angle(xp, polar_axis_angle))
    return K.mat_to_rot6d(xp, K.quat_to_mat(xp, quat, normalize=False))


@takes("euler_angles")
def euler_to_rot_6d(euler_angles: Array, convention: str = "zyx", *, f: Framework = None) -> Array:
    """6D representation of Euler angles (scipy's spelling; see :func:`euler_to_rot_mat`).

    Args:
        euler_angles: angles *[batch_shape, 3]* in radians, in the order of ``convention``.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        6D representations *[batch_shape, 6]*.

    Example:
        >>> euler_to_rot_6d(np.zeros(3), 'ZXZ') + 0.
        array([1., 0., 0., 0., 1., 0.])
    """
    xp = ivy.get_framework(euler_angles, f=f)
    return K.mat_to_rot6d(xp, K.euler_to_mat(xp, euler_angles, convention))
