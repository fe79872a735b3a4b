"""Conversions to rotation matrices ``[..., 3, 3]`` (active, right-handed: ``x' = R @ x``)."""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework
from ivy_mechanics._checks import takes
from ivy_mechanics.orientation import _kernels as K

__all__ = [
    "quaternion_to_rot_mat",
    "rot_vec_to_rot_mat",
    "axis_angle_to_rot_mat",
    "polar_axis_angle_to_rot_mat",
    "euler_to_rot_mat",
    "rot_6d_to_rot_mat",
    "get_random_rot_mat",
    "target_facing_rotation_matrix",
]


@takes("quaternion")
def quaternion_to_rot_mat(quaternion: Array, *, f: Framework = None) -> Array:
    """Rotation matrix of a quaternion ``[x, y, z, w]`` (normalised first, as scipy does).

    Args:
        quaternion: quaternions *[batch_shape, 4]*, scalar-last, any non-zero norm.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotation matrices *[batch_shape, 3, 3]*.

    Example:
        >>> quaternion_to_rot_mat(np.array([0., 0., 1., 1.])).round(6) + 0.
        array([[ 0., -1.,  0.],
               [ 1.,  0.,  0.],
               [ 0.,  0.,  1.]])
    """
    xp = ivy.get_framework(quaternion, f=f)
    return K.quat_to_mat(xp, quaternion)


@takes("rot_vec")
def rot_vec_to_rot_mat(rot_vec: Array, *, f: Framework = None) -> Array:
    """Rotation matrix of a rotation vector ``angle * axis`` (Rodrigues' formula, the SO(3)
    exponential map), exact at zero and at pi.

    Args:
        rot_vec: rotation vectors *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotation matrices *[batch_shape, 3, 3]*.

    Example:
        >>> rot_vec_to_rot_mat(np.array([np.pi / 2, 0., 0.])).round(6) + 0.
        array([[ 1.,  0.,  0.],
               [ 0.,  0., -1.],
               [ 0.,  1.,  0.]])
    """
    xp = ivy.get_framework(rot_vec, f=f)
    return K.rotvec_to_mat(xp, rot_vec)


@takes("axis_angle")
def axis_angle_to_rot_mat(axis_angle: Array, *, f: Framework = None) -> Array:
    """Rotation matrix of ``[ax, ay, az, angle]`` (the axis must be a unit vector).

    Args:
        axis_angle: unit axes and angles *[batch_shape, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotation matrices *[batch_shape, 3, 3]*.

    Example:
        >>> axis_angle_to_rot_mat(np.array([0., 1., 0., np.pi / 2])).round(6) + 0.
        array([[ 0.,  0.,  1.],
               [ 0.,  1.,  0.],
               [-1.,  0.,  0.]])
    """
    xp = ivy.get_framework(axis_angle, f=f)
    return K.quat_to_mat(xp, K.axis_angle_to_quat(xp, axis_angle), normalize=False)


@takes("polar_axis_angle")
def polar_axis_angle_to_rot_mat(polar_axis_angle: Array, *, f: Framework = None) -> Array:
    """Rotation matrix of ``[inclination, azimuth, angle]``: the axis has inclination from +z and
    azimuth from +x in the xy-plane.

    Args:
        polar_axis_angle: polar axis-angles *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotation matrices *[batch_shape, 3, 3]*.

    Example:
        >>> polar_axis_angle_to_rot_mat(np.array([0., 0., np.pi])).round(6) + 0.
        array([[-1.,  0.,  0.],
               [ 0., -1.,  0.],
               [ 0.,  0.,  1.]])
    """
    xp = ivy.get_framework(polar_axis_angle, f=f)
    quat = K.axis_angle_to_quat(xp, K.polar_to_axis_angle(xp, polar_axis_angle))
    return K.quat_to_mat(xp, quat, normalize=False)


