"""The dynamic constants of a MuJoCo model (private), read once into Python floats and tuples.

:func:`dynamics_model` reads masses, inertias, inertial frames, joint axes and anchors,
armature, damping, stiffness, spring references, gravity, the timestep, the integrator, the
actuators and the collision geometry from a compiled ``mujoco.MjModel``. Kernels read only the
Python values kept here (no numpy object is touched while a function is traced:
``torch.compile`` breaks its graph on numpy).

What the smooth dynamics of ivy_robot does not model raises a ``NotImplementedError`` that names
the model's feature, when the model is read: tendons with springs, dampers or limits, gravity
compensation, actuators other than joint-driven motors and position-like (affine) actuators
without activation, ellipsoid fluid shapes, springs on ball and free joints, integrators other
than Euler and RK4.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ivy_robot.mjcf import mujoco_quaternion_to_rot_mat

FREE, BALL, SLIDE, HINGE = 0, 1, 2, 3
EULER, RK4 = 0, 1
MIN_VALUE = 1e-15  # MuJoCo's mjMINVAL
_GEOM_PLANE, _GEOM_HFIELD = 0, 1
_GAIN_FIXED, _GAIN_AFFINE = 0, 1  # mjtGain
_BIAS_NONE, _BIAS_AFFINE = 0, 1  # mjtBias


@dataclass(frozen=True)
class JointSpec:
    kind: int
    body: int
    qadr: int
    dadr: int
    axis: tuple
    pos: tuple
    rot: tuple  # 3x3 skew of the axis (hinge), as nested tuples
    rot2: tuple  # its square
    ref: float  # qpos0 of a hinge or slide


@dataclass(frozen=True)
class BodySpec:
    parent: int
    rot: tuple  # 3x3 in the parent frame
    pos: tuple
    joints: tuple  # JointSpec indices
    mass: float
    inertia: tuple  # principal moments
    ipos: tuple  # centre of mass in the body frame
    irot: tuple  # principal axes in the body frame
    moving: bool  # has a dof in its chain


@dataclass(frozen=True)
class DynamicsModel:
    nq: int
    nv: int
    nu: int
    njnt: int
    bodies: tuple  # BodySpec, index 0 is the world
    joints: tuple  # JointSpec
    dof_parent: tuple  # the parent dof of each dof, -1 at a root
    dof_body: tuple
    armature: tuple
    damping: tuple
    stiffness: tuple  # per joint (hinge and slide)
    springref: tuple  # per joint
    gravity: tuple
    timestep: float
    integrator: int
    euler_damping: bool  # Euler integrates dof damping implicitly
    viscosity: float
    density: float
    wind: tuple
    fluid_bodies: tuple  # bodies under the inertia-box fluid model
    # actuators (joint transmission): dof, gear, ctrl range or None, force range or None,
    # gain (g0, g1, g2), bias (b0, b1, b2), joint qpos address
    actuators: tuple
    actuation: bool
    joint_force_limits: tuple  # (dof, lo, hi) for joints with actfrclimited
    # limits: (qadr, lo, hi, margin, joint) of limited hinges and slides
    limits: tuple
    # contacts: candidate geom pairs (g1, g2, margin), per geom (body, pos, rot, rbound, plane)
    contact_pairs: tuple
    geoms: tuple


def _t(values) -> tuple:
    array = np.asarray(values, dtype=np.float64)
    return tuple(map(float, array)) if array.ndim == 1 else tuple(_t(row) for row in array)


def _skew(axis):
    x, y, z = axis
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


def _flag(m, mujoco, name: str) -> bool:
    return bool(int(m.opt.disableflags) & int(getattr(mujoco.mjtDisableBit, name)))


def read_dynamics(m: Any) -> DynamicsModel:
    """Read the dynamic constants of a compiled ``mujoco.MjModel`` (see the module docstring)."""
    import mujoco

    _check_supported(m, mujoco)
    jnt_type = np.asarray(m.jnt_type)
    joints = []
    for j in range(m.njnt):
        axis = np.asarray(m.jnt_axis[j], dtype=np.float64)
        k = _skew(axis)
        kind = int(jnt_type[j])
        joints.append(
            JointSpec(
                kind=kind,
                body=int(m.jnt_bodyid[j]),
                qadr=int(m.jnt_qposadr[j]),
                dadr=int(m.jnt_dofadr[j]),
                axis=_t(axis),
                pos=_t(m.jnt_pos[j]),
                rot=_t(k),
                rot2=_t(k @ k),
                ref=float(m.qpos0[m.jnt_qposadr[j]]) if kind in (SLIDE, HINGE) else 0.0,
            )
        )
    body_rot = mujoco_quaternion_to_rot_mat(np.asarray(m.body_quat))
    body_irot = mujoco_quaternion_to_rot_mat(np.asarray(m.body_iquat))
    moving = [False] * m.nbody
    bodies = []
    for b in range(m.nbody):
        parent = int(m.body_parentid[b])
        start, count = int(m.body_jntadr[b]), int(m.body_jntnum[b])
        moving[b] = b > 0 and (count > 0 or moving[parent])
        bodies.append(
            BodySpec(
                parent=parent,
                rot=_t(body_rot[b]),
                pos=_t(m.body_pos[b]),
                joints=tuple(range(start, start + count)) if count > 0 else (),
                mass=float(m.body_mass[b]),
                inertia=_t(m.body_inertia[b]),
                ipos=_t(m.body_ipos[b]),
                irot=_t(body_irot[b]),
                moving=moving[b],
            )
        )
    fluid = m.opt.viscosity > 0 or m.opt.density > 0
    fluid_bodies = tuple(
        b for b in range(1, m.nbody) if fluid and moving[b] and m.body_mass[b] >= MIN_VALUE
    )
    no_spring, no_damper = _flag(m, mujoco, "mjDSBL_SPRING"), _flag(m, mujoco, "mjDSBL_DAMPER")
    gravity = (0.0, 0.0, 0.0) if _flag(m, mujoco, "mjDSBL_GRAVITY") else _t(m.opt.gravity)
    damping = tuple(0.0 if no_damper else float(x) for x in m.dof_damping)
    stiffness = tuple(0.0 if no_spring else float(x) for x in m.jnt_stiffness)
    springref = tuple(
        float(m.qpos_spring[m.jnt_qposadr[j]]) if jnt_type[j] in (SLIDE, HINGE) else 0.0
        for j in range(m.njnt)
    )
    return DynamicsModel(
        nq=int(m.nq),
        nv=int(m.nv),
        nu=int(m.nu),
        njnt=int(m.njnt),
        bodies=tuple(bodies),
        joints=tuple(joints),
        dof_parent=tuple(int(p) for p in m.dof_parentid),
        dof_body=tuple(int(b) for b in m.dof_bodyid),
        armature=_t(m.dof_armature) if m.nv else (),
        damping=damping,
        stiffness=stiffness,
        springref=springref,
        gravity=gravity,
        timestep=float(m.opt.timestep),
        integrator=int(m.opt.integrator),
        euler_damping=not _flag(m, mujoco, "mjDSBL_EULERDAMP") and any(d > 0 for d in damping),
        viscosity=float(m.opt.viscosity),
        density=float(m.opt.density),
        wind=_t(m.opt.wind),
        fluid_bodies=fluid_bodies,
        actuators=_actuators(m, mujoco),
        actuation=not _flag(m, mujoco, "mjDSBL_ACTUATION"),
        joint_force_limits=tuple(
            (int(m.jnt_dofadr[j]), *map(float, m.jnt_actfrcrange[j]))
            for j in range(m.njnt)
            if m.jnt_actfrclimited[j]
        ),
        limits=_limits(m, mujoco),
        contact_pairs=_contact_pairs(m, mujoco),
        geoms=_geoms(m),
    )


def _check_supported(m, mujoco) -> None:
    def refuse(what: str) -> None:
        raise NotImplementedError(
            f"KinematicTree dynamics: the model has {what}, which ivy_robot's smooth dynamics "
            "does not model (see docs/ivy_robot_dynamics.md, 'Scope')"
        )

    if m.opt.integrator not in (EULER, RK4):
        name = mujoco.mjtIntegrator(int(m.opt.integrator)).name
        refuse(f"the integrator {name}; use Euler or RK4 (<option integrator=.../>)")
    if m.ntendon and (
        np.any(m.tendon_stiffness) or np.any(m.tendon_damping) or np.any(m.tendon_limited)
    ):
        refuse("tendons with stiffness, damping or limits")
    if np.any(m.body_gravcomp):
        refuse("gravity compensation (body gravcomp)")
    if m.ngeom and np.any(m.geom_fluid[:, 0]):
        refuse("geoms with fluidshape='ellipsoid'")
    if m.neq:
        refuse("equality constraints")
    for j in range(m.njnt):
        if m.jnt_type[j] in (FREE, BALL) and m.jnt_stiffness[j] != 0:
            refuse(f"a spring on the ball or free joint {m.joint(j).name!r}")
        if m.jnt_type[j] == BALL and m.jnt_limited[j]:
            refuse(f"a limited ball joint {m.joint(j).name!r}")
    if hasattr(m, "jnt_springyield") and np.any(m.jnt_springyield):
        refuse("joint springs with yield (springyield)")
    for a in range(m.nu):
        name = m.actuator(a).name or str(a)
        if int(m.actuator_trntype[a]) != int(mujoco.mjtTrn.mjTRN_JOINT):
            refuse(f"actuator {name!r} with a transmission other than a joint")
        if m.jnt_type[m.actuator_trnid[a, 0]] not in (SLIDE, HINGE):
            refuse(f"actuator {name!r} on a ball or free joint")
        if int(m.actuator_dyntype[a]) != int(mujoco.mjtDyn.mjDYN_NONE):
            refuse(f"actuator {name!r} with activation dynamics")
        if int(m.actuator_gaintype[a]) not in (_GAIN_FIXED, _GAIN_AFFINE):
            refuse(f"actuator {name!r} with a muscle or user gain")
        if int(m.actuator_biastype[a]) not in (_BIAS_NONE, _BIAS_AFFINE):
            refuse(f"actuator {name!r} with a muscle or user bias")


def _actuators(m, mujoco) -> tuple:
    clamp = not _flag(m, mujoco, "mjDSBL_CLAMPCTRL")
    out = []
    for a in range(m.nu):
        joint = int(m.actuator_trnid[a, 0])
        gain = m.actuator_gainprm[a, :3]
        if int(m.actuator_gaintype[a]) == _GAIN_FIXED:
            gain = (gain[0], 0.0, 0.0)
        bias = m.actuator_biasprm[a, :3]
        if int(m.actuator_biastype[a]) == _BIAS_NONE:
            bias = (0.0, 0.0, 0.0)
        ctrl = _t(m.actuator_ctrlrange[a]) if clamp and m.actuator_ctrllimited[a] else None
        force = _t(m.actuator_forcerange[a]) if m.actuator_forcelimited[a] else None
        out.append(
            (
                int(m.jnt_dofadr[joint]),
                float(m.actuator_gear[a, 0]),
                ctrl,
                force,
                _t(gain),
                _t(bias),
                int(m.jnt_qposadr[joint]),
            )
        )
    return tuple(out)


def _limits(m, mujoco) -> tuple:
    if _flag(m, mujoco, "mjDSBL_LIMIT") or _flag(m, mujoco, "mjDSBL_CONSTRAINT"):
        return ()
    return tuple(
        (int(m.jnt_qposadr[j]), *map(float, m.jnt_range[j]), float(m.jnt_margin[j]), j)
        for j in range(m.njnt)
        if m.jnt_limited[j] and m.jnt_type[j] in (SLIDE, HINGE)
    )


def _geoms(m) -> tuple:
    rots = mujoco_quaternion_to_rot_mat(np.asarray(m.geom_quat).reshape(-1, 4))
    return tuple(
        (
            int(m.geom_bodyid[g]),
            _t(m.geom_pos[g]),
            _t(rots[g]),
            float(m.geom_rbound[g]),
            int(m.geom_type[g]) == _GEOM_PLANE,
        )
        for g in range(m.ngeom)
    )


def _contact_pairs(m, mujoco) -> tuple:
    """Geom pairs that MuJoCo's collision filters let collide (contype/conaffinity, same weld,
    parent filter, excluded bodies) and explicit ``<pair>``s, with their margins."""
    if _flag(m, mujoco, "mjDSBL_CONTACT") or _flag(m, mujoco, "mjDSBL_CONSTRAINT"):
        return ()
    weld = np.asarray(m.body_weldid)
    parent = np.asarray(m.body_parentid)
    filter_parent = not _flag(m, mujoco, "mjDSBL_FILTERPARENT")
    excluded = (
        {
            frozenset((int(b1), int(b2)))
            for b1, b2 in zip(m.exclude_signature >> 16, m.exclude_signature & 0xFFFF)
        }
        if m.nexclude
        else set()
    )
    pairs = []
    for g1 in range(m.ngeom):
        for g2 in range(g1 + 1, m.ngeom):
            b1, b2 = int(m.geom_bodyid[g1]), int(m.geom_bodyid[g2])
            w1, w2 = int(weld[b1]), int(weld[b2])
            if w1 == w2:
                continue
            if (
                filter_parent
                and w1 != 0
                and w2 != 0
                and (int(weld[parent[w1]]) == w2 or int(weld[parent[w2]]) == w1)
            ):
                continue
            if not (
                m.geom_contype[g1] & m.geom_conaffinity[g2]
                or m.geom_contype[g2] & m.geom_conaffinity[g1]
            ):
                continue
            if frozenset((b1, b2)) in excluded:
                continue
            if w1 == 0 and w2 == 0:
                continue  # both static
            _check_collision_shape(m, g1, g2)
            pairs.append((g1, g2, float(max(m.geom_margin[g1], m.geom_margin[g2]))))
    for p in range(m.npair):
        g1, g2 = int(m.pair_geom1[p]), int(m.pair_geom2[p])
        _check_collision_shape(m, g1, g2)
        pairs.append((g1, g2, float(m.pair_margin[p])))
    return tuple(pairs)


def _check_collision_shape(m, g1: int, g2: int) -> None:
    for g in (g1, g2):
        if m.geom_type[g] == _GEOM_HFIELD:
            raise NotImplementedError(
                f"KinematicTree dynamics: geom {m.geom(g).name or g!r} is a height field; the "
                "contact mask bounds geoms by spheres and planes only"
            )
