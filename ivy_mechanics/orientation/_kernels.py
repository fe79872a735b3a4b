"""The rotation conversions themselves (private), written once against a backend namespace ``xp``.

The public functions in the sibling modules resolve the framework once and call these. Shapes:
quaternions ``[..., 4]`` scalar-last ``[x, y, z, w]``, rotation vectors ``[..., 3]``, axis-angle
``[..., 4]`` ``[ax, ay, az, angle]``, Euler angles ``[..., 3]``, matrices ``[..., 3, 3]``.
"""

from __future__ import annotations

import functools

from ivy_mechanics._series import ATAN_OVER_X, COS_HALF, HALF_PI, HALF_SIN_OVER_X, wrap_angle

# ----------------------------------------------------------------------------------------------
# Quaternions
# ----------------------------------------------------------------------------------------------

# Hamilton product p * q, scalar-last: component r = sum(sign * p[i] * q[j]).
_HAMILTON = (
    ((1, 3, 0), (1, 0, 3), (1, 1, 2), (-1, 2, 1)),
    ((1, 3, 1), (-1, 0, 2), (1, 1, 3), (1, 2, 0)),
    ((1, 3, 2), (1, 0, 1), (-1, 1, 0), (1, 2, 3)),
    ((1, 3, 3), (-1, 0, 0), (-1, 1, 1), (-1, 2, 2)),
)


def hamilton_product(xp, p, q):
    """``p * q`` for quaternions ``[..., 4]`` (batch dims broadcast)."""
    pc = [p[..., i] for i in range(4)]
    qc = [q[..., i] for i in range(4)]
    out = []
    for terms in _HAMILTON:
        acc = None
        for sign, i, j in terms:
            term = pc[i] * qc[j]
            acc = term if acc is None else (acc + term if sign > 0 else acc - term)
        out.append(acc)
    return xp.stack_vector(out)


def canonical_quat(xp, q):
    """The sign of ``q`` with a non-negative scalar part."""
    return xp.where(q[..., 3:4] < 0, -q, q)


def quat_to_mat(xp, q, normalize=True):
    """Rotation matrix of ``q``; ``normalize=False`` assumes a unit quaternion."""
    return _quat_components_to_mat(xp, q[..., 0], q[..., 1], q[..., 2], q[..., 3], normalize)


def _quat_components_to_mat(xp, x, y, z, w, normalize=True):
    xx, yy, zz = x * x, y * y, z * z
    xy, xz, yz = x * y, x * z, y * z
    wx, wy, wz = w * x, w * y, w * z
    s = 2.0 / (xx + yy + zz + w * w) if normalize else 2.0
    rows = [
        [1.0 - s * (yy + zz), s * (xy - wz), s * (xz + wy)],
        [s * (xy + wz), 1.0 - s * (xx + zz), s * (yz - wx)],
        [s * (xz - wy), s * (yz + wx), 1.0 - s * (xx + yy)],
    ]
    return xp.stack_matrix(rows)


def mat_to_quat(xp, m):
    """Unit quaternion (w >= 0) of a rotation matrix, by the best conditioned of four formulas
    (Shepperd's method, as scipy): every candidate is finite, so one ``where`` selects."""
    r00, r01, r02 = m[..., 0, 0], m[..., 0, 1], m[..., 0, 2]
    r10, r11, r12 = m[..., 1, 0], m[..., 1, 1], m[..., 1, 2]
    r20, r21, r22 = m[..., 2, 0], m[..., 2, 1], m[..., 2, 2]
    trace = r00 + r11 + r22
    s01, s02, s12 = r10 + r01, r20 + r02, r21 + r12
    d01, d02, d12 = r10 - r01, r02 - r20, r21 - r12
    one_minus_trace = 1.0 - trace
    c0 = xp.stack_vector([one_minus_trace + 2.0 * r00, s01, s02, d12])
    c1 = xp.stack_vector([s01, one_minus_trace + 2.0 * r11, s12, d02])
    c2 = xp.stack_vector([s02, s12, one_minus_trace + 2.0 * r22, d01])
    c3 = xp.stack_vector([d12, d02, d01, 1.0 + trace])
    # First maximum of [r00, r11, r22, trace], as numpy's argmax (scipy's choice).
    sel0 = xp.logical_and(xp.logical_and(r00 >= r11, r00 >= r22), r00 >= trace)
    sel1 = xp.logical_and(r11 >= r22, r11 >= trace)
    sel2 = r22 >= trace
    q = xp.where(
        sel0[..., None],
        c0,
        xp.where(sel1[..., None], c1, xp.where(sel2[..., None], c2, c3)),
    )
    # The chosen candidate is 4 |q_k| q with |q_k| >= 1/2: its norm is >= 2, never 0.
    q = q / xp.sqrt(xp.sum(q * q, axis=-1, keepdims=True))
    return canonical_quat(xp, q)


