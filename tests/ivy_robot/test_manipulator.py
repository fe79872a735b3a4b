"""DH manipulators and rigid mobile bodies against numpy float64 references written here, and
the Panda in standard DH, modified DH and MJCF (through MuJoCo) giving the same end effector."""

from __future__ import annotations

import math

import numpy as np
import pytest

import ivy
import ivy_robot
from tests.helpers import assert_close, check_gradients, native, numpy_of

# ----------------------------------------------------------------------------------------------
# numpy references: one joint at a time, matrices written out
# ----------------------------------------------------------------------------------------------


def _rot_z(t):
    c, s = np.cos(t), np.sin(t)
    return np.array([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]])


def _rot_x(t):
    c, s = np.cos(t), np.sin(t)
    return np.array([[1, 0, 0, 0], [0, c, -s, 0], [0, s, c, 0], [0, 0, 0, 1.0]])


def _trans(x, y, z):
    m = np.eye(4)
    m[:3, 3] = x, y, z
    return m


def reference_frames(a, d, alpha, theta, convention, base=None):
    """Frames 0..n for one configuration: A_i = Rz Tz Tx Rx (standard) or Rx Tx Rz Tz."""
    frames = [np.eye(4) if base is None else base]
    for ai, di, al, th in zip(a, d, alpha, theta):
        if convention == "standard":
            link = _rot_z(th) @ _trans(0, 0, di) @ _trans(ai, 0, 0) @ _rot_x(al)
        else:
            link = _rot_x(al) @ _trans(ai, 0, 0) @ _rot_z(th) @ _trans(0, 0, di)
        frames.append(frames[-1] @ link)
    return np.stack(frames)


def _random_pose(rng):
    from scipy.spatial.transform import Rotation

    pose = np.eye(4)
    pose[:3, :3] = Rotation.from_rotvec(rng.normal(size=3)).as_matrix()
    pose[:3, 3] = rng.normal(size=3)
    return pose


@pytest.mark.parametrize("convention", ["standard", "modified"])
def test_link_matrices_match_reference(convention, backend):
    rng = np.random.default_rng(1 if convention == "standard" else 2)
    n = 6
    a, d, alpha = rng.normal(size=n) * 0.3, rng.normal(size=n) * 0.3, rng.uniform(-3, 3, n)
    offsets, scales = rng.normal(size=n), rng.choice([-1.0, 1.0, 0.5], n)
    base, tool = _random_pose(rng), _random_pose(rng)
    arm = ivy_robot.Manipulator(
        a, d, alpha, convention=convention, joint_offsets=offsets, joint_scales=scales,
        base_pose=base, tool_pose=tool,
    )  # fmt: skip
    q = rng.uniform(-3, 3, size=(4, n))
    want = np.stack(
        [reference_frames(a, d, alpha, scales * qk + offsets, convention, base) for qk in q]
    )
    got = numpy_of(arm.link_matrices(native(q, backend)))
    assert_close(got, want)
    assert_close(numpy_of(arm.end_effector_pose(native(q, backend))), want[:, -1] @ tool)
    single = numpy_of(arm.end_effector_pose(native(q[0], backend)))
    assert_close(single, want[0, -1] @ tool)


