"""Rigid-body dynamics of MuJoCo kinematic trees, written once for every backend.

:class:`DynamicsMixin` gives :class:`ivy_robot.KinematicTree` the joint-space dynamics of its
model: the mass matrix (composite rigid bodies, with armature), bias forces and inverse dynamics
(recursive Newton-Euler), passive forces (damping, springs, the inertia-box fluid model),
actuator forces (joint motors and affine, position-like actuators), forward dynamics (a sparse
``L^T D L`` factorisation of the mass matrix along the tree) and a step with the model's
integrator (Euler with implicit dof damping, or RK4), as MuJoCo defines each of them.

Spatial quantities are world-frame Plücker vectors about the world origin, as pairs
``(angular, linear)`` of ``[..., 3]`` arrays. Everything is batched over any leading shape, in
the input's dtype, differentiable and compilable. Contacts and joint limits are out of scope:
:meth:`DynamicsMixin.constraint_free` says where a state has none, and the dynamics equal
MuJoCo's (``mj_forward``, ``mj_step``) there.
"""

from __future__ import annotations

from typing import Any

import ivy
import ivy_mechanics as mech
from ivy.typing import Array, Framework
from ivy_robot import _dynamics_model as D

__all__: list[str] = []  # KinematicTree carries these methods; the mixin is not used alone


