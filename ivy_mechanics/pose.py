"""Poses: a position and an orientation.

Formats (the position always comes first):

- matrix pose: homogeneous ``[..., 4, 4]`` ``[[R, t], [0, 0, 0, 1]]``; inputs may also be the
  top ``[..., 3, 4]`` rows. Every function returning a matrix pose returns ``[..., 4, 4]``.
- quaternion pose ``[..., 7]``: ``[x, y, z, qx, qy, qz, qw]``.
- rotation-vector pose ``[..., 6]``: ``[x, y, z, rx, ry, rz]``.
- Euler pose ``[..., 6]``: ``[x, y, z, a, b, c]`` with a scipy-style ``convention``.
- axis-angle pose ``[..., 7]``: ``[x, y, z, ax, ay, az, angle]``.

A pose maps body coordinates to world coordinates: ``p_world = R @ p_body + t``.
"""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework
from ivy_mechanics._checks import takes
from ivy_mechanics.orientation import _kernels as K

__all__ = [
    "make_transformation_homogeneous",
    "quaternion_pose_to_mat_pose",
    "mat_pose_to_quaternion_pose",
    "rot_vec_pose_to_mat_pose",
    "mat_pose_to_rot_vec_pose",
    "euler_pose_to_mat_pose",
    "mat_pose_to_euler_pose",
    "axis_angle_pose_to_mat_pose",
    "mat_pose_to_axis_angle_pose",
    "quaternion_pose_to_rot_vec_pose",
    "rot_vec_pose_to_quaternion_pose",
    "quaternion_pose_to_euler_pose",
    "euler_pose_to_quaternion_pose",
    "quaternion_pose_to_axis_angle_pose",
    "axis_angle_pose_to_quaternion_pose",
    "compose_mat_poses",
    "invert_mat_pose",
    "transform_points",
    "compose_quaternion_poses",
    "invert_quaternion_pose",
    "increment_quaternion_pose_with_velocity",
]


def _bottom_row(xp, top):
    """``[0, 0, 0, 1]`` shaped ``[..., 1, 4]`` like the rows ``top`` ``[..., 3, 4]``."""
    return xp.concat([xp.zeros_like(top[..., 0:1, 0:3]), xp.ones_like(top[..., 0:1, 0:1])], axis=-1)


def assemble_mat_pose(xp, rot_mat, position):
    """``[[R, t], [0, 0, 0, 1]]`` from ``R`` ``[..., 3, 3]`` and ``t`` ``[..., 3]``."""
    top = xp.concat([rot_mat, position[..., None]], axis=-1)
    return xp.concat([top, _bottom_row(xp, top)], axis=-2)


def _split_mat_pose(mat_pose):
    return mat_pose[..., 0:3, 0:3], mat_pose[..., 0:3, 3]


@takes("matrices")
def make_transformation_homogeneous(matrices: Array, *, f: Framework = None) -> Array:
    """Append the row ``[0, 0, 0, 1]`` to ``[R, t]`` matrices.

    Args:
        matrices: transformations *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Homogeneous transformations *[batch_shape, 4, 4]*.

    Example:
        >>> make_transformation_homogeneous(np.eye(3, 4))
        array([[1., 0., 0., 0.],
               [0., 1., 0., 0.],
               [0., 0., 1., 0.],
               [0., 0., 0., 1.]])
    """
    xp = ivy.get_framework(matrices, f=f)
    return xp.concat([matrices, _bottom_row(xp, matrices)], axis=-2)


# ----------------------------------------------------------------------------------------------
# Matrix poses <-> vector poses
# ----------------------------------------------------------------------------------------------


@takes("quat_pose")
def quaternion_pose_to_mat_pose(quat_pose: Array, *, f: Framework = None) -> Array:
    """Homogeneous matrix of a quaternion pose (the quaternion is normalised).

    Args:
        quat_pose: ``[x, y, z, qx, qy, qz, qw]`` *[batch_shape, 7]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Matrix poses *[batch_shape, 4, 4]*.

    Example:
        >>> quaternion_pose_to_mat_pose(np.array([1., 2., 3., 0., 0., 0., 1.]))[:3, 3]
        array([1., 2., 3.])
    """
    xp = ivy.get_framework(quat_pose, f=f)
    return assemble_mat_pose(xp, K.quat_to_mat(xp, quat_pose[..., 3:7]), quat_pose[..., 0:3])


