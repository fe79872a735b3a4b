"""Forward dynamics and integration (MuJoCo's ``mj_forward`` and ``mj_step``), written once.

:func:`forward` runs the stages in ``mj_forward``'s order, each a function of the backend
namespace, the model and the data that returns the data with its fields filled in:

1. :func:`fwd_position`: kinematics, inertias and dof axes, the mass matrix and its factor,
   collision, the constraint rows' positions and impedance;
2. :func:`fwd_velocity`: body velocities, passive forces, the rows' reference accelerations,
   bias forces;
3. :func:`fwd_actuation`: actuator forces;
4. :func:`fwd_acceleration`: the smooth acceleration ``M^-1 qfrc_smooth``;
5. :func:`fwd_constraint`: the constraint solver (warm started from ``qacc_warmstart``).

:func:`step` integrates one ``timestep`` with the model's integrator: Euler (semi-implicit, dof
damping implicit unless disabled) or RK4, whose four stages are one loop over its table (so a
compiler traces the dynamics once: the loop and the solver's are declared pure, which keeps
them as loops inside torch.compile too; measured on the Hopper with contacts, 313 s to compile
with the loops unrolled). As after ``mj_step``, the returned data holds the new
``qpos`` and ``qvel``, ``qacc_warmstart`` for the next step, and everything else as the last
evaluation of the dynamics left it (for RK4, its last stage: what Gymnasium's tasks read).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ivy_robot.physics import _math as mt
from ivy_robot.physics import constraints, smooth, solver
from ivy_robot.physics.data import Data
from ivy_robot.physics.kinematics import com_pos, kinematics
from ivy_robot.physics.model import BALL, FREE, JOINT_KINDS, Model, const

__all__ = [
    "contact_forces",
    "external_forces",
    "find_contacts",
    "forward",
    "fwd_acceleration",
    "fwd_actuation",
    "fwd_constraint",
    "fwd_position",
    "fwd_velocity",
    "integrate_positions",
    "make_data",
    "step",
]

#: MuJoCo's RK4 tableau: each stage starts a fraction of the step along the previous stage's
#: velocity and acceleration; the step averages the stages with these weights.
RK4_FRACTIONS = np.array([0.0, 0.5, 0.5, 1.0])
RK4_WEIGHTS = np.array([1.0, 2.0, 2.0, 1.0]) / 6.0


@dataclass(frozen=True, eq=False)
class Plan:
    """What forward and step index with (numpy constants, Python flags)."""

    simple_joints: bool  # hinges and slides only: qpos and qvel align
    position_segments: tuple  # (kind, qpos address, dof address) per joint, in qpos order
    rotations: tuple  # first dof of each ball or free rotation (Munthe-Kaas stages)
    euler_damping: bool
    euler_diagonal: np.ndarray  # [nv, nv]: h diag(damping)
    no_ctrl: np.ndarray  # [nu]
    empty: np.ndarray  # [0]
    empty_vectors: np.ndarray  # [0, 3]
    empty_frames: np.ndarray  # [0, 3, 3]
    # contact forces (mj_contactForce) and cfrc_ext
    pyramid_edges: tuple  # 4 Gathers over efc rows: each pyramid's k-th edge
    pyramid_mu: tuple  # (mu_1, mu_2) per pyramid
    frictionless_rows: mt.Gather
    contact_order: mt.Gather  # (pyramids, frictionless) -> contact order
    force_scatter: tuple  # per side: ConstMatrix [nbody, ncon], -1 / +1 (the world takes none)
    row_kinds: np.ndarray  # [nefc] the solver's row kinds
    solver: object  # the solver's options (ivy_robot.physics.solver.SolverOptions)
    empty_forces: np.ndarray  # [0, 3]


def plan(model: Model) -> Plan:
    """The forward dynamics' plan of ``model`` (after its constraint rows are laid out)."""
    rows = model.rows
    segments = tuple(
        (int(model.jnt_type[j]), int(model.jnt_qposadr[j]), int(model.jnt_dofadr[j]))
        for j in np.argsort(model.jnt_qposadr, kind="stable")
    )
    rotations = tuple(
        int(model.jnt_dofadr[j]) + (3 if int(model.jnt_type[j]) == FREE else 0)
        for j in range(model.njnt)
        if int(model.jnt_type[j]) in (FREE, BALL)
    )
    first = rows.contact_first_row
    pyramids, plain = rows.pyramids, rows.frictionless
    scatter = []
    for side, sign in ((0, -1.0), (1, 1.0)):
        matrix = np.zeros((model.nbody, rows.ncon))
        matrix[rows.contact_body[:, side], np.arange(rows.ncon)] = sign
        matrix[0] = 0.0
        scatter.append(matrix)
    damping = model.dof_damping
    return Plan(
        simple_joints=not rotations,
        position_segments=segments,
        rotations=rotations,
        euler_damping="eulerdamp" not in model.disabled and bool(np.any(damping > 0)),
        euler_diagonal=np.diag(model.timestep * damping),
        no_ctrl=np.zeros(model.nu),
        empty=np.zeros(0),
        empty_vectors=np.zeros((0, 3)),
        empty_frames=np.zeros((0, 3, 3)),
        pyramid_edges=tuple(mt.gather(first[pyramids] + e, rows.nefc) for e in range(4)),
        pyramid_mu=tuple(rows.contact_friction[pyramids, k].copy() for k in range(2)),
        frictionless_rows=mt.gather(first[plain], rows.nefc),
        contact_order=mt.gather(np.argsort(np.concatenate([pyramids, plain])), rows.ncon),
        force_scatter=tuple(mt.const_matrix(matrix) for matrix in scatter),
        row_kinds=solver.row_kinds(rows.kind) if rows.nefc else np.zeros(0, np.int64),
        solver=solver.SolverOptions(
            solver=model.solver.lower(),
            iterations=model.iterations,
            tolerance=model.tolerance,
            ls_iterations=model.ls_iterations,
            ls_tolerance=model.ls_tolerance,
            meaninertia=model.meaninertia,
            warmstart="warmstart" not in model.disabled,
        ),
        empty_forces=np.zeros((0, 3)),
    )


