"""Collision detection between geoms, as MuJoCo's ``mj_collision`` finds contacts.

A compiled MuJoCo model is read once into a :class:`ContactTable`: every geom pair that MuJoCo's
filters let collide, each with a fixed number of candidate contacts (the most its collision
function can return) and the contact parameters MuJoCo gives them, in the order in which MuJoCo
lists contacts in ``d.contact``. :func:`collide` then computes all candidate contacts at once on
any backend: one vectorised call per pair kind, then one constant permutation into MuJoCo's
order. A candidate is ``found`` where MuJoCo lists it in ``d.contact`` and ``active`` where it
also enters the constraints, so the active candidates, read in order, are MuJoCo's constraint
contacts in MuJoCo's order.

Pair kinds (each a function ``(xp, pos1, mat1, size1, pos2, mat2, size2, margin) -> (dist, pos,
frame, found)``, batched over ``[...]``): plane with sphere, capsule, box and cylinder;
sphere-sphere, sphere-capsule, capsule-capsule. They behave as MuJoCo's ``mjc_PlaneSphere``,
``mjc_PlaneCapsule``, ``mjc_PlaneBox``, ``mjc_PlaneCylinder``, ``mjc_SphereSphere``,
``mjc_SphereCapsule`` and ``mjc_CapsuleCapsule``, degenerate configurations included, and the
contact frames are completed as ``mju_makeFrame`` completes them.

Margins and gaps (MuJoCo 4): a geom pair's margin and gap are the sums of its geoms' (or its
``<pair>``'s); a contact is found where its distance is at most ``margin + gap``, and it enters
the constraints where its distance is below ``includemargin = margin``.

Refused by name when the table is read (``NotImplementedError``): pair kinds outside the list
above, adhesion, flexes, and the options ``sleep``, ``speculative`` and ``ipc``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np

__all__ = [
    "ContactTable",
    "Contacts",
    "PairKind",
    "PAIR_KINDS",
    "capsule_capsule",
    "collide",
    "plane_box",
    "plane_capsule",
    "plane_cylinder",
    "plane_sphere",
    "read_contact_table",
    "sphere_capsule",
    "sphere_sphere",
]

PLANE, HFIELD, SPHERE, CAPSULE, ELLIPSOID, CYLINDER, BOX, MESH, SDF = range(9)
GEOM_TYPE_NAMES = ("plane", "hfield", "sphere", "capsule", "ellipsoid", "cylinder", "box", "mesh")
MIN_VALUE = 1e-15  # MuJoCo's mjMINVAL
MIN_FRICTION = 1e-5  # MuJoCo's mjMINMU
PARALLEL_SIN2 = 1e-8  # capsule axes closer than this squared sine are parallel (MuJoCo 4)
# (lower type, higher type) pairs that MuJoCo has a collision function for (mjCOLLISIONFUNC):
# every pair but plane-plane and those of height fields with planes and height fields
_NO_FUNCTION = {(PLANE, PLANE), (PLANE, HFIELD), (HFIELD, HFIELD)}

# numpy constants of the kernels, made once here (traced code touches numpy only through
# xp.constant)
_X, _Y, _Z = np.eye(3)
_BOX_CORNERS = np.array([[1 if i & b else -1 for b in (1, 2, 4)] for i in range(8)], np.float64)
_BEFORE_8 = np.triu(np.ones((8, 8)), 1)  # [j, i] = 1 where j < i
_SLOTS_4 = np.arange(4.0)[:, None]
_ENDS = np.array([1.0, -1.0])
_FIRST_ONLY = np.array([True, False])
_SIN_60 = 0.8660254037844386  # sqrt(3) / 2


# ----------------------------------------------------------------------------------------------
# Small vector helpers ([..., 3] vectors, [..., 3, 3] row-major matrices)
# ----------------------------------------------------------------------------------------------


def _dot(xp, a, b):
    return xp.sum(a * b, axis=-1)


def _axis(mat, column: int):
    """A geom's local axis in the world: a column of its row-major rotation matrix."""
    return mat[..., :, column]


def _const(xp, like, value: np.ndarray) -> Any:
    """A numpy constant of this module in ``like``'s dtype and device."""
    return xp.constant(value, dtype=like.dtype, device=xp.dev(like))


def _normalize(xp, v):
    """``v / |v|`` as ``mju_normalize3`` (``[1, 0, 0]`` below MIN_VALUE), with finite
    gradients everywhere; returns the unit vector and the norm (below MIN_VALUE: its square,
    as small and with a finite gradient)."""
    square = _dot(xp, v, v)[..., None]
    small = square < MIN_VALUE * MIN_VALUE
    norm = xp.sqrt(xp.where(small, xp.ones_like(square), square))
    unit = xp.where(small, _const(xp, v, _X), v / norm)
    return unit, xp.where(small, square, norm)[..., 0]


def _default_tangent(xp, normal):
    """``mju_makeFrame``'s first tangent where none is given, for unit normals: the y axis if
    the normal's y component is within (-1/2, 1/2), else the z axis, made orthogonal to the
    normal and normalised (never degenerate: the axis is at least 30 degrees off the normal)."""
    ny, nz = normal[..., 1:2], normal[..., 2:3]
    use_y = xp.abs(ny) < 0.5
    along = xp.where(use_y, ny, nz)
    axis = xp.where(use_y, _const(xp, normal, _Y), _const(xp, normal, _Z))
    return (axis - normal * along) / xp.sqrt(1 - along * along)


def _given_tangent(xp, normal, tangent):
    """``mju_makeFrame``'s first tangent from a given unit one: made orthogonal to the normal
    and normalised (``[1, 0, 0]`` where it is parallel to the normal)."""
    return _normalize(xp, tangent - normal * _dot(xp, normal, tangent)[..., None])[0]


def _contact_frame(xp, normal, tangent):
    """The contact frame ``[..., 3, 3]``: rows normal, tangent, normal x tangent."""
    return xp.stack([normal, tangent, xp.cross(normal, tangent)], axis=-2)