# ----------------------------------------------------------------------------------------------
# Rotation vectors and axis-angle
# ----------------------------------------------------------------------------------------------


def rotvec_to_quat(xp, v):
    """Unit quaternion ``[sin(t/2) v/t, cos(t/2)]`` with ``t = |v|`` (series below t = 1e-2)."""
    t2 = xp.sum(v * v, axis=-1, keepdims=True)
    ratio, w = _half_angle_terms(xp, t2)
    return xp.concat([v * ratio, w], axis=-1)


def _half_angle_terms(xp, t2):
    """``(sin(t/2) / t, cos(t/2))`` from ``t2 = t**2``, by their series below ``t = 1e-2``."""
    return xp.taylor_switch(
        t2, (HALF_SIN_OVER_X, COS_HALF), lambda t: (xp.sin(0.5 * t) / t, xp.cos(0.5 * t))
    )


def quat_to_rotvec(xp, q, canonical=False):
    """Rotation vector (angle in [0, pi]) of a quaternion (need not be unit).

    ``2 atan2(n, w) / n`` with ``n = |q_xyz|``; for ``n / w < 1e-2`` the series of atan.
    """
    if not canonical:
        q = canonical_quat(xp, q)
    v, w = q[..., :3], q[..., 3:]
    n2 = xp.sum(v * v, axis=-1, keepdims=True)
    w2 = w * w
    small = n2 < 1e-4 * w2
    one = xp.ones_like(w)
    n = xp.sqrt(xp.where(small, one, n2))
    large_ratio = 2.0 * xp.atan2(n, w) / n
    w_safe = xp.where(small, w, one)
    small_ratio = (2.0 / w_safe) * xp.horner(n2 / (w_safe * w_safe), ATAN_OVER_X)
    return v * xp.where(small, small_ratio, large_ratio)


def _unit_z_like(xp, like):
    """The axis ``[0, 0, 1]`` shaped ``like[..., :1]`` broadcast to ``[..., 3]``."""
    zero = xp.zeros_like(like)
    return xp.concat([zero, zero, xp.ones_like(like)], axis=-1)


def quat_to_axis_angle(xp, q, canonical=False):
    """``[axis, angle]`` with angle in [0, pi]; the axis is ``[0, 0, 1]`` at angle 0."""
    if not canonical:
        q = canonical_quat(xp, q)
    v, w = q[..., :3], q[..., 3:]
    n2 = xp.sum(v * v, axis=-1, keepdims=True)
    positive = n2 > 0
    n = xp.sqrt(xp.where(positive, n2, xp.ones_like(n2)))
    axis = xp.where(positive, v / n, _unit_z_like(xp, w))
    angle = 2.0 * xp.atan2(xp.where(positive, n, xp.zeros_like(n)), w)
    return xp.concat([axis, angle], axis=-1)


def axis_angle_to_quat(xp, aa):
    """Unit quaternion of ``[unit axis, angle]``."""
    half = 0.5 * aa[..., 3:]
    return xp.concat([aa[..., :3] * xp.sin(half), xp.cos(half)], axis=-1)


def rotvec_to_axis_angle(xp, v):
    """``[v / |v|, |v|]``; the axis is ``[0, 0, 1]`` for the zero vector."""
    n2 = xp.sum(v * v, axis=-1, keepdims=True)
    positive = n2 > 0
    n = xp.sqrt(xp.where(positive, n2, xp.ones_like(n2)))
    axis = xp.where(positive, v / n, _unit_z_like(xp, n))
    return xp.concat([axis, xp.where(positive, n, xp.zeros_like(n))], axis=-1)


def axis_angle_to_rotvec(xp, aa):
    """``axis * angle``."""
    return aa[..., :3] * aa[..., 3:]


def axis_angle_to_polar(xp, aa):
    """``[inclination, azimuth, angle]`` of the axis: inclination from +z, azimuth from +x."""
    ax, ay, az = aa[..., 0:1], aa[..., 1:2], aa[..., 2:3]
    inclination = xp.atan2(xp.safe_hypot(ax, ay), az)
    azimuth = xp.safe_atan2(ay, ax)
    return xp.concat([inclination, azimuth, aa[..., 3:]], axis=-1)


def polar_to_axis_angle(xp, paa):
    """``[axis, angle]`` from ``[inclination, azimuth, angle]``."""
    inclination, azimuth = paa[..., 0:1], paa[..., 1:2]
    sin_inc = xp.sin(inclination)
    axis = [sin_inc * xp.cos(azimuth), sin_inc * xp.sin(azimuth), xp.cos(inclination)]
    return xp.concat([*axis, paa[..., 2:]], axis=-1)


