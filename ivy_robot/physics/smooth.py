"""The smooth dynamics: mass matrix and its factor, velocities, bias, passive and actuator
forces (MuJoCo's ``mj_crb``, ``mj_factorM``, ``mj_comVel``, ``mj_rne``, ``mj_passive``,
``mj_fwdActuation``), written once.

Every quantity is about the centre of mass of its body's tree (``com_pos``' ``origin``), as
MuJoCo keeps them, so that a robot far from the world's origin loses no precision. Sums along
the tree are products with constant masks of the model (a body's velocity is the sum over the
dofs of its chain, its composite inertia the sum over its subtree), so the number of operations
does not grow with the number of bodies.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ivy_robot.physics import _math as mt
from ivy_robot.physics.model import FREE, HINGE, MIN_VALUE, SLIDE, Model, const

__all__ = [
    "actuation",
    "bias_forces",
    "body_forces",
    "fluid_wrenches",
    "ldl_factor",
    "ldl_solve",
    "mass_matrix",
    "passive_forces",
    "project",
    "velocities",
]

# ----------------------------------------------------------------------------------------------
# The plan: made once per model
# ----------------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class Factor:
    """Constants of the dense ``L D L^T`` factorisation of an *n x n* matrix."""

    below: tuple  # per column k: [n] 1.0 below the diagonal
    unit: tuple  # per k: [n] the k-th unit vector


def factor_plan(n: int) -> Factor:
    below = np.tril(np.ones((n, n)), -1)
    eye = np.eye(n)
    return Factor(below=tuple(below[:, k].copy() for k in range(n)), unit=tuple(eye))


@dataclass(frozen=True, eq=False)
class Plan:
    """What the smooth dynamics index with (numpy constants, Python flags)."""

    factor: Factor
    dof_body: mt.Gather
    subtree: mt.ConstMatrix  # body_subtree
    chain: mt.ConstMatrix  # body_chain
    velocity_before: mt.ConstMatrix  # dof_velocity_before
    eye: np.ndarray  # [nv, nv]
    off_diagonal: np.ndarray  # [nv, nv]
    cacc_base: np.ndarray  # [6]: the world's acceleration, -gravity
    has_free: bool
    not_free_translation: np.ndarray  # [nv, 1]: 0 on free joints' translations
    negative_damping: np.ndarray  # [nv]
    # springs of hinges and slides
    has_springs: bool
    spring_qpos: mt.Gather
    spring_ref: np.ndarray
    spring_scatter: mt.ConstMatrix  # [nv, nspring], -stiffness
    # the fluid model
    has_fluid: bool
    fluid_bodies: mt.Gather
    fluid_area: np.ndarray  # [nfluid, 3]
    fluid_spin: np.ndarray  # [nfluid, 3]
    fluid_diameter: np.ndarray  # [nfluid, 1]
    fluid_scatter: mt.ConstMatrix  # [nbody, nfluid]
    has_wind: bool
    # actuators
    has_ctrlrange: bool
    has_forcerange: bool
    has_joint_range: bool
    actuator_qpos: mt.Gather
    actuator_qvel: mt.Gather
    actuator_scatter: mt.ConstMatrix  # [nv, nu]: gear
    ctrl_low: np.ndarray
    ctrl_high: np.ndarray
    force_low: np.ndarray
    force_high: np.ndarray
    dof_low: np.ndarray  # [nv]
    dof_high: np.ndarray
    gain: tuple  # (constant, length, velocity) coefficient arrays, None where all zero
    bias: tuple


def plan(model: Model) -> Plan:
    """The smooth dynamics' plan of ``model``."""
    nv, nu = model.nv, model.nu
    free_translation = np.zeros((nv, 1))
    for j in np.flatnonzero(model.jnt_type == FREE):
        free_translation[model.jnt_dofadr[j] : model.jnt_dofadr[j] + 3] = 1.0
    springs = [
        j
        for j in range(model.njnt)
        if model.jnt_stiffness[j] != 0.0 and model.jnt_type[j] in (SLIDE, HINGE)
    ]
    spring_scatter = np.zeros((len(springs), nv))
    for row, j in enumerate(springs):
        spring_scatter[row, model.jnt_dofadr[j]] = -model.jnt_stiffness[j]
    spring_qpos = model.jnt_qposadr[springs] if springs else np.zeros(0, np.int64)
    fluid = _fluid_constants(model)
    scatter = np.zeros((nu, nv))
    scatter[np.arange(nu), model.actuator_dof] = model.actuator_gear
    dof_range = model.jnt_actfrcrange[model.dof_jnt] if nv else np.zeros((0, 2))

    def coefficients(prm):
        return tuple(prm[:, k].copy() if k == 0 or np.any(prm[:, k]) else None for k in range(3))

    return Plan(
        factor=factor_plan(nv),
        dof_body=mt.gather(model.dof_body, model.nbody),
        subtree=mt.const_matrix(model.body_subtree),
        chain=mt.const_matrix(model.body_chain),
        velocity_before=mt.const_matrix(model.dof_velocity_before),
        eye=np.eye(nv),
        off_diagonal=1.0 - np.eye(nv),
        cacc_base=np.concatenate([np.zeros(3), -model.gravity]),
        has_free=bool(free_translation.any()),
        not_free_translation=1.0 - free_translation,
        negative_damping=-model.dof_damping,
        has_springs=bool(springs),
        spring_qpos=mt.gather(spring_qpos, model.nq),
        spring_ref=model.qpos_spring[spring_qpos].copy(),
        spring_scatter=mt.const_matrix(spring_scatter.T),
        has_fluid=bool(model.fluid_bodies),
        fluid_bodies=mt.gather(list(model.fluid_bodies), model.nbody),
        has_wind=bool(np.any(model.wind)),
        **fluid,
        has_ctrlrange=bool(np.isfinite(model.actuator_ctrlrange).any()),
        has_forcerange=bool(np.isfinite(model.actuator_forcerange).any()),
        has_joint_range=bool(np.isfinite(dof_range).any()),
        actuator_qpos=mt.gather(model.actuator_qadr, model.nq),
        actuator_qvel=mt.gather(model.actuator_dof, nv),
        actuator_scatter=mt.const_matrix(scatter.T),
        ctrl_low=model.actuator_ctrlrange[:, 0].copy(),
        ctrl_high=model.actuator_ctrlrange[:, 1].copy(),
        force_low=model.actuator_forcerange[:, 0].copy(),
        force_high=model.actuator_forcerange[:, 1].copy(),
        dof_low=dof_range[:, 0].copy(),
        dof_high=dof_range[:, 1].copy(),
        gain=coefficients(model.actuator_gain),
        bias=coefficients(model.actuator_bias),
    )


