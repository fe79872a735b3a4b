"""Euler conventions: scipy's spelling, the angles themselves, ranges and errors."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import ivy_mechanics as mech
from ivy_mechanics import EULER_CONVENTIONS
from tests.ivy_mechanics._cases import gimbal_lock_euler
from tests.ivy_mechanics._reference import EDGE_SIZE
from tests.ivy_mechanics._utils import call

pytestmark = pytest.mark.filterwarnings("ignore:Gimbal lock")


def test_the_24_conventions():
    assert len(EULER_CONVENTIONS) == len(set(EULER_CONVENTIONS)) == 24
    assert sum(c.islower() for c in EULER_CONVENTIONS) == 12


def _angle_diff(a, b):
    return np.abs(np.remainder(a - b + np.pi, 2 * np.pi) - np.pi)


def test_angles_equal_scipy_away_from_gimbal_lock(backend):
    """Not only the same rotation: the same angles as scipy (up to 2 pi)."""
    rot = Rotation.random(EDGE_SIZE, random_state=4)
    quat, mat = rot.as_quat(), rot.as_matrix()
    for convention in EULER_CONVENTIONS:
        expected = rot.as_euler(convention)
        for name, x in (("quaternion_to_euler", quat), ("rot_mat_to_euler", mat)):
            got = call(backend, name, [x], {"convention": convention})
            np.testing.assert_allclose(
                _angle_diff(got, expected), 0, atol=1e-12, err_msg=f"{name} {convention}"
            )


def test_ranges_and_gimbal_lock(backend):
    """Middle angle in [-pi/2, pi/2] (Tait-Bryan) or [0, pi] (proper); at exact gimbal lock the
    angles are finite and reproduce the matrix."""
    for convention in EULER_CONVENTIONS:
        lock = np.resize(gimbal_lock_euler(convention, (0.0, 1e-9)), (EDGE_SIZE, 3))
        m = Rotation.from_euler(convention, lock).as_matrix()
        got = call(backend, "rot_mat_to_euler", [m], {"convention": convention})
        assert np.all(np.isfinite(got))
        assert np.all(np.abs(got) <= np.pi + 1e-15)
        middle = got[:, 1]
        if convention[0].lower() == convention[2].lower():
            assert np.all((middle >= 0) & (middle <= np.pi))
        else:
            assert np.all(np.abs(middle) <= np.pi / 2 + 1e-15)
        np.testing.assert_allclose(
            Rotation.from_euler(convention, got).as_matrix(), m, rtol=0, atol=1e-12
        )


def test_intrinsic_is_extrinsic_reversed(backend):
    angles = np.random.default_rng(5).uniform(-3, 3, (8, 3))
    for seq in EULER_CONVENTIONS[:12]:
        extrinsic = call(backend, "euler_to_rot_mat", [angles], {"convention": seq})
        intrinsic = call(
            backend, "euler_to_rot_mat", [angles[:, ::-1].copy()], {"convention": seq[::-1].upper()}
        )
        np.testing.assert_allclose(extrinsic, intrinsic, rtol=0, atol=1e-14)


def test_default_convention_is_extrinsic_zyx():
    angles = np.array([0.1, -0.2, 0.3])
    np.testing.assert_array_equal(
        mech.euler_to_rot_mat(angles), mech.euler_to_rot_mat(angles, "zyx")
    )
    expected = Rotation.from_euler("zyx", angles).as_matrix()
    np.testing.assert_allclose(mech.euler_to_rot_mat(angles), expected, atol=1e-15)


@pytest.mark.parametrize("bad", ["xxy", "xYz", "xy", "xyzx", "abc", "XYY", 3])
def test_invalid_conventions_raise(bad):
    with pytest.raises(ValueError, match="convention"):
        mech.euler_to_rot_mat(np.zeros(3), bad)
    with pytest.raises(ValueError, match="convention"):
        mech.quaternion_to_euler(np.array([0.0, 0, 0, 1]), bad)
