"""The Lie groups SO(3) and SE(3): hat and vee, exponential and logarithm maps.

Tangent vectors: ``so(3)`` is a rotation vector ``w`` ``[..., 3]``; ``se(3)`` is a twist
``[v, w]`` ``[..., 6]``, translational part first. The maps are exact near the identity (series
selected with ``where``) and have finite gradients there.
"""

from __future__ import annotations

import ivy
from ivy.typing import Array, Framework
from ivy_mechanics._checks import takes
from ivy_mechanics._series import ONE_MINUS_COS_OVER_X2, SE3_LOG_D, X_MINUS_SIN_OVER_X3
from ivy_mechanics.orientation import _kernels as K
from ivy_mechanics.pose import assemble_mat_pose

__all__ = [
    "so3_hat",
    "so3_vee",
    "so3_exp",
    "so3_log",
    "se3_hat",
    "se3_vee",
    "se3_exp",
    "se3_log",
]


@takes("vector")
def so3_hat(vector: Array, *, f: Framework = None) -> Array:
    """Skew-symmetric matrix ``[w]x`` with ``[w]x @ p = w x p``.

    Args:
        vector: vectors *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Skew-symmetric matrices *[batch_shape, 3, 3]*.

    Example:
        >>> so3_hat(np.array([1., 2., 3.]))
        array([[ 0., -3.,  2.],
               [ 3.,  0., -1.],
               [-2.,  1.,  0.]])
    """
    xp = ivy.get_framework(vector, f=f)
    return K.hat(xp, vector)


@takes(matrix=("...", 3, 3))
def so3_vee(matrix: Array, *, f: Framework = None) -> Array:
    """Inverse of :func:`so3_hat`: the vector of the skew-symmetric part of ``matrix``.

    Args:
        matrix: (skew-symmetric) matrices *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Vectors *[batch_shape, 3]*.

    Example:
        >>> so3_vee(so3_hat(np.array([1., 2., 3.])))
        array([1., 2., 3.])
    """
    xp = ivy.get_framework(matrix, f=f)
    return 0.5 * xp.stack_vector(
        [
            matrix[..., 2, 1] - matrix[..., 1, 2],
            matrix[..., 0, 2] - matrix[..., 2, 0],
            matrix[..., 1, 0] - matrix[..., 0, 1],
        ],
    )


@takes("rot_vec")
def so3_exp(rot_vec: Array, *, f: Framework = None) -> Array:
    """Exponential map of SO(3): the rotation matrix of a rotation vector (same as
    :func:`rot_vec_to_rot_mat`).

    Args:
        rot_vec: rotation vectors *[batch_shape, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotation matrices *[batch_shape, 3, 3]*.

    Example:
        >>> so3_exp(np.zeros(3))
        array([[1., 0., 0.],
               [0., 1., 0.],
               [0., 0., 1.]])
    """
    xp = ivy.get_framework(rot_vec, f=f)
    return K.rotvec_to_mat(xp, rot_vec)


@takes("rot_mat")
def so3_log(rot_mat: Array, *, f: Framework = None) -> Array:
    """Logarithm map of SO(3): the rotation vector (angle in [0, pi]) of a rotation matrix
    (same as :func:`rot_mat_to_rot_vec`).

    Args:
        rot_mat: rotation matrices *[batch_shape, 3, 3]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Rotation vectors *[batch_shape, 3]*.

    Example:
        >>> so3_log(np.eye(3))
        array([0., 0., 0.])
    """
    xp = ivy.get_framework(rot_mat, f=f)
    return K.mat_to_rotvec(xp, rot_mat)


