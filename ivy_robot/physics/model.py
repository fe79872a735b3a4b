"""The model: a compiled MuJoCo model read once into named numpy constants.

:func:`read_model` turns a ``mujoco.MjModel`` into a frozen :class:`Model`: sizes and options as
Python values, per-body, per-joint, per-dof, per-geom, per-site and per-actuator fields as
float64 or integer numpy arrays under MuJoCo's own names (``body_pos``, ``jnt_axis``,
``dof_armature``...), and the static structure the kernels need (the tree's levels, chain and
subtree masks). Kernels bring an array into their dtype and device with :func:`const` and read
Python values directly; nothing of MuJoCo is called after the model is read.

Joints are described by one table, :data:`JOINT_KINDS`: per kind, the width of its ``qpos`` and
``qvel`` and which of its dofs rotate. The kinematics (:mod:`ivy_robot.physics.kinematics`) and
the position integration (:mod:`ivy_robot.physics.pipeline`) read it.

What MuJoCo's ``mj_forward`` would compute and the pipeline does not model is listed in
``Model.unsupported`` when the model is read, and refused by name on first use of the dynamics
(:meth:`Model.check_dynamics`); kinematics work on every model.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from typing import Any, NamedTuple

import numpy as np

from ivy_robot.mjcf import mujoco_quaternion_to_rot_mat

__all__ = ["JOINT_KINDS", "JointKind", "Model", "read_model"]

FREE, BALL, SLIDE, HINGE = 0, 1, 2, 3  # mjtJoint
MIN_VALUE = 1e-15  # mjMINVAL
MIN_IMPEDANCE, MAX_IMPEDANCE = 0.0001, 0.9999  # mjMINIMP, mjMAXIMP


class JointKind(NamedTuple):
    """One row of the joint-kind table (:data:`JOINT_KINDS`).

    Example:
        >>> JOINT_KINDS[0]
        JointKind(name='free', nq=7, nv=6, rotational=(0.0, 0.0, 0.0, 1.0, 1.0, 1.0))
    """

    name: str
    nq: int  # width of its qpos
    nv: int  # width of its qvel (dofs)
    rotational: tuple  # per dof: 1.0 if it rotates, 0.0 if it translates


#: The joint kinds, by MuJoCo's ``mjtJoint`` value. Free and ball rotations are quaternions
#: ``[w, x, y, z]`` in qpos and body-frame angular velocities in qvel.
JOINT_KINDS = {
    FREE: JointKind("free", 7, 6, (0.0, 0.0, 0.0, 1.0, 1.0, 1.0)),
    BALL: JointKind("ball", 4, 3, (1.0, 1.0, 1.0)),
    SLIDE: JointKind("slide", 1, 1, (0.0,)),
    HINGE: JointKind("hinge", 1, 1, (1.0,)),
}

# efc row kinds (the solver's), in MuJoCo's efc order: friction loss, limits, contacts
ROW_FRICTION, ROW_LIMIT, ROW_CONTACT_FRICTIONLESS, ROW_CONTACT_PYRAMIDAL = 1, 3, 5, 6


def const(xp, value: np.ndarray, like):
    """The model constant ``value`` as an array of ``like``'s framework, dtype and device."""
    return xp.constant(value, dtype=like.dtype, device=xp.dev(like))


