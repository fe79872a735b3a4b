"""Kinematic trees from MJCF: forward kinematics, Jacobians and dynamics of every body and site,
a thin front over :mod:`ivy_robot.physics` (MuJoCo's pipeline, written once for every backend).

The model is parsed once through MuJoCo (:func:`ivy_robot.load_mjcf`) and read into the
pipeline's frozen model (``tree.physics``); every method is then plain array code on numpy,
torch, jax or tensorflow, with any leading batch shape, differentiable and compilable. MuJoCo
never runs inside it.

Conventions are MuJoCo's (``mj_kinematics``): bodies and sites in the model's order, body 0 is the
world; a body's pose is its parent's pose composed with the body's ``pos``/``quat`` and then with
its joints, in order:

- hinge: a rotation by ``qpos - qpos0`` about the joint axis through the joint's ``pos``;
- slide: a translation by ``qpos - qpos0`` along the joint axis;
- ball: a rotation by the quaternion ``qpos[adr:adr+4]`` (MuJoCo's ``[w, x, y, z]``, normalised)
  about the joint's ``pos``;
- free: the world pose ``qpos[adr:adr+3]``, ``qpos[adr+3:adr+7]`` (``[w, x, y, z]``), whatever the
  body's ``pos``/``quat``.

Mocap bodies are placed at their model ``pos``/``quat`` (MuJoCo's default ``mocap_pos``).
Jacobians follow ``mj_jac``: columns in MuJoCo's dof order (``nv``), linear rows then angular
rows; ball and free rotational dofs are angular velocities in the body frame (the columns of the
body's rotation), free translational dofs are world x, y, z.

The dynamics (``mass_matrix``, ``forward_dynamics``, ``step``...) are MuJoCo's ``mj_forward`` and
``mj_step`` with contacts, joint limits and friction loss (see ``docs/ivy_robot_dynamics.md``).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, NamedTuple

import numpy as np

import ivy
from ivy.typing import Array, Framework
from ivy_robot.mjcf import SUPPORTED_JOINT_TYPES, load_mjcf
from ivy_robot.physics import _math as mt
from ivy_robot.physics import pipeline as fw
from ivy_robot.physics import smooth
from ivy_robot.physics.constraints import point_jacobians
from ivy_robot.physics.data import Data
from ivy_robot.physics.kinematics import com_pos, kinematics
from ivy_robot.physics.model import HINGE, SLIDE, Model, read_model

__all__ = ["KinematicTree", "BodySpheres"]

_GEOM_SPHERE, _GEOM_CAPSULE, _GEOM_CYLINDER = 2, 3, 5


class BodySpheres(NamedTuple):
    """Spheres attached to bodies (numpy constants), e.g. a collision model of a robot.

    Attributes:
        body_ids: the body of each sphere *[num_spheres]* (int).
        centres: centres in their body's frame *[num_spheres, 3]*.
        radii: radii *[num_spheres]*.
    """

    body_ids: np.ndarray
    centres: np.ndarray
    radii: np.ndarray


class KinematicTree:
    """A MuJoCo kinematic tree: forward kinematics, Jacobians and dynamics on any backend.

    Build it with :meth:`from_mjcf`. Attributes (numpy, MuJoCo's order): ``body_names``,
    ``site_names``, ``joint_names``, ``parent_ids``, ``nbody``, ``nsite``, ``njnt``, ``nq``,
    ``nv``, ``nu``, ``qpos0`` (the reference configuration), ``qpos_lower`` / ``qpos_upper``
    (joint ranges per qpos entry, infinite where unlimited and for quaternions and free
    positions), ``timestep``, ``integrator``; ``physics``: the pipeline's model
    (:class:`ivy_robot.physics.model.Model`).

    Example:
        >>> tree = KinematicTree.from_mjcf(panda_mjcf())
        >>> tree.forward_kinematics(np.zeros((5, tree.nq))).shape   # any backend's arrays
        (5, 10, 4, 4)
    """

    def __init__(self, model: Any) -> None:
        """Read a compiled ``mujoco.MjModel``; prefer :meth:`from_mjcf`."""
        types = np.asarray(model.jnt_type, dtype=np.int64)
        unknown = sorted(set(types.tolist()) - set(SUPPORTED_JOINT_TYPES))
        if unknown:
            raise ValueError(
                f"KinematicTree: joint types {unknown} are not supported; supported are "
                f"{SUPPORTED_JOINT_TYPES}"
            )
        self.physics: Model = read_model(model)
        p = self.physics
        self.nbody, self.njnt, self.nsite = p.nbody, p.njnt, p.nsite
        self.nq, self.nv, self.nu = p.nq, p.nv, p.nu
        self.body_names, self.joint_names, self.site_names = (
            p.body_names,
            p.joint_names,
            p.site_names,
        )
        self.parent_ids = p.body_parent.copy()
        self.qpos0 = p.qpos0.copy()
        self.joint_types = tuple(SUPPORTED_JOINT_TYPES[t] for t in types.tolist())
        lower, upper = np.full(self.nq, -np.inf), np.full(self.nq, np.inf)
        for j in range(self.njnt):
            if p.jnt_limited[j] and p.jnt_type[j] in (HINGE, SLIDE):
                lower[p.jnt_qposadr[j]], upper[p.jnt_qposadr[j]] = p.jnt_range[j]
        self.qpos_lower, self.qpos_upper = lower, upper
        # per body: its index and dof chain, as the point Jacobians take them
        self._body_points = tuple(
            (mt.gather([b], self.nbody), p.body_chain[b][None, :, None].copy())
            for b in range(self.nbody)
        )
        self._limit_joints = tuple(int(p.dof_jnt[d]) for d in p.rows.limit_dof[::2])

    @classmethod
    def from_mjcf(cls, source: Any, **unknown: Any) -> KinematicTree:
        """Parse an MJCF model once, through MuJoCo, into a kinematic tree.

        The tree holds no array of any framework (its constants are numpy): every method
        computes on the backend and device of the arrays passed to it, so there is no
        ``device=`` here: create ``q`` on the device (``asarray(q, device="gpu:0")`` of any
        namespace).

        Args:
            source: a path to an ``.xml`` file, an MJCF XML string, or a ``mujoco.MjModel``.

        Returns:
            The tree.

        Raises:
            ValueError: an unsupported joint type, or a model MuJoCo cannot compile.
            TypeError: an argument other than ``source`` (``device=``, ``dtype=``: see above).

        Example:
            >>> tree = KinematicTree.from_mjcf(panda_mjcf())   # or a path, or an MjModel
            >>> tree.body_names[:3], tree.nq
            (('world', 'link0', 'link1'), 7)
        """
        if unknown:
            raise TypeError(
                f"KinematicTree.from_mjcf takes only the model, got {sorted(unknown)}: the tree "
                "holds no arrays, and every method computes on the backend, device and dtype of "
                "the arrays passed to it: create them there (e.g. q = ivy.torch.asarray(q, "
                "device='gpu:0', dtype='float64'))."
            )
        return cls(load_mjcf(source))

    @property
    def timestep(self) -> float:
        """The model's timestep (``<option timestep>``)."""
        return self.physics.timestep

    @property
    def integrator(self) -> str:
        """The model's integrator: ``'Euler'`` or ``'RK4'``."""
        return self.physics.integrator

    # ------------------------------------------------------------------------------------------
    # Names
    # ------------------------------------------------------------------------------------------

    def body_id(self, body: str | int) -> int:
        """The index of a body given by name (or index, checked).

        Args:
            body: a body name, or its index.

        Returns:
            The index, in MuJoCo's order.

        Example:
            >>> tree.body_id("link1")     # tree: the Panda of panda_mjcf()
            2
        """
        return _lookup(body, self.body_names, "body")

    def site_id(self, site: str | int) -> int:
        """The index of a site given by name (or index, checked).

        Args:
            site: a site name, or its index.

        Returns:
            The index, in MuJoCo's order.

        Example:
            >>> tree.site_id("grasp")
            1
        """
        return _lookup(site, self.site_names, "site")

    def __repr__(self) -> str:
        kinds = ", ".join(sorted(set(self.joint_types))) or "none"
        return (
            f"KinematicTree(nbody={self.nbody}, njnt={self.njnt}, nq={self.nq}, nv={self.nv}, "
            f"nsite={self.nsite}, joints: {kinds})"
        )

    # ------------------------------------------------------------------------------------------
    # Kinematics
    # ------------------------------------------------------------------------------------------

    def forward_kinematics(self, qpos: Array, *, f: Framework = None) -> Array:
        """World poses of every body, as ``mj_kinematics`` computes ``xpos`` and ``xmat``.

        Args:
            qpos: joint positions *[batch_shape, nq]* (ball and free quaternions ``[w, x, y, z]``).
            f: framework name or namespace; inferred from ``qpos`` if None.

        Returns:
            Homogeneous poses *[batch_shape, nbody, 4, 4]*; body 0 is the world (identity).

        Example:
            >>> T = tree.forward_kinematics(np.zeros(tree.nq))
            >>> T[tree.body_id("hand"), :3, 3].round(3)      # its world position
            array([0.088, 0.   , 0.926])
        """
        xp = ivy.get_framework(qpos, f=f)
        self._check_qpos(xp, qpos)

        def poses(qpos):
            kin = kinematics(xp, self.physics, qpos)
            return _homogeneous(xp, kin["xmat"], kin["xpos"])

        return fw.compiled(xp, self.physics, "poses", poses)(qpos)

    def site_poses(self, qpos: Array, *, f: Framework = None) -> Array:
        """World poses of every site (``site_xpos``, ``site_xmat``).

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            f: framework name or namespace; inferred from ``qpos`` if None.

        Returns:
            Homogeneous poses *[batch_shape, nsite, 4, 4]*.

        Example:
            >>> tree.site_poses(np.zeros((3, tree.nq))).shape
            (3, 2, 4, 4)
        """
        xp = ivy.get_framework(qpos, f=f)
        self._check_qpos(xp, qpos)

        def poses(qpos):
            kin = kinematics(xp, self.physics, qpos)
            return _homogeneous(xp, kin["site_xmat"], kin["site_xpos"])

        return fw.compiled(xp, self.physics, "site poses", poses)(qpos)

    def transform_points(
        self, qpos: Array, bodies: Sequence[int | str], points: Array, *, f: Framework = None
    ) -> Array:
        """World positions of points attached to bodies.

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            bodies: the body (index or name) of each point, length ``num_points``.
            points: the points in their body's frame *[num_points, 3]* (or batched like qpos,
                *[batch_shape, num_points, 3]*).
            f: framework name or namespace; inferred from ``qpos`` if None.

        Returns:
            World positions *[batch_shape, num_points, 3]*.

        Example:
            >>> tree.transform_points(np.zeros(7), ["hand"], np.zeros((1, 3))).round(3)
            array([[0.088, 0.   , 0.926]])
        """
        xp = ivy.get_framework(qpos, f=f)
        self._check_qpos(xp, qpos)
        where = mt.gather([self.body_id(b) for b in bodies], self.nbody)
        points = _to_backend(xp, points, qpos)

        def transform(qpos, points):
            kin = kinematics(xp, self.physics, qpos)
            rot = mt.take(xp, kin["xmat"], where, axis=-3)
            return mt.take(xp, kin["xpos"], where, axis=-2) + mt.mv(xp, rot, points)

        key = ("points", tuple(where.indices.tolist()))
        return fw.compiled(xp, self.physics, key, transform)(qpos, points)

    def jacobian(
        self,
        qpos: Array,
        body: str | int | None = None,
        *,
        site: str | int | None = None,
        point: Array | None = None,
        f: Framework = None,
    ) -> Array:
        """The Jacobian of a point attached to a body (``mj_jac``, ``mj_jacBody``,
        ``mj_jacSite``), computed analytically.

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            body: the body (name or index); give ``body`` or ``site``.
            site: a site (name or index) instead of a body: the point is the site's origin.
            point: a point in the body's (or site's) frame *[3]* or *[batch_shape, 3]*; by
                default the frame's origin (``mj_jacBody`` / ``mj_jacSite``).
            f: framework name or namespace; inferred from ``qpos`` if None.

        Returns:
            *[batch_shape, 6, nv]*: rows 0-2 the linear velocity of the point per unit dof
            velocity (``jacp``), rows 3-5 the angular velocity (``jacr``), in the world frame.

        Example:
            >>> J = tree.jacobian(np.zeros(7), "hand")
            >>> J.shape, J[3:, 0]         # joint 1 turns the hand about the world z axis
            ((6, 7), array([0., 0., 1.]))
        """
        xp = ivy.get_framework(qpos, f=f)
        self._check_qpos(xp, qpos)
        if (body is None) == (site is None):
            raise ValueError("KinematicTree.jacobian: give exactly one of body= or site=")
        model = self.physics
        s = self.site_id(site) if site is not None else None
        b = int(model.site_body[s]) if s is not None else self.body_id(body)
        point = None if point is None else _to_backend(xp, point, qpos)

        def jacobian(qpos, point):
            kin = kinematics(xp, model, qpos)
            com = com_pos(xp, model, kin)
            if s is not None:
                frame_pos, frame_rot = kin["site_xpos"][..., s, :], kin["site_xmat"][..., s, :, :]
            else:
                frame_pos, frame_rot = kin["xpos"][..., b, :], kin["xmat"][..., b, :, :]
            target = frame_pos if point is None else frame_pos + mt.mv(xp, frame_rot, point)
            bodies, chain = self._body_points[b]
            jacp, jacr = point_jacobians(xp, model, com["cdof"], com["origin"], bodies, chain,
                                         target[..., None, :])  # fmt: skip
            stacked = xp.concat([jacp[..., 0, :, :], jacr[..., 0, :, :]], axis=-1)
            return xp.swapaxes(stacked, -1, -2)

        key = ("jacobian", b, s, point is None)
        return fw.compiled(xp, model, key, jacobian)(qpos, point)

    def collision_spheres(
        self, spacing: float = 0.05, *, bodies: Sequence[str | int] | None = None
    ) -> BodySpheres:
        """Spheres covering the sphere, capsule and cylinder geoms of the moving bodies: one per
        sphere, and along each capsule's or cylinder's axis, centres at most ``spacing`` apart.

        Args:
            spacing: the largest distance between neighbouring centres along an axis (metres).
            bodies: the bodies whose geoms to cover; by default every body with a dof in its
                chain (geoms of static bodies belong to the scene).

        Returns:
            :class:`BodySpheres` (numpy constants).

        Example:
            >>> spheres = tree.collision_spheres(0.05)
            >>> tree.transform_points(np.zeros(7), spheres.body_ids, spheres.centres).shape
            (31, 3)
        """
        if spacing <= 0:
            raise ValueError(f"collision_spheres: spacing must be positive, got {spacing}")
        if bodies is None:
            chosen = {i for i in range(self.nbody) if self.physics.body_chain[i].any()}
        else:
            chosen = {self.body_id(b) for b in bodies}
        ids, centres, radii = [], [], []
        for g in range(self.physics.ngeom):
            b, kind = int(self.physics.geom_body[g]), int(self.physics.geom_type[g])
            if b not in chosen or kind not in (_GEOM_SPHERE, _GEOM_CAPSULE, _GEOM_CYLINDER):
                continue
            radius, half = self.physics.geom_size[g, 0], self.physics.geom_size[g, 1]
            if kind == _GEOM_SPHERE:
                offsets = np.zeros((1, 3))
            else:
                n = int(np.ceil(2.0 * half / spacing)) + 1
                offsets = np.zeros((n, 3))
                offsets[:, 2] = np.linspace(-half, half, n)
            local = self.physics.geom_pos[g] + offsets @ self.physics.geom_rot[g].T
            ids += [b] * len(local)
            centres.append(local)
            radii += [radius] * len(local)
        if not ids:
            raise ValueError(
                "collision_spheres: the chosen bodies have no sphere, capsule or cylinder geoms"
            )
        return BodySpheres(np.asarray(ids), np.concatenate(centres), np.asarray(radii))

    # ------------------------------------------------------------------------------------------
    # Dynamics (MuJoCo's pipeline: ivy_robot.physics)
    # ------------------------------------------------------------------------------------------

    def make_data(
        self,
        qpos: Array,
        qvel: Array,
        ctrl: Array | None = None,
        qfrc_applied: Array | None = None,
        qacc_warmstart: Array | None = None,
        *,
        f: Framework = None,
    ) -> Data:
        """The checked state and inputs as the pipeline's data record (:func:`step_data`,
        :func:`forward_data` take it).

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            qvel: joint velocities *[batch_shape, nv]* (``qpos``' dtype).
            ctrl: controls *[batch_shape, nu]* (cast to ``qpos``' dtype); zero if None.
            qfrc_applied: further joint forces *[batch_shape, nv]*; zero if None.
            qacc_warmstart: the constraint solver's warm start *[batch_shape, nv]* (the
                previous step's ``qacc_warmstart``); zero if None, as a fresh ``mjData``.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            :class:`ivy_robot.physics.data.Data`.

        Example:
            >>> data = tree.make_data(np.zeros(7), np.zeros(7))
            >>> data.qpos.shape
            (7,)
        """
        xp = ivy.get_framework(qpos, qvel, f=f)
        qpos, qvel, ctrl, applied, warm = self._check(
            xp, qpos=qpos, qvel=qvel, ctrl=ctrl, qfrc_applied=qfrc_applied,
            qacc_warmstart=qacc_warmstart,
        )  # fmt: skip
        return fw.make_data(xp, self.physics, qpos, qvel, ctrl, applied, warm)

    def forward_data(self, data: Data, *, f: Framework = None) -> Data:
        """MuJoCo's ``mj_forward`` on a data record: every field of the forward dynamics.

        Args:
            data: from :meth:`make_data` (or a previous step).
            f: framework name or namespace; inferred from ``data.qpos`` if None.

        Returns:
            The filled-in :class:`ivy_robot.physics.data.Data`.

        Example:
            >>> data = tree.forward_data(tree.make_data(np.zeros(7), np.zeros(7)))
            >>> data.qacc.shape, data.efc_J.shape[-1]
            ((7,), 7)
        """
        xp = ivy.get_framework(data.qpos, f=f)
        return fw.forward(xp, self.physics, data)

    def step_data(self, data: Data, *, f: Framework = None) -> Data:
        """MuJoCo's ``mj_step`` on a data record: the data after one ``timestep``, with the new
        ``qpos``, ``qvel`` and ``qacc_warmstart``, and everything else as the step's last
        evaluation of the dynamics left it (for RK4 its last stage, as MuJoCo leaves ``mjData``
        and Gymnasium's tasks read it).

        Args:
            data: from :meth:`make_data` (or a previous step).
            f: framework name or namespace; inferred from ``data.qpos`` if None.

        Returns:
            The :class:`ivy_robot.physics.data.Data` after the step.

        Example:
            >>> data = tree.make_data(np.zeros(7), np.zeros(7))
            >>> for _ in range(10):
            ...     data = tree.step_data(data)
            >>> data.qpos.shape
            (7,)
        """
        xp = ivy.get_framework(data.qpos, f=f)
        return fw.step(xp, self.physics, data)

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
        model = self._dynamics()
        self._check(xp, qpos=qpos)

        def mass(qpos):
            com = com_pos(xp, model, kinematics(xp, model, qpos))
            return smooth.mass_matrix(xp, model, com["cinert"], com["cdof"])

        return fw.compiled(xp, model, "mass matrix", mass)(qpos)

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
        return self._smooth(qpos, qvel, None, f).qfrc_bias

    def passive_forces(self, qpos: Array, qvel: Array, *, f: Framework = None) -> Array:
        """Joint springs, dampers and fluid forces (MuJoCo's ``qfrc_passive``).

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            qvel: joint velocities *[batch_shape, nv]*.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            *[batch_shape, nv]*.

        Example:
            >>> tree.passive_forces(np.zeros(7), np.ones(7)) + 0.0   # the Panda has no damping
            array([0., 0., 0., 0., 0., 0., 0.])
        """
        return self._smooth(qpos, qvel, None, f).qfrc_passive

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
        model = self._dynamics()
        qpos, qvel, ctrl = self._check(xp, qpos=qpos, qvel=qvel, ctrl=ctrl)

        def actuation(qpos, qvel, ctrl):
            return smooth.actuation(xp, model, qpos, qvel, ctrl)[1]

        return fw.compiled(xp, model, "actuation", actuation)(qpos, qvel, ctrl)

    def inverse_dynamics(
        self, qpos: Array, qvel: Array, qacc: Array, *, f: Framework = None
    ) -> Array:
        """The joint forces that give the acceleration ``qacc`` besides the passive forces,
        without constraints (MuJoCo's ``mj_inverse`` of a constraint-free state:
        ``M qacc + qfrc_bias - qfrc_passive``).

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            qvel: joint velocities *[batch_shape, nv]*.
            qacc: joint accelerations *[batch_shape, nv]*.
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            *[batch_shape, nv]*: the applied plus actuator forces needed.

        Example:
            >>> q, v = np.array([0, 0, 0, -1.5, 0, 1.5, 0.0]), np.zeros(7)   # inside the limits
            >>> tree.inverse_dynamics(q, v, tree.forward_dynamics(q, v)).round(9) + 0.0
            array([0., 0., 0., 0., 0., 0., 0.])
        """
        xp = ivy.get_framework(qpos, qvel, qacc, f=f)
        qpos, qvel, qacc = self._check(xp, qpos=qpos, qvel=qvel, qacc=qacc)
        data = self._smooth(qpos, qvel, None, xp, with_mass=True)
        return xp.matvec(data.qM, qacc) + data.qfrc_bias - data.qfrc_passive

    def forward_dynamics(
        self,
        qpos: Array,
        qvel: Array,
        ctrl: Array | None = None,
        qfrc_applied: Array | None = None,
        qacc_warmstart: Array | None = None,
        *,
        f: Framework = None,
    ) -> Array:
        """Joint accelerations (MuJoCo's ``qacc`` after ``mj_forward``): the smooth dynamics
        with the constraint forces of contacts, joint limits and friction loss.

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            qvel: joint velocities *[batch_shape, nv]*.
            ctrl: controls *[batch_shape, nu]*; zero if None.
            qfrc_applied: further joint forces *[batch_shape, nv]*; zero if None.
            qacc_warmstart: the solver's warm start (see :meth:`make_data`).
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            *[batch_shape, nv]*.

        Example:
            >>> q = np.array([0, 0, 0, -1.5, 0, 1.5, 0.0])   # inside the joint limits
            >>> tree.forward_dynamics(q, np.zeros(7)).round(1) + 0.0
            array([  0. ,  -2.2,   0. , -31.6,   0. ,  25. ,   0. ])
            >>> tree.forward_dynamics(np.zeros(7), np.zeros(7))[3] < 0   # pushed back below its limit
            np.True_
        """
        data = self.make_data(qpos, qvel, ctrl, qfrc_applied, qacc_warmstart, f=f)
        return self.forward_data(data, f=f).qacc

    def step(
        self,
        qpos: Array,
        qvel: Array,
        ctrl: Array | None = None,
        qfrc_applied: Array | None = None,
        qacc_warmstart: Array | None = None,
        *,
        f: Framework = None,
    ) -> tuple[Array, Array]:
        """One step of the model's integrator (MuJoCo's ``mj_step``), returning the new state;
        :meth:`step_data` returns everything else too (and the warm start of the next step).

        Euler: ``qvel += h (M + h diag(damping))^-1 (qfrc_smooth + qfrc_constraint)`` (damping
        implicit, as MuJoCo does unless ``eulerdamp`` is disabled), then ``qpos`` integrated
        with the new velocity. RK4: MuJoCo's four-stage Runge-Kutta on ``(qpos, qvel)``.
        Quaternions of ball and free joints are integrated on the sphere and normalised.

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            qvel: joint velocities *[batch_shape, nv]*.
            ctrl: controls *[batch_shape, nu]*, held over the step; zero if None.
            qfrc_applied: further joint forces *[batch_shape, nv]*; zero if None.
            qacc_warmstart: the solver's warm start (see :meth:`make_data`).
            f: framework name or namespace; inferred from the inputs if None.

        Returns:
            ``(qpos, qvel)`` after ``timestep`` seconds.

        Example:
            >>> qpos, qvel = tree.step(np.zeros((4, 7)), np.zeros((4, 7)))
            >>> qpos.shape, qvel.shape
            ((4, 7), (4, 7))
        """
        data = self.make_data(qpos, qvel, ctrl, qfrc_applied, qacc_warmstart, f=f)
        data = self.step_data(data, f=f)
        return data.qpos, data.qvel

    # ------------------------------------------------------------------------------------------
    # Where constraints act
    # ------------------------------------------------------------------------------------------

    def active_limits(self, qpos: Array, *, f: Framework = None) -> Array:
        """Which limited hinge and slide joints are at (within their margin of) a limit, where
        MuJoCo adds a limit constraint.

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
        model = self.physics
        self._check_qpos(xp, qpos)
        rows = model.rows
        flags = [qpos[..., 0] > np.inf] * model.njnt
        if rows.nl:
            limit = mt.take(xp, qpos, rows.limit_qpos, axis=-1)
            dist = mt.const(xp, rows.limit_side, qpos) * (
                mt.const(xp, rows.limit_bound, qpos) - limit
            )
            active = dist < mt.const(xp, rows.limit_margin, qpos)
            for k, joint in enumerate(self._limit_joints):
                flags[joint] = xp.logical_or(active[..., 2 * k], active[..., 2 * k + 1])
        if not flags:
            return xp.zeros(tuple(qpos.shape[:-1]) + (0,), dtype="bool", device=xp.dev(qpos))
        return xp.stack(flags, axis=-1)

    def possible_contacts(self, qpos: Array, *, f: Framework = None) -> Array:
        """Whether MuJoCo finds a contact in this state (one that enters the constraints).

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
        self._check_qpos(xp, qpos)

        def touching(qpos):
            contacts = fw.find_contacts(xp, self.physics, kinematics(xp, self.physics, qpos))
            if contacts is None:
                return qpos[..., 0] > np.inf
            return xp.any(contacts.active, axis=-1)

        return fw.compiled(xp, self.physics, "contacts", touching)(qpos)

    def constraint_free(self, qpos: Array, *, f: Framework = None) -> Array:
        """Whether a state has no active constraint (no contact, no joint at a limit, no friction
        loss), where the dynamics are the smooth ones: ``M qacc = qfrc_smooth``.

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
        busy = self.possible_contacts(qpos, f=xp)
        if limits.shape[-1]:
            busy = xp.logical_or(busy, xp.any(limits, axis=-1))
        if self.physics.rows.nf:
            busy = xp.logical_or(busy, qpos[..., 0] <= np.inf)
        return xp.logical_not(busy)

    # ------------------------------------------------------------------------------------------
    # Checks and helpers
    # ------------------------------------------------------------------------------------------

    def _dynamics(self) -> Model:
        self.physics.check_dynamics()
        return self.physics

    def _smooth(self, qpos, qvel, ctrl, f, with_mass=False) -> Data:
        """The smooth forces of a state (positions and velocities, no collision)."""
        xp = ivy.get_framework(qpos, qvel, f=f)
        model = self._dynamics()
        qpos, qvel = self._check(xp, qpos=qpos, qvel=qvel)

        def forces(qpos, qvel):
            kin = kinematics(xp, model, qpos)
            com = com_pos(xp, model, kin)
            cvel, cdof_dot = smooth.velocities(xp, model, com["cdof"], qvel)
            passive = smooth.passive_forces(xp, model, qpos, qvel, kin, cvel, com["origin"],
                                            com["cdof"])  # fmt: skip
            bias = smooth.bias_forces(xp, model, com["cinert"], cvel, com["cdof"], cdof_dot, qvel)
            mass = smooth.mass_matrix(xp, model, com["cinert"], com["cdof"]) if with_mass else None
            return Data(qpos=qpos, qvel=qvel, qfrc_bias=bias, qfrc_passive=passive, qM=mass)

        return fw.compiled(xp, model, ("smooth", with_mass), forces)(qpos, qvel)

    def _check_qpos(self, xp, qpos) -> None:
        shape = tuple(qpos.shape)
        if len(shape) == 0 or shape[-1] != self.nq:
            raise ValueError(
                f"KinematicTree: qpos has shape {shape}; its last axis must hold the model's "
                f"nq={self.nq} joint positions (MuJoCo's qpos order)"
            )
        if not xp.isdtype(qpos.dtype, "real floating"):
            raise TypeError(
                f"KinematicTree: qpos has dtype {qpos.dtype}; give a floating-point array "
                "(float32 or float64)"
            )

    def _check(self, xp, **arrays):
        """Check shapes and dtypes; cast ``ctrl``, ``qfrc_applied`` and ``qacc_warmstart`` to
        ``qpos``' dtype. Returns the arrays in order (None for an absent optional one)."""
        model = self.physics
        sizes = {"qpos": model.nq, "qvel": model.nv, "qacc": model.nv, "ctrl": model.nu}
        sizes["qfrc_applied"] = sizes["qacc_warmstart"] = model.nv
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
# Helpers
# ----------------------------------------------------------------------------------------------


_PLURALS = {"body": "bodies", "site": "sites", "joint": "joints"}


def _lookup(key, names: tuple[str, ...], what: str) -> int:
    plural = _PLURALS.get(what, what + "s")
    if isinstance(key, (int, np.integer)) and not isinstance(key, bool):
        if not 0 <= int(key) < len(names):
            raise ValueError(
                f"{what} index {key} is out of range: the model has {len(names)} {plural} "
                f"(indices 0 to {len(names) - 1})"
            )
        return int(key)
    try:
        return names.index(key)
    except ValueError:
        shown = ", ".join(repr(n) for n in names[:20]) + (", ..." if len(names) > 20 else "")
        raise ValueError(f"unknown {what} {key!r}; the model's {plural} are: {shown}") from None


def _homogeneous(xp, rot, pos):
    """``[..., 3, 3]`` and ``[..., 3]`` -> ``[..., 4, 4]``."""
    bottom = xp.zeros_like(rot[..., 0:1, :])
    top = xp.concat([rot, pos[..., None]], axis=-1)
    bottom = xp.concat([bottom, xp.ones_like(bottom[..., 0:1])], axis=-1)
    return xp.concat([top, bottom], axis=-2)


def _to_backend(xp, value, like):
    """``value`` (numpy array, number, nested list, or array) as an array of ``like``'s
    framework, dtype and device; arrays that already are pass through, keeping gradients."""
    if isinstance(value, type(like)) and value.dtype == like.dtype:
        return value
    if isinstance(value, (np.ndarray, np.generic)):
        value = value.tolist()
    return xp.asarray(value, dtype=like.dtype, device=xp.dev(like))