def _fluid_constants(model: Model) -> dict:
    bodies = list(model.fluid_bodies)
    inertia, mass = model.body_inertia[bodies], model.body_mass[bodies]
    i0, i1, i2 = inertia[:, 0], inertia[:, 1], inertia[:, 2]
    box = np.stack(
        [
            np.sqrt(np.maximum(MIN_VALUE, a + c - d) / mass * 6.0)
            for a, c, d in ((i1, i2, i0), (i0, i2, i1), (i0, i1, i2))
        ],
        axis=-1,
    ).reshape(len(bodies), 3)
    others = [[n for n in range(3) if n != k] for k in range(3)]
    scatter = np.zeros((model.nbody, len(bodies)))
    scatter[bodies, np.arange(len(bodies))] = 1.0
    return dict(
        fluid_area=np.stack([box[:, o[0]] * box[:, o[1]] for o in others], axis=-1),
        fluid_spin=np.stack(
            [box[:, k] * (box[:, o[0]] ** 4 + box[:, o[1]] ** 4) for k, o in enumerate(others)],
            axis=-1,
        ),
        fluid_diameter=(box.sum(axis=-1) / 3.0)[:, None],
        fluid_scatter=mt.const_matrix(scatter),
    )


# ----------------------------------------------------------------------------------------------
# Mass matrix
# ----------------------------------------------------------------------------------------------


