"""Constraint rows and their impedance (MuJoCo's ``mj_makeConstraint``, ``mj_makeImpedance``
and ``mj_referenceConstraint``), written once.

The rows are laid out once per model, for every candidate (:func:`layout`), in MuJoCo's order:

- friction loss: one row per dof with ``frictionloss`` (``J = e_dof``, a box on its force);
- joint limits: two rows per limited hinge or slide, lower then upper (``J = -+e_dof``), active
  where the distance to the limit is below the joint's margin;
- contacts: per candidate contact of the model's contact table, in MuJoCo's contact order, one
  frictionless row (``condim`` 1) or the four edges of the pyramidal cone (``condim`` 3:
  ``J_n +- mu_k J_tk``, k = 1, 2), active where the collision finds the contact.

Each row has MuJoCo's soft-constraint parameters: an impedance ``imp(pos - margin)`` from
``solimp``, the regulariser ``R = (1 - imp) / imp * diagApprox`` (``diagApprox`` from the model's
``invweight0``; pyramidal rows share ``2 mu^2 / impratio`` times their normal's), ``D = 1 / R`` and
the reference acceleration ``aref = -B vel - K imp (pos - margin)`` from ``solref``.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from ivy_robot.physics import _math as mt
from ivy_robot.physics.model import (
    HINGE,
    MAX_IMPEDANCE,
    MIN_IMPEDANCE,
    MIN_VALUE,
    ROW_CONTACT_FRICTIONLESS,
    ROW_CONTACT_PYRAMIDAL,
    ROW_FRICTION,
    ROW_LIMIT,
    SLIDE,
    Model,
    const,
)


@dataclass(frozen=True, eq=False)
class Layout:
    """The candidate constraint rows of a model (numpy constants; see the module docstring)."""

    nefc: int
    kind: np.ndarray  # [nefc] ROW_FRICTION, ROW_LIMIT, ROW_CONTACT_*
    frictionloss: np.ndarray  # [nefc]
    margin: np.ndarray  # [nefc]
    diag_approx: np.ndarray  # [nefc]
    solimp: np.ndarray  # [nefc, 5], clamped as MuJoCo
    stiffness: np.ndarray  # [nefc] K
    damping: np.ndarray  # [nefc] B
    # friction loss
    friction_dofs: np.ndarray  # [nf]
    # limits: per limited joint, lower and upper rows
    limit_qadr: np.ndarray  # [nl]
    limit_dof: np.ndarray  # [nl]
    limit_side: np.ndarray  # [nl] -1 lower, +1 upper
    limit_bound: np.ndarray  # [nl] the range's end
    # contacts
    ncon: int
    contact_rows: np.ndarray  # [ncon] rows per contact (1 or 4)
    contact_first_row: np.ndarray  # [ncon] index of its first row in the efc layout
    contact_chain: np.ndarray  # [ncon, 2, nv] dof chains of the two bodies
    contact_body: np.ndarray  # [ncon, 2]
    contact_friction: np.ndarray  # [ncon, 5]
    pyramid_scale: np.ndarray  # [ncon]: R of the cone's rows / R of its normal (2 mu^2 / impratio)
    contact_order: np.ndarray  # [sum rows] permutation from (pyramids, frictionless) to efc order
    pyramids: np.ndarray  # contacts with condim 3
    frictionless: np.ndarray  # contacts with condim 1
    row_contact: np.ndarray  # [sum rows] the contact of each contact row (efc order)


def _solimp(values):
    values = np.array(values, dtype=np.float64)
    values[..., 0] = np.clip(values[..., 0], MIN_IMPEDANCE, MAX_IMPEDANCE)
    values[..., 1] = np.clip(values[..., 1], MIN_IMPEDANCE, MAX_IMPEDANCE)
    values[..., 2] = np.maximum(0.0, values[..., 2])
    values[..., 3] = np.clip(values[..., 3], MIN_IMPEDANCE, MAX_IMPEDANCE)
    values[..., 4] = np.maximum(1.0, values[..., 4])
    return values


def _reference(model: Model, solref, solimp, frictional: bool):
    """``(K, B)`` of one row from its ``solref`` and clamped ``solimp``."""
    solref = np.array(solref, dtype=np.float64)
    if (solref[0] > 0) ^ (solref[1] > 0):
        solref = np.array([0.02, 1.0])  # mixed formats: MuJoCo's default
    if "refsafe" not in model.disabled and solref[0] > 0:
        solref[0] = max(solref[0], 2.0 * model.timestep)
    dmax = solimp[1]
    if frictional:
        stiffness = 0.0
    elif solref[0] > 0:
        stiffness = 1.0 / max(MIN_VALUE, dmax * dmax * solref[0] ** 2 * solref[1] ** 2)
    else:
        stiffness = -solref[0] / max(MIN_VALUE, dmax * dmax)
    if solref[1] > 0:
        damping = 2.0 / max(MIN_VALUE, dmax * solref[0])
    else:
        damping = -solref[1] / max(MIN_VALUE, dmax)
    return stiffness, damping


@functools.cache
def layout(model: Model) -> Layout:
    """The constraint rows of ``model``, made once (see :class:`Layout`)."""
    kind, floss, margin, diag, solimp, stiff, damp = [], [], [], [], [], [], []

    def row(k, f, mg, d, imp, ref, frictional=False):
        imp = _solimp(imp)
        kk, bb = _reference(model, ref, imp, frictional)
        kind.append(k), floss.append(f), margin.append(mg), diag.append(d), solimp.append(imp)
        stiff.append(kk), damp.append(bb)

    constrained = "constraint" not in model.disabled
    friction_dofs = np.flatnonzero(model.dof_frictionloss > 0) if constrained else np.zeros(0)
    for d in friction_dofs:
        row(ROW_FRICTION, model.dof_frictionloss[d], 0.0, model.dof_invweight0[d],
            model.dof_solimp[d], model.dof_solref[d], frictional=True)  # fmt: skip
    qadr, dofs, sides, bounds = [], [], [], []
    if constrained and "limit" not in model.disabled:
        for j in range(model.njnt):
            if not model.jnt_limited[j] or model.jnt_type[j] not in (HINGE, SLIDE):
                continue
            dof = model.jnt_dofadr[j]
            for side in (-1, 1):
                qadr.append(model.jnt_qposadr[j]), dofs.append(dof), sides.append(side)
                bounds.append(model.jnt_range[j, (side + 1) // 2])
                row(ROW_LIMIT, 0.0, model.jnt_margin[j], model.dof_invweight0[dof],
                    model.jnt_solimp[j], model.jnt_solref[j])  # fmt: skip
    contacts = _contact_rows(model, row, len(kind))
    return Layout(
        nefc=len(kind),
        kind=np.array(kind, dtype=np.int64),
        frictionloss=np.array(floss, dtype=np.float64),
        margin=np.array(margin, dtype=np.float64),
        diag_approx=np.array(diag, dtype=np.float64),
        solimp=np.array(solimp, dtype=np.float64).reshape(-1, 5),
        stiffness=np.array(stiff, dtype=np.float64),
        damping=np.array(damp, dtype=np.float64),
        friction_dofs=np.asarray(friction_dofs, dtype=np.int64),
        limit_qadr=np.array(qadr, dtype=np.int64),
        limit_dof=np.array(dofs, dtype=np.int64),
        limit_side=np.array(sides, dtype=np.float64),
        limit_bound=np.array(bounds, dtype=np.float64),
        **contacts,
    )


def _contact_rows(model: Model, row, first: int) -> dict:
    table = model.contacts
    ncon = 0 if table is None else int(table.ncon)
    out = dict(
        ncon=ncon,
        contact_rows=np.zeros(ncon, np.int64),
        contact_first_row=np.zeros(ncon, np.int64),
        contact_chain=np.zeros((ncon, 2, model.nv)),
        contact_body=np.zeros((ncon, 2), np.int64),
        contact_friction=np.zeros((ncon, 5)),
        pyramid_scale=np.zeros(ncon),
        contact_order=np.zeros(0, np.int64),
        pyramids=np.zeros(0, np.int64),
        frictionless=np.zeros(0, np.int64),
        row_contact=np.zeros(0, np.int64),
    )
    if ncon == 0:
        return out
    bodies = model.geom_body[np.asarray(table.geom)]
    out["contact_body"] = bodies
    out["contact_chain"] = model.body_chain[bodies]
    out["contact_friction"] = np.asarray(table.friction, dtype=np.float64)
    dims = np.asarray(table.dim)
    pyramids = [c for c in range(ncon) if dims[c] == 3]
    plain = [c for c in range(ncon) if dims[c] == 1]
    cursor = first
    position = {}
    for c in range(ncon):
        invweight = model.body_invweight0[bodies[c]]
        translation = invweight[0, 0] + invweight[1, 0]
        mu = out["contact_friction"][c]
        solref, solimp = table.solref[c], table.solimp[c]
        if dims[c] == 1:
            rows = [(ROW_CONTACT_FRICTIONLESS, translation)]
        else:
            first_row = translation * (1.0 + mu[0] ** 2)
            rows = [(ROW_CONTACT_PYRAMIDAL, first_row)] * 4
            out["pyramid_scale"][c] = 2.0 * mu[0] ** 2 / max(MIN_VALUE, model.impratio)
        out["contact_rows"][c] = len(rows)
        out["contact_first_row"][c] = cursor
        position[c] = cursor - first
        for kind, diag in rows:
            row(kind, 0.0, table.includemargin[c], diag, solimp, solref)
        cursor += len(rows)
    # rows are computed in blocks: the four edges of every pyramid (edge by edge: all first
    # edges, then all second...), then the frictionless rows; order maps them to efc's
    order = np.zeros(cursor - first, np.int64)
    row_contact = np.zeros(cursor - first, np.int64)
    for p, c in enumerate(pyramids):
        order[position[c] : position[c] + 4] = [e * len(pyramids) + p for e in range(4)]
        row_contact[position[c] : position[c] + 4] = c
    for q, c in enumerate(plain):
        order[position[c]] = 4 * len(pyramids) + q
        row_contact[position[c]] = c
    out["contact_order"] = order
    out["row_contact"] = row_contact
    out["pyramids"] = np.array(pyramids, np.int64)
    out["frictionless"] = np.array(plain, np.int64)
    return out


# ----------------------------------------------------------------------------------------------
# Arrays
# ----------------------------------------------------------------------------------------------


def point_jacobians(xp, model: Model, cdof, origin, bodies, points):
    """Jacobians of points fixed to bodies (MuJoCo's ``mj_jac``), transposed: the linear and
    angular velocity of each point per unit velocity of each dof.

    Args:
        xp: the backend namespace.
        model: the model.
        cdof: *[..., nv, 6]* (``com_pos``).
        origin: each body's tree origin *[..., nbody, 3]* (``com_pos``).
        bodies: the body of each point (numpy ints) *[P]*.
        points: world positions *[..., P, 3]*.

    Returns:
        ``(jacp, jacr)``, each *[..., P, nv, 3]*.
    """
    chain = const(xp, model.body_chain[np.asarray(bodies)][..., None], points)  # [P, nv, 1]
    offset = points - mt.take(xp, origin, bodies, axis=-2)  # [..., P, 3]
    angular = cdof[..., None, :, :3]  # [..., 1, nv, 3]
    linear = cdof[..., None, :, 3:] + mt.cross(xp, angular, offset[..., :, None, :])
    return linear * chain, angular * chain


def make_constraints(xp, model: Model, qpos, cdof, origin, contacts):
    """The position-dependent part of the rows: Jacobian, distance, activity and impedance.

    Args:
        xp: the backend namespace.
        model: the model.
        qpos: *[..., nq]*.
        cdof, origin: from ``com_pos``.
        contacts: the collision's contacts (``dist``, ``pos``, ``frame``, ``active``), or None
            when the model has no candidate contacts.

    Returns:
        ``{"efc_J": [..., nefc, nv], "efc_pos", "efc_active", "efc_imp", "efc_R", "efc_D":
        [..., nefc]}``.
    """
    rows = layout(model)
    like = qpos
    jacobians, positions, actives = [], [], []
    batch_zero = qpos[..., :1] * 0.0
    if len(rows.friction_dofs):
        eye = np.eye(model.nv)[rows.friction_dofs]
        jacobians.append(const(xp, eye, like) + batch_zero[..., None])
        positions.append(xp.zeros_like(batch_zero) + const(xp, np.zeros(len(eye)), like))
        actives.append(positions[-1] == 0.0)
    if len(rows.limit_dof):
        side = rows.limit_side
        dist = const(xp, side, like) * (
            const(xp, rows.limit_bound, like) - mt.take(xp, qpos, rows.limit_qadr, axis=-1)
        )
        jac = np.zeros((len(side), model.nv))
        jac[np.arange(len(side)), rows.limit_dof] = -side
        jacobians.append(const(xp, jac, like) + batch_zero[..., None])
        positions.append(dist)
        nf = len(rows.friction_dofs)
        actives.append(dist < const(xp, rows.margin[nf : nf + len(side)], like))
    if rows.ncon:
        jac, dist, active = _contact_jacobians(xp, model, rows, cdof, origin, contacts)
        jacobians.append(jac)
        positions.append(dist)
        actives.append(active)
    if not jacobians:
        empty = qpos[..., :0] * 0.0
        return {
            "efc_J": empty[..., None] * const(xp, np.zeros(model.nv), like),
            "efc_pos": empty,
            "efc_active": empty > 0.0,
            "efc_imp": empty,
            "efc_R": empty,
            "efc_D": empty,
        }
    pos = xp.concat(positions, axis=-1)
    imp = impedance(xp, rows, pos, like)
    scale = np.ones(rows.nefc)
    contact_rows = rows.kind == ROW_CONTACT_PYRAMIDAL
    scale[contact_rows] = rows.pyramid_scale[_contact_of_rows(rows)[contact_rows]]
    diag = const(xp, rows.diag_approx, like)
    regulariser = xp.maximum((1.0 - imp) * diag / imp, MIN_VALUE) * const(xp, scale, like)
    return {
        "efc_J": xp.concat(jacobians, axis=-2),
        "efc_pos": pos,
        "efc_active": xp.concat(actives, axis=-1),
        "efc_imp": imp,
        "efc_R": regulariser,
        "efc_D": 1.0 / regulariser,
    }


def _contact_of_rows(rows: Layout) -> np.ndarray:
    """The contact of each efc row (-1 for rows that are not contacts)."""
    out = np.full(rows.nefc, -1, np.int64)
    if rows.ncon:
        out[rows.nefc - len(rows.row_contact) :] = rows.row_contact
    return out


def _contact_jacobians(xp, model, rows: Layout, cdof, origin, contacts):
    """Rows of the contacts: the Jacobian of the contact point on the second geom's body minus
    on the first's, in the contact frame; pyramid edges ``J_n +- mu_k J_tk``."""
    pos, frame = contacts.pos, contacts.frame
    jac1, _ = point_jacobians(xp, model, cdof, origin, rows.contact_body[:, 0], pos)
    jac2, _ = point_jacobians(xp, model, cdof, origin, rows.contact_body[:, 1], pos)
    diff = jac2 - jac1  # [..., ncon, nv, 3]
    in_frame = xp.sum(frame[..., :, None, :, :] * diff[..., None, :, :], axis=-1)  # [.,C,3,nv]
    blocks = []
    if len(rows.pyramids):
        p = mt.take(xp, in_frame, rows.pyramids, axis=-3)
        mu = const(xp, rows.contact_friction[rows.pyramids][:, :2, None], p)  # [Cp, 2, 1]
        normal = p[..., 0, :]
        for k in (1, 2):
            edge = mu[:, k - 1] * p[..., k, :]
            blocks += [normal + edge, normal - edge]
    if len(rows.frictionless):
        blocks.append(mt.take(xp, in_frame, rows.frictionless, axis=-3)[..., 0, :])
    jac = mt.take(xp, xp.concat(blocks, axis=-2), rows.contact_order, axis=-2)
    dist = mt.take(xp, contacts.dist, rows.row_contact, axis=-1)
    active = mt.take(xp, contacts.active, rows.row_contact, axis=-1)
    return jac, dist, active


def impedance(xp, rows: Layout, pos, like):
    """MuJoCo's impedance ``imp(pos - margin)`` of every row, from its ``solimp``
    ``(d0, dwidth, width, midpoint, power)``: ``d0`` at no violation to ``dwidth`` at ``width``
    and beyond, along two power curves that meet at the midpoint."""
    s = rows.solimp
    d0, d1, width, mid, power = (const(xp, s[:, k], like) for k in range(5))
    flat = (s[:, 0] == s[:, 1]) | (s[:, 2] <= MIN_VALUE)
    safe_width = const(xp, np.where(s[:, 2] > MIN_VALUE, s[:, 2], 1.0), like)
    x = xp.clip(xp.abs(pos - const(xp, rows.margin, like)) / safe_width, 0.0, 1.0)
    low = xp.pow(x, power) / xp.pow(mid, power - 1.0)
    high = 1.0 - xp.pow(1.0 - x, power) / xp.pow(1.0 - mid, power - 1.0)
    y = xp.where(x <= mid, low, high)
    imp = d0 + y * (d1 - d0)
    if flat.any():
        imp = xp.where(const(xp, flat.astype(np.float64), like) > 0.5, 0.5 * (d0 + d1), imp)
    return imp


def reference(xp, model: Model, efc, qvel):
    """MuJoCo's ``mj_referenceConstraint``: row velocities ``J qvel`` and reference
    accelerations ``aref = -B vel - K imp (pos - margin)``. Returns ``(efc_vel, efc_aref)``."""
    rows = layout(model)
    vel = xp.sum(efc["efc_J"] * qvel[..., None, :], axis=-1)
    stiffness = const(xp, rows.stiffness, qvel)
    damping = const(xp, rows.damping, qvel)
    violation = efc["efc_pos"] - const(xp, rows.margin, qvel)
    return vel, -damping * vel - stiffness * efc["efc_imp"] * violation