def make_data(xp, model: Model, qpos, qvel, ctrl=None, qfrc_applied=None, qacc_warmstart=None):
    """A :class:`Data` holding the state and inputs (absent inputs are zero, as in a fresh
    ``mjData``), in ``qpos``' dtype.

    Args:
        xp: the backend namespace.
        model: the model.
        qpos: *[..., nq]*.
        qvel: *[..., nv]*.
        ctrl: *[..., nu]* or None.
        qfrc_applied: *[..., nv]* or None.
        qacc_warmstart: *[..., nv]* or None (a cold start: zero, as ``mj_resetData``).

    Returns:
        The data.

    Example:
        >>> make_data(xp, model, model.qpos0, np.zeros(model.nv)).ctrl     # the Hopper's
        array([0., 0., 0.])
    """
    if ctrl is None:
        ctrl = qpos[..., :1] * 0.0 + const(xp, model.fwd.no_ctrl, qpos)
    # distinct zeros (one array in two fields would alias where loops lift them as inputs)
    return Data(
        qpos=qpos,
        qvel=qvel,
        ctrl=ctrl,
        qfrc_applied=qvel * 0.0 if qfrc_applied is None else qfrc_applied,
        qacc_warmstart=qvel * 0.0 if qacc_warmstart is None else qacc_warmstart,
    )


# ----------------------------------------------------------------------------------------------
# The stages of mj_forward
# ----------------------------------------------------------------------------------------------


def fwd_position(xp, model: Model, data: Data) -> Data:
    """Kinematics, ``com_pos``, the mass matrix and its factor, collision and the position
    part of the constraint rows.

    Example:
        >>> fwd_position(xp, model, make_data(xp, model, model.qpos0, np.zeros(6))).qM.shape
        (6, 6)
    """
    kin = kinematics(xp, model, data.qpos)
    com = com_pos(xp, model, kin)
    mass = smooth.mass_matrix(xp, model, com["cinert"], com["cdof"])
    lower, pivots = smooth.ldl_factor(xp, model.smooth.factor, mass)
    contacts = find_contacts(xp, model, kin)
    efc = constraints.make_constraints(xp, model, data.qpos, com["cdof"], com["origin"],
                                       contacts)  # fmt: skip
    fields = {k: v for k, v in kin.items()}
    fields.update(subtree_com=com["subtree_com"], cinert=com["cinert"], cdof=com["cdof"])
    fields.update(qM=mass, qLD=lower, qLDiag=pivots)
    fields.update({k: efc[k] for k in ("efc_J", "efc_pos", "efc_active", "efc_D", "efc_R")})
    if contacts is not None:
        fields.update(
            contact_dist=contacts.dist,
            contact_pos=contacts.pos,
            contact_frame=contacts.frame,
            contact_active=contacts.active,
        )
    else:
        p = model.fwd
        empty = data.qpos[..., :0] * 0.0 + const(xp, p.empty, data.qpos)
        fields.update(
            contact_dist=empty,
            contact_pos=empty[..., None] + const(xp, p.empty_vectors, empty),
            contact_frame=empty[..., None, None] + const(xp, p.empty_frames, empty),
            contact_active=empty > 0.0,
        )
    fields["efc_imp"] = efc["efc_imp"]  # for the reference acceleration of the velocity stage
    return data.replace(**fields)