def mass_matrix(xp, model: Model, cinert, cdof):
    """MuJoCo's ``qM`` as a dense *[..., nv, nv]* (``mj_fullM``), with armature: composite
    rigid bodies, ``M[i, j] = cdof_j . (crb[body_i] cdof_i)`` for ``j`` at or above ``i``.

    Example:
        >>> mass_matrix(xp, model, data.cinert, data.cdof).shape    # the Hopper
        (6, 6)
    """
    p = model.smooth
    crb = mt.cmatmul(xp, p.subtree, cinert)  # [..., nbody, 10]
    force = mt.apply_inertia(xp, mt.take(xp, crb, p.dof_body, axis=-2), cdof)  # [..., nv, 6]
    products = mt.contract(xp, force, xp.matrix_transpose(cdof))  # [i, j] = cdof_j . force_i
    lower = products * const(xp, model.dof_ancestors, cinert)
    return (
        lower
        + xp.matrix_transpose(lower) * const(xp, p.off_diagonal, cinert)
        + const(xp, p.eye, cinert) * const(xp, model.dof_armature, cinert)
    )


def ldl_factor(xp, plan: Factor, matrix):
    """``matrix = L diag(D) L^T`` for symmetric positive definite *[..., n, n]*, ``L`` unit
    lower triangular (returned without its unit diagonal), by one column at a time: *n*
    vectorised steps (``plan``: :func:`factor_plan` of *n*). Returns ``(L, D)``.

    Example:
        >>> lower, pivots = ldl_factor(xp, model.smooth.factor, data.qM)
        >>> np.allclose((lower + np.eye(6)) * pivots @ (lower + np.eye(6)).T, data.qM)
        True
    """
    n = len(plan.below)
    if n == 0:
        return matrix, matrix[..., 0]
    columns, pivots, work = [], [], matrix
    for k in range(n):
        pivot = work[..., k, k]
        column = work[..., :, k] / pivot[..., None] * const(xp, plan.below[k], matrix)
        columns.append(column)
        pivots.append(pivot)
        if k < n - 1:
            work = work - pivot[..., None, None] * column[..., :, None] * column[..., None, :]
    return xp.stack(columns, axis=-1), xp.stack(pivots, axis=-1)


def ldl_solve(xp, plan: Factor, factored, rhs):
    """``matrix^-1 rhs`` from :func:`ldl_factor`, ``rhs`` *[..., n]*.

    Example:
        >>> x = ldl_solve(xp, model.smooth.factor, (data.qLD, data.qLDiag), np.ones(6))
        >>> np.allclose(data.qM @ x, 1.0)
        True
    """
    lower, pivots = factored
    n = len(plan.below)
    if n == 0:
        return rhs
    x = rhs
    for k in range(n - 1):  # forward: L y = rhs
        x = x - lower[..., :, k] * x[..., k : k + 1]
    x = x / pivots
    for k in range(n - 2, -1, -1):  # backward: L^T x = y
        x = x - const(xp, plan.unit[k], rhs) * mt.dot(xp, lower[..., :, k], x)[..., None]
    return x


# ----------------------------------------------------------------------------------------------
# Velocities and bias forces
# ----------------------------------------------------------------------------------------------


def velocities(xp, model: Model, cdof, qvel):
    """MuJoCo's ``mj_comVel``: body velocities ``cvel`` *[..., nbody, 6]* and the rates of the
    dof axes ``cdof_dot`` *[..., nv, 6]* (an axis moves with the frame before it; free
    translations are fixed).

    Example:
        >>> cvel, cdof_dot = velocities(xp, model, data.cdof, np.ones(model.nv))
        >>> cvel.shape, cdof_dot.shape
        ((5, 6), (6, 6))
    """
    moving = cdof * qvel[..., None]
    cvel = mt.cmatmul(xp, model.smooth.chain, moving)
    before = mt.cmatmul(xp, model.smooth.velocity_before, moving)
    cdof_dot = mt.cross_motion(xp, before, cdof)
    if model.smooth.has_free:
        cdof_dot = cdof_dot * const(xp, model.smooth.not_free_translation, cdof)
    return cvel, cdof_dot