@takes("twist")
def se3_hat(twist: Array, *, f: Framework = None) -> Array:
    """The 4x4 matrix ``[[ [w]x, v ], [0, 0]]`` of a twist ``[v, w]``.

    Args:
        twist: twists *[batch_shape, 6]*, translational part first.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Matrices *[batch_shape, 4, 4]*.

    Example:
        >>> se3_hat(np.array([1., 2., 3., 0., 0., 0.]))[:3, 3]
        array([1., 2., 3.])
    """
    xp = ivy.get_framework(twist, f=f)
    top = xp.concat([K.hat(xp, twist[..., 3:6]), twist[..., 0:3, None]], axis=-1)
    return xp.concat([top, xp.zeros_like(top[..., 0:1, :])], axis=-2)


@takes(matrix=("...", (3, 4), 4))
def se3_vee(matrix: Array, *, f: Framework = None) -> Array:
    """Inverse of :func:`se3_hat`: the twist ``[v, w]`` of a 4x4 (or 3x4) matrix.

    Args:
        matrix: matrices *[batch_shape, 4, 4]* or *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Twists *[batch_shape, 6]*.

    Example:
        >>> se3_vee(se3_hat(np.arange(6.)))
        array([0., 1., 2., 3., 4., 5.])
    """
    xp = ivy.get_framework(matrix, f=f)
    return xp.concat([matrix[..., 0:3, 3], so3_vee(matrix[..., 0:3, 0:3], f=xp)], axis=-1)


@takes("twist")
def se3_exp(twist: Array, *, f: Framework = None) -> Array:
    """Exponential map of SE(3): the pose ``[[exp(w), V v], [0, 1]]`` reached by moving along a
    twist ``[v, w]`` for unit time, with ``V = I + B [w]x + C [w]x^2``,
    ``B = (1 - cos t) / t^2`` and ``C = (t - sin t) / t^3``.

    Args:
        twist: twists *[batch_shape, 6]*, translational part first.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Matrix poses *[batch_shape, 4, 4]*.

    Example:
        >>> se3_exp(np.array([1., 2., 3., 0., 0., 0.]))[:3, 3]
        array([1., 2., 3.])
    """
    xp = ivy.get_framework(twist, f=f)
    v, w = twist[..., 0:3], twist[..., 3:6]
    t2 = xp.sum(w * w, axis=-1, keepdims=True)
    b, c = xp.taylor_switch(
        t2,
        (ONE_MINUS_COS_OVER_X2, X_MINUS_SIN_OVER_X3),
        lambda t: (2.0 * xp.sin(0.5 * t) ** 2 / (t * t), (t - xp.sin(t)) / (t * t * t)),
    )
    w_v = xp.cross(w, v)
    position = v + b * w_v + c * xp.cross(w, w_v)
    return assemble_mat_pose(xp, K.rotvec_to_mat(xp, w), position)


@takes("mat_pose")
def se3_log(mat_pose: Array, *, f: Framework = None) -> Array:
    """Logarithm map of SE(3): the twist ``[v, w]`` with ``se3_exp([v, w]) = pose``, rotation
    angle in [0, pi]: ``v = t - [w]x t / 2 + D [w]x^2 t``, ``D = (1 - (t/2) cot(t/2)) / t^2``.

    Args:
        mat_pose: matrix poses *[batch_shape, 4, 4]* or *[batch_shape, 3, 4]*.
        f: framework name or namespace; inferred from the inputs if None.

    Returns:
        Twists *[batch_shape, 6]*.

    Example:
        >>> se3_log(np.eye(4))
        array([0., 0., 0., 0., 0., 0.])
    """
    xp = ivy.get_framework(mat_pose, f=f)
    position = mat_pose[..., 0:3, 3]
    w = K.mat_to_rotvec(xp, mat_pose[..., 0:3, 0:3])
    t2 = xp.sum(w * w, axis=-1, keepdims=True)
    d = xp.taylor_switch(
        t2, SE3_LOG_D, lambda t: (1.0 - 0.5 * t * xp.cos(0.5 * t) / xp.sin(0.5 * t)) / (t * t)
    )
    w_p = xp.cross(w, position)
    v = position - 0.5 * w_p + d * xp.cross(w, w_p)
    return xp.concat([v, w], axis=-1)