@takes("mat_pose")
def mat_pose_to_quaternion_pose(mat_pose: Array, *, f: Framework = None) -> Array:
    """Quaternion pose (``qw >= 0``) of a matrix pose.

    Args:
        mat_pose: matrix poses *[batch_shape, 4, 4]* or *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``[x, y, z, qx, qy, qz, qw]`` *[batch_shape, 7]*.

    Example:
        >>> mat_pose_to_quaternion_pose(np.eye(4))
        array([0., 0., 0., 0., 0., 0., 1.])
    """
    xp = ivy.get_framework(mat_pose, f=f)
    rot_mat, position = _split_mat_pose(mat_pose)
    return xp.concat([position, K.mat_to_quat(xp, rot_mat)], axis=-1)


@takes("rot_vec_pose")
def rot_vec_pose_to_mat_pose(rot_vec_pose: Array, *, f: Framework = None) -> Array:
    """Homogeneous matrix of a rotation-vector pose.

    Args:
        rot_vec_pose: ``[x, y, z, rx, ry, rz]`` *[batch_shape, 6]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Matrix poses *[batch_shape, 4, 4]*.

    Example:
        >>> rot_vec_pose_to_mat_pose(np.zeros(6))
        array([[1., 0., 0., 0.],
               [0., 1., 0., 0.],
               [0., 0., 1., 0.],
               [0., 0., 0., 1.]])
    """
    xp = ivy.get_framework(rot_vec_pose, f=f)
    rot_mat = K.rotvec_to_mat(xp, rot_vec_pose[..., 3:6])
    return assemble_mat_pose(xp, rot_mat, rot_vec_pose[..., 0:3])


@takes("mat_pose")
def mat_pose_to_rot_vec_pose(mat_pose: Array, *, f: Framework = None) -> Array:
    """Rotation-vector pose of a matrix pose (angle in [0, pi]).

    Args:
        mat_pose: matrix poses *[batch_shape, 4, 4]* or *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``[x, y, z, rx, ry, rz]`` *[batch_shape, 6]*.

    Example:
        >>> mat_pose_to_rot_vec_pose(np.eye(4))
        array([0., 0., 0., 0., 0., 0.])
    """
    xp = ivy.get_framework(mat_pose, f=f)
    rot_mat, position = _split_mat_pose(mat_pose)
    return xp.concat([position, K.mat_to_rotvec(xp, rot_mat)], axis=-1)


@takes("euler_pose")
def euler_pose_to_mat_pose(
    euler_pose: Array, convention: str = "zyx", *, f: Framework = None
) -> Array:
    """Homogeneous matrix of an Euler pose (scipy's spelling of ``convention``).

    Args:
        euler_pose: ``[x, y, z, a, b, c]`` *[batch_shape, 6]*.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Matrix poses *[batch_shape, 4, 4]*.

    Example:
        >>> euler_pose_to_mat_pose(np.array([1., 2., 3., 0., 0., 0.]), 'XYZ')[:3, 3]
        array([1., 2., 3.])
    """
    xp = ivy.get_framework(euler_pose, f=f)
    rot_mat = K.euler_to_mat(xp, euler_pose[..., 3:6], convention)
    return assemble_mat_pose(xp, rot_mat, euler_pose[..., 0:3])


@takes("mat_pose")
def mat_pose_to_euler_pose(
    mat_pose: Array, convention: str = "zyx", *, f: Framework = None
) -> Array:
    """Euler pose of a matrix pose.

    Args:
        mat_pose: matrix poses *[batch_shape, 4, 4]* or *[batch_shape, 3, 4]*.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``[x, y, z, a, b, c]`` *[batch_shape, 6]*.

    Example:
        >>> mat_pose_to_euler_pose(np.eye(4), 'xyz')
        array([0., 0., 0., 0., 0., 0.])
    """
    xp = ivy.get_framework(mat_pose, f=f)
    rot_mat, position = _split_mat_pose(mat_pose)
    euler = K.quat_to_euler(xp, K.mat_to_quat(xp, rot_mat), convention)
    return xp.concat([position, euler], axis=-1)


@takes("axis_angle_pose")
def axis_angle_pose_to_mat_pose(axis_angle_pose: Array, *, f: Framework = None) -> Array:
    """Homogeneous matrix of an axis-angle pose (unit axis).

    Args:
        axis_angle_pose: ``[x, y, z, ax, ay, az, angle]`` *[batch_shape, 7]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Matrix poses *[batch_shape, 4, 4]*.

    Example:
        >>> axis_angle_pose_to_mat_pose(np.array([1., 2., 3., 0., 0., 1., 0.]))[:3, 3]
        array([1., 2., 3.])
    """
    xp = ivy.get_framework(axis_angle_pose, f=f)
    quat = K.axis_angle_to_quat(xp, axis_angle_pose[..., 3:7])
    return assemble_mat_pose(
        xp, K.quat_to_mat(xp, quat, normalize=False), axis_angle_pose[..., 0:3]
    )