def _first_four(xp, found, like):
    """Selection weights ``[..., 4, 8]`` (0 or 1) that pick the first four found of eight
    candidates ``found`` ``[..., 8]`` in order, as a collision function that stops after four
    contacts fills its output; rows past the number found are zero."""
    weight = xp.astype(found, like.dtype)
    rank = xp.matmul(weight, _const(xp, like, _BEFORE_8))  # found before each (exact)
    return weight[..., None, :] * xp.astype(
        rank[..., None, :] == _const(xp, like, _SLOTS_4), like.dtype
    )


def _last(value):
    """``value[..., None]`` for an array (a number broadcasts as it is)."""
    return value[..., None] if hasattr(value, "shape") else value


# ----------------------------------------------------------------------------------------------
# Raw tests, batched over any trailing candidate axis
# ----------------------------------------------------------------------------------------------


class _Raw(NamedTuple):
    """Candidate contacts of one pair kind before their frames are completed: dist
    ``[..., K]``, pos and normal ``[..., K, 3]`` (unit), the frame's first tangent ``[..., K,
    3]`` or None (MuJoCo's default),
    found ``[..., K]``."""

    dist: Any
    pos: Any
    normal: Any
    tangent: Any
    found: Any


def _raw_plane_sphere(xp, plane_pos, normal, centre, radius, margin):
    """Spheres against a plane through ``plane_pos`` with unit ``normal``: distance, position
    (midway between the surfaces) and found (within ``margin``)."""
    centre_dist = _dot(xp, centre - plane_pos, normal)
    dist = centre_dist - radius
    pos = centre - normal * (dist / 2 + radius)[..., None]
    return dist, pos, centre_dist <= margin + radius


def _raw_sphere_sphere(xp, pos1, z1, r1, pos2, z2, r2, margin):
    """Pairs of spheres, as ``mjraw_SphereSphere``: the normal points from sphere 1 to sphere
    2; at coincident centres it is ``z1 x z2`` normalised (``[1, 0, 0]`` when the z axes are
    parallel). Returns distance, position, normal, found."""
    dif = pos2 - pos1
    normal, centre_dist = _normalize(xp, dif)
    reach = margin + r1 + r2
    found = _dot(xp, dif, dif) <= reach * reach
    coincident = centre_dist < MIN_VALUE
    fallback, _ = _normalize(xp, xp.cross(z1, z2))
    normal = xp.where(coincident[..., None], fallback, normal)
    dist = centre_dist - r1 - r2
    pos = pos1 + normal * (r1 + dist / 2)[..., None]
    return dist, pos, normal, found


def _finish(xp, raw: _Raw):
    """(dist, pos, frame, found) from raw candidates: the frames completed."""
    tangent = _default_tangent(xp, raw.normal) if raw.tangent is None else raw.tangent
    return raw.dist, raw.pos, _contact_frame(xp, raw.normal, tangent), raw.found


# ----------------------------------------------------------------------------------------------
# Pair kinds: (xp, pos1, mat1, size1, pos2, mat2, size2, margin) -> _Raw with K candidates
# ----------------------------------------------------------------------------------------------


def _plane_sphere(xp, pos1, mat1, size1, pos2, mat2, size2, margin) -> _Raw:
    normal = _axis(mat1, 2)[..., None, :]
    dist, pos, found = _raw_plane_sphere(
        xp, pos1[..., None, :], normal, pos2[..., None, :], size2[..., 0:1], _last(margin)
    )
    return _Raw(dist, pos, xp.broadcast_to(normal, pos.shape), None, found)


def _plane_capsule(xp, pos1, mat1, size1, pos2, mat2, size2, margin) -> _Raw:
    normal = _axis(mat1, 2)[..., None, :]
    axis = _axis(mat2, 2)[..., None, :]
    ends = pos2[..., None, :] + axis * (size2[..., 1:2] * _const(xp, pos2, _ENDS))[..., None]
    dist, pos, found = _raw_plane_sphere(
        xp, pos1[..., None, :], normal, ends, size2[..., 0:1], _last(margin)
    )
    tangent = _given_tangent(xp, normal, axis)  # the same for both ends
    return _Raw(
        dist,
        pos,
        xp.broadcast_to(normal, pos.shape),
        xp.broadcast_to(tangent, pos.shape),
        found,
    )


def _plane_box(xp, pos1, mat1, size1, pos2, mat2, size2, margin) -> _Raw:
    normal = _axis(mat1, 2)
    local = _const(xp, pos2, _BOX_CORNERS) * size2[..., None, :]  # [..., 8, 3]
    corner = xp.matmul(local, xp.matrix_transpose(mat2))  # rows: mat2 @ local corner
    centre_dist = _dot(xp, pos2 - pos1, normal)
    ldist = _dot(xp, corner, normal[..., None, :])
    dist = centre_dist[..., None] + ldist
    found = xp.logical_and(dist <= _last(margin), ldist <= 0)
    pos = pos2[..., None, :] + corner - normal[..., None, :] * (dist / 2)[..., None]
    sel = _first_four(xp, found, pos2)
    dist, pos = xp.sum(sel * dist[..., None, :], axis=-1), xp.matmul(sel, pos)
    found = xp.sum(sel, axis=-1) > 0.5
    return _Raw(dist, pos, xp.broadcast_to(normal[..., None, :], pos.shape), None, found)


def _plane_cylinder(xp, pos1, mat1, size1, pos2, mat2, size2, margin) -> _Raw:
    radius, half_height = size2[..., 0], size2[..., 1]
    normal = _axis(mat1, 2)
    axis = _axis(mat2, 2)
    projection = _dot(xp, normal, axis)
    towards = projection > 0  # make the axis point towards the plane
    axis = xp.where(towards[..., None], -axis, axis)
    projection = xp.where(towards, -projection, projection)
    centre_dist = _dot(xp, pos2 - pos1, normal)
    # the component of -normal orthogonal to the axis, scaled to the radius
    vec = axis * projection[..., None] - normal
    length_sqr = _dot(xp, vec, vec)
    flat = length_sqr < MIN_VALUE * MIN_VALUE
    scale = radius / xp.sqrt(xp.where(flat, xp.ones_like(length_sqr), length_sqr))
    vec = xp.where(flat[..., None], _axis(mat2, 0) * radius[..., None], vec * scale[..., None])
    rim = _dot(xp, vec, normal)
    axis = axis * half_height[..., None]
    projection = projection * half_height
    # the nearest rim point, the same rim point on the far cap, two more of the near cap
    side, _ = _normalize(xp, xp.cross(vec, axis))
    side = side * (radius * _SIN_60)[..., None]
    near = centre_dist + projection
    beside = near - rim / 2
    dist = xp.stack([near + rim, centre_dist - projection + rim, beside, beside], axis=-1)
    middle = axis - vec / 2
    offsets = xp.stack([vec + axis, vec - axis, middle + side, middle - side], axis=-2)
    normal4 = xp.broadcast_to(normal[..., None, :], offsets.shape)
    pos = pos2[..., None, :] + offsets - normal4 * (dist / 2)[..., None]
    within = dist <= _last(margin)
    first = within[..., 0:1]
    found = xp.logical_and(first, xp.concat([first, within[..., 1:]], axis=-1))
    return _Raw(dist, pos, normal4, None, found)