def find_contacts(xp, model: Model, kin: dict):
    """The model's contacts (:mod:`ivy_robot.physics.collision`), or None without candidates.

    Example:
        >>> lowered = model.qpos0 - np.array([0, 0.05, 0, 0, 0, 0])   # the foot in its floor
        >>> find_contacts(xp, model, kinematics(xp, model, lowered)).active.sum()
        np.int64(2)
    """
    table = model.contacts
    if table is None or int(table.ncon) == 0:
        return None
    from ivy_robot.physics import collision

    return collision.collide(xp, table, kin["geom_xpos"], kin["geom_xmat"])


def fwd_velocity(xp, model: Model, data: Data) -> Data:
    """Body velocities, passive forces, the rows' reference accelerations and bias forces.

    Example:
        >>> fwd_velocity(xp, model, data).qfrc_bias.shape
        (6,)
    """
    cvel, cdof_dot = smooth.velocities(xp, model, data.cdof, data.qvel)
    origin = mt.take(xp, data.subtree_com, model.kin.root, axis=-2)
    kin = {"xipos": data.xipos, "ximat": data.ximat}
    passive = smooth.passive_forces(xp, model, data.qpos, data.qvel, kin, cvel, origin, data.cdof)
    efc = {"efc_J": data.efc_J, "efc_pos": data.efc_pos, "efc_imp": data.efc_imp}
    vel, aref = constraints.reference(xp, model, efc, data.qvel)
    bias = smooth.bias_forces(xp, model, data.cinert, cvel, data.cdof, cdof_dot, data.qvel)
    return data.replace(
        cvel=cvel,
        cdof_dot=cdof_dot,
        qfrc_passive=passive,
        efc_vel=vel,
        efc_aref=aref,
        qfrc_bias=bias,
    )


def fwd_actuation(xp, model: Model, data: Data) -> Data:
    """Actuator forces.

    Example:
        >>> fwd_actuation(xp, model, data.replace(ctrl=np.ones(3))).qfrc_actuator
        array([  0.,   0.,   0., 200., 200., 200.])
    """
    force, qfrc = smooth.actuation(xp, model, data.qpos, data.qvel, data.ctrl)
    return data.replace(actuator_force=force, qfrc_actuator=qfrc)


def fwd_acceleration(xp, model: Model, data: Data) -> Data:
    """``qfrc_smooth = passive - bias + actuator + applied`` and ``qacc_smooth``.

    Example:
        >>> np.allclose(data.qM @ fwd_acceleration(xp, model, data).qacc_smooth, data.qfrc_smooth)
        True
    """
    qfrc = data.qfrc_passive - data.qfrc_bias + data.qfrc_actuator + data.qfrc_applied
    qacc = smooth.ldl_solve(xp, model.smooth.factor, (data.qLD, data.qLDiag), qfrc)
    return data.replace(qfrc_smooth=qfrc, qacc_smooth=qacc)


def fwd_constraint(xp, model: Model, data: Data) -> Data:
    """The constrained accelerations, the rows' forces and ``qfrc_constraint``.

    Example:
        >>> solved = fwd_constraint(xp, model, data)
        >>> np.allclose(solved.qfrc_constraint, solved.efc_force @ solved.efc_J)
        True
    """
    rows = model.rows
    if rows.nefc == 0:
        zero = data.qacc_smooth * 0.0
        return data.replace(
            qacc=data.qacc_smooth, qfrc_constraint=zero, efc_force=data.efc_pos * 0.0
        )
    problem = solver.ConstraintProblem(
        M=data.qM,
        qfrc_smooth=data.qfrc_smooth,
        qacc_smooth=data.qacc_smooth,
        J=data.efc_J,
        D=data.efc_D,
        R=data.efc_R,
        aref=data.efc_aref,
        frictionloss=const(xp, rows.frictionloss, data.efc_D) + 0.0 * data.efc_D,
        active=data.efc_active,
    )
    p = model.fwd
    solution = solver.solve(xp, problem, p.row_kinds, data.qacc_warmstart, p.solver)
    return data.replace(
        qacc=solution.qacc,
        efc_force=solution.efc_force,
        qfrc_constraint=solution.qfrc_constraint,
    )


