"""Conversions to axis-angle ``[ax, ay, az, angle]`` ``[..., 4]`` with a unit axis.

From a rotation the angle is in [0, pi]; at angle 0 the axis is undefined and ``[0, 0, 1]`` is
returned.
"""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework
from ivy_mechanics._checks import takes
from ivy_mechanics.orientation import _kernels as K

__all__ = [
    "rot_mat_to_axis_angle",
    "quaternion_to_axis_angle",
    "rot_vec_to_axis_angle",
    "polar_axis_angle_to_axis_angle",
    "euler_to_axis_angle",
    "rot_6d_to_axis_angle",
    "get_random_axis_angle",
]


@takes("rot_mat")
def rot_mat_to_axis_angle(rot_mat: Array, *, f: Framework = None) -> Array:
    """Unit axis and angle of a rotation matrix.

    Args:
        rot_mat: rotation matrices *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Axis-angles *[batch_shape, 4]*, angles in [0, pi].

    Example:
        >>> rot_mat_to_axis_angle(np.eye(3))
        array([0., 0., 1., 0.])
    """
    xp = ivy.get_framework(rot_mat, f=f)
    return K.quat_to_axis_angle(xp, K.mat_to_quat(xp, rot_mat), canonical=True)


@takes("quaternion")
def quaternion_to_axis_angle(quaternion: Array, *, f: Framework = None) -> Array:
    """Unit axis and angle ``2 atan2(|v|, |w|)`` of a quaternion ``[v, w]`` (any non-zero norm).

    Args:
        quaternion: quaternions *[batch_shape, 4]*, scalar-last.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Axis-angles *[batch_shape, 4]*, angles in [0, pi].

    Example:
        >>> quaternion_to_axis_angle(np.array([0., 0., 0.6, -0.8])).round(6) + 0.
        array([ 0.      ,  0.      , -1.      ,  1.287002])
    """
    xp = ivy.get_framework(quaternion, f=f)
    return K.quat_to_axis_angle(xp, quaternion)


@takes("rot_vec")
def rot_vec_to_axis_angle(rot_vec: Array, *, f: Framework = None) -> Array:
    """Unit axis ``v / |v|`` and angle ``|v|`` of a rotation vector.

    Args:
        rot_vec: rotation vectors *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Axis-angles *[batch_shape, 4]* (the angle is ``|v|``, not wrapped to [0, pi]).

    Example:
        >>> rot_vec_to_axis_angle(np.array([0., 3., 4.]))
        array([0. , 0.6, 0.8, 5. ])
    """
    xp = ivy.get_framework(rot_vec, f=f)
    return K.rotvec_to_axis_angle(xp, rot_vec)


@takes("polar_axis_angle")
def polar_axis_angle_to_axis_angle(polar_axis_angle: Array, *, f: Framework = None) -> Array:
    """Axis-angle of ``[inclination, azimuth, angle]``: the axis is
    ``[sin(i) cos(a), sin(i) sin(a), cos(i)]``.

    Args:
        polar_axis_angle: polar axis-angles *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Axis-angles *[batch_shape, 4]*.

    Example:
        >>> polar_axis_angle_to_axis_angle(np.array([0., 0., 1.]))
        array([0., 0., 1., 1.])
    """
    xp = ivy.get_framework(polar_axis_angle, f=f)
    return K.polar_to_axis_angle(xp, polar_axis_angle)


@takes("euler_angles")
def euler_to_axis_angle(
    euler_angles: Array, convention: str = "zyx", *, f: Framework = None
) -> Array:
    """Axis-angle of Euler angles (scipy's spelling; see :func:`euler_to_rot_mat`).

    Args:
        euler_angles: angles *[batch_shape, 3]* in radians, in the order of ``convention``.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Axis-angles *[batch_shape, 4]*, angles in [0, pi].

    Example:
        >>> euler_to_axis_angle(np.array([0., 0.5, 0.]), 'xyz')
        array([0. , 1. , 0. , 0.5])
    """
    xp = ivy.get_framework(euler_angles, f=f)
    return K.quat_to_axis_angle(xp, K.euler_to_quat(xp, euler_angles, convention))


@takes("rot_6d")
def rot_6d_to_axis_angle(rot_6d: Array, *, f: Framework = None) -> Array:
    """Axis-angle of the 6D representation (see :func:`rot_6d_to_rot_mat`).

    Args:
        rot_6d: 6D representations *[batch_shape, 6]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Axis-angles *[batch_shape, 4]*, angles in [0, pi].

    Example:
        >>> rot_6d_to_axis_angle(np.array([1., 0., 0., 0., 1., 0.]))
        array([0., 0., 1., 0.])
    """
    xp = ivy.get_framework(rot_6d, f=f)
    quat = K.mat_to_quat(xp, K.rot6d_to_mat(xp, rot_6d))
    return K.quat_to_axis_angle(xp, quat, canonical=True)


@takes()
def get_random_axis_angle(batch_shape=(), dtype=None, *, f: Framework = None) -> Array:
    """Axis-angles of rotations drawn uniformly (Haar measure) from SO(3).

    Args:
        batch_shape: leading shape of the result.
        dtype: float dtype (name or native); float32 by default.
        f: framework name or namespace; the global framework if None.

    Returns:
        Random axis-angles *[batch_shape, 4]*, angles in [0, pi].

    Example:
        >>> get_random_axis_angle((3,), f='numpy').shape
        (3, 4)
    """
    xp = ivy.get_framework(f=f)
    quat = xp.random_normal(0.0, 1.0, (*tuple(batch_shape), 4), dtype=dtype)
    return K.quat_to_axis_angle(xp, quat)