def _sphere_sphere(xp, pos1, mat1, size1, pos2, mat2, size2, margin) -> _Raw:
    dist, pos, normal, found = _raw_sphere_sphere(
        xp,
        pos1[..., None, :],
        _axis(mat1, 2)[..., None, :],
        size1[..., 0:1],
        pos2[..., None, :],
        _axis(mat2, 2)[..., None, :],
        size2[..., 0:1],
        _last(margin),
    )
    return _Raw(dist, pos, normal, None, found)


def _sphere_capsule(xp, pos1, mat1, size1, pos2, mat2, size2, margin) -> _Raw:
    axis = _axis(mat2, 2)
    half_length = size2[..., 1]
    along = xp.clip(_dot(xp, axis, pos1 - pos2), -half_length, half_length)
    nearest = pos2 + axis * along[..., None]
    return _sphere_sphere(xp, pos1, mat1, size1, nearest, mat2, size2, margin)


def _capsule_capsule(xp, pos1, mat1, size1, pos2, mat2, size2, margin) -> _Raw:
    z1, z2 = _axis(mat1, 2), _axis(mat2, 2)
    axis1 = z1 * size1[..., 1:2]
    axis2 = z2 * size2[..., 1:2]
    dif = pos1 - pos2
    ma = _dot(xp, axis1, axis1)
    mb = -_dot(xp, axis1, axis2)
    mc = _dot(xp, axis2, axis2)
    u = -_dot(xp, axis1, dif)
    v = _dot(xp, axis2, dif)
    # the contacts' points on segment 1: the point of line 1 nearest to line 2 (general
    # configuration; the second contact unused), or its ends -z and +z (parallel axes).
    # Parallel is decided on |axis1 x axis2|², the divisor below (= ma mc - mb², MuJoCo's
    # determinant, in exact arithmetic): in float32 the determinant of near-parallel axes can
    # pass the test while the cross product is 0, and the division's derivative is then NaN.
    normal = xp.cross(axis1, axis2)
    sqr = _dot(xp, normal, normal)
    parallel = sqr < PARALLEL_SIN2 * ma * mc
    safe_sqr = xp.where(parallel, xp.ones_like(sqr), sqr)
    nearest = _dot(xp, xp.cross(-dif, axis2), normal) / safe_sqr
    first = xp.where(parallel, -xp.ones_like(nearest), xp.clip(nearest, -1.0, 1.0))
    x1 = xp.stack([first, xp.ones_like(first)], axis=-1)
    # the nearest point of segment 2 to each; where that one is clipped, the nearest point of
    # segment 1 to it instead
    ma, mb, mc, u, v = (a[..., None] for a in (ma, mb, mc, u, v))
    x2 = (v - mb * x1) / mc
    outside = xp.logical_or(x2 > 1, x2 < -1)
    x2 = xp.clip(x2, -1.0, 1.0)
    x1 = xp.where(outside, xp.clip((u - mb * x2) / ma, -1.0, 1.0), x1)
    dist, pos, normal, found = _raw_sphere_sphere(
        xp,
        pos1[..., None, :] + axis1[..., None, :] * x1[..., None],
        z1[..., None, :],
        size1[..., 0:1],
        pos2[..., None, :] + axis2[..., None, :] * x2[..., None],
        z2[..., None, :],
        size2[..., 0:1],
        _last(margin),
    )
    only_first = xp.constant(_FIRST_ONLY, device=xp.dev(found))
    found = xp.logical_and(found, xp.logical_or(parallel[..., None], only_first))
    return _Raw(dist, pos, normal, None, found)


# ----------------------------------------------------------------------------------------------
# The pair kinds' public functions: (dist, pos, frame, found)
# ----------------------------------------------------------------------------------------------

_KIND_DOC = """

    Args:
        xp: the backend namespace (``ivy.jax`` ...).
        pos1, mat1, size1: geom 1's position ``[..., 3]``, rotation ``[..., 3, 3]`` and size
            ``[..., 3]`` (MuJoCo's ``geom_size``; planes are infinite here).
        pos2, mat2, size2: geom 2's.
        margin: ``[...]`` or a number: the distance within which a contact is found (MuJoCo
            passes the pair's margin + gap).

    Returns:
        ``(dist [..., K], pos [..., K, 3], frame [..., K, 3, 3], found [..., K])`` for its
        ``K`` candidate contacts: signed distance (negative: penetration), position midway
        between the surfaces, contact frame (rows: the normal from geom 1 to geom 2, two
        tangents, completed as ``mju_makeFrame`` does) and whether MuJoCo returns the contact.
        Found candidates are in MuJoCo's order; the values of the others are meaningless.
"""


def plane_sphere(xp, pos1, mat1, size1, pos2, mat2, size2, margin):
    """A plane (geom 1) and a sphere: one candidate, as ``mjc_PlaneSphere``.{doc}
    Example:
        >>> dist, pos, frame, found = plane_sphere(ivy.numpy, np.zeros(3), np.eye(3),
        ...     np.zeros(3), np.array([0, 0, 0.09]), np.eye(3), np.array([0.1, 0, 0]), 0.0)
        >>> np.round(dist, 6), found
        (array([-0.01]), array([ True]))
    """
    return _finish(xp, _plane_sphere(xp, pos1, mat1, size1, pos2, mat2, size2, margin))