def test_panda_standard_modified_and_mjcf_agree(backend):
    mujoco = pytest.importorskip("mujoco")
    modified = ivy_robot.PandaModel()
    half_pi = math.pi / 2
    standard = ivy_robot.Manipulator(  # Franka's table regrouped into standard DH by hand
        a=[0.0, 0.0, 0.0825, -0.0825, 0.0, 0.088, 0.0],
        d=[0.333, 0.0, 0.316, 0.0, 0.384, 0.0, 0.107],
        alpha=[-half_pi, half_pi, half_pi, -half_pi, half_pi, half_pi, 0.0],
        convention="standard",
    )
    model = mujoco.MjModel.from_xml_string(ivy_robot.panda_mjcf())
    data = mujoco.MjData(model)
    rng = np.random.default_rng(3)
    q = rng.uniform(modified.joint_lower, modified.joint_upper, size=(5, 7))
    flange = model.site("flange").id
    want = []
    for qk in q:
        data.qpos[:] = qk
        mujoco.mj_kinematics(model, data)
        pose = np.eye(4)
        pose[:3, :3], pose[:3, 3] = data.site_xmat[flange].reshape(3, 3), data.site_xpos[flange]
        want.append(pose)
    want = np.stack(want)
    assert_close(numpy_of(modified.end_effector_pose(native(q, backend))), want)
    assert_close(numpy_of(standard.end_effector_pose(native(q, backend))), want)
    tree = ivy_robot.KinematicTree.from_mjcf(ivy_robot.panda_mjcf())
    assert_close(numpy_of(tree.site_poses(native(q, backend)))[:, 0], want)


def test_mico_matches_kinova_table(backend):
    """Kinova's DH table with the actuator convention theta = scale * q - offset of the original
    ivy_robot (offsets [0, pi/2, -pi/2, 0, pi, -pi/2]), written out here."""
    d1, d2, d3, d4, d5, d6, e2 = 0.2755, 0.29, 0.1233, 0.0741, 0.0741, 0.16, 0.007
    aa = math.radians(30)
    k = math.sin(aa) / math.sin(2 * aa)
    a = [0, d2, 0, 0, 0, 0]
    d = [d1, 0, -e2, -(d3 + k * d4), -(k * d4 + k * d5), -(k * d5 + d6)]
    alpha = [math.pi / 2, math.pi, math.pi / 2, 2 * aa, 2 * aa, math.pi]
    scale = np.array([-1.0, 1, 1, 1, 1, 1])
    offset = np.array([0, math.pi / 2, -math.pi / 2, 0, math.pi, -math.pi / 2])
    q = np.random.default_rng(4).uniform(-3, 3, size=(3, 6))
    want = np.stack([reference_frames(a, d, alpha, scale * qk - offset, "standard") for qk in q])
    got = numpy_of(ivy_robot.MicoModel().link_matrices(native(q, backend)))
    assert_close(got, want)


def test_sample_links(backend):
    arm = ivy_robot.PandaModel(base_pose=_trans(0.1, 0.2, 0.3))
    q = np.random.default_rng(5).uniform(arm.joint_lower, arm.joint_upper, size=(2, 7))
    spm = 25.0
    points = numpy_of(arm.sample_links(native(q, backend), spm))
    assert points.shape == (2, arm.num_link_samples(spm), 3)
    frames = numpy_of(arm.link_matrices(native(q, backend)))
    tool = numpy_of(arm.end_effector_pose(native(q, backend)))
    origins = np.concatenate([frames[..., :3, 3], tool[:, None, :3, 3]], axis=1)
    for k in range(2):
        assert_close(points[k, 0], origins[k, 0])  # the base, ...
        assert_close(points[k, -1], origins[k, -1])  # ... to the tool
        # every point lies on a segment between consecutive origins, none further than
        # 1 / spm from the next point, and the chain is covered in order
        seg_a, seg_b = origins[k, :-1], origins[k, 1:]
        for p in points[k]:
            t = np.clip(np.sum((p - seg_a) * (seg_b - seg_a), -1) / np.maximum(
                np.sum((seg_b - seg_a) ** 2, -1), 1e-30), 0, 1)  # fmt: skip
            dist = np.linalg.norm(seg_a + t[:, None] * (seg_b - seg_a) - p, axis=-1)
            assert dist.min() < 1e-12
        gaps = np.linalg.norm(np.diff(points[k], axis=0), axis=-1)
        assert gaps.max() <= 1.0 / spm + 1e-12
        assert np.isclose(gaps.sum(), np.linalg.norm(np.diff(origins[k], axis=0), axis=-1).sum())


