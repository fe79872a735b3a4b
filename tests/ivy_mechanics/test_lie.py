"""SO(3) and SE(3): hat/vee, exp/log against scipy (Rotation, and scipy.linalg.expm/logm)."""

from __future__ import annotations

import numpy as np
from scipy.linalg import expm, logm
from scipy.spatial.transform import Rotation

from tests.ivy_mechanics._cases import _hat4
from tests.ivy_mechanics._reference import assert_represents, edge_axis_angles
from tests.ivy_mechanics._utils import call


def test_so3_hat_and_vee(backend):
    rng = np.random.default_rng(20)
    v, p = rng.standard_normal((16, 3)), rng.standard_normal((16, 3))
    hat = call(backend, "so3_hat", [v])
    np.testing.assert_allclose(hat, -np.swapaxes(hat, -1, -2), rtol=0, atol=0)
    np.testing.assert_allclose((hat @ p[..., None])[..., 0], np.cross(v, p), rtol=0, atol=1e-14)
    np.testing.assert_array_equal(call(backend, "so3_vee", [hat]), v)


def test_so3_exp_and_log(backend):
    axes, angles = edge_axis_angles(np.random.default_rng(21))
    rot = Rotation.from_rotvec(axes * angles[:, None])
    assert_represents("rot_mat", call(backend, "so3_exp", [rot.as_rotvec()]), rot, 1e-12)
    assert_represents("rot_vec", call(backend, "so3_log", [rot.as_matrix()]), rot, 1e-12)


def _twists(rng):
    """Generic twists, and rotation angles 0, tiny, around the series threshold, near pi."""
    angles = np.array([0.0, 1e-12, 1e-9, 1e-4, 0.00999, 0.01001, 0.5, 2.0, np.pi - 1e-6])
    axes = rng.standard_normal((len(angles), 3))
    w = axes / np.linalg.norm(axes, axis=-1, keepdims=True) * angles[:, None]
    w = np.concatenate([w, Rotation.random(16, random_state=rng).as_rotvec() * 0.95])
    return np.concatenate([rng.standard_normal((len(w), 3)) * 2.0, w], -1)


def test_se3_hat_and_vee(backend):
    twist = _twists(np.random.default_rng(22))
    hat = call(backend, "se3_hat", [twist])
    np.testing.assert_array_equal(hat, _hat4(twist))
    np.testing.assert_array_equal(call(backend, "se3_vee", [hat]), twist)


def test_se3_exp_matches_expm(backend):
    twist = _twists(np.random.default_rng(23))
    got = call(backend, "se3_exp", [twist])
    expected = np.stack([expm(h) for h in _hat4(twist)])
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-12)


def test_se3_log_inverts_exp_and_matches_logm(backend):
    twist = _twists(np.random.default_rng(24))
    pose = np.stack([expm(h) for h in _hat4(twist)])
    got = call(backend, "se3_log", [pose])
    np.testing.assert_allclose(got, twist, rtol=0, atol=1e-12 * 10)
    generic = slice(-16, None)
    expected = np.stack([logm(p).real for p in pose[generic]])
    np.testing.assert_allclose(call(backend, "se3_hat", [got[generic]]), expected, atol=1e-10)
    # 3x4 poses are accepted
    np.testing.assert_allclose(call(backend, "se3_log", [pose[:, :3]]), got, rtol=0, atol=0)