@dataclass(frozen=True, eq=False)
class Model:
    """A MuJoCo model as named constants (see the module docstring). Fields follow MuJoCo's
    names; rotations are 3x3 matrices (``*_rot``) rather than quaternions.

    Example:
        >>> model.body_names, model.body_mass.round(2)          # Gymnasium's Hopper
        (('world', 'torso', 'thigh', 'leg', 'foot'), array([0.  , 3.67, 4.06, 2.78, 5.32]))
    """

    # sizes
    nq: int
    nv: int
    nu: int
    nbody: int
    njnt: int
    ngeom: int
    nsite: int
    # options
    timestep: float
    integrator: str  # "Euler" or "RK4"
    gravity: np.ndarray
    wind: np.ndarray
    density: float
    viscosity: float
    solver: str  # "Newton" or "PGS"
    iterations: int
    tolerance: float
    ls_iterations: int
    ls_tolerance: float
    impratio: float
    meaninertia: float
    disabled: frozenset  # MuJoCo's disable flags that are set, by name ("contact", "limit"...)
    # names
    body_names: tuple
    joint_names: tuple
    geom_names: tuple
    site_names: tuple
    actuator_names: tuple
    # bodies
    body_parent: np.ndarray
    body_rootid: np.ndarray
    body_weldid: np.ndarray
    body_pos: np.ndarray
    body_rot: np.ndarray
    body_ipos: np.ndarray
    body_irot: np.ndarray
    body_mass: np.ndarray
    body_inertia: np.ndarray
    body_subtreemass: np.ndarray
    body_invweight0: np.ndarray  # [nbody, 2]: translation, rotation
    body_moving: np.ndarray  # bool: has a dof in its chain
    # joints
    jnt_type: np.ndarray
    jnt_body: np.ndarray
    jnt_qposadr: np.ndarray
    jnt_dofadr: np.ndarray
    jnt_axis: np.ndarray
    jnt_pos: np.ndarray
    jnt_limited: np.ndarray
    jnt_range: np.ndarray
    jnt_margin: np.ndarray
    jnt_solref: np.ndarray
    jnt_solimp: np.ndarray
    jnt_stiffness: np.ndarray
    qpos0: np.ndarray
    qpos_spring: np.ndarray
    # dofs
    dof_body: np.ndarray
    dof_jnt: np.ndarray
    dof_parent: np.ndarray
    dof_armature: np.ndarray
    dof_damping: np.ndarray
    dof_frictionloss: np.ndarray
    dof_solref: np.ndarray
    dof_solimp: np.ndarray
    dof_invweight0: np.ndarray
    # geoms and sites
    geom_type: np.ndarray
    geom_body: np.ndarray
    geom_size: np.ndarray
    geom_pos: np.ndarray
    geom_rot: np.ndarray
    geom_rbound: np.ndarray
    site_body: np.ndarray
    site_pos: np.ndarray
    site_rot: np.ndarray
    # actuators (joint transmissions, no activation)
    actuator_dof: np.ndarray
    actuator_qadr: np.ndarray
    actuator_gear: np.ndarray
    actuator_ctrlrange: np.ndarray  # [nu, 2], +-inf where unlimited (or clamping disabled)
    actuator_forcerange: np.ndarray  # [nu, 2], +-inf where unlimited
    actuator_gain: np.ndarray  # [nu, 3]: gain = g0 + g1 * length + g2 * velocity
    actuator_bias: np.ndarray  # [nu, 3]: bias = b0 + b1 * length + b2 * velocity
    jnt_actfrcrange: np.ndarray  # [njnt, 2], +-inf where unlimited
    # structure, derived once
    body_chain: np.ndarray  # [nbody, nv]: 1 where the dof moves the body
    body_subtree: np.ndarray  # [nbody, nbody]: 1 where the column body is in the row's subtree
    com_weights: np.ndarray  # [nbody, nbody]: subtree_com[b] = sum_c w[b, c] xipos[c]
    dof_ancestors: np.ndarray  # [nv, nv]: 1 where the column dof is the row's or above it
    dof_velocity_before: np.ndarray  # [nv, nv]: the dofs whose velocity a dof's axis moves with
    dof_rotational: np.ndarray  # [nv]
    fluid_bodies: tuple  # bodies under the inertia-box fluid model
    contacts: Any  # the candidate contacts (ivy_robot.physics.collision), or None
    unsupported: tuple  # names of what the dynamics do not model (empty: all modelled)
    # what each stage precomputes once (index arrays, masks, flags): their modules' plans
    kin: Any = None  # ivy_robot.physics.kinematics.Plan
    smooth: Any = None  # ivy_robot.physics.smooth.Plan
    rows: Any = None  # ivy_robot.physics.constraints.Layout
    fwd: Any = None  # ivy_robot.physics.pipeline.Plan
    #: compiled kernels, made on first use where the backend's eager mode compiles op by op
    #: (:func:`ivy_robot.physics.pipeline.compiled`)
    compiled: dict = field(default_factory=dict, repr=False)

    def check_dynamics(self) -> None:
        """Raise ``NotImplementedError`` naming what the model uses and the dynamics do not
        model (see :data:`Model.unsupported`).

        Example:
            >>> model.check_dynamics()      # the Hopper: everything modelled
        """
        if self.unsupported:
            listed = "; ".join(self.unsupported)
            raise NotImplementedError(
                f"ivy_robot physics: the model uses {listed}, which the pipeline does not model "
                "(docs/ivy_robot_dynamics.md, 'Scope'); remove it from the MJCF or simulate this "
                "model with MuJoCo itself"
            )

    def replace(self, **changes: Any) -> Model:
        """A copy with some fields changed.

        Example:
            >>> model.replace(timestep=0.001).timestep
            0.001
        """
        return dataclasses.replace(self, **changes)