class DynamicsMixin:
    """Joint-space dynamics of a MuJoCo model, for :class:`ivy_robot.KinematicTree`.

    The dynamic constants are read from the compiled MuJoCo model the tree was built from, once,
    on the first call (:attr:`dynamics_model`). Conventions are MuJoCo's: ``qpos`` *[..., nq]*,
    ``qvel`` and forces *[..., nv]*, ``ctrl`` *[..., nu]*.

    Example:
        >>> tree = KinematicTree.from_mjcf(panda_mjcf())          # or Gymnasium's hopper.xml
        >>> qacc = tree.forward_dynamics(np.zeros(7), np.zeros(7))   # mj_forward's qacc
        >>> qpos, qvel = tree.step(np.zeros(7), np.zeros(7))         # mj_step
        >>> tree.timestep, tree.integrator
        (0.002, 'Euler')
    """

    def __new__(cls, *args: Any, **kwargs: Any):
        # read the dynamic constants from the compiled MuJoCo model when the tree is built, not
        # on first use: a first use inside a traced function (torch.compile) cannot call into
        # MuJoCo. What the dynamics do not model is raised on use, so kinematics still work.
        instance = super().__new__(cls)
        source = args[0] if args else kwargs.get("model")
        try:
            instance.__dict__["_dynamics"] = None if source is None else D.read_dynamics(source)
        except NotImplementedError as error:
            instance.__dict__["_dynamics"] = error
        return instance

    # ------------------------------------------------------------------------------------------
    # Model
    # ------------------------------------------------------------------------------------------

    @property
    def dynamics_model(self) -> D.DynamicsModel:
        """The dynamic constants (Python floats and tuples), read from the MuJoCo model when the
        tree was built."""
        dynamics = self.__dict__.get("_dynamics")
        if isinstance(dynamics, NotImplementedError):
            raise NotImplementedError(str(dynamics))
        if dynamics is None:
            raise ValueError(
                "KinematicTree dynamics: this tree was built without a MuJoCo model; build "
                "it with KinematicTree.from_mjcf(...)"
            )
        return dynamics

    @property
    def nu(self) -> int:
        """The number of actuators (the length of ``ctrl``)."""
        return self.dynamics_model.nu

    @property
    def timestep(self) -> float:
        """The model's timestep (``<option timestep>``)."""
        return self.dynamics_model.timestep

    @property
    def integrator(self) -> str:
        """The model's integrator: ``'Euler'`` or ``'RK4'``."""
        return "RK4" if self.dynamics_model.integrator == D.RK4 else "Euler"

    # ------------------------------------------------------------------------------------------
    # Public functions
    # ------------------------------------------------------------------------------------------

    def mass_matrix(self, qpos: Array, *, f: Framework = None) -> Array:
        """The joint-space inertia matrix with armature (MuJoCo's ``mj_fullM`` of ``qM``).

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            f: framework name or namespace; inferred from ``qpos`` if None.

        Returns:
            *[batch_shape, nv, nv]*, symmetric positive definite.

        Example:
            >>> tree.mass_matrix(np.zeros((5, tree.nq))).shape      # the Panda
            (5, 7, 7)
        """
        xp = ivy.get_framework(qpos, f=f)
        model = self.dynamics_model
        self._check(xp, qpos=qpos)
        frames = _kinematics(xp, model, qpos)
        entries = _mass_entries(xp, model, frames)
        return _dense(xp, model, entries, qpos)

    def bias_forces(self, qpos: Array, qvel: Array, *, f: Framework = None) -> Array:
        """Coriolis, centrifugal and gravity forces (MuJoCo's ``qfrc_bias``).

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            qvel: joint velocities *[batch_shape, nv]*.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            *[batch_shape, nv]*.

        Example:
            >>> tree.bias_forces(np.zeros(7), np.zeros(7)).round(2)   # gravity alone
            array([ 0.  , -3.87,  0.  , -2.89,  0.  ,  1.55,  0.  ])
        """
        xp = ivy.get_framework(qpos, qvel, f=f)
        model = self.dynamics_model
        qpos, qvel = self._check(xp, qpos=qpos, qvel=qvel)
        frames = _kinematics(xp, model, qpos)
        motion = _velocities(xp, model, frames, qvel)
        return _stack(xp, _rnea(xp, model, frames, motion, qvel, None), qpos)

    def passive_forces(self, qpos: Array, qvel: Array, *, f: Framework = None) -> Array:
        """Joint springs, dampers and fluid forces (MuJoCo's ``qfrc_passive``).

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            qvel: joint velocities *[batch_shape, nv]*.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            *[batch_shape, nv]*.

        Example:
            >>> tree.passive_forces(np.zeros(7), np.ones(7))      # the Panda has no damping
            array([0., 0., 0., 0., 0., 0., 0.])
        """
        xp = ivy.get_framework(qpos, qvel, f=f)
        model = self.dynamics_model
        qpos, qvel = self._check(xp, qpos=qpos, qvel=qvel)
        frames = _kinematics(xp, model, qpos)
        motion = _velocities(xp, model, frames, qvel) if model.fluid_bodies else None
        return _stack(xp, _passive(xp, model, frames, motion, qpos, qvel), qpos)

    def actuator_forces(
        self, qpos: Array, qvel: Array, ctrl: Array, *, f: Framework = None
    ) -> Array:
        """Joint forces of the actuators (MuJoCo's ``qfrc_actuator``): ``ctrl`` clamped to the
        control range, ``gain * ctrl + bias`` clamped to the force range, times the gear.

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            qvel: joint velocities *[batch_shape, nv]*.
            ctrl: controls *[batch_shape, nu]* (cast to ``qpos``' dtype).
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            *[batch_shape, nv]*.

        Example:
            >>> tree.actuator_forces(np.zeros(7), np.zeros(7), np.zeros(tree.nu)).shape
            (7,)
        """
        xp = ivy.get_framework(qpos, qvel, f=f)
        model = self.dynamics_model
        qpos, qvel, ctrl = self._check(xp, qpos=qpos, qvel=qvel, ctrl=ctrl)
        return _stack(xp, _actuation(xp, model, qpos, qvel, ctrl), qpos)

    def inverse_dynamics(
        self, qpos: Array, qvel: Array, qacc: Array, *, f: Framework = None
    ) -> Array:
        """The joint forces that give the acceleration ``qacc`` besides the passive forces
        (MuJoCo's ``mj_inverse``: ``qfrc_inverse = M qacc + qfrc_bias - qfrc_passive``).

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            qvel: joint velocities *[batch_shape, nv]*.
            qacc: joint accelerations *[batch_shape, nv]*.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            *[batch_shape, nv]*: the applied plus actuator forces needed.

        Example:
            >>> q, v = np.zeros(7), np.zeros(7)
            >>> tree.inverse_dynamics(q, v, tree.forward_dynamics(q, v)).round(9) + 0.0
            array([0., 0., 0., 0., 0., 0., 0.])
        """
        xp = ivy.get_framework(qpos, qvel, qacc, f=f)
        model = self.dynamics_model
        qpos, qvel, qacc = self._check(xp, qpos=qpos, qvel=qvel, qacc=qacc)
        frames = _kinematics(xp, model, qpos)
        motion = _velocities(xp, model, frames, qvel)
        rnea = _rnea(xp, model, frames, motion, qvel, qacc)
        passive = _passive(xp, model, frames, motion, qpos, qvel)
        out = [
            r + model.armature[i] * qacc[..., i] - p for i, (r, p) in enumerate(zip(rnea, passive))
        ]
        return _stack(xp, out, qpos)

    def forward_dynamics(
        self,
        qpos: Array,
        qvel: Array,
        ctrl: Array | None = None,
        qfrc_applied: Array | None = None,
        *,
        f: Framework = None,
    ) -> Array:
        """Joint accelerations (MuJoCo's ``qacc`` after ``mj_forward``, without constraints):
        ``M^-1 (qfrc_passive - qfrc_bias + qfrc_actuator + qfrc_applied)``.

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            qvel: joint velocities *[batch_shape, nv]*.
            ctrl: controls *[batch_shape, nu]*; zero if None.
            qfrc_applied: further joint forces *[batch_shape, nv]*; zero if None.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            *[batch_shape, nv]*.

        Example:
            >>> tree.forward_dynamics(np.zeros(7), np.zeros(7)).round(1) + 0.0
            array([  0. ,  17. ,   0. ,  37.2,   0. , -44. ,   0. ])
        """
        xp = ivy.get_framework(qpos, qvel, f=f)
        model = self.dynamics_model
        qpos, qvel, ctrl, applied = self._check(
            xp, qpos=qpos, qvel=qvel, ctrl=ctrl, qfrc_applied=qfrc_applied
        )
        return _stack(xp, _accelerations(xp, model, qpos, qvel, ctrl, applied, 0.0), qpos)

    def step(
        self,
        qpos: Array,
        qvel: Array,
        ctrl: Array | None = None,
        qfrc_applied: Array | None = None,
        *,
        f: Framework = None,
    ) -> tuple[Array, Array]:
        """One step of the model's integrator (MuJoCo's ``mj_step`` without constraints).

        Euler: ``qvel += h (M + h diag(damping))^-1 qfrc`` (damping implicit, as MuJoCo does
        unless ``eulerdamp`` is disabled), then ``qpos`` integrated with the new velocity. RK4:
        MuJoCo's four-stage Runge-Kutta on ``(qpos, qvel)``. Quaternions of ball and free joints
        are integrated on the sphere and normalised.

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            qvel: joint velocities *[batch_shape, nv]*.
            ctrl: controls *[batch_shape, nu]*, held over the step; zero if None.
            qfrc_applied: further joint forces *[batch_shape, nv]*; zero if None.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            ``(qpos, qvel)`` after ``timestep`` seconds.

        Example:
            >>> qpos, qvel = tree.step(np.zeros((4, 7)), np.zeros((4, 7)))
            >>> qpos.shape, qvel.shape
            ((4, 7), (4, 7))
        """
        xp = ivy.get_framework(qpos, qvel, f=f)
        model = self.dynamics_model
        qpos, qvel, ctrl, applied = self._check(
            xp, qpos=qpos, qvel=qvel, ctrl=ctrl, qfrc_applied=qfrc_applied
        )
        return _step(xp, model, qpos, qvel, ctrl, applied)

    # ------------------------------------------------------------------------------------------
    # Scope: contacts and joint limits
    # ------------------------------------------------------------------------------------------

    def active_limits(self, qpos: Array, *, f: Framework = None) -> Array:
        """Which limited hinge and slide joints are at (within their margin of) a limit, where
        MuJoCo would add a limit constraint that these dynamics leave out.

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            f: framework name or namespace; inferred from ``qpos`` if None.

        Returns:
            bool *[batch_shape, njnt]* (False for unlimited joints).

        Example:
            >>> tree.active_limits(np.zeros(7))           # the Panda's joint 4 is at its limit
            array([False, False, False,  True, False, False, False])
        """
        xp = ivy.get_framework(qpos, f=f)
        model = self.dynamics_model
        self._check(xp, qpos=qpos)
        false = xp.zeros_like(qpos[..., 0]) > 1.0
        flags = [false] * model.njnt
        for qadr, lo, hi, margin, j in model.limits:
            q = qpos[..., qadr]
            flags[j] = xp.logical_or(q - lo < margin, hi - q < margin)
        if not flags:
            return xp.zeros(tuple(qpos.shape[:-1]) + (0,), dtype="bool", device=xp.dev(qpos))
        return xp.stack(flags, axis=-1)

    def possible_contacts(self, qpos: Array, *, f: Framework = None) -> Array:
        """Whether a state may have a contact: a conservative test on the geom pairs that
        MuJoCo's filters let collide (bounding spheres, planes), True wherever MuJoCo could
        find a contact (and sometimes where it finds none).

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            f: framework name or namespace; inferred from ``qpos`` if None.

        Returns:
            bool *[batch_shape]*.

        Example:
            >>> tree.possible_contacts(np.zeros(7))   # no geom pair of the Panda may collide
            np.False_
        """
        xp = ivy.get_framework(qpos, f=f)
        model = self.dynamics_model
        self._check(xp, qpos=qpos)
        return _possible_contacts(xp, model, _kinematics(xp, model, qpos), qpos)

    def constraint_free(self, qpos: Array, *, f: Framework = None) -> Array:
        """Whether a state is free of contacts and active joint limits, where the dynamics
        here equal MuJoCo's: ``~possible_contacts(qpos) & ~active_limits(qpos).any(-1)``.

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            f: framework name or namespace; inferred from ``qpos`` if None.

        Returns:
            bool *[batch_shape]*.

        Example:
            >>> tree.constraint_free(np.zeros((2, 7)))
            array([False, False])
        """
        xp = ivy.get_framework(qpos, f=f)
        limits = self.active_limits(qpos, f=xp)
        contact = self.possible_contacts(qpos, f=xp)
        if limits.shape[-1]:
            contact = xp.logical_or(contact, xp.any(limits, axis=-1))
        return xp.logical_not(contact)

    # ------------------------------------------------------------------------------------------
    # Checks
    # ------------------------------------------------------------------------------------------

    def _check(self, xp, **arrays):
        """Check shapes and dtypes; cast ``ctrl`` and ``qfrc_applied`` to ``qpos``' dtype.
        Returns the arrays in order (None for an absent optional one)."""
        model = self.dynamics_model
        sizes = {"qpos": model.nq, "qvel": model.nv, "qacc": model.nv, "ctrl": model.nu}
        sizes["qfrc_applied"] = model.nv
        qpos = arrays["qpos"]
        out = []
        for name, x in arrays.items():
            if x is None:
                out.append(None)
                continue
            shape = tuple(x.shape)
            if len(shape) == 0 or shape[-1] != sizes[name]:
                raise ValueError(
                    f"KinematicTree: {name} has shape {shape}; its last axis must have length "
                    f"{sizes[name]} (the model's {name} size), with the leading shape of qpos"
                )
            if name in ("qpos", "qvel", "qacc") and not xp.isdtype(x.dtype, "real floating"):
                raise TypeError(
                    f"KinematicTree: {name} has dtype {x.dtype}; give floating-point arrays "
                    "(float32 or float64)"
                )
            if name != "qpos" and x.dtype != qpos.dtype:
                if name in ("qvel", "qacc"):
                    raise TypeError(
                        f"KinematicTree: {name} has dtype {x.dtype} but qpos has {qpos.dtype}; "
                        "give both the same dtype"
                    )
                x = xp.astype(x, qpos.dtype)
            out.append(x)
        return tuple(out) if len(out) != 1 else out[0]