@takes("mat_pose")
def mat_pose_to_axis_angle_pose(mat_pose: Array, *, f: Framework = None) -> Array:
    """Axis-angle pose of a matrix pose (angle in [0, pi], axis +z at angle 0).

    Args:
        mat_pose: matrix poses *[batch_shape, 4, 4]* or *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``[x, y, z, ax, ay, az, angle]`` *[batch_shape, 7]*.

    Example:
        >>> mat_pose_to_axis_angle_pose(np.eye(4))
        array([0., 0., 0., 0., 0., 1., 0.])
    """
    xp = ivy.get_framework(mat_pose, f=f)
    rot_mat, position = _split_mat_pose(mat_pose)
    axis_angle = K.quat_to_axis_angle(xp, K.mat_to_quat(xp, rot_mat), canonical=True)
    return xp.concat([position, axis_angle], axis=-1)


# ----------------------------------------------------------------------------------------------
# Quaternion poses <-> other vector poses
# ----------------------------------------------------------------------------------------------


@takes("quat_pose")
def quaternion_pose_to_rot_vec_pose(quat_pose: Array, *, f: Framework = None) -> Array:
    """Rotation-vector pose of a quaternion pose.

    Args:
        quat_pose: ``[x, y, z, qx, qy, qz, qw]`` *[batch_shape, 7]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``[x, y, z, rx, ry, rz]`` *[batch_shape, 6]*.

    Example:
        >>> quaternion_pose_to_rot_vec_pose(np.array([1., 2., 3., 0., 0., 0., 1.]))
        array([1., 2., 3., 0., 0., 0.])
    """
    xp = ivy.get_framework(quat_pose, f=f)
    return xp.concat([quat_pose[..., 0:3], K.quat_to_rotvec(xp, quat_pose[..., 3:7])], axis=-1)


@takes("rot_vec_pose")
def rot_vec_pose_to_quaternion_pose(rot_vec_pose: Array, *, f: Framework = None) -> Array:
    """Quaternion pose of a rotation-vector pose.

    Args:
        rot_vec_pose: ``[x, y, z, rx, ry, rz]`` *[batch_shape, 6]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``[x, y, z, qx, qy, qz, qw]`` *[batch_shape, 7]*.

    Example:
        >>> rot_vec_pose_to_quaternion_pose(np.array([1., 2., 3., 0., 0., 0.]))
        array([1., 2., 3., 0., 0., 0., 1.])
    """
    xp = ivy.get_framework(rot_vec_pose, f=f)
    quat = K.rotvec_to_quat(xp, rot_vec_pose[..., 3:6])
    return xp.concat([rot_vec_pose[..., 0:3], quat], axis=-1)


@takes("quat_pose")
def quaternion_pose_to_euler_pose(
    quat_pose: Array, convention: str = "zyx", *, f: Framework = None
) -> Array:
    """Euler pose of a quaternion pose.

    Args:
        quat_pose: ``[x, y, z, qx, qy, qz, qw]`` *[batch_shape, 7]*.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``[x, y, z, a, b, c]`` *[batch_shape, 6]*.

    Example:
        >>> quaternion_pose_to_euler_pose(np.array([1., 2., 3., 0., 0., 0., 1.]), 'xyz')
        array([1., 2., 3., 0., 0., 0.])
    """
    xp = ivy.get_framework(quat_pose, f=f)
    euler = K.quat_to_euler(xp, quat_pose[..., 3:7], convention)
    return xp.concat([quat_pose[..., 0:3], euler], axis=-1)


@takes("euler_pose")
def euler_pose_to_quaternion_pose(
    euler_pose: Array, convention: str = "zyx", *, f: Framework = None
) -> Array:
    """Quaternion pose of an Euler pose.

    Args:
        euler_pose: ``[x, y, z, a, b, c]`` *[batch_shape, 6]*.
        convention: the axis sequence, e.g. ``'xyz'``, ``'ZYX'``, ``'zxz'``.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``[x, y, z, qx, qy, qz, qw]`` *[batch_shape, 7]*.

    Example:
        >>> euler_pose_to_quaternion_pose(np.array([1., 2., 3., 0., 0., 0.]), 'xyz')
        array([1., 2., 3., 0., 0., 0., 1.])
    """
    xp = ivy.get_framework(euler_pose, f=f)
    quat = K.euler_to_quat(xp, euler_pose[..., 3:6], convention)
    return xp.concat([euler_pose[..., 0:3], quat], axis=-1)


