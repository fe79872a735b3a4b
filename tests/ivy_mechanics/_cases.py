"""Inputs for the ivy_mechanics tests, built in numpy float64 (and scipy), never with ivy.

``KINDS`` makes inputs of each kind (quaternions, matrices, ...): ``generic`` ones, away from any
singular point, and ``singular`` ones (identity, rotations by pi, gimbal lock, the origin, the
poles). ``CASES`` lists every public function with the kinds of its array arguments, so that the
generic tests (backend agreement, dtypes, batch shapes, compilation, gradients) cover the whole
API from one table.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial.transform import Rotation

PI = np.pi


def _unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _rotations(rng, n):
    return Rotation.random(n, random_state=rng)


def _axis_angle(rng, n, lo=0.1, hi=PI - 0.1):
    return np.concatenate([_unit(rng.standard_normal((n, 3))), rng.uniform(lo, hi, (n, 1))], -1)


def _polar_axis_angle(rng, n):
    return np.stack(
        [rng.uniform(0.2, PI - 0.2, n), rng.uniform(-3.0, 3.0, n), rng.uniform(0.1, PI - 0.1, n)],
        -1,
    )


def _euler(rng, n, convention):
    """Euler angles away from gimbal lock (middle angle at least 0.2 from it)."""
    angles = rng.uniform(-3.0, 3.0, (n, 3))
    if convention[0].lower() == convention[2].lower():  # proper Euler: middle in (0, pi)
        angles[:, 1] = rng.uniform(0.2, PI - 0.2, n)
    else:  # Tait-Bryan: middle in (-pi/2, pi/2)
        angles[:, 1] = rng.uniform(-PI / 2 + 0.2, PI / 2 - 0.2, n)
    return angles


def gimbal_lock_euler(convention, offsets=(0.0,)):
    """Euler angles at (and ``offsets`` away from) gimbal lock for ``convention``."""
    proper = convention[0].lower() == convention[2].lower()
    locks = (0.0, PI) if proper else (PI / 2, -PI / 2)
    rows = []
    for lock in locks:
        for off in offsets:
            for sgn in (1.0, -1.0):
                middle = lock + sgn * off
                if proper and not 0.0 <= middle <= PI:
                    continue
                for first, third in ((0.3, -1.1), (2.9, 0.0), (0.0, 0.0), (-PI, 1.0)):
                    rows.append([first, middle, third])
    return np.array(rows)


def _rot6d(rng, n):
    """Non-orthonormal 6D inputs: scaled first column, second column with a component along it."""
    m = _rotations(rng, n).as_matrix()
    a1 = m[:, :, 0] * rng.uniform(0.5, 2.0, (n, 1))
    a2 = m[:, :, 1] * rng.uniform(0.5, 2.0, (n, 1)) + rng.uniform(-0.5, 0.5, (n, 1)) * a1
    return np.concatenate([a1, a2], -1)


def _mat_pose(rng, n):
    pose = np.zeros((n, 4, 4))
    pose[:, :3, :3] = _rotations(rng, n).as_matrix()
    pose[:, :3, 3] = rng.standard_normal((n, 3))
    pose[:, 3, 3] = 1.0
    return pose


def _pi_rotations():
    axes = _unit(np.array([[1.0, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [1, -2, 3]]))
    return Rotation.from_rotvec(PI * axes)


def _singular_rotations():
    """Identity, a tiny rotation, rotations by pi (coordinate and oblique axes), and gimbal
    lock of the 'XYZ' and 'ZYX' conventions used in CASES ('zxz' locks at the identity)."""
    near = Rotation.from_rotvec([[0.0, 0, 0], [1e-9, 0, 0], [0, 0, PI - 1e-9]])
    lock = Rotation.concatenate(
        [
            Rotation.from_euler("XYZ", [0.3, PI / 2, -1.1]),
            Rotation.from_euler("ZYX", [0.3, -PI / 2, 0.5]),
        ]
    )
    return Rotation.concatenate([near, _pi_rotations(), lock])


def _with_positions(orientations):
    """Poses ``[1, 1, 1, orientation]`` for an array of orientations ``[n, k]``."""
    return np.concatenate([np.ones((len(orientations), 3)), orientations], -1)


def _homogeneous(mats):
    n = len(mats)
    top = np.concatenate([mats, np.ones((n, 3, 1))], -1)
    return np.concatenate([top, np.tile(np.array([[[0.0, 0, 0, 1]]]), (n, 1, 1))], -2)


# Exactly representable rotations by pi/2 (exact zeros at gimbal lock of 'XYZ' and 'ZYX').
_EXACT_QUATS = np.array([[0.0, 1, 0, 1], [0, 0, 1, 1], [1, 0, 0, 1], [1, 1, 1, 1], [1, -1, 1, 1]])
_EXACT_MATS = np.array(
    [
        [[0.0, 0, 1], [0, 1, 0], [-1, 0, 0]],
        [[0.0, -1, 0], [1, 0, 0], [0, 0, 1]],
        [[0.0, 0, 1], [1, 0, 0], [0, 1, 0]],
    ]
)


def _quat_singular():
    q = _singular_rotations().as_quat()
    # sign, scale, and exact (unnormalised) quaternions
    return np.concatenate([q, -q[:1], np.array([[0.0, 0, 0, 2.0]]), _EXACT_QUATS])


# Each kind: generic(rng, n, convention) -> array, singular(convention) -> array.
KINDS = {
    "quat": (
        lambda rng, n, c: _unit(rng.standard_normal((n, 4))),
        lambda c: _quat_singular(),
    ),
    "mat": (
        lambda rng, n, c: _rotations(rng, n).as_matrix(),
        lambda c: np.concatenate([_singular_rotations().as_matrix(), _EXACT_MATS]),
    ),
    "rotvec": (
        lambda rng, n, c: _rotations(rng, n).as_rotvec() * 0.95,
        lambda c: np.concatenate([_singular_rotations().as_rotvec(), [[0, 0, 2 * PI]]]),
    ),
    "axis_angle": (
        lambda rng, n, c: _axis_angle(rng, n),
        lambda c: np.array([[0.0, 0, 1, 0], [1, 0, 0, 0], [0, 1, 0, PI], [0.6, 0, 0.8, PI]]),
    ),
    "polar_aa": (
        lambda rng, n, c: _polar_axis_angle(rng, n),
        lambda c: np.array([[0.0, 0, 0], [0, 0, 1], [PI, 0, 1], [1, 2, 0], [1, 2, PI]]),
    ),
    "euler": (
        lambda rng, n, c: _euler(rng, n, c),
        lambda c: np.concatenate([np.zeros((1, 3)), gimbal_lock_euler(c)]),
    ),
    "rot6d": (
        lambda rng, n, c: _rot6d(rng, n),
        lambda c: np.array([[1.0, 0, 0, 0, 1, 0], [0, 0, 1, 1, 0, 0], [-1, 0, 0, 0, -1, 0]]),
    ),
    "points": (
        lambda rng, n, c: rng.standard_normal((n, 3)) * 2.0,
        lambda c: np.array([[0.0, 0, 0], [0, 0, 1], [0, 0, -2], [1, 0, 0]]),
    ),
    "polar_coords": (
        lambda rng, n, c: np.stack(
            [rng.uniform(-3, 3, n), rng.uniform(0.2, PI - 0.2, n), rng.uniform(0.5, 3, n)], -1
        ),
        lambda c: np.array([[0.0, 0, 0], [1, 0, 2], [1, PI, 2], [0, 1, 0]]),
    ),
    "cyl_coords": (
        lambda rng, n, c: np.stack(
            [rng.uniform(0.5, 3, n), rng.uniform(-3, 3, n), rng.uniform(-2, 2, n)], -1
        ),
        lambda c: np.array([[0.0, 0, 0], [0, 1, 2], [2, PI, 0]]),
    ),
    "coords": (
        lambda rng, n, c: rng.standard_normal((n, 3)),
        lambda c: np.zeros((1, 3)),
    ),
    "mat_pose": (
        lambda rng, n, c: _mat_pose(rng, n),
        lambda c: _homogeneous(KINDS["mat"][1](c)),
    ),
    "mat_pose_34": (
        lambda rng, n, c: _mat_pose(rng, n)[:, :3],
        lambda c: _homogeneous(KINDS["mat"][1](c))[:, :3],
    ),
    "quat_pose": (
        lambda rng, n, c: np.concatenate(
            [rng.standard_normal((n, 3)), _unit(rng.standard_normal((n, 4)))], -1
        ),
        lambda c: _with_positions(_quat_singular()),
    ),
    "rotvec_pose": (
        lambda rng, n, c: np.concatenate(
            [rng.standard_normal((n, 3)), _rotations(rng, n).as_rotvec() * 0.95], -1
        ),
        lambda c: _with_positions(_singular_rotations().as_rotvec()),
    ),
    "euler_pose": (
        lambda rng, n, c: np.concatenate([rng.standard_normal((n, 3)), _euler(rng, n, c)], -1),
        lambda c: np.concatenate(
            [np.ones((17, 3)), np.concatenate([np.zeros((1, 3)), gimbal_lock_euler(c)])], -1
        ),
    ),
    "aa_pose": (
        lambda rng, n, c: np.concatenate([rng.standard_normal((n, 3)), _axis_angle(rng, n)], -1),
        lambda c: np.concatenate([np.ones((4, 3)), KINDS["axis_angle"][1](c)], -1),
    ),
    "twist": (
        lambda rng, n, c: np.concatenate(
            [rng.standard_normal((n, 3)), _rotations(rng, n).as_rotvec() * 0.95], -1
        ),
        lambda c: _with_positions(_singular_rotations().as_rotvec()),
    ),
    "skew": (
        lambda rng, n, c: _hat(rng.standard_normal((n, 3))),
        lambda c: np.zeros((1, 3, 3)),
    ),
    "skew4": (
        lambda rng, n, c: _hat4(rng.standard_normal((n, 6))),
        lambda c: np.zeros((1, 4, 4)),
    ),
    "target": (  # never straight above or below the singular "points"
        lambda rng, n, c: rng.standard_normal((n, 3)),
        lambda c: np.array([[1.0, 2.0, 3.0]]),
    ),
    "t": (
        lambda rng, n, c: rng.uniform(0.0, 1.0, (n, 1)),
        lambda c: np.array([[0.0], [1.0], [0.5], [0.25], [0.0], [1.0], [0.5], [0.5], [0.5]]),
    ),
}


def _hat(v):
    x, y, z = v[..., 0], v[..., 1], v[..., 2]
    zero = np.zeros_like(x)
    return np.stack([np.stack(r, -1) for r in [[zero, -z, y], [z, zero, -x], [-y, x, zero]]], -2)


def _hat4(t):
    top = np.concatenate([_hat(t[..., 3:]), t[..., :3, None]], -1)
    return np.concatenate([top, np.zeros_like(top[..., :1, :])], -2)


# One batch size for the table-driven tests: jax compiles each primitive once per shape, so
# sharing shapes across functions and tests keeps the suite fast.
BATCH = 20
BATCH_SHAPE = (4, 5)  # the same items with two batch dimensions


def _resized(arrays):
    return [np.resize(a, (BATCH, *a.shape[1:])) for a in arrays]


def make_inputs(kinds, rng, convention="zyx", singular=False):
    """One array per kind, ``BATCH`` items each (singular sets are repeated cyclically)."""
    if not singular:
        return [KINDS[k][0](rng, BATCH, convention) for k in kinds]
    return _resized([KINDS[k][1](convention) for k in kinds])


# name -> (kinds of the array arguments, keyword arguments). Functions with a convention are
# listed once per convention in CONVENTION_SAMPLES by the tests that need it.
_REPS = {
    "rot_mat": "mat",
    "quaternion": "quat",
    "rot_vec": "rotvec",
    "axis_angle": "axis_angle",
    "polar_axis_angle": "polar_aa",
    "euler": "euler",
    "rot_6d": "rot6d",
}
CASES: dict[str, tuple[tuple[str, ...], dict]] = {}
for _src, _src_kind in _REPS.items():
    for _dst in _REPS:
        if _src != _dst:
            _kw = {"convention": "XYZ"} if "euler" in (_src, _dst) else {}
            CASES[f"{_src}_to_{_dst}"] = ((_src_kind,), _kw)
CASES.update(
    {
        "hamilton_product": (("quat", "quat"), {}),
        "quaternion_conjugate": (("quat",), {}),
        "inverse_quaternion": (("quat",), {}),
        "normalize_quaternion": (("quat",), {}),
        "scale_quaternion_rotation_angle": (("quat", "t"), {}),
        "rotate_points": (("mat", "points"), {}),
        "quaternion_rotate_points": (("quat", "points"), {}),
        "slerp": (("quat", "quat", "t"), {}),
        "geodesic_distance": (("mat", "mat"), {}),
        "quaternion_geodesic_distance": (("quat", "quat"), {}),
        "target_facing_rotation_matrix": (("points", "target"), {}),
        "so3_hat": (("points",), {}),
        "so3_vee": (("skew",), {}),
        "so3_exp": (("rotvec",), {}),
        "so3_log": (("mat",), {}),
        "se3_hat": (("twist",), {}),
        "se3_vee": (("skew4",), {}),
        "se3_exp": (("twist",), {}),
        "se3_log": (("mat_pose",), {}),
        "make_transformation_homogeneous": (("mat_pose_34",), {}),
        "quaternion_pose_to_mat_pose": (("quat_pose",), {}),
        "mat_pose_to_quaternion_pose": (("mat_pose",), {}),
        "rot_vec_pose_to_mat_pose": (("rotvec_pose",), {}),
        "mat_pose_to_rot_vec_pose": (("mat_pose_34",), {}),
        "euler_pose_to_mat_pose": (("euler_pose",), {"convention": "zxz"}),
        "mat_pose_to_euler_pose": (("mat_pose",), {"convention": "zxz"}),
        "axis_angle_pose_to_mat_pose": (("aa_pose",), {}),
        "mat_pose_to_axis_angle_pose": (("mat_pose",), {}),
        "quaternion_pose_to_rot_vec_pose": (("quat_pose",), {}),
        "rot_vec_pose_to_quaternion_pose": (("rotvec_pose",), {}),
        "quaternion_pose_to_euler_pose": (("quat_pose",), {"convention": "ZYX"}),
        "euler_pose_to_quaternion_pose": (("euler_pose",), {"convention": "ZYX"}),
        "quaternion_pose_to_axis_angle_pose": (("quat_pose",), {}),
        "axis_angle_pose_to_quaternion_pose": (("aa_pose",), {}),
        "compose_mat_poses": (("mat_pose", "mat_pose_34"), {}),
        "invert_mat_pose": (("mat_pose",), {}),
        "transform_points": (("mat_pose", "points"), {}),
        "compose_quaternion_poses": (("quat_pose", "quat_pose"), {}),
        "invert_quaternion_pose": (("quat_pose",), {}),
        "increment_quaternion_pose_with_velocity": (("quat_pose", "quat_pose", "t"), {}),
        "polar_to_cartesian_coords": (("polar_coords",), {}),
        "cartesian_to_polar_coords": (("points",), {}),
        "cylindrical_to_cartesian_coords": (("cyl_coords",), {}),
        "cartesian_to_cylindrical_coords": (("points",), {}),
        "make_coordinates_homogeneous": (("coords",), {}),
    }
)

# Functions with no array argument (random draws): name -> keyword arguments.
RANDOM_CASES = {
    "get_random_quaternion": {},
    "get_random_rot_mat": {},
    "get_random_rot_vec": {},
    "get_random_axis_angle": {},
    "get_random_euler": {"convention": "zxz"},
}

# Public names that are not functions of arrays.
NOT_FUNCTIONS = {"EULER_CONVENTIONS"}


def near_singular_inputs(kinds, rng, convention="zyx"):
    """Inputs a little away from the singular points (small angles on both sides of the series
    threshold, pi - 1e-2, near gimbal lock) where the functions are smooth: for finite
    differences. Only the first argument is near-singular (two equal near-identity quaternions
    would sit on the cone point of their distance); the others are generic."""
    angles = np.array([1e-3, 5e-3, 0.02, PI - 1e-2])
    axes = _unit(rng.standard_normal((4, 3)))
    rot = Rotation.from_rotvec(axes * angles[:, None])
    near = {
        "quat": rot.as_quat(),
        "mat": rot.as_matrix(),
        "rotvec": rot.as_rotvec(),
        "axis_angle": np.concatenate([axes, angles[:, None]], -1),
        "euler": gimbal_lock_euler(convention, (1e-2,))[:4],
        "twist": np.concatenate([rng.standard_normal((4, 3)), rot.as_rotvec()], -1),
        "mat_pose": np.concatenate(
            [np.concatenate([rot.as_matrix(), np.ones((4, 3, 1))], -1), _mat_pose(rng, 4)[:, 3:]],
            -2,
        ),
    }
    first = near.get(kinds[0], KINDS[kinds[0]][0](rng, 4, convention))
    return _resized([first]) + [KINDS[k][0](rng, BATCH, convention) for k in kinds[1:]]


# Functions that are smooth at their "singular" inputs (the identity, gimbal lock of Euler
# angles as inputs): their gradients there must equal finite differences too.
SMOOTH_AT_SINGULAR = {
    "rot_vec_to_quaternion",
    "rot_vec_to_rot_mat",
    "rot_vec_to_rot_6d",
    "so3_exp",
    "se3_exp",
    "euler_to_rot_mat",
    "euler_to_quaternion",
    "euler_to_rot_6d",
    "quaternion_to_rot_mat",
    "quaternion_to_rot_6d",
    "axis_angle_to_rot_mat",
    "axis_angle_to_quaternion",
    "hamilton_product",
}
