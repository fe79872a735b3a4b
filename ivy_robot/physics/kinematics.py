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
(angular, linear), all as products with constant masks of the tree.
"""

from __future__ import annotations

import numpy as np

from ivy_robot.physics import _math as mt
from ivy_robot.physics.model import BALL, FREE, HINGE, SLIDE, Model, const


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
    """
    zero = qpos[..., :1, None] * 0.0  # [..., 1, 1]: broadcasts constants to the batch
    pos_prev = const(xp, np.zeros((1, 3)), qpos) + zero
    mat_prev = const(xp, np.eye(3)[None], qpos) + zero[..., None]
    positions, matrices, anchors, axes = [pos_prev], [mat_prev], [], []
    for level in model.levels:
        parent_pos = mt.take(xp, pos_prev, level.parent, axis=-2)
        parent_mat = mt.take(xp, mat_prev, level.parent, axis=-3)
        pos = parent_pos + mt.mv(xp, parent_mat, const(xp, level.pos, qpos))
        mat = mt.mm(xp, parent_mat, const(xp, level.rot, qpos))
        for slot in level.slots:
            pos, mat, anchor, axis = _apply_joints(xp, slot, qpos, pos, mat)
            anchors.append(anchor)
            axes.append(axis)
        if any(adr >= 0 for adr in level.free):
            pos, mat = _free_joints(xp, model, level, qpos, pos, mat)
            anchors.append(pos)
            axes.append(const(xp, np.tile([0.0, 0.0, 1.0], (len(level.bodies), 1)), qpos) + zero)
        positions.append(pos)
        matrices.append(mat)
        pos_prev, mat_prev = pos, mat
    xpos = mt.take(xp, xp.concat(positions, axis=-2), model.body_order, axis=-2)
    xmat = mt.take(xp, xp.concat(matrices, axis=-3), model.body_order, axis=-3)
    out = {"xpos": xpos, "xmat": xmat}
    if model.njnt:
        out["xanchor"] = mt.take(xp, xp.concat(anchors, axis=-2), model.jnt_order, axis=-2)
        out["xaxis"] = mt.take(xp, xp.concat(axes, axis=-2), model.jnt_order, axis=-2)
    else:
        out["xanchor"] = out["xaxis"] = xpos[..., :0, :]
    out["xipos"], out["ximat"] = local_frames(xp, xpos, xmat, None, model.body_ipos,
                                              model.body_irot)  # fmt: skip
    out["geom_xpos"], out["geom_xmat"] = local_frames(
        xp, xpos, xmat, model.geom_body, model.geom_pos, model.geom_rot
    )
    out["site_xpos"], out["site_xmat"] = local_frames(
        xp, xpos, xmat, model.site_body, model.site_pos, model.site_rot
    )
    return out


def local_frames(xp, xpos, xmat, bodies, pos, rot):
    """World frames of frames fixed to bodies (``mj_local2Global``): ``bodies`` the body of
    each (None: one per body), ``pos``/``rot`` their offsets in the body frame."""
    if bodies is not None:
        if len(bodies) == 0:
            return xpos[..., :0, :], xmat[..., :0, :, :]
        xpos = mt.take(xp, xpos, bodies, axis=-2)
        xmat = mt.take(xp, xmat, bodies, axis=-3)
    return (
        xpos + mt.mv(xp, xmat, const(xp, pos, xpos)),
        mt.mm(xp, xmat, const(xp, rot, xpos)),
    )


