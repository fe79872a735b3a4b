"""Reference rotations from scipy.spatial.transform.Rotation and comparisons that respect each
representation's ambiguities (quaternion sign, the axis at angle 0, the sign of a rotation
vector at exactly pi, Euler angles at gimbal lock: compared by the matrix they produce)."""

from __future__ import annotations

import numpy as np
from scipy.spatial.transform import Rotation

PI = np.pi

# Rotation angles of the edge set: exactly 0, tiny, around the series threshold (1e-2), generic,
# and pi - (1e-3 ... 1e-9) and exactly pi.
EDGE_ANGLES = np.array(
    [0.0, 1e-12, 1e-9, 1e-6, 1e-4, 1e-3, 0.00999, 0.01001, 0.5, PI / 2, 2.0]
    + [PI - 1e-3, PI - 1e-6, PI - 1e-9, PI]
)
# Middle-angle offsets from gimbal lock.
GIMBAL_OFFSETS = (0.0, 1e-12, 1e-9, 1e-6, 1e-3)
# Every reference set has this many rotations (shared shapes keep jax's compile cache warm).
EDGE_SIZE = 256


def edge_axis_angles(rng):
    """``(axes [EDGE_SIZE, 3], angles [EDGE_SIZE])``: every edge angle about coordinate and
    oblique axes, then uniform random rotations."""
    axes = np.array([[1.0, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0], [0, 0, -1], [1, 1, 1]])
    axes = np.concatenate([axes, rng.standard_normal((3, 3))])
    axes /= np.linalg.norm(axes, axis=-1, keepdims=True)
    all_axes = np.repeat(axes, len(EDGE_ANGLES), axis=0)
    all_angles = np.tile(EDGE_ANGLES, len(axes))
    rotvec = Rotation.random(EDGE_SIZE - len(all_angles), random_state=rng).as_rotvec()
    angle = np.linalg.norm(rotvec, axis=-1)
    return (
        np.concatenate([all_axes, rotvec / angle[:, None]]),
        np.concatenate([all_angles, angle]),
    )


def polar_of_axis_angle(axis_angle):
    ax, ay, az = axis_angle[:, 0], axis_angle[:, 1], axis_angle[:, 2]
    return np.stack([np.arctan2(np.hypot(ax, ay), az), np.arctan2(ay, ax), axis_angle[:, 3]], -1)


def axis_angle_of_polar(polar):
    inc, azi = polar[:, 0], polar[:, 1]
    axis = np.stack([np.sin(inc) * np.cos(azi), np.sin(inc) * np.sin(azi), np.cos(inc)], -1)
    return np.concatenate([axis, polar[:, 2:3]], -1)


def represent(kind, axes, angles, rng, convention=None):
    """``(input array of kind, reference Rotation)`` for the rotations ``angles`` about ``axes``."""
    rot = Rotation.from_rotvec(axes * angles[:, None])
    if kind == "rot_mat":
        return rot.as_matrix(), rot
    if kind == "quaternion":
        # Any sign and norm is accepted.
        scale = rng.uniform(0.5, 2.0, (len(angles), 1)) * rng.choice([-1.0, 1.0], (len(angles), 1))
        return rot.as_quat() * scale, rot
    if kind == "rot_vec":
        return axes * angles[:, None], rot
    if kind == "axis_angle":
        return np.concatenate([axes, angles[:, None]], -1), rot
    if kind == "polar_axis_angle":
        return polar_of_axis_angle(np.concatenate([axes, angles[:, None]], -1)), rot
    if kind == "euler":
        euler = rot.as_euler(convention)
        return euler, Rotation.from_euler(convention, euler)
    if kind == "rot_6d":
        m = rot.as_matrix()
        a1 = m[:, :, 0] * rng.uniform(0.5, 2.0, (len(angles), 1))
        a2 = m[:, :, 1] + rng.uniform(-0.5, 0.5, (len(angles), 1)) * m[:, :, 0]
        return np.concatenate([a1, a2], -1), rot
    raise ValueError(kind)


def _rows_max(a):
    return np.abs(a).reshape(len(a), -1).max(-1)


def _check(err, tol, what):
    worst = int(np.argmax(err))
    assert err[worst] <= tol, f"{what}: error {err[worst]:.3g} > {tol:.0e} at row {worst}"


def _rot_vec_error(got, ref_rotvec):
    err = _rows_max(got - ref_rotvec)
    at_pi = np.abs(np.linalg.norm(ref_rotvec, axis=-1) - PI) < 1e-13  # v and -v are the same
    return np.where(at_pi, np.minimum(err, _rows_max(got + ref_rotvec)), err)


def assert_represents(kind, got, rot, tol, convention=None, what=""):
    """Assert that ``got`` (numpy, representation ``kind``) is the rotation ``rot``."""
    what = f"{what} -> {kind}"
    assert got.shape[0] == len(rot), f"{what}: batch {got.shape[0]} != {len(rot)}"
    if kind == "rot_mat":
        _check(_rows_max(got - rot.as_matrix()), tol, what)
    elif kind == "quaternion":
        q = rot.as_quat()
        _check(np.minimum(_rows_max(got - q), _rows_max(got + q)), tol, what)
    elif kind == "rot_vec":
        _check(_rot_vec_error(got, rot.as_rotvec()), tol, what)
    elif kind == "axis_angle":
        ref = rot.as_rotvec()
        _check(np.abs(got[:, 3] - np.linalg.norm(ref, axis=-1)), tol, what + " (angle)")
        _check(np.abs(np.linalg.norm(got[:, :3], axis=-1) - 1.0), tol, what + " (unit axis)")
        _check(_rot_vec_error(got[:, :3] * got[:, 3:], ref), tol, what + " (axis * angle)")
    elif kind == "polar_axis_angle":
        assert np.all((got[:, 0] >= 0) & (got[:, 0] <= PI)), f"{what}: inclination range"
        assert np.all((got[:, 1] >= -PI) & (got[:, 1] <= PI)), f"{what}: azimuth range"
        assert_represents("axis_angle", axis_angle_of_polar(got), rot, tol, what=what)
    elif kind == "euler":
        assert np.all(np.abs(got) <= PI + 1e-15), f"{what}: angles out of [-pi, pi]"
        m = Rotation.from_euler(convention, got).as_matrix()
        _check(_rows_max(m - rot.as_matrix()), tol, f"{what} {convention} (as matrix)")
    elif kind == "rot_6d":
        m = rot.as_matrix()
        _check(_rows_max(got - np.concatenate([m[:, :, 0], m[:, :, 1]], -1)), tol, what)
    else:
        raise ValueError(kind)
