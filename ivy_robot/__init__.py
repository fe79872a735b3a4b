"""ivy_robot: kinematic trees from MJCF, DH manipulators, rigid mobile bodies, spline paths,
signed distances and trajectory optimisation, written once for every ivy backend.
"""

from ivy_robot import (
    kinematic_tree,
    manipulator,
    mjcf,
    models,
    planning,
    rigid_mobile,
    sdf,
    splines,
)
from ivy_robot.kinematic_tree import *  # noqa: F403
from ivy_robot.manipulator import *  # noqa: F403
from ivy_robot.mjcf import *  # noqa: F403
from ivy_robot.models import *  # noqa: F403
from ivy_robot.planning import *  # noqa: F403
from ivy_robot.rigid_mobile import *  # noqa: F403
from ivy_robot.sdf import *  # noqa: F403
from ivy_robot.splines import *  # noqa: F403

__all__ = [
    *mjcf.__all__,
    *kinematic_tree.__all__,
    *manipulator.__all__,
    *rigid_mobile.__all__,
    *models.__all__,
    *splines.__all__,
    *sdf.__all__,
    *planning.__all__,
]