def plane_capsule(xp, pos1, mat1, size1, pos2, mat2, size2, margin):
    """A plane and a capsule: two candidates (the ends of its segment, ``+z`` first), as
    ``mjc_PlaneCapsule``; the first tangent of each frame follows the capsule's axis.{doc}
    Example:
        >>> tilted = np.array([[1, 0, 0], [0, 0.8, -0.6], [0, 0.6, 0.8]])
        >>> dist, pos, frame, found = plane_capsule(ivy.numpy, np.zeros(3), np.eye(3),
        ...     np.zeros(3), np.array([0, 0, 0.2]), tilted, np.array([0.1, 0.2, 0]), 0.0)
        >>> np.round(dist, 6), found
        (array([ 0.26, -0.06]), array([False,  True]))
    """
    return _finish(xp, _plane_capsule(xp, pos1, mat1, size1, pos2, mat2, size2, margin))


def plane_box(xp, pos1, mat1, size1, pos2, mat2, size2, margin):
    """A plane and a box: up to four contacts at its corners, as ``mjc_PlaneBox``: the first
    four corners (ordered by their local sign bits x, y, z) below the centre and within
    ``margin``, found ones first.{doc}
    Example:
        >>> dist, pos, frame, found = plane_box(ivy.numpy, np.zeros(3), np.eye(3),
        ...     np.zeros(3), np.array([0, 0, 0.09]), np.eye(3), np.array([.1, .2, .1]), 0.0)
        >>> np.round(dist, 6), found
        (array([-0.01, -0.01, -0.01, -0.01]), array([ True,  True,  True,  True]))
    """
    return _finish(xp, _plane_box(xp, pos1, mat1, size1, pos2, mat2, size2, margin))


def plane_cylinder(xp, pos1, mat1, size1, pos2, mat2, size2, margin):
    """A plane and a cylinder: up to four contacts, as ``mjc_PlaneCylinder``: the rim point
    nearest the plane, the same rim point of the far cap, and two more rim points of the near
    cap (at +-120 degrees); none where the nearest point is beyond ``margin``. A cap parallel
    to the plane takes its rim point along the cylinder's x axis.{doc}
    Example:
        >>> dist, pos, frame, found = plane_cylinder(ivy.numpy, np.zeros(3), np.eye(3),
        ...     np.zeros(3), np.array([0, 0, 0.19]), np.eye(3), np.array([.1, .2, 0]), 0.0)
        >>> np.round(dist, 6), found
        (array([-0.01,  0.39, -0.01, -0.01]), array([ True, False,  True,  True]))
    """
    return _finish(xp, _plane_cylinder(xp, pos1, mat1, size1, pos2, mat2, size2, margin))


def sphere_sphere(xp, pos1, mat1, size1, pos2, mat2, size2, margin):
    """Two spheres: one candidate, as ``mjc_SphereSphere``; at coincident centres the normal
    is the cross product of their z axes (``[1, 0, 0]`` where they are parallel).{doc}
    Example:
        >>> dist, pos, frame, found = sphere_sphere(ivy.numpy, np.zeros(3), np.eye(3),
        ...     np.array([.1, 0, 0]), np.array([.15, 0, 0]), np.eye(3), np.array([.1, 0, 0]), 0.)
        >>> np.round(dist, 6), frame[0, 0]
        (array([-0.05]), array([1., 0., 0.]))
    """
    return _finish(xp, _sphere_sphere(xp, pos1, mat1, size1, pos2, mat2, size2, margin))


def sphere_capsule(xp, pos1, mat1, size1, pos2, mat2, size2, margin):
    """A sphere and a capsule: one candidate, as ``mjc_SphereCapsule`` (the sphere against the
    nearest point of the capsule's segment).{doc}
    Example:
        >>> dist, pos, frame, found = sphere_capsule(ivy.numpy, np.zeros(3), np.eye(3),
        ...     np.array([.1, 0, 0]), np.array([.15, 0, .2]), np.eye(3), np.array([.1, .3, 0]), 0.)
        >>> np.round(dist, 6), found
        (array([-0.05]), array([ True]))
    """
    return _finish(xp, _sphere_capsule(xp, pos1, mat1, size1, pos2, mat2, size2, margin))


def capsule_capsule(xp, pos1, mat1, size1, pos2, mat2, size2, margin):
    """Two capsules: up to two contacts, as MuJoCo 4's ``mjc_CapsuleCapsule``. In general one,
    between the nearest points of the segments. Where the axes are parallel (squared sine of
    the angle below 1e-8), two: from each end of segment 1 (``-z`` first) to its nearest point
    of segment 2, or, where that is an end of segment 2, from that end to its nearest point of
    segment 1 (the ends of the overlap; where the segments do not overlap, twice the same).{doc}
    Example:
        >>> dist, pos, frame, found = capsule_capsule(ivy.numpy, np.zeros(3), np.eye(3),
        ...     np.array([.1, .3, 0]), np.array([.15, 0, .1]), np.eye(3), np.array([.1, .3, 0]), 0.)
        >>> np.round(dist, 6), found, np.round(pos[:, 2], 6)
        (array([-0.05, -0.05]), array([ True,  True]), array([-0.2,  0.3]))
    """
    return _finish(xp, _capsule_capsule(xp, pos1, mat1, size1, pos2, mat2, size2, margin))


for _function in (
    plane_sphere, plane_capsule, plane_box, plane_cylinder, sphere_sphere, sphere_capsule,
    capsule_capsule,
):  # fmt: skip
    _function.__doc__ = _function.__doc__.replace("{doc}", _KIND_DOC)


