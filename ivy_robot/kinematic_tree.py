"""Kinematic trees from MJCF: forward kinematics of every body and site, and analytic Jacobians,
written once for every backend.

The model is parsed once through MuJoCo (:func:`ivy_robot.load_mjcf`) into float64 numpy
constants; forward kinematics is then plain array code on numpy, torch, jax or tensorflow, with
any leading batch shape, differentiable and compilable. MuJoCo never runs inside it.

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
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, NamedTuple

import numpy as np

import ivy
import ivy_mechanics as mech
from ivy.typing import Array, Framework
from ivy_robot import _arrays as A
from ivy_robot import _entries as E
from ivy_robot.dynamics import DynamicsMixin
from ivy_robot.mjcf import SUPPORTED_JOINT_TYPES, load_mjcf, mujoco_quaternion_to_rot_mat

__all__ = ["KinematicTree", "BodySpheres"]

_FREE, _BALL, _SLIDE, _HINGE = 0, 1, 2, 3
#: Per joint type, whether each of its dofs is rotational (1) or translational (0), in MuJoCo's
#: dof order; the number of dofs is the length. A new joint type adds a row here, a case in
#: :meth:`KinematicTree._apply_joint` (fast path), :func:`_joint_transform` (reference path) and
#: :meth:`KinematicTree._dof_axes` (Jacobian).
_DOF_ROTATIONAL = {
    _HINGE: (1.0,),
    _SLIDE: (0.0,),
    _BALL: (1.0, 1.0, 1.0),
    _FREE: (0.0, 0.0, 0.0, 1.0, 1.0, 1.0),
}
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


class _HingeTerms(NamedTuple):
    """The pose of a body whose first joint is a hinge, relative to its parent, as constants
    times functions of the joint angle ``theta = qpos - qpos0``.

    The body's offset is ``(R, p)`` (its ``quat`` and ``pos``); the hinge rotates about the unit
    axis ``a`` through the anchor ``c`` (in the body frame). With ``K`` the cross-product matrix
    of ``a``, Rodrigues' formula gives the joint rotation ``J = I + sin(theta) K +
    versine(theta) K^2`` (``versine = 1 - cos``), so the body's pose is::

        rotation = R J             = rot + sin(theta) rot_sin + versine(theta) rot_versine
        position = p + R (c - J c) = pos - sin(theta) pos_sin - versine(theta) pos_versine

    (:meth:`KinematicTree.reference_forward_kinematics` computes the same with 4x4 products.)
    """

    rot: Any  # R: the body's rotation from its parent (theta = 0)
    rot_sin: Any  # R K: multiplies sin(theta)
    rot_versine: Any  # R K^2: multiplies 1 - cos(theta)
    pos: Any  # p: the body's position in its parent
    pos_sin: Any  # R K c: subtracted times sin(theta)
    pos_versine: Any  # R K^2 c: subtracted times 1 - cos(theta)


class _BodyPlan(NamedTuple):
    """How one body's world pose is computed (all indices are static)."""

    kind: str  # "world", "static", "fixed", "free", "chain"
    parent: int | None  # the moving parent to compose with, or None
    mat: int  # index into the 3x3 constants ("static", "fixed", non-hinge "chain" start)
    vec: int  # index into the vector constants
    hinge: int | None  # index in the vectorised first-hinge group ("chain")
    joints: tuple[int, ...]  # the body's joints ("chain": all after a vectorised first hinge
    # are applied one by one)