# ----------------------------------------------------------------------------------------------
# Spatial algebra on (angular, linear) pairs of [..., 3] arrays, about the world origin
# ----------------------------------------------------------------------------------------------


def _cross_motion(xp, v, u):
    return (
        xp.cross(v[0], u[0], axis=-1),
        xp.cross(v[0], u[1], axis=-1) + xp.cross(v[1], u[0], axis=-1),
    )


def _cross_force(xp, v, force):
    return (
        xp.cross(v[0], force[0], axis=-1) + xp.cross(v[1], force[1], axis=-1),
        xp.cross(v[0], force[1], axis=-1),
    )


def _apply_inertia(xp, inertia, v):
    """Momentum of a rigid body (or composite) ``(mass, first moment h = m c, rotational
    inertia J about the origin)`` moving with ``v``: ``(J w + h x v, m v + w x h)``."""
    mass, h, rot_inertia = inertia
    return (
        xp.matvec(rot_inertia, v[0]) + xp.cross(h, v[1], axis=-1),
        mass * v[1] + xp.cross(v[0], h, axis=-1),
    )


def _add(a, b):
    return (a[0] + b[0], a[1] + b[1])


def _scale(a, s):
    return (a[0] * s[..., None], a[1] * s[..., None])


def _dot(a, b, xp):
    return xp.sum(a[0] * b[0], axis=-1) + xp.sum(a[1] * b[1], axis=-1)