#: (geom type 1, geom type 2) -> (pair-kind function, number of candidate contacts), with
#: geom type 1 <= geom type 2 (MuJoCo's order of a contact's geoms)
PAIR_KINDS: dict[tuple[int, int], tuple[Callable, int]] = {
    (PLANE, SPHERE): (plane_sphere, 1),
    (PLANE, CAPSULE): (plane_capsule, 2),
    (PLANE, BOX): (plane_box, 4),
    (PLANE, CYLINDER): (plane_cylinder, 4),
    (SPHERE, SPHERE): (sphere_sphere, 1),
    (SPHERE, CAPSULE): (sphere_capsule, 1),
    (CAPSULE, CAPSULE): (capsule_capsule, 2),
}
# the same kinds' raw kernels, frames left to complete (collide completes them all at once)
_RAW_KERNELS: dict[tuple[int, int], Callable] = {
    (PLANE, SPHERE): _plane_sphere,
    (PLANE, CAPSULE): _plane_capsule,
    (PLANE, BOX): _plane_box,
    (PLANE, CYLINDER): _plane_cylinder,
    (SPHERE, SPHERE): _sphere_sphere,
    (SPHERE, CAPSULE): _sphere_capsule,
    (CAPSULE, CAPSULE): _capsule_capsule,
}


# ----------------------------------------------------------------------------------------------
# The contact table
# ----------------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class PairKind:
    """The geom pairs of one kind, computed in one vectorised call.

    Attributes:
        types: (geom type 1, geom type 2), a key of :data:`PAIR_KINDS`.
        ncon: candidate contacts per pair.
        geom1, geom2: the pairs' geom ids (tuples of ints, MuJoCo's order).
        size1, size2: their sizes, numpy ``[npairs, 3]``.
        reach: numpy ``[npairs]``, margin + gap: the distance within which a contact is found.
        index1, index2: ``geom1``, ``geom2`` as int32 numpy arrays (gather indices).
    """

    types: tuple
    ncon: int
    geom1: tuple
    geom2: tuple
    size1: np.ndarray
    size2: np.ndarray
    reach: np.ndarray
    index1: np.ndarray
    index2: np.ndarray

    @property
    def function(self) -> Callable:
        """The kind's public function (:data:`PAIR_KINDS`)."""
        return PAIR_KINDS[self.types][0]


@dataclass(frozen=True, eq=False)
class ContactTable:
    """The candidate contacts of a model, in MuJoCo's ``d.contact`` order (numpy, read once).

    Per candidate contact (arrays of length ``ncon``): the geoms ``geom1``, ``geom2`` (as in
    MuJoCo's ``contact.geom``: lower geom type first), their bodies ``body1``, ``body2``,
    ``pair`` (the explicit ``<pair>`` it comes from, or -1), ``condim``, ``friction [ncon, 5]``,
    ``solref [ncon, 2]``, ``solreffriction [ncon, 2]``, ``solimp [ncon, 5]``, ``margin``,
    ``gap``, ``includemargin`` (MuJoCo 4: ``= margin``) and ``acts`` (False where MuJoCo
    leaves a found contact out of the constraints whatever its distance: its two bodies move
    with no dof apart; only explicit pairs can have it).

    Structure: ``kinds`` (one :class:`PairKind` per pair kind present), ``order`` (int32
    ``[ncon]``: for each candidate, its index in the concatenation of the kinds' candidates,
    pair by pair, contact by contact) and ``in_order`` (whether ``order`` is the identity).
    """

    geom1: np.ndarray
    geom2: np.ndarray
    body1: np.ndarray
    body2: np.ndarray
    pair: np.ndarray
    condim: np.ndarray
    friction: np.ndarray
    solref: np.ndarray
    solreffriction: np.ndarray
    solimp: np.ndarray
    margin: np.ndarray
    gap: np.ndarray
    includemargin: np.ndarray
    acts: np.ndarray
    kinds: tuple
    order: np.ndarray
    in_order: bool

    @property
    def ncon(self) -> int:
        """The number of candidate contacts."""
        return int(self.geom1.shape[0])


class Contacts(NamedTuple):
    """The candidate contacts of a :class:`ContactTable` at some geom poses.

    Attributes:
        dist: ``[..., C]`` signed distances (negative: penetration).
        pos: ``[..., C, 3]`` positions, midway between the surfaces.
        frame: ``[..., C, 3, 3]`` contact frames (rows: normal from geom1 to geom2, tangents).
        found: ``[..., C]`` whether MuJoCo lists the contact in ``d.contact``.
        active: ``[..., C]`` whether it enters the constraints (found, below
            ``includemargin``, and ``acts``).
    """

    dist: Any
    pos: Any
    frame: Any
    found: Any
    active: Any


def _flag(m, mujoco, name: str, enable: bool = False) -> bool:
    if enable:
        return bool(m.opt.enableflags & int(getattr(mujoco.mjtEnableBit, name)))
    return bool(m.opt.disableflags & int(getattr(mujoco.mjtDisableBit, name)))


def _geom_label(m, g: int) -> str:
    name = m.geom(g).name
    kind = int(m.geom_type[g])
    label = GEOM_TYPE_NAMES[kind] if kind < len(GEOM_TYPE_NAMES) else f"type {kind}"
    return f"geom {name!r} ({label})" if name else f"geom #{g} ({label})"


def _refuse_options(m, mujoco) -> None:
    for flag, what in (
        ("mjENBL_SLEEP", "sleeping bodies"),
        ("mjENBL_SPECULATIVE", "speculative contacts"),
        ("mjENBL_IPC", "IPC contacts"),
    ):
        if hasattr(mujoco.mjtEnableBit, flag) and _flag(m, mujoco, flag, enable=True):
            raise NotImplementedError(
                f"collision: the model enables {what} (option flag {flag[6:].lower()!r}), "
                "which the contact table does not model; disable the flag"
            )
    if m.nflex:
        raise NotImplementedError(
            f"collision: the model has {m.nflex} flex(es); flex contacts are not modelled. "
            "Remove the flexes or disable their contacts (contype/conaffinity 0)"
        )