class KinematicTree(DynamicsMixin):
    """A MuJoCo kinematic tree as float64 constants; forward kinematics and Jacobians on any
    backend.

    Build it with :meth:`from_mjcf`. Attributes (numpy, MuJoCo's order): ``body_names``,
    ``site_names``, ``joint_names``, ``parent_ids``, ``nbody``, ``nsite``, ``njnt``, ``nq``,
    ``nv``, ``qpos0`` (the reference configuration), ``qpos_lower`` / ``qpos_upper`` (joint
    ranges per qpos entry, infinite where unlimited and for quaternions and free positions).

    Example:
        >>> tree = KinematicTree.from_mjcf(panda_mjcf())
        >>> tree.forward_kinematics(np.zeros((5, tree.nq))).shape   # any backend's arrays
        (5, 10, 4, 4)
    """

    def __init__(self, model: Any) -> None:
        """Read a compiled ``mujoco.MjModel``; prefer :meth:`from_mjcf`."""
        m = model
        types = np.asarray(m.jnt_type, dtype=np.int64)
        unknown = sorted(set(types.tolist()) - set(SUPPORTED_JOINT_TYPES))
        if unknown:
            raise ValueError(
                f"KinematicTree: joint types {unknown} are not supported; supported are "
                f"{SUPPORTED_JOINT_TYPES}"
            )
        self.nbody, self.njnt, self.nsite = int(m.nbody), int(m.njnt), int(m.nsite)
        self.nq, self.nv = int(m.nq), int(m.nv)
        self.body_names = tuple(m.body(i).name for i in range(self.nbody))
        self.joint_names = tuple(m.joint(i).name for i in range(self.njnt))
        self.site_names = tuple(m.site(i).name for i in range(self.nsite))
        self.parent_ids = np.asarray(m.body_parentid, dtype=np.int64).copy()
        self.qpos0 = np.asarray(m.qpos0, dtype=np.float64).copy()
        self.joint_types = tuple(SUPPORTED_JOINT_TYPES[t] for t in types.tolist())

        self._jnt_type = types
        self._jnt_body = np.asarray(m.jnt_bodyid, dtype=np.int64)
        self._jnt_qadr = np.asarray(m.jnt_qposadr, dtype=np.int64)
        self._jnt_dadr = np.asarray(m.jnt_dofadr, dtype=np.int64)
        self._jnt_axis = np.asarray(m.jnt_axis, dtype=np.float64).copy()
        self._jnt_pos = np.asarray(m.jnt_pos, dtype=np.float64).copy()
        self._body_pos = np.asarray(m.body_pos, dtype=np.float64).copy()
        self._body_rot = mujoco_quaternion_to_rot_mat(np.asarray(m.body_quat))
        self._site_body = np.asarray(m.site_bodyid, dtype=np.int64).copy()
        self._site_pos = np.asarray(m.site_pos, dtype=np.float64).copy()
        self._site_rot = mujoco_quaternion_to_rot_mat(np.asarray(m.site_quat).reshape(-1, 4))
        self._geom_type = np.asarray(m.geom_type, dtype=np.int64).copy()
        self._geom_body = np.asarray(m.geom_bodyid, dtype=np.int64).copy()
        self._geom_size = np.asarray(m.geom_size, dtype=np.float64).copy()
        self._geom_pos = np.asarray(m.geom_pos, dtype=np.float64).copy()
        self._geom_rot = mujoco_quaternion_to_rot_mat(np.asarray(m.geom_quat).reshape(-1, 4))
        self._body_offsets = np.stack([_homogeneous_np(r, p) for r, p in zip(
            self._body_rot, self._body_pos)])  # fmt: skip
        self._qpos_limits(m)
        self._build_plan(np.asarray(m.body_jntadr), np.asarray(m.body_jntnum))
        self._build_dofs()
        self._build_kernel_data()

    # ------------------------------------------------------------------------------------------
    # Construction
    # ------------------------------------------------------------------------------------------

    @classmethod
    def from_mjcf(cls, source: Any) -> KinematicTree:
        """Parse an MJCF model once, through MuJoCo, into a kinematic tree.

        Args:
            source: a path to an ``.xml`` file, an MJCF XML string, or a ``mujoco.MjModel``.

        Returns:
            The tree.

        Raises:
            ValueError: an unsupported joint type, or a model MuJoCo cannot compile.

        Example:
            >>> tree = KinematicTree.from_mjcf(panda_mjcf())   # or a path, or an MjModel
            >>> tree.body_names[:3], tree.nq
            (('world', 'link0', 'link1'), 7)
        """
        return cls(load_mjcf(source))

    def _qpos_limits(self, m) -> None:
        lower = np.full(self.nq, -np.inf)
        upper = np.full(self.nq, np.inf)
        limited = np.asarray(m.jnt_limited, dtype=bool)
        ranges = np.asarray(m.jnt_range, dtype=np.float64)
        for j in range(self.njnt):
            if limited[j] and self._jnt_type[j] in (_HINGE, _SLIDE):
                lower[self._jnt_qadr[j]], upper[self._jnt_qadr[j]] = ranges[j]
        self.qpos_lower, self.qpos_upper = lower, upper

    def _build_plan(self, body_jntadr, body_jntnum) -> None:
        """Sort every body into a kind and precompute its constants (numpy float64)."""
        mats, vecs = [np.eye(3)], [np.zeros(3)]
        hinge = {k: [] for k in (*_HingeTerms._fields, "qadr", "q0")}
        world_rot = {0: np.eye(3)}  # world poses of static bodies
        world_pos = {0: np.zeros(3)}
        plan = [_BodyPlan("world", None, 0, 0, None, ())]
        for i in range(1, self.nbody):
            parent = int(self.parent_ids[i])
            joints = tuple(range(int(body_jntadr[i]), int(body_jntadr[i] + body_jntnum[i])))
            rot, pos = self._body_rot[i], self._body_pos[i]
            parent_static = parent in world_rot
            if parent_static:  # fold the parent's constant pose into this body's offset
                rot, pos = world_rot[parent] @ rot, world_pos[parent] + world_rot[parent] @ pos
            if not joints and parent_static:
                world_rot[i], world_pos[i] = rot, pos
                mats.append(rot), vecs.append(pos)
                plan.append(_BodyPlan("static", None, len(mats) - 1, len(vecs) - 1, None, ()))
            elif not joints:
                mats.append(rot), vecs.append(pos)
                plan.append(_BodyPlan("fixed", parent, len(mats) - 1, len(vecs) - 1, None, ()))
            elif self._jnt_type[joints[0]] == _FREE:
                plan.append(_BodyPlan("free", None, 0, 0, None, joints))
            else:
                moving_parent = None if parent_static else parent
                j = joints[0]
                if self._jnt_type[j] == _HINGE:
                    cross = A.skew(self._jnt_axis[j])  # K: cross-product matrix of the axis
                    cross_sq = cross @ cross
                    anchor = self._jnt_pos[j]
                    terms = _HingeTerms(
                        rot=rot,
                        rot_sin=rot @ cross,
                        rot_versine=rot @ cross_sq,
                        pos=pos,
                        pos_sin=rot @ cross @ anchor,
                        pos_versine=rot @ cross_sq @ anchor,
                    )
                    for name, value in terms._asdict().items():
                        hinge[name].append(value)
                    hinge["qadr"].append(self._jnt_qadr[j])
                    hinge["q0"].append(self.qpos0[self._jnt_qadr[j]])
                    index = len(hinge["qadr"]) - 1
                    plan.append(_BodyPlan("chain", moving_parent, 0, 0, index, joints))
                else:
                    mats.append(rot), vecs.append(pos)
                    plan.append(
                        _BodyPlan(
                            "chain", moving_parent, len(mats) - 1, len(vecs) - 1, None, joints
                        )
                    )
        self._plan = tuple(plan)
        self._hinge_qadr = np.asarray(hinge.pop("qadr"), dtype=np.int64)
        consts = {"mats": np.stack(mats), "vecs": np.stack(vecs)}
        if len(self._hinge_qadr):
            consts.update({"hinge_" + k: np.stack(v) for k, v in hinge.items()})
        self._consts = consts

    def _build_dofs(self) -> None:
        """Per-dof flags and the dof order of the Jacobian's blocks."""
        rotational = []
        for j in range(self.njnt):
            rotational += _DOF_ROTATIONAL[int(self._jnt_type[j])]
        # dof chains: the dofs of a body and of its ancestors
        chains = np.zeros((self.nbody, self.nv))
        for i in range(1, self.nbody):
            chains[i] = chains[self.parent_ids[i]]
            for j in np.flatnonzero(self._jnt_body == i):
                n = len(_DOF_ROTATIONAL[int(self._jnt_type[j])])
                chains[i, self._jnt_dadr[j] : self._jnt_dadr[j] + n] = 1.0
        self._chains = chains
        self._dof_consts = {
            "rot": np.asarray(rotational).reshape(self.nv, 1),
            "trans": 1.0 - np.asarray(rotational).reshape(self.nv, 1),
        }

    def _build_kernel_data(self) -> None:
        """The static structure the kernels read (Python ints and tuples) and the entry-wise
        constants; array constants stay numpy, brought in by :func:`ivy_robot._arrays.constant`."""
        self._k_hinge = A.gather_spec(self._hinge_qadr, self.nq)
        self._k_joints = tuple(
            (int(t), int(q), float(self.qpos0[q]), int(b))
            for t, q, b in zip(self._jnt_type, self._jnt_qadr, self._jnt_body)
        )
        self._k_site_body = tuple(int(b) for b in self._site_body)
        self._k_dof_adr = tuple(int(d) for d in self._jnt_dadr)
        self._chain_columns = tuple(self._chains[b][:, None] for b in range(self.nbody))
        # entry-wise constants (Python floats, snapped): see ivy_robot._entries
        consts = self._consts
        self._e_mats = [E.constant_matrix(m) for m in consts["mats"]]
        self._e_vecs = [E.constant_vector(v) for v in consts["vecs"]]
        self._e_hinge = tuple(
            _HingeTerms(
                *(E.constant_matrix(consts["hinge_" + k][h]) for k in _HingeTerms._fields[:3]),
                *(E.constant_vector(consts["hinge_" + k][h]) for k in _HingeTerms._fields[3:]),
            )
            for h in range(len(self._hinge_qadr))
        )
        self._hinge_has_ref = bool(np.any(self.qpos0[self._hinge_qadr] != 0.0))
        self._e_joint = tuple(
            {
                "axis": E.constant_vector(self._jnt_axis[j]),
                "pos": E.constant_vector(self._jnt_pos[j]),
                "cross": E.constant_matrix(A.skew(self._jnt_axis[j])),
                "cross_sq": E.constant_matrix(
                    A.skew(self._jnt_axis[j]) @ A.skew(self._jnt_axis[j])
                ),
            }
            for j in range(self.njnt)
        )
        self._e_sites = tuple(
            (E.constant_matrix(self._site_rot[s]), E.constant_vector(self._site_pos[s]))
            for s in range(self.nsite)
        )

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
        rots, poss, _ = self._frames(xp, qpos)
        entries = [e for rot, pos in zip(rots, poss) for e in E.pose_entries(rot, pos)]
        return E.poses_to_array(xp, entries, qpos, self.nbody)

    def reference_forward_kinematics(self, qpos: Array, *, f: Framework = None) -> Array:
        """The specification of :meth:`forward_kinematics`, and its test oracle: 4x4
        homogeneous transforms composed along the tree, body by body (slower; the fast path
        works entry by entry on folded constants).

        A body's pose is its parent's pose, times its offset (``pos``, ``quat``), times the
        transform of each of its joints in order (:func:`_joint_transform`); a free joint sets
        the world pose.

        Args:
            qpos: joint positions *[batch_shape, nq]*.
            f: framework name or namespace; inferred from ``qpos`` if None.

        Returns:
            Homogeneous poses *[batch_shape, nbody, 4, 4]*.

        Example:
            >>> q = np.random.default_rng(0).uniform(-1, 1, (4, tree.nq))
            >>> bool(np.allclose(tree.reference_forward_kinematics(q), tree.forward_kinematics(q)))
            True
        """
        xp = ivy.get_framework(qpos, f=f)
        self._check_qpos(xp, qpos)
        offsets = A.constant(xp, self._body_offsets, qpos)
        axes = A.constant(xp, self._jnt_axis, qpos)
        anchors = A.constant(xp, self._jnt_pos, qpos)
        poses = [A.broadcast_leading(xp, offsets[0], qpos, 1)]  # the world: identity
        for body in range(1, self.nbody):
            pose = xp.matmul(poses[self.parent_ids[body]], offsets[body])
            for j in np.flatnonzero(self._jnt_body == body):
                kind, adr = int(self._jnt_type[j]), int(self._jnt_qadr[j])
                local = _joint_transform(xp, kind, qpos, adr, self.qpos0[adr], axes[j], anchors[j])
                pose = local if kind == _FREE else xp.matmul(pose, local)
            poses.append(pose)
        return xp.stack(poses, axis=-3)

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
        if self.nsite == 0:
            shape = tuple(qpos.shape[:-1]) + (0, 4, 4)
            return xp.zeros(shape, dtype=qpos.dtype, device=xp.dev(qpos))
        rots, poss, _ = self._frames(xp, qpos)
        entries = []
        for s, b in enumerate(self._k_site_body):
            entries += E.pose_entries(*E.compose(rots[b], poss[b], *self._e_sites[s]))
        return E.poses_to_array(xp, entries, qpos, self.nsite)

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
        ids = [self.body_id(b) for b in bodies]
        rots, poss, _ = self._frames(xp, qpos)
        body_rot = E.to_array(
            xp, [e for b in ids for row in rots[b] for e in row], qpos, (len(ids), 3, 3)
        )
        body_pos = E.to_array(xp, [e for b in ids for e in poss[b]], qpos, (len(ids), 3))
        points = A.to_backend(xp, points, qpos)
        return body_pos + xp.matvec(body_rot, points)

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
        rots, poss, joint_frames = self._frames(xp, qpos)
        if site is not None:
            s = self.site_id(site)
            b = self._k_site_body[s]
            frame_rot, frame_pos = E.compose(rots[b], poss[b], *self._e_sites[s])
        else:
            b = self.body_id(body)
            frame_rot, frame_pos = rots[b], poss[b]
        frame_rot = E.to_array(xp, [e for row in frame_rot for e in row], qpos, (3, 3))
        frame_pos = E.to_array(xp, frame_pos, qpos, (3,))
        target = frame_pos
        if point is not None:
            point = A.to_backend(xp, point, qpos)
            target = frame_pos + xp.matvec(frame_rot, point)
        axes, anchors = self._dof_axes(xp, qpos, rots, poss, joint_frames)
        c = A.constants(xp, qpos, {**self._dof_consts, "chain": self._chain_columns[b]})
        offset = target[..., None, :] - anchors
        linear = c["rot"] * xp.cross(axes, offset, axis=-1) + c["trans"] * axes
        angular = c["rot"] * axes
        jac = xp.concat([linear, angular], axis=-1) * c["chain"]
        return xp.swapaxes(jac, -1, -2)

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
            chosen = {i for i in range(self.nbody) if self._chains[i].any()}
        else:
            chosen = {self.body_id(b) for b in bodies}
        ids, centres, radii = [], [], []
        for g in range(len(self._geom_type)):
            b, kind = int(self._geom_body[g]), int(self._geom_type[g])
            if b not in chosen or kind not in (_GEOM_SPHERE, _GEOM_CAPSULE, _GEOM_CYLINDER):
                continue
            radius, half = self._geom_size[g, 0], self._geom_size[g, 1]
            if kind == _GEOM_SPHERE:
                offsets = np.zeros((1, 3))
            else:
                n = int(np.ceil(2.0 * half / spacing)) + 1
                offsets = np.zeros((n, 3))
                offsets[:, 2] = np.linspace(-half, half, n)
            local = self._geom_pos[g] + offsets @ self._geom_rot[g].T
            ids += [b] * len(local)
            centres.append(local)
            radii += [radius] * len(local)
        if not ids:
            raise ValueError(
                "collision_spheres: the chosen bodies have no sphere, capsule or cylinder geoms"
            )
        return BodySpheres(np.asarray(ids), np.concatenate(centres), np.asarray(radii))

    # ------------------------------------------------------------------------------------------
    # Kernels
    # ------------------------------------------------------------------------------------------

    def _check_qpos(self, xp, qpos) -> None:
        meaning = f"the model's nq={self.nq} joint positions (MuJoCo's qpos order)"
        A.check_last_axis(xp, qpos, self.nq, "qpos", "KinematicTree", meaning)

    def _frames(self, xp, qpos):
        """World rotations and positions of every body, and of the frame right after each
        joint (for the Jacobian), entry by entry (:mod:`ivy_robot._entries`)."""
        rots, poss = [None] * self.nbody, [None] * self.nbody
        frames = [None] * self.njnt
        if self._e_hinge:
            theta = A.gather_last(xp, qpos, self._k_hinge)
            if self._hinge_has_ref:
                theta = theta - A.constant(xp, self._consts["hinge_q0"], qpos)
            sin, vers = _sin_versine(xp, theta)
        for i, step in enumerate(self._plan):
            if step.kind in ("world", "static"):
                rots[i], poss[i] = self._e_mats[step.mat], self._e_vecs[step.vec]
                continue
            if step.kind == "free":
                adr = self._k_joints[step.joints[0]][1]
                rot = E.from_array(_quaternion_rot(xp, qpos[..., adr + 3 : adr + 7]))
                pos = [qpos[..., adr + k] for k in range(3)]
                frames[step.joints[0]] = (rot, pos)
                rots[i], poss[i] = rot, pos
                continue
            if step.hinge is not None:
                s, v = sin[..., step.hinge], vers[..., step.hinge]
                h = self._e_hinge[step.hinge]
                rot = [
                    [
                        E.affine(
                            h.rot[r][col], [(h.rot_sin[r][col], s), (h.rot_versine[r][col], v)]
                        )
                        for col in range(3)
                    ]
                    for r in range(3)
                ]
                pos = [
                    E.affine(h.pos[r], [(-h.pos_sin[r], s), (-h.pos_versine[r], v)])
                    for r in range(3)
                ]
            else:
                rot, pos = self._e_mats[step.mat], self._e_vecs[step.vec]
            if step.parent is not None:
                rot, pos = E.compose(rots[step.parent], poss[step.parent], rot, pos)
            joints = step.joints
            if step.hinge is not None:
                frames[joints[0]] = (rot, pos)
                joints = joints[1:]
            for j in joints:
                rot, pos = self._apply_joint(xp, qpos, j, rot, pos)
                frames[j] = (rot, pos)
            rots[i], poss[i] = rot, pos
        return rots, poss, frames

    def _apply_joint(self, xp, qpos, j, rot, pos):
        """The frame after joint ``j``, given the (world) frame before it (entries)."""
        kind, adr, ref, _ = self._k_joints[j]
        c = self._e_joint[j]
        if kind == _SLIDE:
            shift = qpos[..., adr] - ref if ref != 0.0 else qpos[..., adr]
            axis = E.matvec(rot, c["axis"])
            return rot, [E.add(pos[r], E.dot([(axis[r], shift)])) for r in range(3)]
        if kind == _HINGE:
            theta = qpos[..., adr] - ref if ref != 0.0 else qpos[..., adr]
            s, v = _sin_versine(xp, theta)
            eye = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
            local = [
                [E.affine(eye[r][col], [(c["cross"][r][col], s), (c["cross_sq"][r][col], v)])
                 for col in range(3)]
                for r in range(3)
            ]  # fmt: skip
        else:  # ball
            local = E.from_array(_quaternion_rot(xp, qpos[..., adr : adr + 4]))
        anchor = [E.add(pos[r], x) for r, x in enumerate(E.matvec(rot, c["pos"]))]
        new_rot = E.matmul(rot, local)
        back = E.matvec(new_rot, c["pos"])
        return new_rot, [E.add(anchor[r], E.dot([(back[r], -1.0)])) for r in range(3)]

    def _dof_axes(self, xp, qpos, rots, poss, frames):
        """World axes and anchors of every dof *[batch_shape, nv, 3]*, in dof order."""
        axes, anchors = [None] * self.nv, [None] * self.nv
        eye = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
        for j in range(self.njnt):
            kind, _, _, b = self._k_joints[j]
            dof = self._k_dof_adr[j]
            if kind == _FREE:
                body_axes = [[rots[b][r][col] for r in range(3)] for col in range(3)]
                axes[dof : dof + 6] = eye + body_axes
                anchors[dof : dof + 6] = [poss[b]] * 6
                continue
            rot, pos = frames[j]
            offset = E.matvec(rot, self._e_joint[j]["pos"])
            anchor = [E.add(pos[r], x) for r, x in enumerate(offset)]
            if kind == _BALL:  # angular velocity in the body frame: the body's axes
                axes[dof : dof + 3] = [[rots[b][r][col] for r in range(3)] for col in range(3)]
                anchors[dof : dof + 3] = [anchor] * 3
            else:
                axes[dof] = E.matvec(rot, self._e_joint[j]["axis"])
                anchors[dof] = anchor
        flat_axes = [e for axis in axes for e in axis]
        flat_anchors = [e for anchor in anchors for e in anchor]
        return (
            E.to_array(xp, flat_axes, qpos, (self.nv, 3)),
            E.to_array(xp, flat_anchors, qpos, (self.nv, 3)),
        )


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