# ----------------------------------------------------------------------------------------------
# Kinematics: body frames, centres of mass, inertias and dof motion axes
# ----------------------------------------------------------------------------------------------


class _Frames:
    """Per body: world rotation, position and inertia (mass, h, J about the origin); per dof:
    the motion axis ``(w, v)`` about the origin."""

    def __init__(self):
        self.rot, self.pos, self.inertia, self.com, self.irot = {}, {}, {}, {}, {}
        self.dofs = {}


def _const(xp, values, like):
    return xp.asarray(values, dtype=like.dtype, device=xp.dev(like))


def _kinematics(xp, model: D.DynamicsModel, qpos) -> _Frames:
    frames = _Frames()
    zero = xp.zeros_like(qpos[..., :1])  # [..., 1]: broadcasts constants to the batch
    eye = _const(xp, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], qpos)
    frames.rot[0] = eye + zero[..., None]
    frames.pos[0] = zero + _const(xp, [0.0, 0.0, 0.0], qpos)
    for b in range(1, len(model.bodies)):
        body = model.bodies[b]
        if not body.moving:
            continue
        parent_rot, parent_pos = _static_or(xp, model, frames, body.parent, qpos, zero)
        rot = xp.matmul(parent_rot, _const(xp, body.rot, qpos))
        pos = parent_pos + xp.matvec(parent_rot, _const(xp, body.pos, qpos))
        for j in body.joints:
            rot, pos = _joint(xp, model, frames, j, qpos, rot, pos, zero)
        for j in body.joints:
            _ball_like_axes(xp, model, frames, j, rot, pos)
        frames.rot[b], frames.pos[b] = rot, pos
        com = pos + xp.matvec(rot, _const(xp, body.ipos, qpos))
        irot = xp.matmul(rot, _const(xp, body.irot, qpos))
        scaled = irot * _const(xp, body.inertia, qpos)[..., None, :]
        about_com = xp.matmul(scaled, xp.swapaxes(irot, -1, -2))
        squared = xp.sum(com * com, axis=-1)[..., None, None]
        outer = com[..., :, None] * com[..., None, :]
        about_origin = about_com + body.mass * (squared * eye - outer)
        frames.inertia[b] = (body.mass, body.mass * com, about_origin)
        frames.com[b], frames.irot[b] = com, irot
    return frames


def _static_or(xp, model, frames, b, qpos, zero):
    """The world frame of body ``b``: computed if it moves, else its constant pose."""
    if b in frames.rot:
        return frames.rot[b], frames.pos[b]
    chain = []
    while b != 0:
        chain.append(model.bodies[b])
        b = model.bodies[b].parent
    rot, pos = frames.rot[0], frames.pos[0]
    for body in reversed(chain):
        pos = pos + xp.matvec(rot, _const(xp, body.pos, qpos))
        rot = xp.matmul(rot, _const(xp, body.rot, qpos))
    return rot, pos


