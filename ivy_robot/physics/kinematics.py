"""Kinematics (MuJoCo's ``mj_kinematics`` and ``mj_comPos``), written once.

:func:`kinematics` places every body, joint, geom and site in the world from ``qpos``: the tree
is walked level by level (all bodies at one depth at once, their joints slot by slot), so the
number of operations grows with the tree's depth, not with its number of bodies. A body's frame
is its parent's composed with its offset, then with each of its joints in order:

- hinge: a rotation by ``qpos - qpos0`` about the joint's axis through its anchor;
- slide: a translation by ``qpos - qpos0`` along the axis;
- ball: a rotation by the quaternion ``qpos[adr:adr+4]`` about the anchor;
- free: the world pose ``qpos[adr:adr+7]``.

:func:`com_pos` then computes what the dynamics need about each tree's centre of mass (MuJoCo's
``subtree_com`` of the tree's root): body inertias ``cinert`` and the dofs' motion axes ``cdof``
(angular, linear), as products with constant masks of the tree.

Everything the kernels index with is made once, when the model is read (:func:`plan`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ivy_robot.mjcf import mujoco_quaternion_to_rot_mat
from ivy_robot.physics import _math as mt
from ivy_robot.physics.model import BALL, FREE, HINGE, SLIDE, Model, const

__all__ = ["com_pos", "dof_axes", "kinematics"]

# ----------------------------------------------------------------------------------------------
# The plan: made once per model
# ----------------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class JointSlot:
    """One joint of each body of a level (the ``s``-th of each; none where a body has fewer)."""

    qadr: mt.Gather  # qpos address per body (0 where none: masked by the kind flags)
    qpos0: np.ndarray  # [n]
    axis: np.ndarray  # [n, 3] joint axis in the body frame
    pos: np.ndarray  # [n, 3] joint anchor in the body frame
    hinge: np.ndarray  # [n] 1.0 for hinges
    slide: np.ndarray  # [n] 1.0 for slides
    cross: np.ndarray  # [n, 3, 3] skew(axis) of hinges, zero elsewhere
    cross_sq: np.ndarray  # [n, 3, 3] its square
    has_ball: bool
    ball: np.ndarray  # [n, 1, 1] 1.0 for ball joints
    ball_qpos: mt.Gather  # 4 qpos addresses per body (flattened)


@dataclass(frozen=True, eq=False)
class Level:
    """The bodies at one depth of the tree, computed together."""

    n: int
    parent: mt.Gather  # each body's parent in the previous level
    pos: np.ndarray  # [n, 3] offset from the parent (body_pos)
    rot: np.ndarray  # [n, 3, 3] (body_quat)
    slots: tuple  # JointSlot
    has_free: bool
    free: np.ndarray  # [n, 1] 1.0 for bodies with a free joint
    free_qpos: mt.Gather  # 7 qpos addresses per body (flattened)
    free_axis: np.ndarray  # [n, 3]: MuJoCo's xaxis of a free joint (its unrotated axis)


@dataclass(frozen=True, eq=False)
class Plan:
    """What the kinematics index with (numpy constants, Python flags)."""

    levels: tuple
    body_order: mt.Gather  # each body's position in the levels' concatenation
    jnt_order: mt.Gather  # each joint's position in the slots' concatenation
    world_pos: np.ndarray  # [1, 3]
    world_mat: np.ndarray  # [1, 3, 3]
    geom_body: mt.Gather
    site_body: mt.Gather
    # com_pos
    com_weights: mt.ConstMatrix  # subtree_com = com_weights @ xipos
    root: mt.Gather  # body_rootid
    inertia_rows: np.ndarray  # [nbody, 1, 3] principal moments, as rows
    mass_column: np.ndarray  # [nbody, 1]
    # dof axes
    dof_jnt: mt.Gather
    dof_body: mt.Gather
    simple: np.ndarray  # [nv, 1]: hinge and slide dofs take their joint's axis
    column: tuple  # 3 x [nv, 1]: ball and free rotations take a column of the body's frame
    translation: np.ndarray  # [nv, 3]: free translations along the world's axes
    has_column: bool
    has_translation: bool
    rotational: np.ndarray  # [nv, 1]
    empty_cdof: np.ndarray  # [0, 6]


def _skew(axis):
    x, y, z = axis
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


def plan(m, model: Model) -> Plan:
    """The kinematics' plan of a compiled ``mujoco.MjModel`` ``m`` read into ``model``."""
    nbody, njnt, nv = model.nbody, model.njnt, model.nv
    depth = np.zeros(nbody, dtype=np.int64)
    for b in range(1, nbody):
        depth[b] = depth[model.body_parent[b]] + 1
    body_rot = mujoco_quaternion_to_rot_mat(np.asarray(m.body_quat))
    levels, previous = [], [0]
    body_order, jnt_order = np.zeros(nbody, np.int64), np.zeros(njnt, np.int64)
    cursor, jnt_cursor = 1, 0
    for level in range(1, int(depth.max(initial=0)) + 1):
        bodies = [b for b in range(nbody) if depth[b] == level]
        n = len(bodies)
        adrs = [int(m.body_jntadr[b]) for b in bodies]
        counts = [int(m.body_jntnum[b]) for b in bodies]
        free = [c >= 1 and model.jnt_type[a] == FREE for a, c in zip(adrs, counts)]
        slots = []
        for s in range(max([c for c, f in zip(counts, free) if not f], default=0)):
            joints = [a + s if s < c and not f else -1 for a, c, f in zip(adrs, counts, free)]
            slots.append(_slot(model, joints, n))
            for k, j in enumerate(joints):
                if j >= 0:
                    jnt_order[j] = jnt_cursor + k
            jnt_cursor += n
        if any(free):  # free joints are recorded after the slots
            for k, (a, f) in enumerate(zip(adrs, free)):
                if f:
                    jnt_order[a] = jnt_cursor + k
            jnt_cursor += n
        body_order[bodies] = cursor + np.arange(n)
        cursor += n
        qadr = [int(model.jnt_qposadr[a]) if f else 0 for a, f in zip(adrs, free)]
        levels.append(
            Level(
                n=n,
                parent=mt.gather(
                    [previous.index(model.body_parent[b]) for b in bodies], len(previous)
                ),  # fmt: skip
                pos=np.array(m.body_pos[bodies], dtype=np.float64),
                rot=body_rot[bodies],
                slots=tuple(slots),
                has_free=any(free),
                free=np.array(free, dtype=np.float64)[:, None],
                free_qpos=mt.gather([a + k for a in qadr for k in range(7)], model.nq),
                free_axis=np.array(
                    [model.jnt_axis[a] if f else [0.0, 0.0, 1.0] for a, f in zip(adrs, free)]
                ),
            )
        )
        previous = bodies

    kinds = model.jnt_type[model.dof_jnt] if nv else np.zeros(0, np.int64)
    offset_in_joint = np.arange(nv) - model.jnt_dofadr[model.dof_jnt] if nv else np.zeros(0)
    column, translation = np.zeros((nv, 1, 3)), np.zeros((nv, 3))
    for d in range(nv):
        k = int(offset_in_joint[d])
        if kinds[d] == BALL:
            column[d, 0, k] = 1.0
        elif kinds[d] == FREE and k >= 3:
            column[d, 0, k - 3] = 1.0
        elif kinds[d] == FREE:
            translation[d, k] = 1.0
    return Plan(
        levels=tuple(levels),
        body_order=mt.gather(body_order, nbody),
        jnt_order=mt.gather(jnt_order, njnt),
        world_pos=np.zeros((1, 3)),
        world_mat=np.eye(3)[None],
        geom_body=mt.gather(model.geom_body, nbody),
        site_body=mt.gather(model.site_body, nbody),
        com_weights=mt.const_matrix(model.com_weights),
        root=mt.gather(model.body_rootid, nbody),
        inertia_rows=model.body_inertia[:, None, :].copy(),
        mass_column=model.body_mass[:, None].copy(),
        dof_jnt=mt.gather(model.dof_jnt, njnt),
        dof_body=mt.gather(model.dof_body, nbody),
        simple=np.isin(kinds, (HINGE, SLIDE)).astype(np.float64)[:, None],
        column=tuple(column[:, 0, k : k + 1].copy() for k in range(3)),
        translation=translation,
        has_column=bool(column.any()),
        has_translation=bool(translation.any()),
        rotational=model.dof_rotational[:, None].copy(),
        empty_cdof=np.zeros((0, 6)),
    )