def _homogeneous_np(rot, pos):
    pose = np.eye(4)
    pose[:3, :3], pose[:3, 3] = rot, pos
    return pose


def _homogeneous(xp, rot, pos):
    """``[..., 3, 3]`` and ``[..., 3]`` -> ``[..., 4, 4]``."""
    bottom = xp.zeros_like(rot[..., 0:1, :])
    top = xp.concat([rot, pos[..., None]], axis=-1)
    bottom = xp.concat([bottom, xp.ones_like(bottom[..., 0:1])], axis=-1)
    return xp.concat([top, bottom], axis=-2)


def _joint_transform(xp, kind, qpos, adr, ref, axis, anchor):
    """The reference transform of one joint *[batch_shape, 4, 4]*, in its body's frame (for a
    free joint, the world pose): a hinge rotates by ``qpos - ref`` about ``axis`` through
    ``anchor`` (Rodrigues), a slide translates by ``qpos - ref`` along ``axis``, a ball rotates
    by its quaternion about ``anchor``, a free joint is the pose ``qpos[adr:adr+7]``."""
    if kind == _FREE:
        return _homogeneous(xp, _quaternion_rot(xp, qpos[..., adr + 3 : adr + 7]),
                            qpos[..., adr : adr + 3])  # fmt: skip
    if kind == _SLIDE:
        shift = (qpos[..., adr] - ref)[..., None]
        eye = xp.broadcast_to(xp.eye(3, dtype=qpos.dtype, device=xp.dev(qpos)),
                              (*qpos.shape[:-1], 3, 3))  # fmt: skip
        return _homogeneous(xp, eye, shift * axis)
    if kind == _HINGE:
        theta = (qpos[..., adr] - ref)[..., None, None]
        x, y, z = axis[0], axis[1], axis[2]
        zero = xp.zeros_like(x)
        cross = xp.stack([xp.stack([zero, -z, y]), xp.stack([z, zero, -x]),
                          xp.stack([-y, x, zero])])  # fmt: skip
        eye = xp.eye(3, dtype=qpos.dtype, device=xp.dev(qpos))
        rot = eye + xp.sin(theta) * cross + (1.0 - xp.cos(theta)) * xp.matmul(cross, cross)
    else:  # ball
        rot = _quaternion_rot(xp, qpos[..., adr : adr + 4])
    return _homogeneous(xp, rot, anchor - xp.matvec(rot, anchor))


def _sin_versine(xp, theta):
    """``sin(theta)`` and ``1 - cos(theta)``, the latter as ``2 sin(theta / 2)**2`` (no
    cancellation at small angles)."""
    half = xp.sin(theta * 0.5)
    return xp.sin(theta), 2.0 * half * half


def _quaternion_rot(xp, quat_wxyz):
    """Rotation matrices of MuJoCo quaternions ``[w, x, y, z]`` (normalised), through
    ivy_mechanics, whose quaternions are ``[x, y, z, w]``."""
    xyzw = xp.concat([quat_wxyz[..., 1:4], quat_wxyz[..., 0:1]], axis=-1)
    return mech.quaternion_to_rot_mat(xyzw, f=xp)