def _flags(m, mujoco, enum, prefix: str, value: int) -> frozenset:
    return frozenset(
        name[len(prefix) :].lower()
        for name in dir(enum)
        if name.startswith(prefix) and int(getattr(enum, name)) & int(value)
    )


def read_model(m: Any) -> Model:
    """Read a compiled ``mujoco.MjModel`` into a :class:`Model` (see the module docstring).

    Args:
        m: the compiled MuJoCo model.

    Returns:
        The model.

    Example:
        >>> model = read_model(mujoco.MjModel.from_xml_path(hopper_xml))   # Gymnasium's Hopper
        >>> model.nq, model.integrator, model.solver, model.unsupported
        (6, 'RK4', 'Newton', ())
    """
    import mujoco

    disabled = _flags(m, mujoco, mujoco.mjtDisableBit, "mjDSBL_", m.opt.disableflags)
    enabled = _flags(m, mujoco, mujoco.mjtEnableBit, "mjENBL_", m.opt.enableflags)
    f64 = lambda x: np.array(x, dtype=np.float64)  # noqa: E731 (a copy)
    i64 = lambda x: np.array(x, dtype=np.int64)  # noqa: E731
    name = lambda obj, i: obj(i).name  # noqa: E731
    jnt_type = i64(m.jnt_type)
    body_parent = i64(m.body_parentid)
    moving = np.zeros(m.nbody, dtype=bool)
    for b in range(1, m.nbody):
        moving[b] = m.body_jntnum[b] > 0 or moving[body_parent[b]]

    no_spring, no_damper = "spring" in disabled, "damper" in disabled
    clamp = "clampctrl" not in disabled
    gain = f64(m.actuator_gainprm[:, :3]) if m.nu else np.zeros((0, 3))
    bias = f64(m.actuator_biasprm[:, :3]) if m.nu else np.zeros((0, 3))
    if m.nu:
        gain[np.asarray(m.actuator_gaintype) == 0, 1:] = 0.0  # fixed gain
        bias[np.asarray(m.actuator_biastype) == 0] = 0.0  # no bias
    act_joint = np.asarray(m.actuator_trnid[:, 0], dtype=np.int64) if m.nu else np.zeros(0, int)
    act_joint = np.clip(act_joint, 0, max(m.njnt - 1, 0))
    inf = np.inf

    def ranges(limited, values, n, enabled_flag=True):
        out = np.tile([-inf, inf], (n, 1))
        for i in range(n):
            if enabled_flag and limited[i]:
                out[i] = values[i]
        return out

    fluid = m.opt.viscosity > 0 or m.opt.density > 0
    structure = _structure(m, jnt_type, body_parent)
    contacts = _contacts(m, disabled)
    model = Model(
        nq=int(m.nq),
        nv=int(m.nv),
        nu=int(m.nu),
        nbody=int(m.nbody),
        njnt=int(m.njnt),
        ngeom=int(m.ngeom),
        nsite=int(m.nsite),
        timestep=float(m.opt.timestep),
        integrator={0: "Euler", 1: "RK4"}.get(int(m.opt.integrator), "implicit"),
        gravity=np.zeros(3) if "gravity" in disabled else f64(m.opt.gravity),
        wind=f64(m.opt.wind),
        density=float(m.opt.density),
        viscosity=float(m.opt.viscosity),
        solver={0: "PGS", 1: "CG", 2: "Newton"}[int(m.opt.solver)],
        iterations=int(m.opt.iterations),
        tolerance=float(m.opt.tolerance),
        ls_iterations=int(m.opt.ls_iterations),
        ls_tolerance=float(m.opt.ls_tolerance),
        impratio=float(m.opt.impratio),
        meaninertia=float(m.stat.meaninertia),
        disabled=disabled,
        body_names=tuple(name(m.body, i) for i in range(m.nbody)),
        joint_names=tuple(name(m.joint, i) for i in range(m.njnt)),
        geom_names=tuple(name(m.geom, i) for i in range(m.ngeom)),
        site_names=tuple(name(m.site, i) for i in range(m.nsite)),
        actuator_names=tuple(name(m.actuator, i) for i in range(m.nu)),
        body_parent=body_parent,
        body_rootid=i64(m.body_rootid),
        body_weldid=i64(m.body_weldid),
        body_pos=f64(m.body_pos),
        body_rot=mujoco_quaternion_to_rot_mat(np.asarray(m.body_quat)),
        body_ipos=f64(m.body_ipos),
        body_irot=mujoco_quaternion_to_rot_mat(np.asarray(m.body_iquat)),
        body_mass=f64(m.body_mass),
        body_inertia=f64(m.body_inertia),
        body_subtreemass=f64(m.body_subtreemass),
        body_invweight0=f64(m.body_invweight0).reshape(-1, 2),
        body_moving=moving,
        jnt_type=jnt_type,
        jnt_body=i64(m.jnt_bodyid),
        jnt_qposadr=i64(m.jnt_qposadr),
        jnt_dofadr=i64(m.jnt_dofadr),
        jnt_axis=f64(m.jnt_axis).reshape(-1, 3),
        jnt_pos=f64(m.jnt_pos).reshape(-1, 3),
        jnt_limited=np.array(m.jnt_limited, dtype=bool),
        jnt_range=f64(m.jnt_range).reshape(-1, 2),
        jnt_margin=f64(m.jnt_margin),
        jnt_solref=f64(m.jnt_solref).reshape(-1, 2),
        jnt_solimp=f64(m.jnt_solimp).reshape(-1, 5),
        jnt_stiffness=np.zeros(m.njnt) if no_spring else f64(m.jnt_stiffness),
        qpos0=f64(m.qpos0),
        qpos_spring=f64(m.qpos_spring),
        dof_body=i64(m.dof_bodyid),
        dof_jnt=i64(m.dof_jntid),
        dof_parent=i64(m.dof_parentid),
        dof_armature=f64(m.dof_armature),
        dof_damping=np.zeros(m.nv) if no_damper else f64(m.dof_damping),
        dof_frictionloss=np.zeros(m.nv) if "frictionloss" in disabled else f64(m.dof_frictionloss),
        dof_solref=f64(m.dof_solref).reshape(-1, 2),
        dof_solimp=f64(m.dof_solimp).reshape(-1, 5),
        dof_invweight0=f64(m.dof_invweight0),
        geom_type=i64(m.geom_type),
        geom_body=i64(m.geom_bodyid),
        geom_size=f64(m.geom_size).reshape(-1, 3),
        geom_pos=f64(m.geom_pos).reshape(-1, 3),
        geom_rot=mujoco_quaternion_to_rot_mat(np.asarray(m.geom_quat).reshape(-1, 4)),
        geom_rbound=f64(m.geom_rbound),
        site_body=i64(m.site_bodyid),
        site_pos=f64(m.site_pos).reshape(-1, 3),
        site_rot=mujoco_quaternion_to_rot_mat(np.asarray(m.site_quat).reshape(-1, 4)),
        actuator_dof=i64(m.jnt_dofadr[act_joint]) if m.nu else np.zeros(0, np.int64),
        actuator_qadr=i64(m.jnt_qposadr[act_joint]) if m.nu else np.zeros(0, np.int64),
        actuator_gear=f64(m.actuator_gear[:, 0]) if m.nu else np.zeros(0),
        actuator_ctrlrange=ranges(m.actuator_ctrllimited, m.actuator_ctrlrange, m.nu, clamp),
        actuator_forcerange=ranges(m.actuator_forcelimited, m.actuator_forcerange, m.nu),
        actuator_gain=gain,
        actuator_bias=bias,
        jnt_actfrcrange=ranges(m.jnt_actfrclimited, m.jnt_actfrcrange, m.njnt),
        fluid_bodies=tuple(
            b for b in range(1, m.nbody) if fluid and moving[b] and m.body_mass[b] >= MIN_VALUE
        ),
        contacts=None if isinstance(contacts, NotImplementedError) else contacts,
        unsupported=_unsupported(m, mujoco, disabled, enabled, contacts),
        **structure,
    )
    # (by module path: the package exports a function named kinematics)
    from ivy_robot.physics.constraints import plan as rows_plan
    from ivy_robot.physics.kinematics import plan as kinematics_plan
    from ivy_robot.physics.pipeline import plan as pipeline_plan
    from ivy_robot.physics.smooth import plan as smooth_plan

    model = model.replace(kin=kinematics_plan(m, model), smooth=smooth_plan(model))
    model = model.replace(rows=rows_plan(model))
    return model.replace(fwd=pipeline_plan(model))