def test_gradients(diff_backend):
    arm = ivy_robot.MicoModel()
    q = np.random.default_rng(6).uniform(-2, 2, size=(2, 6))
    check_gradients(diff_backend, lambda x: arm.sample_links(x, 10.0), [q], n_directions=2)
    check_gradients(diff_backend, lambda x: arm.end_effector_pose(x), [q], n_directions=2)


def test_compiled_equals_eager(graph_backend):
    arm = ivy_robot.PandaModel()
    q = native(np.random.default_rng(7).uniform(-2, 2, size=(3, 7)), graph_backend)

    def both(x):
        return arm.end_effector_pose(x), arm.sample_links(x, 20.0)

    for got, want in zip(ivy.compile_fn(both)(q), both(q)):
        assert_close(numpy_of(got), numpy_of(want))


def test_float32(backend):
    arm = ivy_robot.PandaModel()
    q = np.random.default_rng(8).uniform(-2, 2, size=(2, 7))
    got = arm.end_effector_pose(native(q.astype(np.float32), backend))
    assert str(numpy_of(got).dtype) == "float32"
    assert_close(numpy_of(got), numpy_of(arm.end_effector_pose(q)), rtol=1e-5, atol=1e-5)


def test_bad_input(backend):
    with pytest.raises(ValueError, match="'standard' or 'modified'"):
        ivy_robot.Manipulator([0.0], [0.0], [0.0], convention="craig")
    with pytest.raises(ValueError, match="d has 2 entries; give one per joint"):
        ivy_robot.Manipulator([0.0], [0.0, 1.0], [0.0])
    with pytest.raises(ValueError, match="base_pose must be a 4x4"):
        ivy_robot.Manipulator([0.0], [0.0], [0.0], base_pose=np.eye(3))
    arm = ivy_robot.PandaModel()
    with pytest.raises(ValueError, match="must hold 7 joint angles"):
        arm.link_matrices(native(np.zeros((2, 6)), backend))
    with pytest.raises(TypeError, match="floating"):
        arm.end_effector_pose(native(np.zeros(7, dtype=np.int32), backend))
    with pytest.raises(ValueError, match="samples_per_metre must be positive"):
        arm.sample_links(native(np.zeros(7), backend), 0.0)


# ----------------------------------------------------------------------------------------------
# Rigid mobile bodies
# ----------------------------------------------------------------------------------------------


def test_rigid_mobile(backend):
    from scipy.spatial.transform import Rotation

    rng = np.random.default_rng(9)
    points = rng.normal(size=(5, 3))
    body = ivy_robot.RigidMobile(points)
    rot = Rotation.from_rotvec(rng.normal(size=(2, 3, 3)).reshape(-1, 3)).as_matrix()
    pos = rng.normal(size=(6, 3))
    poses = np.zeros((6, 4, 4))
    poses[:, :3, :3], poses[:, :3, 3], poses[:, 3, 3] = rot, pos, 1.0
    want = np.einsum("bij,pj->bpi", rot, points) + pos[:, None]
    got = numpy_of(body.sample_body(native(poses.reshape(2, 3, 4, 4), backend)))
    assert_close(got, want.reshape(2, 3, 5, 3))
    got34 = numpy_of(body.sample_body(native(poses[:, :3], backend)))
    assert_close(got34, want)
    with pytest.raises(ValueError, match=r"\[num_points, 3\]"):
        ivy_robot.RigidMobile(np.zeros((4, 2)))
    with pytest.raises(ValueError, match=r"\[\.\.\., 4, 4\]"):
        body.sample_body(native(np.zeros((2, 3, 3)), backend))


def test_rigid_mobile_gradients(diff_backend):
    import ivy_mechanics as mech

    body = ivy_robot.RigidMobile(np.random.default_rng(10).normal(size=(4, 3)))
    poses = np.random.default_rng(11).normal(size=(3, 6))
    check_gradients(
        diff_backend, lambda p: body.sample_body(mech.rot_vec_pose_to_mat_pose(p)), [poses]
    )