def _slot(model: Model, joints, n: int) -> JointSlot:
    qadr, qpos0 = np.zeros(n, np.int64), np.zeros(n)
    axis, pos = np.zeros((n, 3)), np.zeros((n, 3))
    hinge, slide, ball = np.zeros(n), np.zeros(n), np.zeros((n, 1, 1))
    cross, cross_sq = np.zeros((n, 3, 3)), np.zeros((n, 3, 3))
    ball_qpos = np.zeros((n, 4), np.int64)
    for k, j in enumerate(joints):
        if j < 0:
            continue
        kind = int(model.jnt_type[j])
        axis[k], pos[k] = model.jnt_axis[j], model.jnt_pos[j]
        if kind in (HINGE, SLIDE):
            qadr[k] = model.jnt_qposadr[j]
            qpos0[k] = model.qpos0[qadr[k]]
        if kind == HINGE:
            hinge[k] = 1.0
            cross[k] = _skew(axis[k])
            cross_sq[k] = cross[k] @ cross[k]
        elif kind == SLIDE:
            slide[k] = 1.0
        elif kind == BALL:
            ball[k] = 1.0
            ball_qpos[k] = model.jnt_qposadr[j] + np.arange(4)
    return JointSlot(
        qadr=mt.gather(qadr, model.nq),
        qpos0=qpos0,
        axis=axis,
        pos=pos,
        hinge=hinge,
        slide=slide,
        cross=cross,
        cross_sq=cross_sq,
        has_ball=bool(ball.any()),
        ball=ball,
        ball_qpos=mt.gather(ball_qpos.reshape(-1), model.nq),
    )