# ----------------------------------------------------------------------------------------------
# Euler angles
# ----------------------------------------------------------------------------------------------


@functools.cache
def parse_convention(convention: str) -> tuple[tuple[int, int, int], bool]:
    """``(axes, extrinsic)`` of a scipy-style sequence: 'xyz' extrinsic, 'XYZ' intrinsic."""
    if not isinstance(convention, str) or len(convention) != 3:
        raise ValueError(
            f"Euler convention must be 3 axes such as 'xyz' (extrinsic) or 'XYZ' (intrinsic); "
            f"got {convention!r}."
        )
    if set(convention) <= set("xyz"):
        extrinsic = True
    elif set(convention) <= set("XYZ"):
        extrinsic = False
    else:
        raise ValueError(
            f"Euler convention {convention!r} must use only x, y, z (extrinsic) or only X, Y, Z "
            f"(intrinsic), as scipy's Rotation.from_euler."
        )
    if convention[0] == convention[1] or convention[1] == convention[2]:
        raise ValueError(f"Euler convention {convention!r} repeats an axis consecutively.")
    return tuple("xyz".index(c) for c in convention.lower()), extrinsic


# Sparse symbolic products: an entry is None (zero) or (sign, value), value an array or _ONE.
_ONE = object()


def _smul(a, b, sign=1):
    if a is None or b is None:
        return None
    (sa, va), (sb, vb) = a, b
    if va is _ONE:
        return (sign * sa * sb, vb)
    if vb is _ONE:
        return (sign * sa * sb, va)
    return (sign * sa * sb, va * vb)


def _ssum(xp, terms, like):
    terms = [t for t in terms if t is not None]
    if len(terms) <= 1:
        return terms[0] if terms else None
    values = [(s, xp.ones_like(like) if v is _ONE else v) for s, v in terms]
    values.sort(key=lambda t: -t[0])  # a positive term first, if any
    sign0, acc = values[0]
    for s, v in values[1:]:
        acc = acc + v if s == sign0 else acc - v
    return (sign0, acc)


def _dense(xp, entry, like):
    if entry is None:
        return xp.zeros_like(like)
    sign, value = entry
    if value is _ONE:
        value = xp.ones_like(like)
    return value if sign > 0 else -value


def _elementary_mat(axis, c, s):
    m = [[None] * 3 for _ in range(3)]
    j, k = (axis + 1) % 3, (axis + 2) % 3
    m[axis][axis] = (1, _ONE)
    m[j][j] = m[k][k] = (1, c)
    m[j][k], m[k][j] = (-1, s), (1, s)
    return m


def _sparse_matmul(xp, a, b, like):
    return [
        [_ssum(xp, [_smul(a[i][r], b[r][j]) for r in range(3)], like) for j in range(3)]
        for i in range(3)
    ]


def _elementary_quat(axis, c, s):
    q = [None] * 4
    q[axis], q[3] = (1, s), (1, c)
    return q


def _sparse_hamilton(xp, p, q, like):
    return [
        _ssum(xp, [_smul(p[i], q[j], sign) for sign, i, j in terms], like) for terms in _HAMILTON
    ]


def _ordered(factors, extrinsic):
    """Elementary factors (in the order of the angles) in the order of the product."""
    return factors[::-1] if extrinsic else factors


def euler_to_mat(xp, euler, convention):
    """Product of the three elementary rotations, multiplied out symbolically so that only the
    non-zero terms are computed. Extrinsic 'xyz': Rz(c) Ry(b) Rx(a); intrinsic 'XYZ':
    Rx(a) Ry(b) Rz(c)."""
    axes, extrinsic = parse_convention(convention)
    angles = [euler[..., i] for i in range(3)]
    factors = [_elementary_mat(ax, xp.cos(t), xp.sin(t)) for ax, t in zip(axes, angles)]
    first, second, third = _ordered(factors, extrinsic)
    like = angles[0]
    product = _sparse_matmul(xp, _sparse_matmul(xp, first, second, like), third, like)
    return xp.stack_matrix([[_dense(xp, e, like) for e in row] for row in product])


def euler_to_quat(xp, euler, convention):
    """Hamilton product of the three elementary quaternions (only non-zero terms computed)."""
    axes, extrinsic = parse_convention(convention)
    halves = [0.5 * euler[..., i] for i in range(3)]
    factors = [_elementary_quat(ax, xp.cos(t), xp.sin(t)) for ax, t in zip(axes, halves)]
    first, second, third = _ordered(factors, extrinsic)
    like = halves[0]
    product = _sparse_hamilton(xp, _sparse_hamilton(xp, first, second, like), third, like)
    return xp.stack_vector([_dense(xp, e, like) for e in product])