def _contacts(m, disabled):
    """The candidate contacts (ivy_robot.physics.collision), or what refuses them."""
    try:
        from ivy_robot.physics import collision
    except ImportError:  # pragma: no cover - during the rewrite
        return None
    try:
        return collision.read_contact_table(m)
    except NotImplementedError as error:
        return error


# ----------------------------------------------------------------------------------------------
# Structure
# ----------------------------------------------------------------------------------------------


def _structure(m, jnt_type, body_parent) -> dict:
    """The masks of the tree that the vectorised kernels multiply with."""
    nbody, nv, njnt = int(m.nbody), int(m.nv), int(m.njnt)
    # chains and subtrees
    body_chain = np.zeros((nbody, nv))
    for b in range(1, nbody):
        body_chain[b] = body_chain[body_parent[b]]
        start, count = int(m.body_dofadr[b]), int(m.body_dofnum[b])
        if count > 0:
            body_chain[b, start : start + count] = 1.0
    body_subtree = np.zeros((nbody, nbody))
    for c in range(nbody):
        b = c
        while True:
            body_subtree[b, c] = 1.0
            if b == 0:
                break
            b = body_parent[b]
    mass = np.asarray(m.body_mass, dtype=np.float64)
    subtree_mass = np.asarray(m.body_subtreemass, dtype=np.float64)
    com_weights = np.zeros((nbody, nbody))
    for b in range(nbody):
        if subtree_mass[b] < MIN_VALUE:
            com_weights[b, b] = 1.0
        else:
            com_weights[b] = body_subtree[b] * mass / subtree_mass[b]

    dof_parent = np.asarray(m.dof_parentid, dtype=np.int64)
    dof_jnt = np.asarray(m.dof_jntid, dtype=np.int64)
    ancestors = np.zeros((nv, nv))
    rotational = np.zeros(nv)
    for j in range(njnt):
        kind = JOINT_KINDS[int(jnt_type[j])]
        start = int(m.jnt_dofadr[j])
        rotational[start : start + kind.nv] = kind.rotational
    for d in range(nv):
        p = d
        while p >= 0:
            ancestors[d, p] = 1.0
            p = dof_parent[p]
    # a dof's axis moves with the velocity of the frame before it: its strict ancestors, where
    # the three rotations of a ball (or free) joint all move with the frame before the first
    before = ancestors - np.eye(nv)
    for d in range(nv):
        kind = int(jnt_type[dof_jnt[d]])
        if kind in (BALL, FREE) and rotational[d]:
            start = int(m.jnt_dofadr[dof_jnt[d]])
            first_rotation = start + (3 if kind == FREE else 0)
            before[d, first_rotation:d] = 0.0
    return dict(
        body_chain=body_chain,
        body_subtree=body_subtree,
        com_weights=com_weights,
        dof_ancestors=ancestors,
        dof_velocity_before=before,
        dof_rotational=rotational,
    )


