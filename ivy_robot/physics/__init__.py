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
``forward``         ``forward`` (``mj_forward``) and ``step`` (``mj_step``: Euler and RK4)
==================  ===========================================================================

Example:
    >>> model = read_model(mujoco.MjModel.from_xml_path("hopper.xml"))
    >>> data = step(ivy.jax, model, qpos, qvel, ctrl)         # a Data record
    >>> data.qpos, data.qvel, data.xpos, data.contact_dist
"""

from ivy_robot.physics.data import Data
from ivy_robot.physics.model import Model, read_model
from ivy_robot.physics.pipeline import forward, make_data, step

__all__ = ["Data", "Model", "forward", "make_data", "read_model", "step"]