def compiled(xp, model: Model, key, fn):
    """``fn`` itself, or, on a backend whose eager mode compiles every operation on first use
    (``xp.capabilities.eager_compiles_ops``: jax), ``ivy.compile_fn(fn)`` made once per
    ``key`` and kept with the model: a first eager call of the pipeline then compiles one
    program (seconds) instead of each of its operations (a minute), and its solver's loop is
    not compiled again at every call. Inside a user's compiled function the inner compiled
    function is inlined (jax's nested ``jit``)."""
    capabilities = getattr(xp, "capabilities", None)
    if not getattr(capabilities, "eager_compiles_ops", False):
        return fn
    full_key = (key, xp.__name__)
    if full_key not in model.compiled:
        model.compiled[full_key] = xp.compile_fn(fn)
    return model.compiled[full_key]


def forward(xp, model: Model, data: Data) -> Data:
    """MuJoCo's ``mj_forward``: every stage, in order (see the module docstring).

    Args:
        xp: the backend namespace.
        model: the model (see :func:`~ivy_robot.physics.model.read_model`).
        data: the state and inputs (:func:`make_data`).

    Returns:
        The data with every field of the forward dynamics filled in.

    Example:
        >>> lowered = model.qpos0 - np.array([0, 0.05, 0, 0, 0, 0])   # the foot in its floor
        >>> pressed = forward(xp, model, make_data(xp, model, lowered, np.zeros(6)))
        >>> pressed.qacc.shape, int(pressed.efc_active.sum())   # two contacts' pyramids
        ((6,), 8)
    """
    model.check_dynamics()
    return compiled(xp, model, "forward", lambda d: _forward(xp, model, d))(_unshared(xp, data))


def _forward(xp, model: Model, data: Data) -> Data:
    data = fwd_position(xp, model, data)
    data = fwd_velocity(xp, model, data)
    data = fwd_actuation(xp, model, data)
    data = fwd_acceleration(xp, model, data)
    return fwd_constraint(xp, model, data)


# ----------------------------------------------------------------------------------------------
# After the constraints: external forces on the bodies
# ----------------------------------------------------------------------------------------------


def contact_forces(xp, model: Model, data: Data):
    """Each candidate contact's force in its frame *[..., ncon, 3]* (normal, tangents; MuJoCo's
    ``mj_contactForce``, zero where inactive): a pyramid's normal force is the sum of its edges'
    forces, its tangential forces their differences times the friction.

    Example:
        >>> contact_forces(xp, model, data).shape         # the Hopper's 14 candidate contacts
        (14, 3)
    """
    rows, p = model.rows, model.fwd
    if rows.ncon == 0:
        return data.qpos[..., :0, None] * 0.0 + const(xp, p.empty_forces, data.qpos)
    force = xp.where(data.efc_active, data.efc_force, 0.0)
    parts = []
    if len(rows.pyramids):
        edges = [mt.take(xp, force, g, axis=-1) for g in p.pyramid_edges]
        mu1, mu2 = (const(xp, mu, force) for mu in p.pyramid_mu)
        parts.append(
            xp.stack(
                [
                    edges[0] + edges[1] + edges[2] + edges[3],
                    (edges[0] - edges[1]) * mu1,
                    (edges[2] - edges[3]) * mu2,
                ],
                axis=-1,
            )
        )
    if len(rows.frictionless):
        normal = mt.take(xp, force, p.frictionless_rows, axis=-1)
        parts.append(xp.stack([normal, normal * 0.0, normal * 0.0], axis=-1))
    return mt.take(xp, xp.concat(parts, axis=-2), p.contact_order, axis=-2)


