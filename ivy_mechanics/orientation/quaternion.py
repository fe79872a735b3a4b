"""Quaternions ``[x, y, z, w]`` (scalar-last, Hamilton convention): conversions and algebra.

``q`` and ``-q`` are the same rotation. Conversions from a matrix return the sign with ``w >= 0``.
"""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework
from ivy_mechanics._checks import takes
from ivy_mechanics.orientation import _kernels as K

__all__ = [
    "rot_mat_to_quaternion",
    "rot_vec_to_quaternion",
    "axis_angle_to_quaternion",
    "polar_axis_angle_to_quaternion",
    "euler_to_quaternion",
    "rot_6d_to_quaternion",
    "hamilton_product",
    "quaternion_conjugate",
    "inverse_quaternion",
    "normalize_quaternion",
    "scale_quaternion_rotation_angle",
    "get_random_quaternion",
]


@takes("rot_mat")
def rot_mat_to_quaternion(rot_mat: Array, *, f: Framework = None) -> Array:
    """Unit quaternion of a rotation matrix, with ``w >= 0``.

    Uses the best conditioned of four formulas (Shepperd's method), so it is exact near the
    identity and near rotations by pi. The matrix is taken to be orthonormal: unlike scipy, no
    SVD projection is made (a matrix slightly off SO(3) gives a nearby unit quaternion).

    Args:
        rot_mat: rotation matrices *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Quaternions *[batch_shape, 4]*, scalar-last.

    Example:
        >>> rot_mat_to_quaternion(np.diag([1., -1., -1.]))
        array([1., 0., 0., 0.])
    """
    xp = ivy.get_framework(rot_mat, f=f)
    return K.mat_to_quat(xp, rot_mat)


@takes("rot_vec")
def rot_vec_to_quaternion(rot_vec: Array, *, f: Framework = None) -> Array:
    """Unit quaternion ``[sin(t/2) u, cos(t/2)]`` of a rotation vector ``t u``.

    Args:
        rot_vec: rotation vectors *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Quaternions *[batch_shape, 4]*, scalar-last.

    Example:
        >>> rot_vec_to_quaternion(np.zeros(3))
        array([0., 0., 0., 1.])
    """
    xp = ivy.get_framework(rot_vec, f=f)
    return K.rotvec_to_quat(xp, rot_vec)


@takes("axis_angle")
def axis_angle_to_quaternion(axis_angle: Array, *, f: Framework = None) -> Array:
    """Unit quaternion of ``[ax, ay, az, angle]`` (the axis must be a unit vector).

    Args:
        axis_angle: unit axes and angles *[batch_shape, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Quaternions *[batch_shape, 4]*, scalar-last.

    Example:
        >>> axis_angle_to_quaternion(np.array([0., 0., 1., np.pi])).round(6) + 0.
        array([0., 0., 1., 0.])
    """
    xp = ivy.get_framework(axis_angle, f=f)
    return K.axis_angle_to_quat(xp, axis_angle)


@takes("polar_axis_angle")
def polar_axis_angle_to_quaternion(polar_axis_angle: Array, *, f: Framework = None) -> Array:
    """Unit quaternion of ``[inclination, azimuth, angle]`` (axis inclination from +z, azimuth
    from +x).

    Args:
        polar_axis_angle: polar axis-angles *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Quaternions *[batch_shape, 4]*, scalar-last.

    Example:
        >>> polar_axis_angle_to_quaternion(np.array([np.pi / 2, 0., np.pi])).round(6) + 0.
        array([1., 0., 0., 0.])
    """
    xp = ivy.get_framework(polar_axis_angle, f=f)
    return K.axis_angle_to_quat(xp, K.polar_to_axis_angle(xp, polar_axis_angle))


@takes("euler_angles")
def euler_to_quaternion(
    euler_angles: Array, convention: str = "zyx", *, f: Framework = None
) -> Array:
    """Unit quaternion of Euler angles (scipy's spelling: ``'xyz'`` extrinsic, ``'XYZ'``
    intrinsic; see :func:`euler_to_rot_mat`).

    Args:
        euler_angles: angles *[batch_shape, 3]* in radians, in the order of ``convention``.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Quaternions *[batch_shape, 4]*, scalar-last (not sign-normalised, as scipy).

    Example:
        >>> euler_to_quaternion(np.array([0., 0., np.pi]), 'XYZ').round(6) + 0.
        array([0., 0., 1., 0.])
    """
    xp = ivy.get_framework(euler_angles, f=f)
    return K.euler_to_quat(xp, euler_angles, convention)


@takes("rot_6d")
def rot_6d_to_quaternion(rot_6d: Array, *, f: Framework = None) -> Array:
    """Unit quaternion (``w >= 0``) of the 6D representation (see :func:`rot_6d_to_rot_mat`).

    Args:
        rot_6d: 6D representations *[batch_shape, 6]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Quaternions *[batch_shape, 4]*, scalar-last.

    Example:
        >>> rot_6d_to_quaternion(np.array([1., 0., 0., 0., 1., 0.]))
        array([0., 0., 0., 1.])
    """
    xp = ivy.get_framework(rot_6d, f=f)
    return K.mat_to_quat(xp, K.rot6d_to_mat(xp, rot_6d))