def body_forces(xp, model: Model, cinert, cvel, cdof, cdof_dot, qvel, qacc=None):
    """The net spatial force on each body *[..., nbody, 6]* (torque, force about its tree's
    origin) for the accelerations ``qacc`` (None: zero), gravity included, MuJoCo's ``mj_rne``
    forward pass: ``cacc = -gravity + sum over the chain (cdof_dot qvel + cdof qacc)``, then
    ``cinert cacc + cvel x* (cinert cvel)``. Returns ``(cacc, cfrc_body)``.

    Example:
        >>> cacc, forces = body_forces(xp, model, data.cinert, data.cvel, data.cdof,
        ...                            data.cdof_dot, data.qvel)
        >>> cacc[1, 3:]                                     # gravity, as a base acceleration
        array([0.  , 0.  , 9.81])
    """
    rate = cdof_dot * qvel[..., None]
    if qacc is not None:
        rate = rate + cdof * qacc[..., None]
    base = const(xp, model.smooth.cacc_base, cdof)
    cacc = base + mt.cmatmul(xp, model.smooth.chain, rate)
    inertial = mt.apply_inertia(xp, cinert, cacc)
    gyroscopic = mt.cross_force(xp, cvel, mt.apply_inertia(xp, cinert, cvel))
    return cacc, inertial + gyroscopic


def project(xp, model: Model, cdof, wrenches):
    """Joint forces *[..., nv]* of body wrenches *[..., nbody, 6]* (about each body's tree
    origin): each dof takes the wrenches of its body's subtree along its axis.

    Example:
        >>> _, forces = body_forces(xp, model, data.cinert, data.cvel, data.cdof,
        ...                         data.cdof_dot, data.qvel)
        >>> np.allclose(project(xp, model, data.cdof, forces), data.qfrc_bias)
        True
    """
    subtree = mt.cmatmul(xp, model.smooth.subtree, wrenches)
    return mt.dot(xp, cdof, mt.take(xp, subtree, model.smooth.dof_body, axis=-2))


def bias_forces(xp, model: Model, cinert, cvel, cdof, cdof_dot, qvel):
    """MuJoCo's ``qfrc_bias`` *[..., nv]*: Coriolis, centrifugal and gravity forces.

    Example:
        >>> bias_forces(xp, model, data.cinert, data.cvel, data.cdof, data.cdof_dot,
        ...             data.qvel).round(1)                # at rest: gravity alone
        array([  0. , 155.2,  -3.4,   3.4,   3.4,   3.4])
    """
    _, forces = body_forces(xp, model, cinert, cvel, cdof, cdof_dot, qvel)
    return project(xp, model, cdof, forces)


# ----------------------------------------------------------------------------------------------
# Passive forces
# ----------------------------------------------------------------------------------------------


def passive_forces(xp, model: Model, qpos, qvel, kin=None, cvel=None, origin=None, cdof=None):
    """MuJoCo's ``qfrc_passive`` *[..., nv]*: joint springs and dampers, and the inertia-box
    fluid model (``kin``, ``cvel``, ``origin`` and ``cdof`` are needed only for the fluid).

    Example:
        >>> passive_forces(xp, model, model.qpos0, np.ones(model.nv)) + 0.0  # its dampers
        array([ 0.,  0.,  0., -1., -1., -1.])
    """
    p = model.smooth
    out = qvel * const(xp, p.negative_damping, qvel)
    if p.has_springs:
        stretch = mt.take(xp, qpos, p.spring_qpos, axis=-1) - const(xp, p.spring_ref, qpos)
        out = out + mt.cmatmul(xp, p.spring_scatter, stretch[..., :, None])[..., 0]
    if p.has_fluid:
        out = out + project(xp, model, cdof, fluid_wrenches(xp, model, kin, cvel, origin))
    return out