def external_forces(xp, model: Model, data: Data):
    """MuJoCo's ``cfrc_ext`` *[..., nbody, 6]* (``mj_rnePostConstraint``): the contact forces on
    each body, as torque and force about its tree's centre of mass.

    Example:
        >>> external_forces(xp, model, data).shape
        (5, 6)
    """
    zero = data.cinert[..., :6] * 0.0
    rows = model.rows
    if rows.ncon == 0:
        return zero
    local = contact_forces(xp, model, data)  # [..., ncon, 3] in the contact frames
    world = mt.mtv(xp, data.contact_frame, local)  # frame^T f
    origin = mt.take(xp, data.subtree_com, model.kin.root, axis=-2)
    total = zero
    for (bodies, _), scatter in zip(rows.contact_side, model.fwd.force_scatter):
        arm = data.contact_pos - mt.take(xp, origin, bodies, axis=-2)
        wrench = xp.concat([mt.cross(xp, arm, world), world], axis=-1)
        total = total + mt.cmatmul(xp, scatter, wrench)
    return total


# ----------------------------------------------------------------------------------------------
# Integration
# ----------------------------------------------------------------------------------------------


def integrate_positions(xp, model: Model, qpos, qvel, h):
    """MuJoCo's ``mj_integratePos``: ``qpos`` advanced by the velocities ``qvel`` over ``h``;
    quaternions rotate in the body frame and are normalised.

    Example:
        >>> integrate_positions(xp, model, model.qpos0, np.ones(6), 0.5)
        array([0.5 , 1.75, 0.5 , 0.5 , 0.5 , 0.5 ])
    """
    if model.fwd.simple_joints:
        return qpos + h * qvel  # hinges and slides only: qpos and qvel align
    parts, cursor = [], 0
    for kind, adr, dof in model.fwd.position_segments:
        if adr > cursor:
            parts.append(qpos[..., cursor:adr])
        width = JOINT_KINDS[kind].nq
        if kind == FREE:
            parts.append(qpos[..., adr : adr + 3] + h * qvel[..., dof : dof + 3])
        if kind in (FREE, BALL):
            at, rotation = adr + width - 4, dof + JOINT_KINDS[kind].nv - 3
            quat, omega = qpos[..., at : at + 4], qvel[..., rotation : rotation + 3]
            parts.append(_rotate_quaternion(xp, quat, omega, h))
        else:
            parts.append(qpos[..., adr : adr + 1] + h * qvel[..., dof : dof + 1])
        cursor = adr + width
    if cursor < model.nq:
        parts.append(qpos[..., cursor:])
    return xp.concat(parts, axis=-1)


def _rotate_quaternion(xp, quat, omega, h):
    """``normalise(quat) * exp(h omega / 2)``, ``omega`` in the body frame (``[w, x, y, z]``),
    with a series near zero rotation (finite gradients at rest)."""
    half_sq = xp.sum(omega * omega, axis=-1) * (0.25 * h * h)
    cos, sinc = xp.taylor_switch(
        half_sq,
        ((1.0, -1 / 2, 1 / 24, -1 / 720), (1.0, -1 / 6, 1 / 120, -1 / 5040)),
        lambda x: (xp.cos(x), xp.sin(x) / x),
    )
    vector = omega * (0.5 * h * sinc)[..., None]
    quat = quat / xp.safe_norm(quat, axis=-1, keepdims=True)
    w1, v1 = quat[..., :1], quat[..., 1:]
    w2 = cos[..., None]
    w = w1 * w2 - xp.sum(v1 * vector, axis=-1, keepdims=True)
    v = w1 * vector + w2 * v1 + mt.cross(xp, v1, vector)
    return xp.concat([w, v], axis=-1)


def _munthe_kaas(xp, model: Model, velocity, rotation):
    """RK4 stage velocities of ball and free joints as increments of the rotation vector: the
    body angular velocity ``w`` at the rotation ``r`` from the step's start becomes
    ``w + r x w / 2 + r x (r x w) / 12`` (MuJoCo 4's Runge-Kutta-Munthe-Kaas stages)."""
    if not model.fwd.rotations:
        return velocity
    parts, cursor = [], 0
    for first in model.fwd.rotations:
        if first > cursor:
            parts.append(velocity[..., cursor:first])
        w, r = velocity[..., first : first + 3], rotation[..., first : first + 3]
        rw = mt.cross(xp, r, w)
        parts.append(w + 0.5 * rw + mt.cross(xp, r, rw) / 12.0)
        cursor = first + 3
    if cursor < model.nv:
        parts.append(velocity[..., cursor:])
    return xp.concat(parts, axis=-1)