@takes("euler_angles")
def euler_to_rot_mat(euler_angles: Array, convention: str = "zyx", *, f: Framework = None) -> Array:
    """Rotation matrix of Euler angles, in scipy's spelling of the sequence.

    Lower case is extrinsic (about the fixed axes): ``'xyz'`` gives ``Rz(c) @ Ry(b) @ Rx(a)``.
    Upper case is intrinsic (about the moving axes): ``'XYZ'`` gives ``Rx(a) @ Ry(b) @ Rz(c)``.
    All 12 axis sequences each way are supported.

    Args:
        euler_angles: angles *[batch_shape, 3]* in radians, in the order of ``convention``.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotation matrices *[batch_shape, 3, 3]*.

    Example:
        >>> euler_to_rot_mat(np.array([np.pi / 2, 0., 0.]), 'zyx').round(6) + 0.
        array([[ 0., -1.,  0.],
               [ 1.,  0.,  0.],
               [ 0.,  0.,  1.]])
    """
    xp = ivy.get_framework(euler_angles, f=f)
    return K.euler_to_mat(xp, euler_angles, convention)


@takes("rot_6d")
def rot_6d_to_rot_mat(rot_6d: Array, *, f: Framework = None) -> Array:
    """Rotation matrix of the 6D representation (Zhou et al., 2019): the two vectors
    ``rot_6d[..., :3]`` and ``rot_6d[..., 3:]`` are orthonormalised (Gram-Schmidt) into the first
    two columns; the third column is their cross product.

    Args:
        rot_6d: 6D representations *[batch_shape, 6]*; need not be orthonormal.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotation matrices *[batch_shape, 3, 3]*.

    Example:
        >>> rot_6d_to_rot_mat(np.array([2., 0., 0., 1., 3., 0.]))
        array([[1., 0., 0.],
               [0., 1., 0.],
               [0., 0., 1.]])
    """
    xp = ivy.get_framework(rot_6d, f=f)
    return K.rot6d_to_mat(xp, rot_6d)


@takes()
def get_random_rot_mat(batch_shape=(), dtype=None, *, f: Framework = None) -> Array:
    """Rotation matrices drawn uniformly (Haar measure) from SO(3).

    Args:
        batch_shape: leading shape of the result.
        dtype: float dtype (name or native); float32 by default.
        f: framework name or namespace; the global framework if None.

    Returns:
        Random rotation matrices *[batch_shape, 3, 3]*.

    Example:
        >>> get_random_rot_mat((5,), f='numpy').shape
        (5, 3, 3)
    """
    xp = ivy.get_framework(f=f)
    quat = xp.random_normal(0.0, 1.0, (*tuple(batch_shape), 4), dtype=dtype)
    return K.quat_to_mat(xp, quat)


@takes("body_pos", "target_pos", "up")
def target_facing_rotation_matrix(
    body_pos: Array, target_pos: Array, up: Array | None = None, *, f: Framework = None
) -> Array:
    """Orientation of a body at ``body_pos`` whose +z axis faces ``target_pos`` and whose +x axis
    is horizontal (perpendicular to ``up``), as used to aim cameras ("look-at").

    The columns are the body's x, y and z axes in world coordinates: ``x = up x z``,
    ``y = z x x``. Undefined when the target is straight along ``up`` from the body.

    Args:
        body_pos: body positions *[batch_shape, 3]*.
        target_pos: target positions *[batch_shape, 3]*.
        up: the world's up direction *[batch_shape, 3]*; +z if None.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotation matrices *[batch_shape, 3, 3]* (body to world).

    Example:
        >>> target_facing_rotation_matrix(np.zeros(3), np.array([1., 0., 0.])).round(6) + 0.
        array([[0., 0., 1.],
               [1., 0., 0.],
               [0., 1., 0.]])
    """
    xp = ivy.get_framework(body_pos, target_pos, up, f=f)
    z = target_pos - body_pos
    z = z / xp.sqrt(xp.sum(z * z, axis=-1, keepdims=True))
    if up is None:
        zero = xp.zeros_like(z[..., 0:1])
        up = xp.concat([zero, zero, xp.ones_like(zero)], axis=-1)
    x = xp.cross(up, z)
    x = x / xp.sqrt(xp.sum(x * x, axis=-1, keepdims=True))
    y = xp.cross(z, x)
    return xp.stack([x, y, z], axis=-1)