def fluid_wrenches(xp, model: Model, kin, cvel, origin):
    """MuJoCo's inertia-box fluid model: viscous (Stokes) and quadratic drag on each body's
    equivalent inertia box, in its inertial frame, applied at its centre of mass. Returns
    wrenches *[..., nbody, 6]* about each body's tree origin (zero for bodies without).

    Example:
        >>> swimmer = read_model(mujoco.MjModel.from_xml_path(swimmer_xml))
        >>> at_rest = forward(xp, swimmer, make_data(xp, swimmer, swimmer.qpos0, np.ones(5)))
        >>> origin = at_rest.subtree_com[swimmer.body_rootid]
        >>> kin = {"xipos": at_rest.xipos, "ximat": at_rest.ximat}
        >>> fluid_wrenches(xp, swimmer, kin, at_rest.cvel, origin).shape
        (4, 6)
    """
    p = model.smooth
    like = kin["xipos"]
    com = mt.take(xp, kin["xipos"], p.fluid_bodies, axis=-2)
    irot = mt.take(xp, kin["ximat"], p.fluid_bodies, axis=-3)
    o = mt.take(xp, origin, p.fluid_bodies, axis=-2)
    velocity = mt.take(xp, cvel, p.fluid_bodies, axis=-2)
    w, v = velocity[..., :3], velocity[..., 3:] + mt.cross(xp, velocity[..., :3], com - o)
    local_w, local_v = mt.mtv(xp, irot, w), mt.mtv(xp, irot, v)
    if p.has_wind:
        local_v = local_v - mt.mtv(xp, irot, const(xp, model.wind, like))
    torque, force = local_w * 0.0, local_v * 0.0
    if model.viscosity > 0:
        d = const(xp, p.fluid_diameter, like)
        torque = torque - math.pi * model.viscosity * d**3 * local_w
        force = force - 3.0 * math.pi * model.viscosity * d * local_v
    if model.density > 0:
        rho = model.density
        force = force - 0.5 * rho * const(xp, p.fluid_area, like) * xp.abs(local_v) * local_v
        torque = torque - rho / 64.0 * const(xp, p.fluid_spin, like) * xp.abs(local_w) * local_w
    world_torque, world_force = mt.mv(xp, irot, torque), mt.mv(xp, irot, force)
    wrench = xp.concat([world_torque + mt.cross(xp, com - o, world_force), world_force], axis=-1)
    return mt.cmatmul(xp, p.fluid_scatter, wrench)


# ----------------------------------------------------------------------------------------------
# Actuators
# ----------------------------------------------------------------------------------------------


def actuation(xp, model: Model, qpos, qvel, ctrl):
    """MuJoCo's ``mj_fwdActuation`` for joint transmissions without activation: ``ctrl``
    clamped to the control range, ``force = gain * ctrl + bias`` (gain and bias affine in the
    actuator's length and velocity) clamped to the force range, ``qfrc_actuator = gear * force``
    per joint, clamped to the joint's ``actuatorfrcrange``. Returns ``(actuator_force [..., nu],
    qfrc_actuator [..., nv])``.

    Example:
        >>> force, qfrc = actuation(xp, model, model.qpos0, np.zeros(6), np.array([1.0, 0, 0]))
        >>> force, qfrc                          # the thigh's motor: gear 200
        (array([1., 0., 0.]), array([  0.,   0.,   0., 200.,   0.,   0.]))
    """
    if model.nu == 0 or ctrl is None or "actuation" in model.disabled:
        zero = qvel * 0.0
        return zero[..., :0], zero
    p = model.smooth
    u = ctrl
    if p.has_ctrlrange:
        u = xp.clip(u, const(xp, p.ctrl_low, qpos), const(xp, p.ctrl_high, qpos))
    gear = const(xp, model.actuator_gear, qpos)
    length = gear * mt.take(xp, qpos, p.actuator_qpos, axis=-1)
    speed = gear * mt.take(xp, qvel, p.actuator_qvel, axis=-1)
    force = _affine(xp, p.gain, length, speed, qpos) * u + _affine(xp, p.bias, length, speed, qpos)
    if p.has_forcerange:
        force = xp.clip(force, const(xp, p.force_low, qpos), const(xp, p.force_high, qpos))
    qfrc = mt.cmatmul(xp, p.actuator_scatter, force[..., :, None])[..., 0]
    if p.has_joint_range:
        qfrc = xp.clip(qfrc, const(xp, p.dof_low, qpos), const(xp, p.dof_high, qpos))
    return force, qfrc


def _affine(xp, coefficients, length, speed, like):
    constant, per_length, per_speed = coefficients
    value = const(xp, constant, like) + length * 0.0
    if per_length is not None:
        value = value + const(xp, per_length, like) * length
    if per_speed is not None:
        value = value + const(xp, per_speed, like) * speed
    return value
