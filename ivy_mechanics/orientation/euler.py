"""Conversions to Euler angles ``[..., 3]``, spelled as scipy does.

A convention is three axes: lower case ``'xyz'`` is extrinsic (rotations about the fixed axes,
``R = Rz(c) @ Ry(b) @ Rx(a)``), upper case ``'XYZ'`` intrinsic (about the moving axes,
``R = Rx(a) @ Ry(b) @ Rz(c)``). All 12 sequences (6 Tait-Bryan such as ``'xyz'``, 6 proper
Euler such as ``'zxz'``) are supported each way: 24 conventions.

Angles are returned in (-pi, pi], the middle one in [-pi/2, pi/2] (Tait-Bryan) or [0, pi]
(proper Euler), computed from the quaternion by the method of Bernardes and Viollet (2022), as
scipy does. At gimbal lock (middle angle +-pi/2, or 0/pi) only the sum or difference of the first
and third angles is defined; it is split evenly between them (scipy sets the third to zero), so
compare results by the rotation they produce.
"""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework
from ivy_mechanics._checks import takes
from ivy_mechanics.orientation import _kernels as K

__all__ = [
    "EULER_CONVENTIONS",
    "rot_mat_to_euler",
    "quaternion_to_euler",
    "rot_vec_to_euler",
    "axis_angle_to_euler",
    "polar_axis_angle_to_euler",
    "rot_6d_to_euler",
    "get_random_euler",
]

_SEQUENCES = tuple(a + b + c for a in "xyz" for b in "xyz" for c in "xyz" if a != b and b != c)
#: The 24 supported conventions: 12 extrinsic (lower case), then 12 intrinsic (upper case).
EULER_CONVENTIONS: tuple[str, ...] = _SEQUENCES + tuple(s.upper() for s in _SEQUENCES)


@takes("rot_mat")
def rot_mat_to_euler(rot_mat: Array, convention: str = "zyx", *, f: Framework = None) -> Array:
    """Euler angles of a rotation matrix.

    Args:
        rot_mat: rotation matrices *[batch_shape, 3, 3]*.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Euler angles *[batch_shape, 3]* in the order of ``convention``.

    Example:
        >>> m = euler_to_rot_mat(np.array([0.1, 0.2, 0.3]), 'XYZ')
        >>> rot_mat_to_euler(m, 'XYZ').round(6)
        array([0.1, 0.2, 0.3])
    """
    xp = ivy.get_framework(rot_mat, f=f)
    return K.quat_to_euler(xp, K.mat_to_quat(xp, rot_mat), convention)


@takes("quaternion")
def quaternion_to_euler(
    quaternion: Array, convention: str = "zyx", *, f: Framework = None
) -> Array:
    """Euler angles of a quaternion (any non-zero norm).

    Args:
        quaternion: quaternions *[batch_shape, 4]*, scalar-last.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Euler angles *[batch_shape, 3]* in the order of ``convention``.

    Example:
        >>> quaternion_to_euler(np.array([0., 0., 0., 1.]), 'zxz')
        array([0., 0., 0.])
    """
    xp = ivy.get_framework(quaternion, f=f)
    return K.quat_to_euler(xp, quaternion, convention)


@takes("rot_vec")
def rot_vec_to_euler(rot_vec: Array, convention: str = "zyx", *, f: Framework = None) -> Array:
    """Euler angles of a rotation vector.

    Args:
        rot_vec: rotation vectors *[batch_shape, 3]*.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Euler angles *[batch_shape, 3]* in the order of ``convention``.

    Example:
        >>> rot_vec_to_euler(np.array([0., 0., 0.5]), 'zyx') + 0.
        array([0.5, 0. , 0. ])
    """
    xp = ivy.get_framework(rot_vec, f=f)
    return K.quat_to_euler(xp, K.rotvec_to_quat(xp, rot_vec), convention)


@takes("axis_angle")
def axis_angle_to_euler(
    axis_angle: Array, convention: str = "zyx", *, f: Framework = None
) -> Array:
    """Euler angles of ``[ax, ay, az, angle]`` (unit axis).

    Args:
        axis_angle: unit axes and angles *[batch_shape, 4]*.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Euler angles *[batch_shape, 3]* in the order of ``convention``.

    Example:
        >>> axis_angle_to_euler(np.array([1., 0., 0., 0.5]), 'xyz')
        array([0.5, 0. , 0. ])
    """
    xp = ivy.get_framework(axis_angle, f=f)
    return K.quat_to_euler(xp, K.axis_angle_to_quat(xp, axis_angle), convention)


@takes("polar_axis_angle")
def polar_axis_angle_to_euler(
    polar_axis_angle: Array, convention: str = "zyx", *, f: Framework = None
) -> Array:
    """Euler angles of ``[inclination, azimuth, angle]``.

    Args:
        polar_axis_angle: polar axis-angles *[batch_shape, 3]*.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Euler angles *[batch_shape, 3]* in the order of ``convention``.

    Example:
        >>> polar_axis_angle_to_euler(np.array([0., 0., 0.5]), 'zyx') + 0.
        array([0.5, 0. , 0. ])
    """
    xp = ivy.get_framework(polar_axis_angle, f=f)
    quat = K.axis_angle_to_quat(xp, K.polar_to_axis_angle(xp, polar_axis_angle))
    return K.quat_to_euler(xp, quat, convention)


@takes("rot_6d")
def rot_6d_to_euler(rot_6d: Array, convention: str = "zyx", *, f: Framework = None) -> Array:
    """Euler angles of the 6D representation (see :func:`rot_6d_to_rot_mat`).

    Args:
        rot_6d: 6D representations *[batch_shape, 6]*.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Euler angles *[batch_shape, 3]* in the order of ``convention``.

    Example:
        >>> rot_6d_to_euler(np.array([1., 0., 0., 0., 1., 0.]), 'xyz')
        array([0., 0., 0.])
    """
    xp = ivy.get_framework(rot_6d, f=f)
    return K.quat_to_euler(xp, K.mat_to_quat(xp, K.rot6d_to_mat(xp, rot_6d)), convention)


@takes()
def get_random_euler(
    batch_shape=(), convention: str = "zyx", dtype=None, *, f: Framework = None
) -> Array:
    """Euler angles of rotations drawn uniformly (Haar measure) from SO(3).

    Args:
        batch_shape: leading shape of the result.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        dtype: float dtype (name or native); float32 by default.
        f: framework name or namespace; the global framework if None.

    Returns:
        Random Euler angles *[batch_shape, 3]*.

    Example:
        >>> get_random_euler((2,), 'XYZ', f='numpy').shape
        (2, 3)
    """
    xp = ivy.get_framework(f=f)
    quat = xp.random_normal(0.0, 1.0, (*tuple(batch_shape), 4), dtype=dtype)
    return K.quat_to_euler(xp, quat, convention)
