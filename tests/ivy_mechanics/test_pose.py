"""Poses: conversions between matrix, quaternion, rotation-vector, Euler and axis-angle poses,
composition, inversion, transforming points and integrating a velocity."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from tests.ivy_mechanics._reference import assert_represents, edge_axis_angles, represent
from tests.ivy_mechanics._utils import call

pytestmark = pytest.mark.filterwarnings("ignore:Gimbal lock")

TOL = dict(rtol=0, atol=1e-12)
# pose name -> orientation representation
POSES = {
    "quaternion_pose": "quaternion",
    "rot_vec_pose": "rot_vec",
    "euler_pose": "euler",
    "axis_angle_pose": "axis_angle",
}


def _poses(seed):
    rng = np.random.default_rng(seed)
    axes, angles = edge_axis_angles(rng)
    position = rng.standard_normal((len(angles), 3))
    return rng, axes, angles, position


def _mat_pose(rot, position):
    pose = np.zeros((len(position), 4, 4))
    pose[:, :3, :3], pose[:, :3, 3], pose[:, 3, 3] = rot.as_matrix(), position, 1.0
    return pose


@pytest.mark.parametrize("pose", POSES)
def test_vector_pose_to_and_from_mat_pose(backend, pose):
    rng, axes, angles, position = _poses(30)
    kind = POSES[pose]
    convention = "zxy"
    orientation, rot = represent(kind, axes, angles, rng, convention)
    kwargs = {"convention": convention} if kind == "euler" else {}
    vector_pose = np.concatenate([position, orientation], -1)
    mat = call(backend, f"{pose}_to_mat_pose", [vector_pose], kwargs)
    np.testing.assert_allclose(mat, _mat_pose(rot, position), **TOL)
    for rows in (4, 3):  # homogeneous 4x4 and 3x4 inputs
        back = call(backend, f"mat_pose_to_{pose}", [mat[:, :rows]], kwargs)
        np.testing.assert_array_equal(back[:, :3], position)
        assert_represents(kind, back[:, 3:], rot, 1e-12, convention, what=pose)
    if pose != "quaternion_pose":  # through the quaternion pose
        quat_pose = call(backend, f"{pose}_to_quaternion_pose", [vector_pose], kwargs)
        np.testing.assert_array_equal(quat_pose[:, :3], position)
        assert_represents("quaternion", quat_pose[:, 3:], rot, 1e-12, what=pose)
        back = call(backend, f"quaternion_pose_to_{pose}", [quat_pose], kwargs)
        assert_represents(kind, back[:, 3:], rot, 1e-12, convention, what=pose)


def test_compose_invert_transform(backend):
    _, axes, angles, position = _poses(31)
    rot = Rotation.from_rotvec(axes * angles[:, None])
    a = _mat_pose(rot, position)
    b = _mat_pose(Rotation.random(len(a), random_state=32), position[::-1].copy())
    np.testing.assert_allclose(call(backend, "compose_mat_poses", [a, b[:, :3]]), a @ b, **TOL)
    np.testing.assert_allclose(call(backend, "invert_mat_pose", [a]), np.linalg.inv(a), **TOL)
    points = np.random.default_rng(33).standard_normal((len(a), 3))
    expected = (a @ np.concatenate([points, np.ones((len(a), 1))], -1)[..., None])[:, :3, 0]
    np.testing.assert_allclose(call(backend, "transform_points", [a, points]), expected, **TOL)
    # quaternion poses agree with the matrices
    qa = np.concatenate([position, rot.as_quat()], -1)
    qb = call(backend, "mat_pose_to_quaternion_pose", [b])
    composed = call(backend, "compose_quaternion_poses", [qa, qb])
    np.testing.assert_allclose(
        call("numpy", "quaternion_pose_to_mat_pose", [composed]), a @ b, **TOL
    )
    inverse = call(backend, "invert_quaternion_pose", [qa])
    np.testing.assert_allclose(
        call("numpy", "quaternion_pose_to_mat_pose", [inverse]), np.linalg.inv(a), **TOL
    )


def test_make_transformation_homogeneous(backend):
    m = np.random.default_rng(34).standard_normal((2, 5, 3, 4))
    got = call(backend, "make_transformation_homogeneous", [m])
    assert got.shape == (2, 5, 4, 4)
    np.testing.assert_array_equal(got[..., :3, :], m)
    np.testing.assert_array_equal(got[..., 3, :], np.broadcast_to([0.0, 0, 0, 1], (2, 5, 4)))


def test_increment_quaternion_pose_with_velocity(backend):
    rng = np.random.default_rng(35)
    rot, rot_vel = Rotation.random(16, random_state=36), Rotation.random(16, random_state=37)
    position, velocity = rng.standard_normal((16, 3)), rng.standard_normal((16, 3))
    pose = np.concatenate([position, rot.as_quat()], -1)
    vel = np.concatenate([velocity, rot_vel.as_quat()], -1)
    for dt in (0.0, 0.01, 0.5, 1.0):
        got = call(backend, "increment_quaternion_pose_with_velocity", [pose, vel, np.array(dt)])
        np.testing.assert_allclose(got[:, :3], position + velocity * dt, **TOL)
        assert_represents("quaternion", got[:, 3:], rot * rot_vel**dt, 1e-12)
    dts = rng.uniform(0, 1, (16, 1))
    got = call(backend, "increment_quaternion_pose_with_velocity", [pose, vel, dts])
    expected = Rotation.concatenate([rot[i] * rot_vel[i] ** dts[i, 0] for i in range(16)])
    assert_represents("quaternion", got[:, 3:], expected, 1e-12)