@takes("quaternion1", "quaternion2")
def hamilton_product(quaternion1: Array, quaternion2: Array, *, f: Framework = None) -> Array:
    """Hamilton product ``q1 * q2``: the rotation ``q2`` followed by ``q1``, i.e.
    ``R(q1 * q2) = R(q1) @ R(q2)``. Batch dimensions broadcast.

    Args:
        quaternion1: quaternions *[batch_shape, 4]*, scalar-last.
        quaternion2: quaternions *[batch_shape, 4]*, scalar-last.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Products *[batch_shape, 4]*.

    Example:
        >>> i, j = np.array([1., 0., 0., 0.]), np.array([0., 1., 0., 0.])
        >>> hamilton_product(i, j)
        array([0., 0., 1., 0.])
    """
    xp = ivy.get_framework(quaternion1, quaternion2, f=f)
    return K.hamilton_product(xp, quaternion1, quaternion2)


@takes("quaternion")
def quaternion_conjugate(quaternion: Array, *, f: Framework = None) -> Array:
    """Conjugate ``[-x, -y, -z, w]`` (the inverse rotation for a unit quaternion).

    Args:
        quaternion: quaternions *[batch_shape, 4]*, scalar-last.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Conjugates *[batch_shape, 4]*.

    Example:
        >>> quaternion_conjugate(np.array([1., 2., 3., 4.]))
        array([-1., -2., -3.,  4.])
    """
    xp = ivy.get_framework(quaternion, f=f)
    return xp.concat([-quaternion[..., :3], quaternion[..., 3:]], axis=-1)


@takes("quaternion")
def inverse_quaternion(quaternion: Array, *, f: Framework = None) -> Array:
    """Multiplicative inverse ``conj(q) / |q|**2``.

    Args:
        quaternion: non-zero quaternions *[batch_shape, 4]*, scalar-last.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Inverses *[batch_shape, 4]*.

    Example:
        >>> inverse_quaternion(np.array([0., 0., 1., 1.])) + 0.
        array([ 0. ,  0. , -0.5,  0.5])
    """
    xp = ivy.get_framework(quaternion, f=f)
    conj = xp.concat([-quaternion[..., :3], quaternion[..., 3:]], axis=-1)
    return conj / xp.sum(quaternion * quaternion, axis=-1, keepdims=True)


@takes("quaternion")
def normalize_quaternion(quaternion: Array, *, f: Framework = None) -> Array:
    """``q / |q|``, the unit quaternion of the same rotation.

    Args:
        quaternion: non-zero quaternions *[batch_shape, 4]*, scalar-last.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Unit quaternions *[batch_shape, 4]*.

    Example:
        >>> normalize_quaternion(np.array([0., 0., 3., 4.]))
        array([0. , 0. , 0.6, 0.8])
    """
    xp = ivy.get_framework(quaternion, f=f)
    return quaternion / xp.sqrt(xp.sum(quaternion * quaternion, axis=-1, keepdims=True))


@takes("quaternion")
def scale_quaternion_rotation_angle(
    quaternion: Array, scale: Array | float, *, f: Framework = None
) -> Array:
    """The rotation about the same axis by ``scale`` times the angle (``q ** scale`` on the
    shortest arc), e.g. to integrate an angular velocity over a time step.

    Args:
        quaternion: quaternions *[batch_shape, 4]*, scalar-last.
        scale: a float or an array *[batch_shape, 1]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Unit quaternions *[batch_shape, 4]*.

    Example:
        >>> q = axis_angle_to_quaternion(np.array([0., 0., 1., 1.]))
        >>> bool(np.allclose(scale_quaternion_rotation_angle(q, 0.5),
        ...                  axis_angle_to_quaternion(np.array([0., 0., 1., 0.5]))))
        True
    """
    xp = ivy.get_framework(quaternion, scale, f=f)
    return K.rotvec_to_quat(xp, K.quat_to_rotvec(xp, quaternion) * scale)


@takes()
def get_random_quaternion(batch_shape=(), dtype=None, *, f: Framework = None) -> Array:
    """Unit quaternions of rotations drawn uniformly (Haar measure) from SO(3): normalised
    4D standard normal samples.

    Args:
        batch_shape: leading shape of the result.
        dtype: float dtype (name or native); float32 by default.
        f: framework name or namespace; the global framework if None.

    Returns:
        Random unit quaternions *[batch_shape, 4]*.

    Example:
        >>> get_random_quaternion((2, 3), f='numpy').shape
        (2, 3, 4)
    """
    xp = ivy.get_framework(f=f)
    quat = xp.random_normal(0.0, 1.0, (*tuple(batch_shape), 4), dtype=dtype)
    return quat / xp.sqrt(xp.sum(quat * quat, axis=-1, keepdims=True))