# ----------------------------------------------------------------------------------------------
# Kernels
# ----------------------------------------------------------------------------------------------


def kinematics(xp, model: Model, qpos) -> dict:
    """Frames of every body, joint, geom and site.

    Args:
        xp: the backend namespace.
        model: the model.
        qpos: joint positions *[..., nq]*.

    Returns:
        ``{"xpos": [..., nbody, 3], "xmat": [..., nbody, 3, 3], "xanchor": [..., njnt, 3],
        "xaxis": [..., njnt, 3], "xipos", "ximat", "geom_xpos", "geom_xmat", "site_xpos",
        "site_xmat"}``, MuJoCo's fields of those names (matrices as ``[..., 3, 3]``).

    Example:
        >>> kinematics(xp, model, model.qpos0)["xpos"][:, 2]     # the Hopper's body heights
        array([0.  , 1.25, 1.05, 0.35, 0.  ])
    """
    p = model.kin
    zero = qpos[..., :1, None] * 0.0  # [..., 1, 1]: broadcasts constants to the batch
    pos_prev = const(xp, p.world_pos, qpos) + zero
    mat_prev = const(xp, p.world_mat, qpos) + zero[..., None]
    positions, matrices, anchors, axes = [pos_prev], [mat_prev], [], []
    for level in p.levels:
        parent_pos = mt.take(xp, pos_prev, level.parent, axis=-2)
        parent_mat = mt.take(xp, mat_prev, level.parent, axis=-3)
        pos = parent_pos + mt.mv(xp, parent_mat, const(xp, level.pos, qpos))
        mat = mt.mm(xp, parent_mat, const(xp, level.rot, qpos))
        for slot in level.slots:
            pos, mat, anchor, axis = _apply_joints(xp, slot, qpos, pos, mat)
            anchors.append(anchor)
            axes.append(axis)
        if level.has_free:
            values = mt.take(xp, qpos, level.free_qpos, axis=-1)
            values = xp.reshape(values, tuple(values.shape[:-1]) + (level.n, 7))
            flag = const(xp, level.free, qpos) > 0.5
            pos = xp.where(flag, values[..., :3], pos)
            mat = xp.where(flag[..., None], mt.quat_to_mat(xp, values[..., 3:]), mat)
            anchors.append(pos)
            axes.append(const(xp, level.free_axis, qpos) + zero)
        positions.append(pos)
        matrices.append(mat)
        pos_prev, mat_prev = pos, mat
    xpos = mt.take(xp, xp.concat(positions, axis=-2), p.body_order, axis=-2)
    xmat = mt.take(xp, xp.concat(matrices, axis=-3), p.body_order, axis=-3)
    out = {"xpos": xpos, "xmat": xmat}
    if model.njnt:
        out["xanchor"] = mt.take(xp, xp.concat(anchors, axis=-2), p.jnt_order, axis=-2)
        out["xaxis"] = mt.take(xp, xp.concat(axes, axis=-2), p.jnt_order, axis=-2)
    else:
        out["xanchor"] = out["xaxis"] = xpos[..., :0, :]
    out["xipos"], out["ximat"] = local_frames(
        xp, xpos, xmat, None, model.body_ipos, model.body_irot
    )
    out["geom_xpos"], out["geom_xmat"] = local_frames(
        xp, xpos, xmat, p.geom_body if model.ngeom else False, model.geom_pos, model.geom_rot
    )
    out["site_xpos"], out["site_xmat"] = local_frames(
        xp, xpos, xmat, p.site_body if model.nsite else False, model.site_pos, model.site_rot
    )
    return out