@takes("quat_pose")
def quaternion_pose_to_axis_angle_pose(quat_pose: Array, *, f: Framework = None) -> Array:
    """Axis-angle pose of a quaternion pose.

    Args:
        quat_pose: ``[x, y, z, qx, qy, qz, qw]`` *[batch_shape, 7]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``[x, y, z, ax, ay, az, angle]`` *[batch_shape, 7]*.

    Example:
        >>> quaternion_pose_to_axis_angle_pose(np.array([1., 2., 3., 0., 0., 0., 1.]))
        array([1., 2., 3., 0., 0., 1., 0.])
    """
    xp = ivy.get_framework(quat_pose, f=f)
    axis_angle = K.quat_to_axis_angle(xp, quat_pose[..., 3:7])
    return xp.concat([quat_pose[..., 0:3], axis_angle], axis=-1)


@takes("axis_angle_pose")
def axis_angle_pose_to_quaternion_pose(axis_angle_pose: Array, *, f: Framework = None) -> Array:
    """Quaternion pose of an axis-angle pose (unit axis).

    Args:
        axis_angle_pose: ``[x, y, z, ax, ay, az, angle]`` *[batch_shape, 7]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        ``[x, y, z, qx, qy, qz, qw]`` *[batch_shape, 7]*.

    Example:
        >>> axis_angle_pose_to_quaternion_pose(np.array([1., 2., 3., 0., 0., 1., 0.]))
        array([1., 2., 3., 0., 0., 0., 1.])
    """
    xp = ivy.get_framework(axis_angle_pose, f=f)
    quat = K.axis_angle_to_quat(xp, axis_angle_pose[..., 3:7])
    return xp.concat([axis_angle_pose[..., 0:3], quat], axis=-1)


# ----------------------------------------------------------------------------------------------
# Operations
# ----------------------------------------------------------------------------------------------


@takes("mat_pose1", "mat_pose2")
def compose_mat_poses(mat_pose1: Array, mat_pose2: Array, *, f: Framework = None) -> Array:
    """``P1 @ P2``: the pose ``P2`` expressed in the frame of ``P1`` (apply ``P2``, then ``P1``).

    Args:
        mat_pose1: matrix poses *[batch_shape, 4, 4]* or *[batch_shape, 3, 4]*.
        mat_pose2: matrix poses *[batch_shape, 4, 4]* or *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Matrix poses *[batch_shape, 4, 4]*.

    Example:
        >>> p = euler_pose_to_mat_pose(np.array([1., 0., 0., 0.3, 0., 0.]), 'zyx')
        >>> bool(np.allclose(compose_mat_poses(p, invert_mat_pose(p)), np.eye(4)))
        True
    """
    xp = ivy.get_framework(mat_pose1, mat_pose2, f=f)
    rot1, pos1 = _split_mat_pose(mat_pose1)
    rot2, pos2 = _split_mat_pose(mat_pose2)
    return assemble_mat_pose(xp, xp.matmul(rot1, rot2), xp.matvec(rot1, pos2) + pos1)


@takes("mat_pose")
def invert_mat_pose(mat_pose: Array, *, f: Framework = None) -> Array:
    """Inverse of a rigid transformation: ``[[R^T, -R^T t], [0, 1]]``.

    Args:
        mat_pose: matrix poses *[batch_shape, 4, 4]* or *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Inverse matrix poses *[batch_shape, 4, 4]*.

    Example:
        >>> invert_mat_pose(np.array([[1., 0., 0., 2.], [0., 1., 0., 0.], [0., 0., 1., 0.]]))[0]
        array([ 1.,  0.,  0., -2.])
    """
    xp = ivy.get_framework(mat_pose, f=f)
    rot_mat, position = _split_mat_pose(mat_pose)
    rot_t = xp.swapaxes(rot_mat, -1, -2)
    return assemble_mat_pose(xp, rot_t, -xp.matvec(rot_t, position))


@takes("mat_pose", "points")
def transform_points(mat_pose: Array, points: Array, *, f: Framework = None) -> Array:
    """``R @ p + t``: points from the body frame to the world frame. Batch dimensions
    broadcast, so a cloud ``[B, N, 3]`` is transformed by poses ``[B, 1, 4, 4]``.

    Args:
        mat_pose: matrix poses *[batch_shape, 4, 4]* or *[batch_shape, 3, 4]*.
        points: points *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Transformed points *[batch_shape, 3]*.

    Example:
        >>> pose = quaternion_pose_to_mat_pose(np.array([1., 0., 0., 0., 0., 1., 0.]))
        >>> transform_points(pose, np.array([1., 1., 1.])).round(6) + 0.
        array([ 0., -1.,  1.])
    """
    xp = ivy.get_framework(mat_pose, points, f=f)
    rot_mat, position = _split_mat_pose(mat_pose)
    return xp.matvec(rot_mat, points) + position