def quat_to_euler(xp, q, convention):
    """Euler angles of a quaternion by the method of Bernardes and Viollet (2022), as scipy.

    Angles are in (-pi, pi]; the middle one in [-pi/2, pi/2] (Tait-Bryan) or [0, pi] (proper).
    At gimbal lock the first and third angles are not unique; the formula used everywhere (no
    branch) then splits their sum evenly, and its gradients stay finite.
    """
    axes, extrinsic = parse_convention(convention)
    i, j, k = axes if extrinsic else axes[::-1]
    symmetric = i == k
    if symmetric:
        k = 3 - i - j
    sign = (i - j) * (j - k) * (k - i) // 2  # +1 for an even permutation, -1 for an odd one
    w, qi, qj, qk = q[..., 3], q[..., i], q[..., j], q[..., k]
    if sign < 0:
        qk = -qk
    if symmetric:
        a, b, c, d = w, qi, qj, qk
    else:
        a, b, c, d = w - qj, qi + qk, qj + w, qk - qi
    half_sum = xp.safe_atan2(b, a)
    half_diff = xp.safe_atan2(d, c)
    middle = 2.0 * xp.atan2(xp.safe_hypot(c, d), xp.safe_hypot(a, b))
    first = wrap_angle(xp, half_sum - half_diff)
    third = half_sum + half_diff
    if not symmetric:
        middle = middle - HALF_PI
        if sign < 0:
            third = -third
    third = wrap_angle(xp, third)
    ordered = [first, middle, third] if extrinsic else [third, middle, first]
    return xp.stack_vector(ordered)


# ----------------------------------------------------------------------------------------------
# The 6D representation (first two columns of the matrix, Zhou et al. 2019)
# ----------------------------------------------------------------------------------------------


def rot6d_to_mat(xp, d6):
    """Gram-Schmidt on the two columns ``d6[..., :3]`` and ``d6[..., 3:]``; the third column is
    their cross product."""
    a1, a2 = d6[..., 0:3], d6[..., 3:6]
    b1 = a1 / xp.sqrt(xp.sum(a1 * a1, axis=-1, keepdims=True))
    b2 = a2 - xp.sum(b1 * a2, axis=-1, keepdims=True) * b1
    b2 = b2 / xp.sqrt(xp.sum(b2 * b2, axis=-1, keepdims=True))
    x1, y1, z1 = b1[..., 0], b1[..., 1], b1[..., 2]
    x2, y2, z2 = b2[..., 0], b2[..., 1], b2[..., 2]
    b3 = [y1 * z2 - z1 * y2, z1 * x2 - x1 * z2, x1 * y2 - y1 * x2]
    return xp.stack_matrix([[x1, x2, b3[0]], [y1, y2, b3[1]], [z1, z2, b3[2]]])


def mat_to_rot6d(xp, m):
    """``[R[:, 0], R[:, 1]]`` flattened to ``[..., 6]``."""
    return xp.concat([m[..., :, 0], m[..., :, 1]], axis=-1)


# ----------------------------------------------------------------------------------------------
# Shared by several public modules
# ----------------------------------------------------------------------------------------------


def rotvec_to_mat(xp, v):
    """Rodrigues' formula via the unit quaternion (robust at 0 and at pi), on components."""
    vx, vy, vz = v[..., 0], v[..., 1], v[..., 2]
    t2 = vx * vx + vy * vy + vz * vz
    ratio, w = _half_angle_terms(xp, t2)
    return _quat_components_to_mat(xp, vx * ratio, vy * ratio, vz * ratio, w, normalize=False)


def mat_to_rotvec(xp, m):
    return quat_to_rotvec(xp, mat_to_quat(xp, m), canonical=True)


def hat(xp, v):
    """Skew-symmetric matrix ``[v]x`` of ``v`` ``[..., 3]``."""
    x, y, z = v[..., 0], v[..., 1], v[..., 2]
    zero = xp.zeros_like(x)
    return xp.stack_matrix([[zero, -z, y], [z, zero, -x], [-y, x, zero]])


__all__ = [
    "hamilton_product",
    "canonical_quat",
    "quat_to_mat",
    "mat_to_quat",
    "rotvec_to_quat",
    "quat_to_rotvec",
    "quat_to_axis_angle",
    "axis_angle_to_quat",
    "rotvec_to_axis_angle",
    "axis_angle_to_rotvec",
    "axis_angle_to_polar",
    "polar_to_axis_angle",
    "parse_convention",
    "euler_to_mat",
    "euler_to_quat",
    "quat_to_euler",
    "rot6d_to_mat",
    "mat_to_rot6d",
    "rotvec_to_mat",
    "mat_to_rotvec",
    "hat",
]
