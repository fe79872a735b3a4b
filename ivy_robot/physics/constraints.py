"""Constraint rows and their impedance (MuJoCo's ``mj_makeConstraint``, ``mj_makeImpedance``
and ``mj_referenceConstraint``), written once.

The rows are laid out once per model, for every candidate (:func:`plan`), in MuJoCo's order:

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

__all__ = ["Layout", "impedance", "make_constraints", "point_jacobians", "reference"]


@dataclass(frozen=True, eq=False)
class Layout:
    """The candidate constraint rows of a model (numpy constants, Python flags; see the module
    docstring), ``model.rows``.

    Example:
        >>> model.rows.nefc, model.rows.nf, model.rows.nl, model.rows.ncon   # the Hopper
        (44, 0, 6, 14)
    """

    nefc: int
    kind: np.ndarray  # [nefc] ROW_FRICTION, ROW_LIMIT, ROW_CONTACT_*
    frictionloss: np.ndarray  # [nefc]
    margin: np.ndarray  # [nefc]
    diag_approx: np.ndarray  # [nefc]
    scale: np.ndarray  # [nefc]: 2 mu^2 / impratio on pyramid rows, 1 elsewhere
    stiffness: np.ndarray  # [nefc] K
    damping: np.ndarray  # [nefc] B
    solimp: tuple  # (d0, dwidth, width, midpoint, power), each [nefc], clamped as MuJoCo
    safe_width: np.ndarray  # [nefc] width, 1 where zero
    has_flat: bool
    flat: np.ndarray  # [nefc] 1.0 where the impedance is constant
    empty: np.ndarray  # [0]
    empty_jacobian: np.ndarray  # [0, nv]
    # friction loss
    nf: int
    friction_dofs: np.ndarray  # [nf]
    friction_jacobian: np.ndarray  # [nf, nv]
    friction_zero: np.ndarray  # [nf]
    # limits: per limited joint, lower and upper rows
    nl: int
    limit_qpos: mt.Gather
    limit_dof: np.ndarray  # [nl]
    limit_side: np.ndarray  # [nl] -1 lower, +1 upper
    limit_bound: np.ndarray  # [nl] the range's end
    limit_margin: np.ndarray  # [nl]
    limit_jacobian: np.ndarray  # [nl, nv]
    # contacts
    ncon: int
    contact_rows: np.ndarray  # [ncon] rows per contact (1 or 4)
    contact_first_row: np.ndarray  # [ncon] index of its first row in the efc layout
    contact_body: np.ndarray  # [ncon, 2]
    contact_side: tuple  # per side: (body Gather over nbody, chain [ncon, nv, 1])
    contact_friction: np.ndarray  # [ncon, 5]
    pyramids: np.ndarray  # contacts with condim 3
    pyramid_gather: mt.Gather
    pyramid_mu: np.ndarray  # [npyramid, 2, 1]
    frictionless: np.ndarray  # contacts with condim 1
    frictionless_gather: mt.Gather
    contact_order: mt.Gather  # from (pyramid edges in blocks, frictionless) to efc order
    row_contact: mt.Gather  # the contact of each contact row, in efc order


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


def plan(model: Model) -> Layout:
    """The constraint rows of ``model``, laid out once (see :class:`Layout`)."""
    nv = model.nv
    kind, floss, margin, diag, scale, solimp, stiff, damp = ([] for _ in range(8))

    def row(k, f, mg, d, imp, ref, frictional=False, factor=1.0):
        imp = _solimp(imp)
        kk, bb = _reference(model, ref, imp, frictional)
        kind.append(k), floss.append(f), margin.append(mg), diag.append(d), solimp.append(imp)
        stiff.append(kk), damp.append(bb), scale.append(factor)

    constrained = "constraint" not in model.disabled
    friction_dofs = np.flatnonzero(model.dof_frictionloss > 0) if constrained else []
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
    nf, nl = len(friction_dofs), len(dofs)
    contacts = _contact_rows(model, row, nf + nl)
    solimp = np.array(solimp, dtype=np.float64).reshape(-1, 5)
    limit_jacobian = np.zeros((nl, nv))
    limit_jacobian[np.arange(nl), np.asarray(dofs, np.int64)] = -np.asarray(sides, np.float64)
    return Layout(
        nefc=len(kind),
        kind=np.array(kind, dtype=np.int64),
        frictionloss=np.array(floss, dtype=np.float64),
        margin=np.array(margin, dtype=np.float64),
        diag_approx=np.array(diag, dtype=np.float64),
        scale=np.array(scale, dtype=np.float64),
        stiffness=np.array(stiff, dtype=np.float64),
        damping=np.array(damp, dtype=np.float64),
        solimp=tuple(solimp[:, k].copy() for k in range(5)),
        safe_width=np.where(solimp[:, 2] > MIN_VALUE, solimp[:, 2], 1.0),
        has_flat=bool(np.any((solimp[:, 0] == solimp[:, 1]) | (solimp[:, 2] <= MIN_VALUE))),
        flat=((solimp[:, 0] == solimp[:, 1]) | (solimp[:, 2] <= MIN_VALUE)).astype(np.float64),
        empty=np.zeros(0),
        empty_jacobian=np.zeros((0, nv)),
        nf=nf,
        friction_dofs=np.asarray(friction_dofs, dtype=np.int64),
        friction_jacobian=np.eye(nv)[np.asarray(friction_dofs, dtype=np.int64)],
        friction_zero=np.zeros(nf),
        nl=nl,
        limit_qpos=mt.gather(qadr, model.nq),
        limit_dof=np.array(dofs, dtype=np.int64),
        limit_side=np.array(sides, dtype=np.float64),
        limit_bound=np.array(bounds, dtype=np.float64),
        limit_margin=np.array(margin[nf : nf + nl], dtype=np.float64),
        limit_jacobian=limit_jacobian,
        **contacts,
    )


def _contact_rows(model: Model, row, first: int) -> dict:
    table = model.contacts
    ncon = 0 if table is None else int(table.ncon)
    if ncon:
        bodies = np.stack([np.asarray(table.body1), np.asarray(table.body2)], axis=-1)
        friction = np.asarray(table.friction, dtype=np.float64)
        dims = np.asarray(table.condim)
    else:
        bodies, friction, dims = np.zeros((0, 2), np.int64), np.zeros((0, 5)), np.zeros(0)
    pyramids = [c for c in range(ncon) if dims[c] == 3]
    plain = [c for c in range(ncon) if dims[c] == 1]
    rows_of, first_row = np.zeros(ncon, np.int64), np.zeros(ncon, np.int64)
    cursor, position = first, {}
    for c in range(ncon):
        invweight = model.body_invweight0[bodies[c]]
        translation = invweight[0, 0] + invweight[1, 0]
        mu = friction[c]
        solref, solimp = table.solref[c], table.solimp[c]
        if dims[c] == 1:
            edges = [(ROW_CONTACT_FRICTIONLESS, translation, 1.0)]
        else:
            pyramid_scale = 2.0 * mu[0] ** 2 / max(MIN_VALUE, model.impratio)
            edges = [(ROW_CONTACT_PYRAMIDAL, translation * (1.0 + mu[0] ** 2), pyramid_scale)] * 4
        rows_of[c], first_row[c], position[c] = len(edges), cursor, cursor - first
        for kind, diag, factor in edges:
            row(kind, 0.0, table.includemargin[c], diag, solimp, solref, factor=factor)
        cursor += len(edges)
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
    sides = tuple(
        (mt.gather(bodies[:, s], model.nbody), model.body_chain[bodies[:, s]][..., None].copy())
        for s in range(2)
    )
    return dict(
        ncon=ncon,
        contact_rows=rows_of,
        contact_first_row=first_row,
        contact_body=bodies,
        contact_side=sides,
        contact_friction=friction,
        pyramids=np.array(pyramids, np.int64),
        pyramid_gather=mt.gather(pyramids, ncon),
        pyramid_mu=friction[pyramids][:, :2, None].copy() if pyramids else np.zeros((0, 2, 1)),
        frictionless=np.array(plain, np.int64),
        frictionless_gather=mt.gather(plain, ncon),
        contact_order=mt.gather(order, len(order)),
        row_contact=mt.gather(row_contact, ncon),
    )


# ----------------------------------------------------------------------------------------------
# Kernels
# ----------------------------------------------------------------------------------------------


def point_jacobians(xp, model: Model, cdof, origin, bodies, chain, points):
    """Jacobians of points fixed to bodies (MuJoCo's ``mj_jac``), transposed: the linear and
    angular velocity of each point per unit velocity of each dof.

    Args:
        xp: the backend namespace.
        model: the model.
        cdof: *[..., nv, 6]* (``com_pos``).
        origin: each body's tree origin *[..., nbody, 3]* (``com_pos``).
        bodies: the body of each point (a :class:`~ivy_robot.physics._math.Gather`).
        chain: their dof chains, numpy *[P, nv, 1]* (``model.body_chain[bodies][..., None]``).
        points: world positions *[..., P, 3]*.

    Returns:
        ``(jacp, jacr)``, each *[..., P, nv, 3]*.

    Example:
        >>> foot = model.body_names.index("foot")
        >>> bodies, chain = gather([foot], model.nbody), model.body_chain[[foot]][..., None]
        >>> origin = data.subtree_com[model.body_rootid]
        >>> jacp, jacr = point_jacobians(xp, model, data.cdof, origin, bodies, chain,
        ...                              data.xpos[[foot]])          # at the foot's origin
        >>> jacp.shape, jacp[0, 0]                                   # rootx moves it along x
        ((1, 6, 3), array([1., 0., 0.]))
    """
    chain = const(xp, chain, points)
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

    Example:
        >>> contacts = find_contacts(xp, model, {"geom_xpos": data.geom_xpos,
        ...                                      "geom_xmat": data.geom_xmat})
        >>> rows = make_constraints(xp, model, data.qpos, data.cdof,
        ...                         data.subtree_com[model.body_rootid], contacts)
        >>> rows["efc_J"].shape, rows["efc_R"].shape    # the Hopper's candidate rows
        ((44, 6), (44,))
    """
    rows = model.rows
    like = qpos
    batch_zero = qpos[..., :1] * 0.0
    if rows.nefc == 0:
        empty = batch_zero[..., :0] + const(xp, rows.empty, like)
        return {
            "efc_J": empty[..., None] + const(xp, rows.empty_jacobian, like),
            "efc_pos": empty,
            "efc_active": empty > 0.0,
            "efc_imp": empty,
            "efc_R": empty,
            "efc_D": empty,
        }
    jacobians, positions, actives = [], [], []
    if rows.nf:
        jacobians.append(const(xp, rows.friction_jacobian, like) + batch_zero[..., None])
        positions.append(batch_zero + const(xp, rows.friction_zero, like))
        actives.append(positions[-1] == 0.0)
    if rows.nl:
        limit = mt.take(xp, qpos, rows.limit_qpos, axis=-1)
        dist = const(xp, rows.limit_side, like) * (const(xp, rows.limit_bound, like) - limit)
        jacobians.append(const(xp, rows.limit_jacobian, like) + batch_zero[..., None])
        positions.append(dist)
        actives.append(dist < const(xp, rows.limit_margin, like))
    if rows.ncon:
        jac, dist, active = _contact_jacobians(xp, model, rows, cdof, origin, contacts)
        jacobians.append(jac)
        positions.append(dist)
        actives.append(active)
    pos = xp.concat(positions, axis=-1)
    imp = impedance(xp, rows, pos, like)
    diag = const(xp, rows.diag_approx, like)
    regulariser = xp.maximum((1.0 - imp) * diag / imp, MIN_VALUE) * const(xp, rows.scale, like)
    return {
        "efc_J": xp.concat(jacobians, axis=-2),
        "efc_pos": pos,
        "efc_active": xp.concat(actives, axis=-1),
        "efc_imp": imp,
        "efc_R": regulariser,
        "efc_D": 1.0 / regulariser,
    }


def _contact_jacobians(xp, model, rows: Layout, cdof, origin, contacts):
    """Rows of the contacts: the Jacobian of the contact point on the second geom's body minus
    on the first's, in the contact frame; pyramid edges ``J_n +- mu_k J_tk``."""
    pos, frame = contacts.pos, contacts.frame
    (bodies1, chain1), (bodies2, chain2) = rows.contact_side
    jac1, _ = point_jacobians(xp, model, cdof, origin, bodies1, chain1, pos)
    jac2, _ = point_jacobians(xp, model, cdof, origin, bodies2, chain2, pos)
    diff = jac2 - jac1  # [..., ncon, nv, 3]
    in_frame = mt.contract(xp, frame, xp.matrix_transpose(diff))  # [..., C, 3, nv]
    blocks = []
    if len(rows.pyramids):
        p = mt.take(xp, in_frame, rows.pyramid_gather, axis=-3)
        mu = const(xp, rows.pyramid_mu, p)  # [Cp, 2, 1]
        normal = p[..., 0, :]
        for k in (1, 2):
            edge = mu[:, k - 1] * p[..., k, :]
            blocks += [normal + edge, normal - edge]
    if len(rows.frictionless):
        blocks.append(mt.take(xp, in_frame, rows.frictionless_gather, axis=-3)[..., 0, :])
    jac = mt.take(xp, xp.concat(blocks, axis=-2), rows.contact_order, axis=-2)
    dist = mt.take(xp, contacts.dist, rows.row_contact, axis=-1)
    active = mt.take(xp, contacts.active, rows.row_contact, axis=-1)
    return jac, dist, active


def impedance(xp, rows: Layout, pos, like):
    """MuJoCo's impedance ``imp(pos - margin)`` of every row, from its ``solimp``
    ``(d0, dwidth, width, midpoint, power)``: ``d0`` at no violation to ``dwidth`` at ``width``
    and beyond, along two power curves that meet at the midpoint.

    Example:
        >>> impedance(xp, model.rows, np.zeros(model.rows.nefc), data.qpos)[:2]  # at rest
        array([0.9, 0.9])
    """
    d0, d1, _, mid, power = (const(xp, s, like) for s in rows.solimp)
    safe_width = const(xp, rows.safe_width, like)
    x = xp.clip(xp.abs(pos - const(xp, rows.margin, like)) / safe_width, 0.0, 1.0)
    low = xp.pow(x, power) / xp.pow(mid, power - 1.0)
    high = 1.0 - xp.pow(1.0 - x, power) / xp.pow(1.0 - mid, power - 1.0)
    imp = d0 + xp.where(x <= mid, low, high) * (d1 - d0)
    if rows.has_flat:
        imp = xp.where(const(xp, rows.flat, like) > 0.5, 0.5 * (d0 + d1), imp)
    return imp


def reference(xp, model: Model, efc, qvel):
    """MuJoCo's ``mj_referenceConstraint``: row velocities ``J qvel`` and reference
    accelerations ``aref = -B vel - K imp (pos - margin)``. Returns ``(efc_vel, efc_aref)``.

    Example:
        >>> vel, aref = reference(xp, model, data.fields(), np.ones(model.nv))
        >>> vel.shape, aref.shape
        ((44,), (44,))
    """
    rows = model.rows
    vel = xp.matmul(efc["efc_J"], qvel[..., :, None])[..., 0]
    if rows.nefc == 0:
        return vel, vel
    stiffness = const(xp, rows.stiffness, qvel)
    damping = const(xp, rows.damping, qvel)
    violation = efc["efc_pos"] - const(xp, rows.margin, qvel)
    return vel, -damping * vel - stiffness * efc["efc_imp"] * violation