@takes("quat_pose1", "quat_pose2")
def compose_quaternion_poses(quat_pose1: Array, quat_pose2: Array, *, f: Framework = None) -> Array:
    """Quaternion-pose equivalent of :func:`compose_mat_poses`: ``[t1 + R1 t2, q1 * q2]``.

    Args:
        quat_pose1: ``[x, y, z, qx, qy, qz, qw]`` *[batch_shape, 7]* (unit quaternion).
        quat_pose2: ``[x, y, z, qx, qy, qz, qw]`` *[batch_shape, 7]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Quaternion poses *[batch_shape, 7]*.

    Example:
        >>> p = np.array([1., 2., 3., 0., 0., 0., 1.])
        >>> compose_quaternion_poses(p, p)
        array([2., 4., 6., 0., 0., 0., 1.])
    """
    xp = ivy.get_framework(quat_pose1, quat_pose2, f=f)
    q1, q2 = quat_pose1[..., 3:7], quat_pose2[..., 3:7]
    position = quat_pose1[..., 0:3] + _quat_rotate(xp, q1, quat_pose2[..., 0:3])
    return xp.concat([position, K.hamilton_product(xp, q1, q2)], axis=-1)


@takes("quat_pose")
def invert_quaternion_pose(quat_pose: Array, *, f: Framework = None) -> Array:
    """Inverse of a quaternion pose: ``[-R^T t, conj(q)]`` (unit quaternion).

    Args:
        quat_pose: ``[x, y, z, qx, qy, qz, qw]`` *[batch_shape, 7]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Quaternion poses *[batch_shape, 7]*.

    Example:
        >>> invert_quaternion_pose(np.array([1., 2., 3., 0., 0., 0., 1.]))
        array([-1., -2., -3., -0., -0., -0.,  1.])
    """
    xp = ivy.get_framework(quat_pose, f=f)
    conj = xp.concat([-quat_pose[..., 3:6], quat_pose[..., 6:7]], axis=-1)
    return xp.concat([-_quat_rotate(xp, conj, quat_pose[..., 0:3]), conj], axis=-1)


def _quat_rotate(xp, q, p):
    v, w = q[..., :3], q[..., 3:]
    t = 2.0 * xp.cross(v, p)
    return p + w * t + xp.cross(v, t)


@takes("quat_pose", "quat_vel")
def increment_quaternion_pose_with_velocity(
    quat_pose: Array, quat_vel: Array, delta_t: Array | float, *, f: Framework = None
) -> Array:
    """Step a quaternion pose forward by ``delta_t`` at a constant velocity.

    The velocity is itself a quaternion pose: a linear velocity ``[vx, vy, vz]`` and the
    rotation made in one second as a quaternion. The position moves by ``v * delta_t``; the
    orientation becomes ``q * q_vel ** delta_t`` (the rotation applied in the body frame, as in
    the original ivy_mech).

    Args:
        quat_pose: ``[x, y, z, qx, qy, qz, qw]`` *[batch_shape, 7]*.
        quat_vel: ``[vx, vy, vz, qx, qy, qz, qw]`` per second *[batch_shape, 7]*.
        delta_t: time step in seconds, a float or an array *[batch_shape, 1]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Quaternion poses *[batch_shape, 7]*.

    Example:
        >>> pose = np.array([0., 0., 0., 0., 0., 0., 1.])
        >>> vel = np.array([1., 0., 0., 0., 0., 1., 0.])  # pi rad/s about z
        >>> increment_quaternion_pose_with_velocity(pose, vel, 0.5).round(6)
        array([0.5     , 0.      , 0.      , 0.      , 0.      , 0.707107, 0.707107])
    """
    xp = ivy.get_framework(quat_pose, quat_vel, delta_t, f=f)
    step = K.rotvec_to_quat(xp, K.quat_to_rotvec(xp, quat_vel[..., 3:7]) * delta_t)
    quat = K.hamilton_product(xp, quat_pose[..., 3:7], step)
    return xp.concat([quat_pose[..., 0:3] + quat_vel[..., 0:3] * delta_t, quat], axis=-1)