def _joint(xp, model, frames, j, qpos, rot, pos, zero):
    """Apply joint ``j`` to the frame ``(rot, pos)``; record its dofs' motion axes."""
    joint = model.joints[j]
    adr, dof = joint.qadr, joint.dadr
    if joint.kind == D.FREE:
        pos = qpos[..., adr : adr + 3]
        rot = _quaternion_rot(xp, qpos[..., adr + 3 : adr + 7])
        for k in range(3):
            axis = [0.0, 0.0, 0.0]
            axis[k] = 1.0
            frames.dofs[dof + k] = (
                zero + _const(xp, [0.0] * 3, qpos),
                zero + _const(xp, axis, qpos),
            )
        return rot, pos
    anchor = pos + xp.matvec(rot, _const(xp, joint.pos, qpos))
    axis = xp.matvec(rot, _const(xp, joint.axis, qpos))
    if joint.kind == D.SLIDE:
        frames.dofs[dof] = (xp.zeros_like(axis), axis)
        shift = qpos[..., adr] - joint.ref if joint.ref != 0.0 else qpos[..., adr]
        return rot, pos + axis * shift[..., None]
    if joint.kind == D.HINGE:
        frames.dofs[dof] = (axis, xp.cross(anchor, axis, axis=-1))
        theta = qpos[..., adr] - joint.ref if joint.ref != 0.0 else qpos[..., adr]
        half = xp.sin(theta * 0.5)
        sin, versine = xp.sin(theta), 2.0 * half * half
        local = (
            _const(xp, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], qpos)
            + sin[..., None, None] * _const(xp, joint.rot, qpos)
            + versine[..., None, None] * _const(xp, joint.rot2, qpos)
        )
    else:  # ball
        frames.dofs[(dof, "anchor")] = anchor
        local = _quaternion_rot(xp, qpos[..., adr : adr + 4])
    rot = xp.matmul(rot, local)
    return rot, anchor - xp.matvec(rot, _const(xp, joint.pos, qpos))


def _ball_like_axes(xp, model, frames, j, rot, pos):
    """Rotational dofs of ball and free joints: the axes of the body's final frame (MuJoCo's
    ``cdof``), about the joint's anchor."""
    joint = model.joints[j]
    if joint.kind == D.FREE:
        first, anchor = joint.dadr + 3, pos
    elif joint.kind == D.BALL:
        first, anchor = joint.dadr, frames.dofs.pop((joint.dadr, "anchor"))
    else:
        return
    for k in range(3):
        w = rot[..., :, k]
        frames.dofs[first + k] = (w, xp.cross(anchor, w, axis=-1))


def _quaternion_rot(xp, quat_wxyz):
    xyzw = xp.concat([quat_wxyz[..., 1:4], quat_wxyz[..., 0:1]], axis=-1)
    return mech.quaternion_to_rot_mat(xyzw, f=xp)


# ----------------------------------------------------------------------------------------------
# Velocities and the recursive Newton-Euler algorithm
# ----------------------------------------------------------------------------------------------


def _velocities(xp, model, frames, qvel):
    """Body velocities and the time derivatives of the dof axes (MuJoCo's ``cvel``,
    ``cdof_dot``): a dof's axis moves with the velocity of the frame before it."""
    zero = frames.pos[0] * 0.0
    velocity = {0: (zero, zero)}
    axis_rate = {}
    for b in range(1, len(model.bodies)):
        body = model.bodies[b]
        if not body.moving:
            continue
        v = velocity.get(body.parent, (zero, zero))
        for j in body.joints:
            joint = model.joints[j]
            dof = joint.dadr
            if joint.kind == D.FREE:
                for k in range(3):
                    axis_rate[dof + k] = None  # world-fixed translation axes
                    v = _add(v, _scale(frames.dofs[dof + k], qvel[..., dof + k]))
                dof += 3
            count = 3 if joint.kind in (D.FREE, D.BALL) else 1
            rates = [_cross_motion(xp, v, frames.dofs[dof + k]) for k in range(count)]
            for k in range(count):
                axis_rate[dof + k] = rates[k]
                v = _add(v, _scale(frames.dofs[dof + k], qvel[..., dof + k]))
        velocity[b] = v
    return velocity, axis_rate


def _rnea(xp, model, frames, motion, qvel, qacc):
    """``qfrc_bias`` (``qacc`` None) or ``qfrc_bias + (M - armature) qacc``, per dof."""
    velocity, axis_rate = motion
    zero = frames.pos[0] * 0.0
    gravity = _const(xp, [-g for g in model.gravity], zero) + zero
    acceleration = {0: (zero, gravity)}
    wrench = {}
    for b in range(1, len(model.bodies)):
        body = model.bodies[b]
        if not body.moving:
            continue
        a = acceleration.get(body.parent, (zero, gravity))
        for dof in _body_dofs(model, b):
            if axis_rate[dof] is not None:
                a = _add(a, _scale(axis_rate[dof], qvel[..., dof]))
            if qacc is not None:
                a = _add(a, _scale(frames.dofs[dof], qacc[..., dof]))
        acceleration[b] = a
        inertia = frames.inertia[b]
        v = velocity[b]
        wrench[b] = _add(
            _apply_inertia(xp, inertia, a),
            _cross_force(xp, v, _apply_inertia(xp, inertia, v)),
        )
    return _project(xp, model, frames, wrench)