# ----------------------------------------------------------------------------------------------
# What the dynamics do not model
# ----------------------------------------------------------------------------------------------


def _unsupported(m, mujoco, disabled, enabled, contacts) -> tuple:
    """Names of the features the model uses that the pipeline does not model."""
    out = []
    nonzero = lambda x: bool(np.any(np.asarray(x) != 0))  # noqa: E731
    if int(m.opt.integrator) not in (0, 1):
        out.append(f"the integrator {mujoco.mjtIntegrator(int(m.opt.integrator)).name} (use "
                   "Euler or RK4)")  # fmt: skip
    if int(m.opt.solver) not in (0, 2):
        out.append("the CG solver (use Newton or PGS)")
    if int(m.opt.cone) != 0:
        out.append("elliptic friction cones (use cone='pyramidal')")
    if int(m.opt.noslip_iterations) > 0:
        out.append("the noslip solver (noslip_iterations > 0)")
    for flag in ("override", "sleep", "diagexact", "ipc", "speculative"):
        if flag in enabled:
            out.append(f"the enable flag '{flag}'")
    if int(getattr(m.opt, "disableactuator", 0)):
        out.append("disabled actuator groups (actuatorgroupdisable)")
    if m.neq and "equality" not in disabled and "constraint" not in disabled:
        out.append("equality constraints")
    if m.nflex:
        out.append("flexes")
    if m.nplugin:
        out.append("plugins")
    if nonzero(m.body_gravcomp):
        out.append("gravity compensation (body gravcomp)")
    if m.ngeom and nonzero(m.geom_fluid[:, 0]):
        out.append("geoms with fluidshape='ellipsoid'")
    if nonzero(m.dof_dampingpoly):
        out.append("polynomial joint damping (dampingpoly)")
    if nonzero(m.jnt_stiffnesspoly):
        out.append("polynomial joint stiffness (stiffnesspoly)")
    if hasattr(m, "jnt_springyield") and nonzero(m.jnt_springyield):
        out.append("joint springs with yield (springyield)")
    for j in range(m.njnt):
        kind = int(m.jnt_type[j])
        if kind in (FREE, BALL) and m.jnt_stiffness[j] != 0 and "spring" not in disabled:
            out.append(f"a spring on the {JOINT_KINDS[kind].name} joint {m.joint(j).name!r}")
        if kind == BALL and m.jnt_limited[j]:
            out.append(f"a limited ball joint {m.joint(j).name!r}")
    if m.ntendon:
        for field, what in (
            ("tendon_stiffness", "tendon stiffness"),
            ("tendon_damping", "tendon damping"),
            ("tendon_frictionloss", "tendon friction loss"),
            ("tendon_armature", "tendon armature"),
            ("tendon_limited", "tendon limits"),
            ("tendon_dampingpoly", "polynomial tendon damping"),
            ("tendon_stiffnesspoly", "polynomial tendon stiffness"),
        ):
            if hasattr(m, field) and nonzero(getattr(m, field)):
                out.append(what)
    for a in range(m.nu):
        label = repr(m.actuator(a).name or str(a))
        if int(m.actuator_trntype[a]) != int(mujoco.mjtTrn.mjTRN_JOINT):
            out.append(f"actuator {label} with a transmission other than a joint")
        elif m.jnt_type[m.actuator_trnid[a, 0]] not in (SLIDE, HINGE):
            out.append(f"actuator {label} on a ball or free joint")
        if int(m.actuator_dyntype[a]) != int(mujoco.mjtDyn.mjDYN_NONE):
            out.append(f"actuator {label} with activation dynamics")
        if int(m.actuator_gaintype[a]) not in (0, 1):
            out.append(f"actuator {label} with a muscle or user gain")
        if int(m.actuator_biastype[a]) not in (0, 1):
            out.append(f"actuator {label} with a muscle or user bias")
        if hasattr(m, "actuator_damping") and m.actuator_damping[a] != 0:
            out.append(f"actuator {label} with damping")
        if hasattr(m, "actuator_dampingpoly") and nonzero(m.actuator_dampingpoly[a]):
            out.append(f"actuator {label} with polynomial damping")
        if hasattr(m, "actuator_armature") and m.actuator_armature[a] != 0:
            out.append(f"actuator {label} with armature")
        if hasattr(m, "actuator_delay") and m.actuator_delay[a] != 0:
            out.append(f"actuator {label} with a delay")
    if m.nhistory if hasattr(m, "nhistory") else False:
        out.append("control or sensor history buffers (delay)")
    if hasattr(m, "geom_adhesion") and m.ngeom and nonzero(m.geom_adhesion):
        out.append("adhesive geoms")
    if isinstance(contacts, NotImplementedError):
        out.append(str(contacts))
    elif contacts is not None and contacts.ncon:
        dims = sorted({int(d) for d in np.asarray(contacts.condim)} - {1, 3})
        if dims:
            out.append(
                f"contacts with condim {dims} (torsional or rolling friction; give the geoms "
                "condim 1 or 3)"
            )
    return tuple(out)