def local_frames(xp, xpos, xmat, bodies, pos, rot):
    """World frames of frames fixed to bodies (``mj_local2Global``): ``bodies`` the body of
    each (a :class:`~ivy_robot.physics._math.Gather`; None: one per body; False: no frame),
    ``pos``/``rot`` their offsets in the body frame."""
    if bodies is False:
        return xpos[..., :0, :], xmat[..., :0, :, :]
    if bodies is not None:
        xpos = mt.take(xp, xpos, bodies, axis=-2)
        xmat = mt.take(xp, xmat, bodies, axis=-3)
    return (
        xpos + mt.mv(xp, xmat, const(xp, pos, xpos)),
        mt.mm(xp, xmat, const(xp, rot, xpos)),
    )


def _apply_joints(xp, slot: JointSlot, qpos, pos, mat):
    """One joint of every body of a level (hinge or slide; ball where a body has one)."""
    axis = mt.mv(xp, mat, const(xp, slot.axis, qpos))
    anchor = pos + mt.mv(xp, mat, const(xp, slot.pos, qpos))
    theta = mt.take(xp, qpos, slot.qadr, axis=-1) - const(xp, slot.qpos0, qpos)
    angle = theta * const(xp, slot.hinge, qpos)
    shift = theta * const(xp, slot.slide, qpos)
    half = xp.sin(angle * 0.5)
    sin, versine = xp.sin(angle), 2.0 * half * half  # versine = 1 - cos, without cancellation
    local = (
        mt.eye3(xp, qpos)
        + sin[..., None, None] * const(xp, slot.cross, qpos)
        + versine[..., None, None] * const(xp, slot.cross_sq, qpos)
    )
    if slot.has_ball:
        quat = mt.take(xp, qpos, slot.ball_qpos, axis=-1)
        quat = xp.reshape(quat, tuple(quat.shape[:-1]) + (len(slot.qpos0), 4))
        local = xp.where(const(xp, slot.ball, qpos) > 0.5, mt.quat_to_mat(xp, quat), local)
    mat = mt.mm(xp, mat, local)
    pos = anchor - mt.mv(xp, mat, const(xp, slot.pos, qpos)) + axis * shift[..., None]
    return pos, mat, anchor, axis