def _candidate_body_pairs(m, mujoco) -> list[tuple[int, int]]:
    """Body pairs (b1 < b2) that MuJoCo's broadphase can return, in signature order."""
    weld = np.asarray(m.body_weldid)
    parent_weld = weld[np.asarray(m.body_parentid)[weld]]
    dofs = np.asarray(m.body_dofnum)[weld]
    contype = np.zeros(m.nbody, np.int64)
    conaffinity = np.zeros(m.nbody, np.int64)
    for g in range(m.ngeom):
        contype[m.geom_bodyid[g]] |= int(m.geom_contype[g])
        conaffinity[m.geom_bodyid[g]] |= int(m.geom_conaffinity[g])
    collides = (contype != 0) | (conaffinity != 0)
    filter_parent = not _flag(m, mujoco, "mjDSBL_FILTERPARENT")
    pairs = []
    for b1 in range(m.nbody):
        for b2 in range(b1 + 1, m.nbody):
            if not (collides[b1] and collides[b2]) or weld[b1] == weld[b2]:
                continue
            if dofs[b1] == 0 and dofs[b2] == 0:
                continue
            w1, w2 = weld[b1], weld[b2]
            if filter_parent and w1 and w2 and (w1 == parent_weld[w2] or w2 == parent_weld[w1]):
                continue
            if not (contype[b1] & conaffinity[b2] or contype[b2] & conaffinity[b1]):
                continue
            pairs.append((b1, b2))
    return pairs


def _mujoco_order(m, g1: int, g2: int) -> tuple[int, int]:
    """A geom pair in the order of MuJoCo's contacts: lower geom type first."""
    return (g2, g1) if m.geom_type[g1] > m.geom_type[g2] else (g1, g2)


def _has_function(m, g1: int, g2: int) -> bool:
    t1, t2 = sorted((int(m.geom_type[g1]), int(m.geom_type[g2])))
    return (t1, t2) not in _NO_FUNCTION


def _body_pair_geoms(m, mujoco, b1, b2, explicit: list) -> list[tuple[int, int]]:
    """The geom pairs of one body pair, in the order MuJoCo's narrowphase lists them."""
    out = []
    for g1 in range(m.body_geomadr[b1], m.body_geomadr[b1] + m.body_geomnum[b1]):
        for g2 in range(m.body_geomadr[b2], m.body_geomadr[b2] + m.body_geomnum[b2]):
            if not (
                m.geom_contype[g1] & m.geom_conaffinity[g2]
                or m.geom_contype[g2] & m.geom_conaffinity[g1]
            ):
                continue
            if {g1, g2} in explicit or not _has_function(m, g1, g2):
                continue
            out.append(_mujoco_order(m, g1, g2))
    single = m.body_geomnum[b1] == 1 and m.body_geomnum[b2] == 1
    if not single and not _flag(m, mujoco, "mjDSBL_MIDPHASE"):
        out.sort()  # the midphase sorts a body pair's contacts by their geom ids (stable)
    return out


def _ordered_geom_pairs(m, mujoco) -> list[tuple[int, int, int]]:
    """Every geom pair (g1, g2, explicit pair or -1) that MuJoCo may collide, in its order:
    body pairs by signature, each preceded by the explicit pairs of no greater signature."""
    signature = np.asarray(m.pair_signature, np.int64)
    if np.any(np.diff(signature) < 0):  # the compiler sorts them; the merge below needs it
        raise NotImplementedError("collision: the model's <pair>s are not sorted by signature")
    excluded = set(np.asarray(m.exclude_signature, np.int64).tolist())
    out, next_pair = [], 0

    def emit_explicit(up_to: int | None) -> list:
        nonlocal next_pair
        emitted = []
        while next_pair < m.npair and (up_to is None or signature[next_pair] <= up_to):
            g1, g2 = int(m.pair_geom1[next_pair]), int(m.pair_geom2[next_pair])
            if _has_function(m, g1, g2):
                out.append((*_mujoco_order(m, g1, g2), next_pair))
            if up_to is not None and signature[next_pair] == up_to:
                emitted.append({g1, g2})
            next_pair += 1
        return emitted

    for b1, b2 in _candidate_body_pairs(m, mujoco):
        key = (b1 << 16) + b2
        merged = emit_explicit(key)
        if key in excluded:
            continue
        out.extend((g1, g2, -1) for g1, g2 in _body_pair_geoms(m, mujoco, b1, b2, merged))
    emit_explicit(None)
    return out


def _mix_parameters(m, g1: int, g2: int) -> dict:
    """Contact parameters of a geom pair by MuJoCo's rules: the geom of higher priority gives
    them; at equal priority condim and friction are the maxima, solimp (and solref where both
    are positive: else the minimum) mix by solmix."""
    p1, p2 = int(m.geom_priority[g1]), int(m.geom_priority[g2])
    adhesion = np.asarray(getattr(m, "geom_adhesion", np.zeros(m.ngeom)))
    if p1 != p2:
        g = g1 if p1 > p2 else g2
        return dict(
            condim=int(m.geom_condim[g]),
            solref=np.array(m.geom_solref[g]),
            solimp=np.array(m.geom_solimp[g]),
            friction=np.array(m.geom_friction[g]),
            adhesion=float(adhesion[g]),
        )
    s1, s2 = float(m.geom_solmix[g1]), float(m.geom_solmix[g2])
    if s1 >= MIN_VALUE and s2 >= MIN_VALUE:
        mix = s1 / (s1 + s2)
    elif s1 < MIN_VALUE and s2 < MIN_VALUE:
        mix = 0.5
    else:
        mix = 0.0 if s1 < MIN_VALUE else 1.0
    ref1, ref2 = np.array(m.geom_solref[g1]), np.array(m.geom_solref[g2])
    if ref1[0] > 0 and ref2[0] > 0:
        solref = mix * ref1 + (1 - mix) * ref2
    else:
        solref = np.minimum(ref1, ref2)
    return dict(
        condim=max(int(m.geom_condim[g1]), int(m.geom_condim[g2])),
        solref=solref,
        solimp=mix * np.array(m.geom_solimp[g1]) + (1 - mix) * np.array(m.geom_solimp[g2]),
        friction=np.maximum(m.geom_friction[g1], m.geom_friction[g2]),
        adhesion=float(adhesion[g1] + adhesion[g2]),
    )


