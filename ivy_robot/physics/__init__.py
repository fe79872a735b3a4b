"""MuJoCo's simulation pipeline, written once for every ivy backend.

A compiled MuJoCo model is read once into a frozen :class:`~ivy_robot.physics.model.Model` of
named numpy constants (:func:`read_model`); the pipeline then runs as array code on numpy, torch,
jax or tensorflow, batched over any leading shape, differentiable and compilable. Its stages are
those of MuJoCo's ``mj_forward``, each a function of the backend namespace ``xp``, the model and
a :class:`~ivy_robot.physics.data.Data` record of named arrays:

==================  ===========================================================================
module              stage
==================  ===========================================================================
``kinematics``      body, joint, geom and site frames; centres of mass, inertias and dof axes
``smooth``          mass matrix and its factor, velocities, bias, passive and actuator forces
``collision``       contacts between geoms
``constraints``     constraint rows (friction loss, joint limits, contacts) and impedance
``solver``          the constrained accelerations (Newton, PGS)
``pipeline``        ``forward`` (``mj_forward``) and ``step`` (``mj_step``: Euler and RK4)
==================  ===========================================================================

Example:
    >>> model = read_model(mujoco.MjModel.from_xml_path(hopper_xml))      # Gymnasium's Hopper
    >>> data = make_data(ivy.numpy, model, model.qpos0, np.zeros(model.nv), np.zeros(model.nu))
    >>> data = step(ivy.numpy, model, data)                                # mj_step
    >>> data.qpos.shape, data.xpos.shape, data.contact_dist.shape
    ((6,), (5, 3), (14,))
"""

from ivy_robot.physics import collision, constraints, data, model, pipeline, smooth
from ivy_robot.physics import kinematics as kinematics_module
from ivy_robot.physics import solver as solver_module
from ivy_robot.physics._math import Gather, gather
from ivy_robot.physics.collision import *  # noqa: F403
from ivy_robot.physics.constraints import *  # noqa: F403
from ivy_robot.physics.data import *  # noqa: F403
from ivy_robot.physics.kinematics import *  # noqa: F403
from ivy_robot.physics.model import *  # noqa: F403
from ivy_robot.physics.pipeline import *  # noqa: F403
from ivy_robot.physics.smooth import *  # noqa: F403
from ivy_robot.physics.solver import *  # noqa: F403

__all__ = [
    "Gather",
    "gather",
    *model.__all__,
    *data.__all__,
    *kinematics_module.__all__,
    *smooth.__all__,
    *collision.__all__,
    *constraints.__all__,
    *solver_module.__all__,
    *pipeline.__all__,
]
