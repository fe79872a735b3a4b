"""ivy_robot: kinematic trees from MJCF, DH manipulators, rigid mobile bodies, spline paths,
signed distances and trajectory optimisation, written once for every ivy backend.
"""

from ivy_robot import kinematic_tree, mjcf
from ivy_robot.kinematic_tree import *  # noqa: F403
from ivy_robot.mjcf import *  # noqa: F403

__all__ = [*mjcf.__all__, *kinematic_tree.__all__]
