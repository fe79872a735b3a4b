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

import numpy as np

from ivy_robot.physics import _math as mt
from ivy_robot.physics.model import FREE, HINGE, MIN_VALUE, SLIDE, Model, const

# ----------------------------------------------------------------------------------------------
# Mass matrix
# ----------------------------------------------------------------------------------------------


def mass_matrix(xp, model: Model, cinert, cdof):
    """MuJoCo's ``qM`` as a dense *[..., nv, nv]* (``mj_fullM``), with armature: composite
    rigid bodies, ``M[i, j] = cdof_j . (crb[body_i] cdof_i)`` for ``j`` at or above ``i``."""
    crb = xp.matmul(const(xp, model.body_subtree, cinert), cinert)  # [..., nbody, 10]
    force = mt.apply_inertia(xp, mt.take(xp, crb, model.dof_body, axis=-2), cdof)  # [..., nv, 6]
    products = xp.matmul(force, xp.matrix_transpose(cdof))  # [i, j] = cdof_j . force_i
    lower = products * const(xp, model.dof_ancestors, cinert)
    diagonal = const(xp, np.eye(model.nv), cinert)
    return (
        lower
        + xp.matrix_transpose(lower) * (1.0 - diagonal)
        + diagonal * const(xp, model.dof_armature, cinert)
    )


def factor(xp, matrix):
    """``matrix = L diag(D) L^T`` for symmetric positive definite *[..., n, n]*, ``L`` unit
    lower triangular (returned without its unit diagonal), by one column at a time: *n*
    vectorised steps. Returns ``(L, D)``."""
    n = matrix.shape[-1]
    if n == 0:
        return matrix, matrix[..., 0]
    columns, pivots, work = [], [], matrix
    below = np.tril(np.ones((n, n)), -1)  # [i, k] = 1 where i > k
    for k in range(n):
        pivot = work[..., k, k]
        column = work[..., :, k] / pivot[..., None] * const(xp, below[:, k], matrix)
        columns.append(column)
        pivots.append(pivot)
        if k < n - 1:
            work = work - pivot[..., None, None] * column[..., :, None] * column[..., None, :]
    return xp.stack(columns, axis=-1), xp.stack(pivots, axis=-1)


def solve(xp, factored, rhs):
    """``matrix^-1 rhs`` from :func:`factor`, ``rhs`` *[..., n]*."""
    lower, pivots = factored
    n = pivots.shape[-1]
    if n == 0:
        return rhs
    eye = np.eye(n)
    x = rhs
    for k in range(n - 1):  # forward: L y = rhs
        x = x - lower[..., :, k] * x[..., k : k + 1]
    x = x / pivots
    for k in range(n - 2, -1, -1):  # backward: L^T x = y
        x = x - const(xp, eye[k], rhs) * mt.dot(xp, lower[..., :, k], x)[..., None]
    return x


# ----------------------------------------------------------------------------------------------
# Velocities and bias forces
# ----------------------------------------------------------------------------------------------


def velocities(xp, model: Model, cdof, qvel):
    """MuJoCo's ``mj_comVel``: body velocities ``cvel`` *[..., nbody, 6]* and the rates of the
    dof axes ``cdof_dot`` *[..., nv, 6]* (an axis moves with the frame before it; free
    translations are fixed)."""
    moving = cdof * qvel[..., None]
    cvel = xp.matmul(const(xp, model.body_chain, cdof), moving)
    before = xp.matmul(const(xp, model.dof_velocity_before, cdof), moving)
    fixed = np.zeros((model.nv, 1))
    for j in np.flatnonzero(model.jnt_type == FREE):
        fixed[model.jnt_dofadr[j] : model.jnt_dofadr[j] + 3] = 1.0
    cdof_dot = mt.cross_motion(xp, before, cdof)
    if fixed.any():
        cdof_dot = cdof_dot * const(xp, 1.0 - fixed, cdof)
    return cvel, cdof_dot