def step(xp, model: Model, data: Data) -> Data:
    """MuJoCo's ``mj_step`` (see the module docstring).

    Args:
        xp: the backend namespace.
        model: the model.
        data: the state and inputs (:func:`make_data`); ``ctrl`` and ``qfrc_applied`` are held
            over the step.

    Returns:
        The data after one ``timestep``: the new ``qpos``, ``qvel`` and ``qacc_warmstart``, the
        forward dynamics of the last evaluation, and ``cfrc_ext``.

    Example:
        >>> after = step(xp, model, make_data(xp, model, model.qpos0, np.zeros(6)))
        >>> after.qpos.shape, after.qacc_warmstart.shape
        ((6,), (6,))
    """
    model.check_dynamics()
    return compiled(xp, model, "step", lambda d: _step(xp, model, d))(_unshared(xp, data))


def _unshared(xp, data: Data) -> Data:
    """The data with each field in memory of its own, on backends whose arrays can share it
    (``mutable_arrays``): torch's loop operators, which keep the RK4 stages and the solver's
    iterations as loops under ``torch.compile``, refuse two captured tensors that share memory,
    as the slices of one state vector (``qpos``, ``qvel``) do. Elsewhere (no compiler, or
    arrays that never share memory) the data itself."""
    capabilities = getattr(xp, "capabilities", None)
    if not (getattr(capabilities, "mutable_arrays", False) and capabilities.compilation):
        return data
    fields = data.fields().items()
    return data.replace(**{k: xp.asarray(v, copy=True) for k, v in fields if v is not None})


def _step(xp, model: Model, data: Data) -> Data:
    if model.integrator == "Euler":
        data = _forward(xp, model, data)
        qacc = _euler_acceleration(xp, model, data)
        qvel = data.qvel + model.timestep * qacc
        qpos = integrate_positions(xp, model, data.qpos, qvel, model.timestep)
        new = data.replace(qpos=qpos, qvel=qvel, qacc_warmstart=data.qacc)
    else:
        new = _runge_kutta(xp, model, data)
    return new.replace(cfrc_ext=external_forces(xp, model, new))


def _euler_acceleration(xp, model: Model, data: Data):
    """The acceleration of Euler's velocity update: with dof damping (and ``eulerdamp`` on),
    ``(M + h diag(damping))^-1 (qfrc_smooth + qfrc_constraint)``, else ``qacc``."""
    if not model.fwd.euler_damping:
        return data.qacc
    plan = model.smooth.factor
    implicit = smooth.ldl_factor(xp, plan, data.qM + const(xp, model.fwd.euler_diagonal, data.qM))
    return smooth.ldl_solve(xp, plan, implicit, data.qfrc_smooth + data.qfrc_constraint)


def _runge_kutta(xp, model: Model, data: Data) -> Data:
    h = model.timestep
    qpos0, qvel0 = data.qpos, data.qvel
    like = qvel0
    fractions = const(xp, RK4_FRACTIONS, like)
    weights = const(xp, RK4_WEIGHTS, like)

    def stage(carry, x):
        velocity, acceleration, mean_vel, mean_acc = carry
        fraction, weight = x
        qpos = integrate_positions(xp, model, qpos0, fraction * velocity, h)
        qvel = qvel0 + (h * fraction) * acceleration
        evaluated = _forward(xp, model, data.replace(qpos=qpos, qvel=qvel))
        corrected = _munthe_kaas(xp, model, qvel, (h * fraction) * velocity)
        carry = (
            corrected,
            evaluated.qacc,
            mean_vel + weight * corrected,
            mean_acc + weight * evaluated.qacc,
        )
        return carry, _loop_fields(evaluated)

    zero = qvel0 * 0.0
    (_, last_acc, mean_vel, mean_acc), stages = xp.scan(
        stage, (zero, zero, zero, zero), (fractions, weights), pure=True
    )
    last = Data(**{k: v[-1] for k, v in stages.items()})
    qpos = integrate_positions(xp, model, qpos0, mean_vel, h)
    qvel = qvel0 + h * mean_acc
    return last.replace(
        qpos=qpos,
        qvel=qvel,
        ctrl=data.ctrl,
        qfrc_applied=data.qfrc_applied,
        qacc_warmstart=last_acc,
    )


_INPUTS = ("ctrl", "qfrc_applied", "qacc_warmstart")


def _loop_fields(data: Data) -> dict:
    """The fields of an RK4 stage's data that leave the loop: every array the stage computed
    (not the inputs it passes through, which loops must not return as they came)."""
    return {k: v for k, v in data.fields().items() if v is not None and k not in _INPUTS}
