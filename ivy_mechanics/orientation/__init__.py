"""Orientations: conversions between every pair of representations, quaternion algebra and
operations on rotations.

Representations (active, right-handed rotations: ``x' = R @ x``):

- ``rot_mat`` ``[..., 3, 3]``: rotation matrix.
- ``quaternion`` ``[..., 4]``: ``[x, y, z, w]``, scalar-last, Hamilton convention.
- ``rot_vec`` ``[..., 3]``: ``angle * unit_axis`` (the SO(3) logarithm).
- ``axis_angle`` ``[..., 4]``: ``[ax, ay, az, angle]`` with a unit axis.
- ``polar_axis_angle`` ``[..., 3]``: ``[inclination, azimuth, angle]``, the axis in spherical
  coordinates (inclination from +z, azimuth from +x).
- ``euler`` ``[..., 3]``: angles of a scipy-style sequence (``'xyz'`` extrinsic, ``'XYZ'``
  intrinsic; 24 conventions, see :data:`EULER_CONVENTIONS`).
- ``rot_6d`` ``[..., 6]``: the first two matrix columns (Zhou et al. 2019).

Every pair has a function ``<from>_to_<to>`` (e.g. ``rot_mat_to_quaternion``,
``euler_to_rot_vec(euler_angles, convention)``).
"""

from ivy_mechanics.orientation import (
    axis_angle,
    euler,
    operations,
    polar_axis_angle,
    quaternion,
    rot_6d,
    rotation_matrix,
    rotation_vector,
)
from ivy_mechanics.orientation.axis_angle import *  # noqa: F403
from ivy_mechanics.orientation.euler import *  # noqa: F403
from ivy_mechanics.orientation.operations import *  # noqa: F403
from ivy_mechanics.orientation.polar_axis_angle import *  # noqa: F403
from ivy_mechanics.orientation.quaternion import *  # noqa: F403
from ivy_mechanics.orientation.rot_6d import *  # noqa: F403
from ivy_mechanics.orientation.rotation_matrix import *  # noqa: F403
from ivy_mechanics.orientation.rotation_vector import *  # noqa: F403

_MODULES = (
    rotation_matrix,
    quaternion,
    rotation_vector,
    axis_angle,
    polar_axis_angle,
    euler,
    rot_6d,
    operations,
)
__all__ = [name for module in _MODULES for name in module.__all__]