def body_forces(xp, model: Model, cinert, cvel, cdof, cdof_dot, qvel, qacc=None):
    """The net spatial force on each body *[..., nbody, 6]* (torque, force about its tree's
    origin) for the accelerations ``qacc`` (None: zero), gravity included, MuJoCo's ``mj_rne``
    forward pass: ``cacc = -gravity + sum over the chain (cdof_dot qvel + cdof qacc)``, then
    ``cinert cacc + cvel x* (cinert cvel)``. Returns ``(cacc, cfrc_body)``."""
    rate = cdof_dot * qvel[..., None]
    if qacc is not None:
        rate = rate + cdof * qacc[..., None]
    base = const(xp, np.concatenate([np.zeros(3), -model.gravity]), cdof)
    cacc = base + xp.matmul(const(xp, model.body_chain, cdof), rate)
    inertial = mt.apply_inertia(xp, cinert, cacc)
    gyroscopic = mt.cross_force(xp, cvel, mt.apply_inertia(xp, cinert, cvel))
    return cacc, inertial + gyroscopic


def project(xp, model: Model, cdof, wrenches):
    """Joint forces *[..., nv]* of body wrenches *[..., nbody, 6]* (about each body's tree
    origin): each dof takes the wrenches of its body's subtree along its axis."""
    subtree = xp.matmul(const(xp, model.body_subtree, cdof), wrenches)
    return mt.dot(xp, cdof, mt.take(xp, subtree, model.dof_body, axis=-2))


def bias_forces(xp, model: Model, cinert, cvel, cdof, cdof_dot, qvel):
    """MuJoCo's ``qfrc_bias`` *[..., nv]*: Coriolis, centrifugal and gravity forces."""
    _, forces = body_forces(xp, model, cinert, cvel, cdof, cdof_dot, qvel)
    return project(xp, model, cdof, forces)


# ----------------------------------------------------------------------------------------------
# Passive forces
# ----------------------------------------------------------------------------------------------


def passive_forces(xp, model: Model, qpos, qvel, kin=None, cvel=None, origin=None, cdof=None):
    """MuJoCo's ``qfrc_passive`` *[..., nv]*: joint springs and dampers, and the inertia-box
    fluid model (``kin``, ``cvel``, ``origin`` and ``cdof`` are needed only for the fluid)."""
    out = qvel * const(xp, -model.dof_damping, qvel)
    springs = [
        j
        for j in range(model.njnt)
        if model.jnt_stiffness[j] != 0.0 and model.jnt_type[j] in (SLIDE, HINGE)
    ]
    if springs:
        scatter = np.zeros((len(springs), model.nv))
        for row, j in enumerate(springs):
            scatter[row, model.jnt_dofadr[j]] = -model.jnt_stiffness[j]
        adr = model.jnt_qposadr[springs]
        stretch = mt.take(xp, qpos, adr, axis=-1) - const(xp, model.qpos_spring[adr], qpos)
        out = out + xp.matmul(stretch[..., None, :], const(xp, scatter, qpos))[..., 0, :]
    if model.fluid_bodies:
        out = out + project(xp, model, cdof, fluid_wrenches(xp, model, kin, cvel, origin))
    return out


def _fluid_constants(model: Model):
    bodies = list(model.fluid_bodies)
    inertia, mass = model.body_inertia[bodies], model.body_mass[bodies]
    i0, i1, i2 = inertia[:, 0], inertia[:, 1], inertia[:, 2]
    box = np.stack(
        [
            np.sqrt(np.maximum(MIN_VALUE, a + c - d) / mass * 6.0)
            for a, c, d in ((i1, i2, i0), (i0, i2, i1), (i0, i1, i2))
        ],
        axis=-1,
    )
    others = [[n for n in range(3) if n != k] for k in range(3)]
    area = np.stack([box[:, o[0]] * box[:, o[1]] for o in others], axis=-1)
    spin = np.stack(
        [box[:, k] * (box[:, o[0]] ** 4 + box[:, o[1]] ** 4) for k, o in enumerate(others)], axis=-1
    )
    diameter = box.sum(axis=-1) / 3.0
    return bodies, area, spin, diameter