def _pair_parameters(m, mujoco, g1: int, g2: int, ipair: int) -> dict:
    """The parameters of one geom pair's contacts, as MuJoCo's narrowphase sets them."""
    if ipair >= 0:
        solreffriction = np.array(m.pair_solreffriction[ipair])
        adhesion = getattr(m, "pair_adhesion", None)
        params = dict(
            condim=int(m.pair_dim[ipair]),
            solref=np.array(m.pair_solref[ipair]),
            solimp=np.array(m.pair_solimp[ipair]),
            friction5=np.array(m.pair_friction[ipair]),
            solreffriction=solreffriction if np.any(solreffriction) else np.zeros(2),
            adhesion=0.0 if adhesion is None else float(adhesion[ipair]),
            margin=float(m.pair_margin[ipair]),
            gap=float(m.pair_gap[ipair]),
        )
    else:
        mixed = _mix_parameters(m, g1, g2)
        f = mixed.pop("friction")
        params = dict(
            mixed,
            friction5=np.array([f[0], f[0], f[1], f[2], f[2]]),
            solreffriction=np.zeros(2),
            margin=float(m.geom_margin[g1] + m.geom_margin[g2]),
            gap=float(m.geom_gap[g1] + m.geom_gap[g2]),
        )
    if params["adhesion"] != 0:
        raise NotImplementedError(
            f"collision: {_geom_label(m, g1)} and {_geom_label(m, g2)} have adhesion "
            f"{params['adhesion']}, which is not modelled; set their adhesion to 0"
        )
    if _flag(m, mujoco, "mjENBL_OVERRIDE", enable=True):
        params.update(
            margin=float(m.opt.o_margin),
            solref=np.array(m.opt.o_solref),
            solreffriction=np.array(m.opt.o_solref),
            solimp=np.array(m.opt.o_solimp),
            friction5=np.array(m.opt.o_friction),
        )
    params["friction5"] = np.maximum(params["friction5"], MIN_FRICTION)
    return params


def _acts(m, g1: int, g2: int) -> bool:
    """Whether a contact of the two geoms can enter the constraints. MuJoCo leaves a contact
    out where its Jacobian has no dof once the dofs common to both bodies are skipped: both
    bodies welded to the same body, or both without dofs (only explicit pairs can have it)."""
    w1, w2 = (int(m.body_weldid[m.geom_bodyid[g]]) for g in (g1, g2))
    if m.nv == 0 or (m.body_dofnum[w1] == 0 and m.body_dofnum[w2] == 0):
        return False
    return w1 != w2


def _refuse_kind(m, g1: int, g2: int) -> None:
    supported = ", ".join(
        f"{GEOM_TYPE_NAMES[a]}-{GEOM_TYPE_NAMES[b]}" for a, b in sorted(PAIR_KINDS)
    )
    raise NotImplementedError(
        f"collision: {_geom_label(m, g1)} and {_geom_label(m, g2)} may collide, and that pair "
        f"kind is not modelled (modelled: {supported}). Keep them apart with contype/"
        "conaffinity or an <exclude>, or give them modelled shapes"
    )


def read_contact_table(mjmodel) -> ContactTable:
    """The candidate contacts of a compiled ``mujoco.MjModel``, read once.

    Every geom pair that MuJoCo's filters let collide (contype/conaffinity, same weld body,
    parent and child unless ``filterparent`` is disabled, two bodies without dofs, excluded
    body pairs, explicit pairs, the ``contact`` and ``constraint`` disable flags), with as many
    candidate contacts as its collision function can return, in MuJoCo's ``d.contact`` order,
    with their contact parameters mixed as MuJoCo mixes them.

    Args:
        mjmodel: a compiled ``mujoco.MjModel``.

    Returns:
        A :class:`ContactTable`.

    Raises:
        NotImplementedError: naming the geoms of a pair kind that is not modelled, adhesion,
            flexes, or an option that is not modelled.

    Example:
        >>> import mujoco
        >>> model = mujoco.MjModel.from_xml_string('''<mujoco><worldbody>
        ...   <geom type="plane" size="1 1 1"/>
        ...   <body pos="0 0 0.09"><freejoint/><geom type="capsule" size="0.1 0.2"/></body>
        ... </worldbody></mujoco>''')
        >>> table = read_contact_table(model)
        >>> table.ncon, table.geom1, table.geom2, table.condim
        (2, array([0, 0]), array([1, 1]), array([3, 3]))
    """
    import mujoco

    m = mjmodel
    disabled = _flag(m, mujoco, "mjDSBL_CONTACT") or _flag(m, mujoco, "mjDSBL_CONSTRAINT")
    if disabled or m.nbody + m.nflex < 2:
        return _build_table(m, mujoco, [])
    _refuse_options(m, mujoco)
    return _build_table(m, mujoco, _ordered_geom_pairs(m, mujoco))


def _build_table(m, mujoco, pairs: list) -> ContactTable:
    rows: dict[str, list] = {k: [] for k in _ROW_FIELDS}
    groups: dict[tuple, list] = {}
    slots = []  # (kind types, index of the pair in its kind, contact)
    for g1, g2, ipair in pairs:
        types = (int(m.geom_type[g1]), int(m.geom_type[g2]))
        if types not in PAIR_KINDS:
            _refuse_kind(m, g1, g2)
        params = _pair_parameters(m, mujoco, g1, g2, ipair)
        ncon = PAIR_KINDS[types][1]
        group = groups.setdefault(types, [])
        group.append((g1, g2, params["margin"] + params["gap"]))
        for k in range(ncon):
            slots.append((types, len(group) - 1, k))
            _append_row(m, rows, g1, g2, ipair, params)
    kinds, offsets, start = [], {}, 0
    for types in sorted(groups):
        group = groups[types]
        g1s, g2s, reach = zip(*group)
        ncon = PAIR_KINDS[types][1]
        kinds.append(
            PairKind(
                types=types,
                ncon=ncon,
                geom1=tuple(g1s),
                geom2=tuple(g2s),
                size1=np.array(m.geom_size[list(g1s)], np.float64),
                size2=np.array(m.geom_size[list(g2s)], np.float64),
                reach=np.array(reach, np.float64),
                index1=np.array(g1s, np.int32),
                index2=np.array(g2s, np.int32),
            )
        )
        offsets[types] = start
        start += ncon * len(group)
    order = np.array([offsets[t] + i * PAIR_KINDS[t][1] + k for t, i, k in slots], np.int32)
    return ContactTable(
        **{k: _as_array(k, v) for k, v in rows.items()},
        kinds=tuple(kinds),
        order=order,
        in_order=bool(np.array_equal(order, np.arange(len(order)))),
    )