def _project(xp, model, frames, wrench):
    """Accumulate body wrenches up the tree and project them on each dof's axis."""
    total = dict(wrench)
    for b in range(len(model.bodies) - 1, 0, -1):
        parent = model.bodies[b].parent
        if b in total and model.bodies[parent].moving:
            total[parent] = _add(total[parent], total[b]) if parent in total else total[b]
    zero = frames.pos[0][..., 0] * 0.0
    return [
        _dot(frames.dofs[i], total[model.dof_body[i]], xp) if model.dof_body[i] in total else zero
        for i in range(model.nv)
    ]


def _body_dofs(model, b):
    dofs = []
    for j in model.bodies[b].joints:
        joint = model.joints[j]
        count = {D.FREE: 6, D.BALL: 3}.get(joint.kind, 1)
        dofs += range(joint.dadr, joint.dadr + count)
    return dofs


# ----------------------------------------------------------------------------------------------
# Mass matrix (composite rigid bodies) and its sparse L^T D L factorisation
# ----------------------------------------------------------------------------------------------


def _ancestors(model, i):
    """The dofs above dof ``i`` in the tree, nearest first."""
    out = []
    p = model.dof_parent[i]
    while p >= 0:
        out.append(p)
        p = model.dof_parent[p]
    return out


def _mass_entries(xp, model, frames):
    """``{(i, j): M[i, j]}`` for each dof ``i`` and ``j`` equal to ``i`` or above it."""
    composite = {b: frames.inertia[b] for b in frames.inertia}
    for b in range(len(model.bodies) - 1, 0, -1):
        parent = model.bodies[b].parent
        if b in composite and parent in composite:
            mine, theirs = composite[b], composite[parent]
            composite[parent] = (
                theirs[0] + mine[0],
                theirs[1] + mine[1],
                theirs[2] + mine[2],
            )
    entries = {}
    for i in range(model.nv):
        force = _apply_inertia(xp, composite[model.dof_body[i]], frames.dofs[i])
        entries[(i, i)] = _dot(frames.dofs[i], force, xp) + model.armature[i]
        for j in _ancestors(model, i):
            entries[(i, j)] = _dot(frames.dofs[j], force, xp)
    return entries


def _dense(xp, model, entries, like):
    zero = like[..., 0] * 0.0
    rows = []
    for i in range(model.nv):
        row = []
        for j in range(model.nv):
            value = entries.get((i, j), entries.get((j, i)))
            row.append(zero if value is None else value + zero)
        rows.append(xp.stack(row, axis=-1))
    return xp.stack(rows, axis=-2)


def _factor(model, entries):
    """MuJoCo's sparse ``M = L^T D L`` (no fill-in along a tree): returns ``(L, D)`` with
    ``L[(i, j)]`` for ``j`` above ``i`` and the diagonal ``D[i]``."""
    work = dict(entries)
    for k in range(model.nv - 1, -1, -1):
        above = _ancestors(model, k)
        for n, i in enumerate(above):
            ratio = work[(k, i)] / work[(k, k)]
            for j in [i] + above[n + 1 :]:
                work[(i, j)] = work[(i, j)] - ratio * work[(k, j)]
            work[(k, i)] = ratio
    lower = {key: value for key, value in work.items() if key[0] != key[1]}
    return lower, [work[(i, i)] for i in range(model.nv)]


def _solve(model, factor, rhs):
    """``M^-1 rhs`` from :func:`_factor`, ``rhs`` a list of per-dof arrays."""
    lower, diagonal = factor
    x = list(rhs)
    for i in range(model.nv - 1, -1, -1):
        for j in _ancestors(model, i):
            x[j] = x[j] - lower[(i, j)] * x[i]
    x = [x[i] / diagonal[i] for i in range(model.nv)]
    for i in range(model.nv):
        for j in _ancestors(model, i):
            x[i] = x[i] - lower[(i, j)] * x[j]
    return x


# ----------------------------------------------------------------------------------------------
# Passive and actuator forces
# ----------------------------------------------------------------------------------------------


def _passive(xp, model, frames, motion, qpos, qvel):
    zero = qpos[..., 0] * 0.0
    out = [zero] * model.nv
    for j, joint in enumerate(model.joints):
        k = model.stiffness[j]
        if k != 0.0 and joint.kind in (D.SLIDE, D.HINGE):
            out[joint.dadr] = out[joint.dadr] - k * (qpos[..., joint.qadr] - model.springref[j])
    for i, damping in enumerate(model.damping):
        if damping != 0.0:
            out[i] = out[i] - damping * qvel[..., i]
    if model.fluid_bodies:
        fluid = _project(xp, model, frames, _fluid_wrenches(xp, model, frames, motion))
        out = [a + b for a, b in zip(out, fluid)]
    return out


