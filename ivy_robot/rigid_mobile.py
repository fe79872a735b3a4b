"""Rigid mobile bodies (a drone, a mobile base): points fixed in the body, placed by poses."""

from __future__ import annotations

import numpy as np

import ivy
import ivy_mechanics as mech
from ivy.typing import Array, Framework
from ivy_robot import _arrays as A

__all__ = ["RigidMobile"]


class RigidMobile:
    """A rigid body described by points in its own frame.

    Args:
        body_points: points in the body frame *[num_points, 3]* (numpy or array-like).

    Example:
        >>> drone = RigidMobile(np.array([[0., 0., 0.], [0.15, 0., 0.], [-0.15, 0., 0.]]))
        >>> drone.sample_body(np.eye(4)[None]).shape
        (1, 3, 3)
    """

    def __init__(self, body_points) -> None:
        points = np.asarray(body_points, dtype=np.float64)
        if points.ndim != 2 or points.shape[-1] != 3 or points.shape[0] == 0:
            raise ValueError(
                f"RigidMobile: body_points must have shape [num_points, 3], got {points.shape}"
            )
        self.body_points = points
        self.num_points = int(points.shape[0])

    def sample_body(self, poses: Array, *, f: Framework = None) -> Array:
        """World positions of the body points under a batch of poses.

        Args:
            poses: world-from-body matrix poses *[batch_shape, 4, 4]* (or *[batch_shape, 3, 4]*).
            f: framework name or namespace; inferred from ``poses`` if None.

        Returns:
            *[batch_shape, num_points, 3]*.

        Example:
            >>> drone = RigidMobile(np.array([[0.0, 0.0, 0.0], [0.15, 0.0, 0.0]]))
            >>> poses = mech.rot_vec_pose_to_mat_pose(np.zeros((10, 6)))
            >>> drone.sample_body(poses).shape
            (10, 2, 3)
        """
        xp = ivy.get_framework(poses, f=f)
        shape = tuple(poses.shape)
        if len(shape) < 2 or shape[-1] != 4 or shape[-2] not in (3, 4):
            raise ValueError(
                f"RigidMobile.sample_body: poses must have shape [..., 4, 4] or [..., 3, 4], "
                f"got {shape}"
            )
        A.check_floating(xp, poses, "poses", "RigidMobile")
        points = A.constant(xp, self.body_points, poses)
        return mech.transform_points(poses[..., None, :, :], points, f=xp)