def fluid_wrenches(xp, model: Model, kin, cvel, origin):
    """MuJoCo's inertia-box fluid model: viscous (Stokes) and quadratic drag on each body's
    equivalent inertia box, in its inertial frame, applied at its centre of mass. Returns
    wrenches *[..., nbody, 6]* about each body's tree origin (zero for bodies without)."""
    bodies, area, spin, diameter = _fluid_constants(model)
    like = kin["xipos"]
    com = mt.take(xp, kin["xipos"], bodies, axis=-2)
    irot = mt.take(xp, kin["ximat"], bodies, axis=-3)
    o = mt.take(xp, origin, bodies, axis=-2)
    velocity = mt.take(xp, cvel, bodies, axis=-2)
    w, v = velocity[..., :3], velocity[..., 3:] + mt.cross(xp, velocity[..., :3], com - o)
    local_w, local_v = mt.mtv(xp, irot, w), mt.mtv(xp, irot, v)
    if np.any(model.wind):
        local_v = local_v - mt.mtv(xp, irot, const(xp, model.wind, like))
    torque, force = local_w * 0.0, local_v * 0.0
    if model.viscosity > 0:
        d = const(xp, diameter[:, None], like)
        torque = torque - math.pi * model.viscosity * d**3 * local_w
        force = force - 3.0 * math.pi * model.viscosity * d * local_v
    if model.density > 0:
        rho = model.density
        force = force - 0.5 * rho * const(xp, area, like) * xp.abs(local_v) * local_v
        torque = torque - rho / 64.0 * const(xp, spin, like) * xp.abs(local_w) * local_w
    world_torque, world_force = mt.mv(xp, irot, torque), mt.mv(xp, irot, force)
    wrench = xp.concat([world_torque + mt.cross(xp, com - o, world_force), world_force], axis=-1)
    scatter = np.zeros((model.nbody, len(bodies)))
    scatter[bodies, np.arange(len(bodies))] = 1.0
    return xp.matmul(const(xp, scatter, like), wrench)


# ----------------------------------------------------------------------------------------------
# Actuators
# ----------------------------------------------------------------------------------------------


def actuation(xp, model: Model, qpos, qvel, ctrl):
    """MuJoCo's ``mj_fwdActuation`` for joint transmissions without activation: ``ctrl``
    clamped to the control range, ``force = gain * ctrl + bias`` (gain and bias affine in the
    actuator's length and velocity) clamped to the force range, ``qfrc_actuator = gear * force``
    per joint, clamped to the joint's ``actuatorfrcrange``. Returns ``(actuator_force [..., nu],
    qfrc_actuator [..., nv])``."""
    if model.nu == 0 or ctrl is None or "actuation" in model.disabled:
        zero = qvel * 0.0
        return zero[..., :0], zero
    lo, hi = model.actuator_ctrlrange[:, 0], model.actuator_ctrlrange[:, 1]
    u = ctrl
    if np.isfinite(model.actuator_ctrlrange).any():
        u = xp.clip(u, const(xp, lo, qpos), const(xp, hi, qpos))
    gear = const(xp, model.actuator_gear, qpos)
    length = gear * mt.take(xp, qpos, model.actuator_qadr, axis=-1)
    speed = gear * mt.take(xp, qvel, model.actuator_dof, axis=-1)
    gain, bias = model.actuator_gain, model.actuator_bias
    force = _affine(xp, gain, length, speed, qpos) * u + _affine(xp, bias, length, speed, qpos)
    if np.isfinite(model.actuator_forcerange).any():
        frange = model.actuator_forcerange
        force = xp.clip(force, const(xp, frange[:, 0], qpos), const(xp, frange[:, 1], qpos))
    scatter = np.zeros((model.nu, model.nv))
    scatter[np.arange(model.nu), model.actuator_dof] = model.actuator_gear
    qfrc = xp.matmul(force[..., None, :], const(xp, scatter, qpos))[..., 0, :]
    dof_range = model.jnt_actfrcrange[model.dof_jnt]
    if np.isfinite(dof_range).any():
        qfrc = xp.clip(qfrc, const(xp, dof_range[:, 0], qpos), const(xp, dof_range[:, 1], qpos))
    return force, qfrc


def _affine(xp, prm, length, speed, like):
    value = const(xp, prm[:, 0], like) + length * 0.0
    if np.any(prm[:, 1]):
        value = value + const(xp, prm[:, 1], like) * length
    if np.any(prm[:, 2]):
        value = value + const(xp, prm[:, 2], like) * speed
    return value