def _fluid_wrenches(xp, model, frames, motion):
    """MuJoCo's inertia-box fluid model: viscous (Stokes) and quadratic drag on each body's
    equivalent inertia box, in the body's inertial frame, applied at its centre of mass."""
    velocity = motion[0]
    wrenches = {}
    for b in model.fluid_bodies:
        body = model.bodies[b]
        i0, i1, i2 = body.inertia
        box = [
            (max(D.MIN_VALUE, a + c - d) / body.mass * 6.0) ** 0.5
            for a, c, d in ((i1, i2, i0), (i0, i2, i1), (i0, i1, i2))
        ]
        irot, com = frames.irot[b], frames.com[b]
        w, v_origin = velocity[b]
        v_com = v_origin + xp.cross(w, com, axis=-1)
        local_w = xp.matvec(xp.swapaxes(irot, -1, -2), w)
        local_v = xp.matvec(xp.swapaxes(irot, -1, -2), v_com)
        if any(model.wind):
            wind = _const(xp, model.wind, com)
            local_v = local_v - xp.matvec(xp.swapaxes(irot, -1, -2), wind)
        torque = [xp.zeros_like(local_w[..., 0])] * 3
        force = [xp.zeros_like(local_w[..., 0])] * 3
        if model.viscosity > 0:
            diameter = sum(box) / 3.0
            for k in range(3):
                torque[k] = (
                    torque[k] - 3.141592653589793 * diameter**3 * model.viscosity * local_w[..., k]
                )
                force[k] = (
                    force[k]
                    - 3.0 * 3.141592653589793 * diameter * model.viscosity * local_v[..., k]
                )
        if model.density > 0:
            rho = model.density
            for k in range(3):
                a, c = [box[n] for n in range(3) if n != k]
                vk, wk = local_v[..., k], local_w[..., k]
                force[k] = force[k] - 0.5 * rho * a * c * xp.abs(vk) * vk
                torque[k] = torque[k] - rho * box[k] * (a**4 + c**4) * xp.abs(wk) * wk / 64.0
        world_torque = xp.matvec(irot, xp.stack(torque, axis=-1))
        world_force = xp.matvec(irot, xp.stack(force, axis=-1))
        wrenches[b] = (world_torque + xp.cross(com, world_force, axis=-1), world_force)
    return wrenches


def _actuation(xp, model, qpos, qvel, ctrl):
    zero = qpos[..., 0] * 0.0
    out = [zero] * model.nv
    if ctrl is None or not model.actuation:
        return out
    for a, (dof, gear, ctrl_range, force_range, gain, bias, qadr) in enumerate(model.actuators):
        u = ctrl[..., a]
        if ctrl_range is not None:
            u = xp.clip(u, ctrl_range[0], ctrl_range[1])
        length, speed = gear * qpos[..., qadr], gear * qvel[..., dof]
        force = _affine(gain, length, speed) * u + _affine(bias, length, speed)
        if force_range is not None:
            force = xp.clip(force, force_range[0], force_range[1])
        out[dof] = out[dof] + gear * force
    for dof, lo, hi in model.joint_force_limits:
        out[dof] = xp.clip(out[dof], lo, hi)
    return out


def _affine(prm, length, speed):
    value = prm[0]
    if prm[1] != 0.0:
        value = value + prm[1] * length
    if prm[2] != 0.0:
        value = value + prm[2] * speed
    return value


# ----------------------------------------------------------------------------------------------
# Forward dynamics and integration
# ----------------------------------------------------------------------------------------------


def _accelerations(xp, model, qpos, qvel, ctrl, applied, implicit_damping):
    """``(M + implicit_damping * diag(damping))^-1 qfrc_smooth`` per dof."""
    frames = _kinematics(xp, model, qpos)
    motion = _velocities(xp, model, frames, qvel)
    bias = _rnea(xp, model, frames, motion, qvel, None)
    passive = _passive(xp, model, frames, motion, qpos, qvel)
    actuation = _actuation(xp, model, qpos, qvel, ctrl)
    force = [p - b + u for p, b, u in zip(passive, bias, actuation)]
    if applied is not None:
        force = [x + applied[..., i] for i, x in enumerate(force)]
    entries = _mass_entries(xp, model, frames)
    if implicit_damping:
        for i, damping in enumerate(model.damping):
            entries[(i, i)] = entries[(i, i)] + implicit_damping * damping
    return _solve(model, _factor(model, entries), force)


def _integrate_positions(xp, model, qpos, qvel, h):
    """MuJoCo's ``mj_integratePos``: ``qpos`` advanced by velocities ``qvel`` (per-dof arrays)
    over ``h``, quaternions rotated in the body frame and normalised."""
    parts, cursor = [], 0
    for joint in model.joints:
        adr, dof = joint.qadr, joint.dadr
        if adr > cursor:
            parts.append(qpos[..., cursor:adr])
        if joint.kind in (D.SLIDE, D.HINGE):
            parts.append((qpos[..., adr] + h * qvel[dof])[..., None])
            cursor = adr + 1
            continue
        if joint.kind == D.FREE:
            parts.append(qpos[..., adr : adr + 3] + h * xp.stack(qvel[dof : dof + 3], axis=-1))
            adr, dof = adr + 3, dof + 3
        quat = qpos[..., adr : adr + 4]
        omega = xp.stack(qvel[dof : dof + 3], axis=-1)
        parts.append(_quaternion_integrate(xp, quat, omega, h))
        cursor = adr + 4
    if cursor < model.nq:
        parts.append(qpos[..., cursor:])
    return xp.concat(parts, axis=-1)