# ----------------------------------------------------------------------------------------------
# Quantities about each tree's centre of mass (mj_comPos)
# ----------------------------------------------------------------------------------------------


def com_pos(xp, model: Model, kin: dict) -> dict:
    """MuJoCo's ``mj_comPos``: subtree centres of mass, body inertias and dof motion axes about
    the centre of mass of each body's tree (``subtree_com[body_rootid]``).

    Args:
        xp: the backend namespace.
        model: the model.
        kin: :func:`kinematics`' result.

    Returns:
        ``{"subtree_com": [..., nbody, 3], "cinert": [..., nbody, 10], "cdof": [..., nv, 6],
        "origin": [..., nbody, 3]}``: MuJoCo's fields (``cinert`` in MuJoCo's layout: the
        rotational inertia's ``xx, yy, zz, xy, xz, yz``, then ``mass * (xipos - origin)`` and
        the mass), and each body's frame origin (its tree's centre of mass).

    Example:
        >>> com = com_pos(xp, model, kinematics(xp, model, model.qpos0))
        >>> com["cinert"][1:, 9]                                  # the bodies' masses
        array([3.66519143, 4.05789051, 2.7813567 , 5.31557477])
    """
    p = model.kin
    xipos, ximat = kin["xipos"], kin["ximat"]
    subtree_com = mt.cmatmul(xp, p.com_weights, xipos)
    origin = mt.take(xp, subtree_com, p.root, axis=-2)
    offset = xipos - origin
    mass = const(xp, model.body_mass, xipos)
    scaled = ximat * const(xp, p.inertia_rows, xipos)
    about_com = mt.contract(xp, scaled, xp.matrix_transpose(ximat))  # R diag(inertia) R^T
    square = mt.dot(xp, offset, offset)
    rows = []
    for r, c in ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)):
        shift = (square if r == c else 0.0) - offset[..., r] * offset[..., c]
        rows.append(about_com[..., r, c] + mass * shift)
    h = const(xp, p.mass_column, xipos) * offset
    cinert = xp.stack(rows + [h[..., 0], h[..., 1], h[..., 2], mass + 0.0 * square], axis=-1)
    return {
        "subtree_com": subtree_com,
        "origin": origin,
        "cinert": cinert,
        "cdof": dof_axes(xp, model, kin, origin),
    }


def dof_axes(xp, model: Model, kin: dict, origin):
    """MuJoCo's ``cdof`` *[..., nv, 6]*: each dof's motion (angular, linear) about its body's
    tree origin. Hinges rotate about their world axis through their anchor, slides translate
    along it; ball and free rotations are about the body's final axes, free translations along
    the world's.

    Example:
        >>> kin = kinematics(xp, model, model.qpos0)
        >>> dof_axes(xp, model, kin, com_pos(xp, model, kin)["origin"])[0]   # rootx slides
        array([0., 0., 0., 1., 0., 0.])
    """
    p = model.kin
    xmat = kin["xmat"]
    if model.nv == 0:
        return xmat[..., :0, 0, :] * 0.0 + const(xp, p.empty_cdof, xmat)
    axis = mt.take(xp, kin["xaxis"], p.dof_jnt, axis=-2) * const(xp, p.simple, xmat)
    if p.has_column:
        body_mat = mt.take(xp, xmat, p.dof_body, axis=-3)
        for k in range(3):
            axis = axis + body_mat[..., :, k] * const(xp, p.column[k], xmat)
    if p.has_translation:
        axis = axis + const(xp, p.translation, xmat)
    anchor = mt.take(xp, kin["xanchor"], p.dof_jnt, axis=-2)
    dof_origin = mt.take(xp, origin, p.dof_body, axis=-2)
    rot = const(xp, p.rotational, xmat)
    angular = rot * axis
    linear = rot * mt.cross(xp, axis, dof_origin - anchor) + (1.0 - rot) * axis
    return xp.concat([angular, linear], axis=-1)
