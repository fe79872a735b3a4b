"""Conversions to polar axis-angle ``[inclination, azimuth, angle]`` ``[..., 3]``.

The axis is ``[sin(i) cos(a), sin(i) sin(a), cos(i)]``: inclination ``i`` in [0, pi] from +z,
azimuth ``a`` in (-pi, pi] from +x. From a rotation the angle is in [0, pi]; at angle 0 the axis
is +z, i.e. ``[0, 0, 0]``.
"""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework
from ivy_mechanics._checks import takes
from ivy_mechanics.orientation import _kernels as K

__all__ = [
    "rot_mat_to_polar_axis_angle",
    "quaternion_to_polar_axis_angle",
    "rot_vec_to_polar_axis_angle",
    "axis_angle_to_polar_axis_angle",
    "euler_to_polar_axis_angle",
    "rot_6d_to_polar_axis_angle",
]


@takes("rot_mat")
def rot_mat_to_polar_axis_angle(rot_mat: Array, *, f: Framework = None) -> Array:
    """Polar axis-angle of a rotation matrix.

    Args:
        rot_mat: rotation matrices *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Polar axis-angles *[batch_shape, 3]*.

    Example:
        >>> rot_mat_to_polar_axis_angle(np.eye(3))
        array([0., 0., 0.])
    """
    xp = ivy.get_framework(rot_mat, f=f)
    axis_angle = K.quat_to_axis_angle(xp, K.mat_to_quat(xp, rot_mat), canonical=True)
    return K.axis_angle_to_polar(xp, axis_angle)


@takes("quaternion")
def quaternion_to_polar_axis_angle(quaternion: Array, *, f: Framework = None) -> Array:
    """Polar axis-angle of a quaternion (any non-zero norm).

    Args:
        quaternion: quaternions *[batch_shape, 4]*, scalar-last.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Polar axis-angles *[batch_shape, 3]*.

    Example:
        >>> quaternion_to_polar_axis_angle(np.array([0., 1., 0., 0.])).round(6)
        array([1.570796, 1.570796, 3.141593])
    """
    xp = ivy.get_framework(quaternion, f=f)
    return K.axis_angle_to_polar(xp, K.quat_to_axis_angle(xp, quaternion))


@takes("rot_vec")
def rot_vec_to_polar_axis_angle(rot_vec: Array, *, f: Framework = None) -> Array:
    """Polar axis-angle of a rotation vector (the angle is ``|v|``, not wrapped).

    Args:
        rot_vec: rotation vectors *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Polar axis-angles *[batch_shape, 3]*.

    Example:
        >>> rot_vec_to_polar_axis_angle(np.array([0., 0., 2.]))
        array([0., 0., 2.])
    """
    xp = ivy.get_framework(rot_vec, f=f)
    return K.axis_angle_to_polar(xp, K.rotvec_to_axis_angle(xp, rot_vec))


@takes("axis_angle")
def axis_angle_to_polar_axis_angle(axis_angle: Array, *, f: Framework = None) -> Array:
    """Polar axis-angle of ``[ax, ay, az, angle]``.

    Args:
        axis_angle: unit axes and angles *[batch_shape, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Polar axis-angles *[batch_shape, 3]*.

    Example:
        >>> axis_angle_to_polar_axis_angle(np.array([1., 0., 0., 1.])).round(6)
        array([1.570796, 0.      , 1.      ])
    """
    xp = ivy.get_framework(axis_angle, f=f)
    return K.axis_angle_to_polar(xp, axis_angle)


@takes("euler_angles")
def euler_to_polar_axis_angle(
    euler_angles: Array, convention: str = "zyx", *, f: Framework = None
) -> Array:
    """Polar axis-angle of Euler angles (scipy's spelling; see :func:`euler_to_rot_mat`).

    Args:
        euler_angles: angles *[batch_shape, 3]* in radians, in the order of ``convention``.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Polar axis-angles *[batch_shape, 3]*.

    Example:
        >>> euler_to_polar_axis_angle(np.array([0., 0., 0.5]), 'xyz')
        array([0. , 0. , 0.5])
    """
    xp = ivy.get_framework(euler_angles, f=f)
    quat = K.euler_to_quat(xp, euler_angles, convention)
    return K.axis_angle_to_polar(xp, K.quat_to_axis_angle(xp, quat))


@takes("rot_6d")
def rot_6d_to_polar_axis_angle(rot_6d: Array, *, f: Framework = None) -> Array:
    """Polar axis-angle of the 6D representation (see :func:`rot_6d_to_rot_mat`).

    Args:
        rot_6d: 6D representations *[batch_shape, 6]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Polar axis-angles *[batch_shape, 3]*.

    Example:
        >>> rot_6d_to_polar_axis_angle(np.array([1., 0., 0., 0., 1., 0.]))
        array([0., 0., 0.])
    """
    xp = ivy.get_framework(rot_6d, f=f)
    quat = K.mat_to_quat(xp, K.rot6d_to_mat(xp, rot_6d))
    return K.axis_angle_to_polar(xp, K.quat_to_axis_angle(xp, quat, canonical=True))