def _quaternion_integrate(xp, quat, omega, h):
    """``normalise(quat) * exp(h omega / 2)``, ``omega`` in the body frame (``[w, x, y, z]``)."""
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
    v = w1 * vector + w2 * v1 + xp.cross(v1, vector, axis=-1)
    return xp.concat([w, v], axis=-1)


def _step(xp, model, qpos, qvel, ctrl, applied):
    h = model.timestep
    velocities = [qvel[..., i] for i in range(model.nv)]
    if model.integrator == D.EULER:
        damping = h if model.euler_damping else 0.0
        qacc = _accelerations(xp, model, qpos, qvel, ctrl, applied, damping)
        new_vel = [v + h * a for v, a in zip(velocities, qacc)]
        new_pos = _integrate_positions(xp, model, qpos, new_vel, h)
        return new_pos, _stack(xp, new_vel, qpos)
    # RK4, MuJoCo's tableau: stages at 0, h/2, h/2, h; weights 1/6, 1/3, 1/3, 1/6; the angular
    # velocities of ball and free joints enter as Runge-Kutta-Munthe-Kaas increments
    stage_vel = [velocities]
    stage_acc = [_accelerations(xp, model, qpos, qvel, ctrl, applied, 0.0)]
    for fraction in (0.5, 0.5, 1.0):
        dv, da = stage_vel[-1], stage_acc[-1]
        pos_i = _integrate_positions(xp, model, qpos, [fraction * x for x in dv], h)
        vel_i = [v + (h * fraction) * a for v, a in zip(velocities, da)]
        rotation = [(h * fraction) * x for x in dv]  # where stage i sits on the group
        stage_vel.append(_munthe_kaas(xp, model, vel_i, rotation))
        stage_acc.append(
            _accelerations(xp, model, pos_i, _stack(xp, vel_i, qpos), ctrl, applied, 0.0)
        )
    weights = (1 / 6, 1 / 3, 1 / 3, 1 / 6)
    mean_vel = [sum(w * s[i] for w, s in zip(weights, stage_vel)) for i in range(model.nv)]
    mean_acc = [sum(w * s[i] for w, s in zip(weights, stage_acc)) for i in range(model.nv)]
    new_pos = _integrate_positions(xp, model, qpos, mean_vel, h)
    new_vel = [v + h * a for v, a in zip(velocities, mean_acc)]
    return new_pos, _stack(xp, new_vel, qpos)


def _munthe_kaas(xp, model, velocity, rotation):
    """Stage velocities as increments of the rotation vector: for ball and free joints, the body
    angular velocity ``w`` at the rotation ``r`` from the step's start becomes
    ``dexp^-1(w) = w + r x w / 2 + r x (r x w) / 12`` (the series to fourth order)."""
    out = list(velocity)
    for joint in model.joints:
        if joint.kind not in (D.FREE, D.BALL):
            continue
        first = joint.dadr + (3 if joint.kind == D.FREE else 0)
        w = xp.stack(velocity[first : first + 3], axis=-1)
        r = xp.stack(rotation[first : first + 3], axis=-1)
        rw = xp.cross(r, w, axis=-1)
        corrected = w + 0.5 * rw + xp.cross(r, rw, axis=-1) / 12.0
        out[first : first + 3] = [corrected[..., k] for k in range(3)]
    return out


def _stack(xp, per_dof, like):
    zero = like[..., 0] * 0.0
    if not per_dof:
        return xp.zeros(tuple(like.shape[:-1]) + (0,), dtype=like.dtype, device=xp.dev(like))
    return xp.stack([x + zero for x in per_dof], axis=-1)


def _possible_contacts(xp, model, frames, qpos):
    false = qpos[..., 0] * 0.0 > 1.0
    flag = false
    centres, normals = {}, {}

    def place(g):
        if g not in centres:
            body, pos, rot, _, _ = model.geoms[g]
            if body in frames.rot or body == 0:
                brot, bpos = frames.rot[body], frames.pos[body]
            else:
                brot, bpos = _static_or(xp, model, frames, body, qpos, None)
            centres[g] = bpos + xp.matvec(brot, _const(xp, pos, qpos))
            normals[g] = xp.matmul(brot, _const(xp, rot, qpos))[..., :, 2]
        return centres[g], normals[g]

    for g1, g2, margin in model.contact_pairs:
        plane1, plane2 = model.geoms[g1][4], model.geoms[g2][4]
        if plane1 and plane2:
            continue
        if plane2:
            g1, g2 = g2, g1
        c1, n1 = place(g1)
        c2, _ = place(g2)
        reach = model.geoms[g2][3] + margin
        if plane1 or plane2:
            near = xp.sum((c2 - c1) * n1, axis=-1) < reach
        else:
            reach = reach + model.geoms[g1][3]
            near = xp.sum((c2 - c1) ** 2, axis=-1) < reach * reach
        flag = xp.logical_or(flag, near)
    return flag
