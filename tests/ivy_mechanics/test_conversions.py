"""Every representation pair against scipy.spatial.transform.Rotation, on every backend.

Float64 to 1e-12 on an edge set: angle exactly 0, 1e-12 ... 1e-3, around the series threshold,
pi - (1e-3 ... 1e-9) and exactly pi, about coordinate and oblique axes, plus random rotations.
Euler angles: all 24 conventions, and for Euler inputs also gimbal lock (middle angle +-pi/2
or 0/pi, +- 1e-12 ... 1e-3). Results are compared as the rotation they represent: quaternions
up to sign, Euler angles by their matrix, axis-angle by angle and axis * angle.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from ivy_mechanics import EULER_CONVENTIONS
from tests.helpers import HYPOTHESIS
from tests.ivy_mechanics._cases import gimbal_lock_euler
from tests.ivy_mechanics._reference import (
    EDGE_SIZE,
    GIMBAL_OFFSETS,
    assert_represents,
    edge_axis_angles,
    represent,
)
from tests.ivy_mechanics._utils import call

pytestmark = pytest.mark.filterwarnings("ignore:Gimbal lock")

REPRESENTATIONS = (
    "rot_mat",
    "quaternion",
    "rot_vec",
    "axis_angle",
    "polar_axis_angle",
    "rot_6d",
)
TOL64 = 1e-12


@pytest.mark.parametrize("source", REPRESENTATIONS)
def test_pairs_against_scipy_float64(backend, source):
    rng = np.random.default_rng(0)
    axes, angles = edge_axis_angles(rng)
    x, rot = represent(source, axes, angles, rng)
    for target in REPRESENTATIONS:
        if target != source:
            got = call(backend, f"{source}_to_{target}", [x])
            assert_represents(target, got, rot, TOL64, what=source)
    for convention in EULER_CONVENTIONS:
        got = call(backend, f"{source}_to_euler", [x], {"convention": convention})
        assert_represents("euler", got, rot, TOL64, convention, what=source)


def _euler_inputs(rng, convention):
    """Euler angles of the edge rotations, generic angles, and gimbal lock +- offsets."""
    from scipy.spatial.transform import Rotation

    axes, angles = edge_axis_angles(rng)
    euler, _ = represent("euler", axes, angles, rng, convention)
    generic = rng.uniform(-np.pi, np.pi, (EDGE_SIZE, 3))
    euler = np.concatenate([gimbal_lock_euler(convention, GIMBAL_OFFSETS), euler, generic])
    euler = euler[:EDGE_SIZE]  # gimbal lock, the edge rotations, then generic angles
    return euler, Rotation.from_euler(convention, euler)


@pytest.mark.parametrize("target", REPRESENTATIONS + ("euler",))
def test_euler_to_every_representation_float64(backend, target):
    rng = np.random.default_rng(1)
    for convention in EULER_CONVENTIONS:
        euler, rot = _euler_inputs(rng, convention)
        if target == "euler":  # round trip through another convention's matrix
            other = convention[::-1]
            got = call(backend, "euler_to_rot_mat", [euler], {"convention": convention})
            got = call(backend, "rot_mat_to_euler", [got], {"convention": other})
            assert_represents("euler", got, rot, TOL64, other, what=f"euler {convention}")
            continue
        got = call(backend, f"euler_to_{target}", [euler], {"convention": convention})
        assert_represents(target, got, rot, TOL64, convention, what=f"euler {convention}")


@pytest.mark.parametrize("source", REPRESENTATIONS + ("euler",))
def test_pairs_against_scipy_float32(backend, source):
    """Generic rotations in float32: float32 results, within float32 accuracy."""
    from scipy.spatial.transform import Rotation

    rng = np.random.default_rng(2)
    rotvec = Rotation.random(EDGE_SIZE, random_state=rng).as_rotvec()
    angles = np.linalg.norm(rotvec, axis=-1)
    axes = rotvec / angles[:, None]
    x, rot = represent(source, axes, angles, rng, "ZXY")
    for target in REPRESENTATIONS + ("euler",):
        if target == source:
            continue
        kwargs = {"convention": "ZXY"} if "euler" in (source, target) else {}
        got = call(backend, f"{source}_to_{target}", [x.astype(np.float32)], kwargs)
        assert got.dtype == np.float32, f"{source}_to_{target} returned {got.dtype}"
        assert_represents(target, got.astype(np.float64), rot, 2e-5, "ZXY", what=source)


def test_rot_6d_round_trip(backend):
    from scipy.spatial.transform import Rotation

    m = Rotation.random(32, random_state=3).as_matrix()
    six_d = call(backend, "rot_mat_to_rot_6d", [m])
    np.testing.assert_array_equal(six_d, np.concatenate([m[:, :, 0], m[:, :, 1]], -1))
    np.testing.assert_allclose(call(backend, "rot_6d_to_rot_mat", [six_d]), m, rtol=0, atol=TOL64)


@HYPOTHESIS
@given(
    axis=st.tuples(*[st.floats(-1, 1)] * 3).filter(lambda a: np.linalg.norm(a) > 1e-3),
    log_angle=st.floats(-14, 0),
    near_pi=st.booleans(),
)
def test_round_trips_at_any_scale(backend, axis, log_angle, near_pi):
    """Rotation vectors from 1e-14 rad up to pi - 1e-14 rad survive matrix and quaternion
    round trips, and match scipy."""
    from scipy.spatial.transform import Rotation

    axis = np.array(axis) / np.linalg.norm(axis)
    angle = np.pi - 10.0**log_angle if near_pi else 10.0**log_angle
    rotvec = (axis * angle)[None]
    rot = Rotation.from_rotvec(rotvec)
    m = call(backend, "rot_vec_to_rot_mat", [rotvec])
    assert_represents("rot_mat", m, rot, TOL64)
    assert_represents("rot_vec", call(backend, "rot_mat_to_rot_vec", [m]), rot, TOL64)
    q = call(backend, "rot_vec_to_quaternion", [rotvec])
    assert_represents("quaternion", q, rot, TOL64)
    np.testing.assert_allclose(call(backend, "quaternion_to_rot_vec", [q]), rotvec, atol=TOL64)