def _apply_joints(xp, slot, qpos, pos, mat):
    """One joint of every body of a level (hinge or slide; ball where a body has one)."""
    axis = mt.mv(xp, mat, const(xp, slot.axis, qpos))
    anchor = pos + mt.mv(xp, mat, const(xp, slot.pos, qpos))
    theta = mt.take(xp, qpos, slot.qadr, axis=-1) - const(xp, slot.qpos0, qpos)
    angle = theta * const(xp, slot.hinge[:, 0], qpos)
    shift = theta * const(xp, slot.slide[:, 0], qpos)
    half = xp.sin(angle * 0.5)
    sin, versine = xp.sin(angle), 2.0 * half * half  # versine = 1 - cos, without cancellation
    local = (
        mt.eye3(xp, qpos)
        + sin[..., None, None] * const(xp, slot.cross, qpos)
        + versine[..., None, None] * const(xp, slot.cross_sq, qpos)
    )
    balls = [adr for adr in slot.ball if adr >= 0]
    if balls:
        is_ball = np.array([[[adr >= 0]] for adr in slot.ball])
        gather = np.array([[max(adr, 0) + k for k in range(4)] for adr in slot.ball])
        quat = mt.take(xp, qpos, gather.reshape(-1), axis=-1)
        quat = xp.reshape(quat, tuple(quat.shape[:-1]) + gather.shape)
        local = xp.where(const(xp, is_ball, qpos) > 0.5, mt.quat_to_mat(xp, quat), local)
    mat = mt.mm(xp, mat, local)
    pos = anchor - mt.mv(xp, mat, const(xp, slot.pos, qpos)) + axis * shift[..., None]
    return pos, mat, anchor, axis


def _free_joints(xp, model, level, qpos, pos, mat):
    """Bodies of a level with a free joint take their world pose from ``qpos``."""
    is_free = np.array([adr >= 0 for adr in level.free])
    gather = np.array([[max(adr, 0) + k for k in range(7)] for adr in level.free])
    values = mt.take(xp, qpos, gather.reshape(-1), axis=-1)
    values = xp.reshape(values, tuple(values.shape[:-1]) + gather.shape)
    flag = const(xp, is_free[:, None], qpos) > 0.5
    pos = xp.where(flag, values[..., :3], pos)
    mat = xp.where(flag[..., None], mt.quat_to_mat(xp, values[..., 3:]), mat)
    return pos, mat


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
    """
    xipos, ximat = kin["xipos"], kin["ximat"]
    subtree_com = xp.matmul(const(xp, model.com_weights, xipos), xipos)
    origin = mt.take(xp, subtree_com, model.body_rootid, axis=-2)
    offset = xipos - origin
    mass = const(xp, model.body_mass, xipos)
    scaled = ximat * const(xp, model.body_inertia[:, None, :], xipos)
    about_com = xp.sum(scaled[..., :, None, :] * ximat[..., None, :, :], axis=-1)  # R diag R^T
    square = mt.dot(xp, offset, offset)
    rows = []
    for r, c in ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)):
        shift = (square if r == c else 0.0) - offset[..., r] * offset[..., c]
        rows.append(about_com[..., r, c] + mass * shift)
    h = mass[:, None] * offset
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
    the world's."""
    nv = model.nv
    xmat = kin["xmat"]
    if nv == 0:
        return xmat[..., :0, 0, :] * const(xp, np.zeros(6), xmat)
    kinds = model.jnt_type[model.dof_jnt]
    first = model.jnt_dofadr[model.dof_jnt]
    offset_in_joint = np.arange(nv) - first
    rotational = model.dof_rotational
    simple = np.isin(kinds, (HINGE, SLIDE)).astype(np.float64)
    # the k-th rotation of a ball or free joint turns about the k-th column of the body's frame
    column = np.zeros((nv, 1, 3))
    translation = np.zeros((nv, 3))
    for d in range(nv):
        if kinds[d] == BALL:
            column[d, 0, offset_in_joint[d]] = 1.0
        elif kinds[d] == FREE:
            if offset_in_joint[d] >= 3:
                column[d, 0, offset_in_joint[d] - 3] = 1.0
            else:
                translation[d, offset_in_joint[d]] = 1.0
    axis = mt.take(xp, kin["xaxis"], model.dof_jnt, axis=-2) * const(xp, simple[:, None], xmat)
    if column.any():
        body_mat = mt.take(xp, xmat, model.dof_body, axis=-3)
        axis = axis + xp.sum(body_mat * const(xp, column, xmat), axis=-1)
    if translation.any():
        axis = axis + const(xp, translation, xmat)
    anchor = mt.take(xp, kin["xanchor"], model.dof_jnt, axis=-2)
    dof_origin = mt.take(xp, origin, model.dof_body, axis=-2)
    rot = const(xp, rotational[:, None], xmat)
    angular = rot * axis
    linear = rot * mt.cross(xp, axis, dof_origin - anchor) + (1.0 - rot) * axis
    return xp.concat([angular, linear], axis=-1)