_ROW_FIELDS = (
    "geom1",
    "geom2",
    "body1",
    "body2",
    "pair",
    "condim",
    "friction",
    "solref",
    "solreffriction",
    "solimp",
    "margin",
    "gap",
    "includemargin",
    "acts",
)
_ROW_WIDTH = {"friction": 5, "solref": 2, "solreffriction": 2, "solimp": 5}
_INT_FIELDS = ("geom1", "geom2", "body1", "body2", "pair", "condim")


def _append_row(m, rows, g1, g2, ipair, params) -> None:
    rows["geom1"].append(g1)
    rows["geom2"].append(g2)
    rows["body1"].append(int(m.geom_bodyid[g1]))
    rows["body2"].append(int(m.geom_bodyid[g2]))
    rows["pair"].append(ipair)
    rows["condim"].append(params["condim"])
    rows["friction"].append(params["friction5"])
    rows["solref"].append(params["solref"])
    rows["solreffriction"].append(params["solreffriction"])
    rows["solimp"].append(params["solimp"])
    rows["margin"].append(params["margin"])
    rows["gap"].append(params["gap"])
    rows["includemargin"].append(params["margin"])
    rows["acts"].append(_acts(m, g1, g2))


def _as_array(name: str, values: list) -> np.ndarray:
    if name in _INT_FIELDS:
        return np.array(values, np.int64).reshape(-1)
    if name == "acts":
        return np.array(values, bool).reshape(-1)
    width = _ROW_WIDTH.get(name)
    out = np.array(values, np.float64)
    return out.reshape(-1, width) if width else out.reshape(-1)


# ----------------------------------------------------------------------------------------------
# Collision
# ----------------------------------------------------------------------------------------------


def collide(xp, table: ContactTable, geom_xpos, geom_xmat) -> Contacts:
    """All candidate contacts of ``table`` at the geom poses, in MuJoCo's order.

    Args:
        xp: the backend namespace (``ivy.torch`` ...).
        table: from :func:`read_contact_table`.
        geom_xpos: ``[..., ngeom, 3]`` geom positions (MuJoCo's ``d.geom_xpos``).
        geom_xmat: ``[..., ngeom, 3, 3]`` geom rotations (``d.geom_xmat`` reshaped).

    Returns:
        :class:`Contacts` over the table's candidates; the active ones, in order, are the
        contacts of MuJoCo's ``d.contact`` that enter the constraints, in MuJoCo's order.

    Example:
        >>> import mujoco
        >>> model = mujoco.MjModel.from_xml_string('''<mujoco><worldbody>
        ...   <geom type="plane" size="1 1 1"/>
        ...   <body pos="0 0 0.09"><freejoint/><geom type="sphere" size="0.1"/></body>
        ... </worldbody></mujoco>''')
        >>> data = mujoco.MjData(model)
        >>> mujoco.mj_forward(model, data)
        >>> table = read_contact_table(model)
        >>> c = collide(ivy.numpy, table, data.geom_xpos, data.geom_xmat.reshape(-1, 3, 3))
        >>> np.round(c.dist, 6), c.active
        (array([-0.01]), array([ True]))
    """
    batch = tuple(geom_xpos.shape[:-2])
    if not table.kinds:
        return _no_contacts(xp, geom_xpos, batch)
    dev = xp.dev(geom_xpos)
    parts: list[list] = [[], [], [], [], []]  # dist, pos, normal, tangent, found
    tangents = any(kind.types == (PLANE, CAPSULE) for kind in table.kinds)
    for kind in table.kinds:
        count = len(kind.geom1) * kind.ncon
        index1 = xp.constant(kind.index1, device=dev)
        index2 = xp.constant(kind.index2, device=dev)
        raw = _RAW_KERNELS[kind.types](
            xp,
            xp.take(geom_xpos, index1, axis=-2),
            xp.take(geom_xmat, index1, axis=-3),
            _constant(xp, kind.size1, geom_xpos),
            xp.take(geom_xpos, index2, axis=-2),
            xp.take(geom_xmat, index2, axis=-3),
            _constant(xp, kind.size2, geom_xpos),
            _constant(xp, kind.reach, geom_xpos),
        )
        tangent = raw.tangent
        if tangents and tangent is None:
            tangent = _default_tangent(xp, raw.normal)
        for part, value, tail in zip(
            parts, (raw.dist, raw.pos, raw.normal, tangent, raw.found), ((), (3,), (3,), (3,), ())
        ):
            part.append(None if value is None else xp.reshape(value, batch + (count,) + tail))
    dist, pos, normal, tangent, found = (
        None if not tangents and k == 3 else _in_order(xp, table, p, -1 if k in (0, 4) else -2)
        for k, p in enumerate(parts)
    )
    include = _constant(xp, table.includemargin, geom_xpos)
    acts = xp.constant(table.acts, device=dev)
    active = xp.logical_and(xp.logical_and(found, dist < include), acts)
    if tangent is None:
        tangent = _default_tangent(xp, normal)
    return Contacts(dist, pos, _contact_frame(xp, normal, tangent), found, active)


def _in_order(xp, table: ContactTable, parts: list, axis: int):
    """The kinds' candidates, concatenated, in MuJoCo's order (one constant permutation)."""
    joined = parts[0] if len(parts) == 1 else xp.concat(parts, axis=axis)
    if table.in_order:
        return joined
    return xp.take(joined, xp.constant(table.order, device=xp.dev(joined)), axis=axis)


def _constant(xp, value: np.ndarray, like):
    return xp.constant(value, dtype=like.dtype, device=xp.dev(like))


def _no_contacts(xp, like, batch: tuple) -> Contacts:
    dev = xp.dev(like)
    none = xp.zeros(batch + (0,), dtype="bool", device=dev)
    return Contacts(
        dist=xp.zeros(batch + (0,), dtype=like.dtype, device=dev),
        pos=xp.zeros(batch + (0, 3), dtype=like.dtype, device=dev),
        frame=xp.zeros(batch + (0, 3, 3), dtype=like.dtype, device=dev),
        found=none,
        active=none,
    )
