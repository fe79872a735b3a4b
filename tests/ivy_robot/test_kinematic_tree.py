"""KinematicTree against MuJoCo: FK of every body and site (``mj_kinematics``) and Jacobians
(``mj_jacBody``, ``mj_jacSite``, ``mj_jac``) on the models Gymnasium ships and on test models with
every joint type and orientation attribute, to 1e-12 in float64 on every backend; Jacobians
equal to the autodiff Jacobian of the FK; compiled equals eager; bad input raises."""

from __future__ import annotations

import os

import numpy as np
import pytest

import ivy
import ivy_robot
from tests.conftest import device_for
from tests.helpers import assert_close, native, numpy_of
from tests.ivy_robot._models import ALL_FEATURES, HINGE_SLIDE, gymnasium_models, random_qpos
from tests.ivy_robot._utils import autodiff_jacobian, mujoco_jacobians, mujoco_kinematics

mujoco = pytest.importorskip("mujoco")

GYMNASIUM = {os.path.basename(p)[:-4]: p for p in gymnasium_models()}
MODELS = {
    **GYMNASIUM,
    "all_features": ALL_FEATURES,
    "hinge_slide": HINGE_SLIDE,
    "panda": ivy_robot.panda_mjcf(),
}
BATCH = 3


def _model(source):
    if source.lstrip().startswith("<"):
        return mujoco.MjModel.from_xml_string(source)
    return mujoco.MjModel.from_xml_path(source)


@pytest.fixture(scope="module")
def compiled():
    """Each model compiled once by MuJoCo and once as a KinematicTree."""
    return {
        name: (_model(src), ivy_robot.KinematicTree.from_mjcf(src)) for name, src in MODELS.items()
    }


def test_gymnasium_models_present():
    expected = {
        "reacher",
        "pusher",
        "ant",
        "humanoid",
        "half_cheetah",
        "hopper",
        "walker2d",
        "swimmer",
    }
    assert expected <= set(GYMNASIUM), f"missing Gymnasium models: {expected - set(GYMNASIUM)}"


@pytest.mark.parametrize("name", sorted(MODELS))
def test_forward_kinematics_matches_mujoco(name, backend, compiled):
    model, tree = compiled[name]
    q = random_qpos(model, np.random.default_rng(len(name)), BATCH)
    ref = mujoco_kinematics(model, q)
    poses = numpy_of(tree.forward_kinematics(native(q, backend)))
    assert_close(poses[..., :3, 3], ref["xpos"])
    assert_close(poses[..., :3, :3], ref["xmat"])
    assert_close(poses[..., 3, :], np.broadcast_to([0.0, 0.0, 0.0, 1.0], poses[..., 3, :].shape))
    sites = numpy_of(tree.site_poses(native(q, backend)))
    assert sites.shape == (BATCH, model.nsite, 4, 4)
    assert_close(sites[..., :3, 3], ref["site_xpos"])
    assert_close(sites[..., :3, :3], ref["site_xmat"])


@pytest.mark.parametrize("name", sorted(MODELS))
def test_jacobians_match_mujoco(name, backend, compiled):
    model, tree = compiled[name]
    q = random_qpos(model, np.random.default_rng(7 + len(name)), BATCH)
    qb = native(q, backend)
    # the leaves: each body's chain is a prefix of a leaf's, so the leaves take every joint
    # through the code of every depth (on jax each body's Jacobian is a program of its own)
    leaves = sorted(set(range(1, model.nbody)) - set(model.body_parentid.tolist()))
    for body in leaves:
        jac = numpy_of(tree.jacobian(qb, body))
        assert_close(jac, mujoco_jacobians(model, q, "body", body))
    for site in range(model.nsite):
        jac = numpy_of(tree.jacobian(qb, site=tree.site_names[site]))
        assert_close(jac, mujoco_jacobians(model, q, "site", site))


def test_jacobian_of_a_point(backend, compiled):
    model, tree = compiled["all_features"]
    q = random_qpos(model, np.random.default_rng(3), BATCH)
    point = np.array([0.1, -0.2, 0.05])
    for body in ("hand", "spinner", "drone", "ball_child", "base"):
        index = tree.body_id(body)
        jac = tree.jacobian(native(q, backend), body, point=native(point, backend))
        assert_close(numpy_of(jac), mujoco_jacobians(model, q, "body", index, point))


def test_names_and_attributes(compiled):
    model, tree = compiled["all_features"]
    assert tree.body_names == tuple(model.body(i).name for i in range(model.nbody))
    assert tree.body_names[0] == "world"
    assert tree.site_names == ("elbow_site", "tip", "drone_cam")
    assert (tree.nq, tree.nv, tree.nbody, tree.nsite) == (
        model.nq,
        model.nv,
        model.nbody,
        model.nsite,
    )
    assert tree.joint_types[tree.joint_names.index("drone_free")] == "free"
    np.testing.assert_array_equal(tree.parent_ids, model.body_parentid)
    np.testing.assert_array_equal(tree.qpos0, model.qpos0)
    knee = model.jnt_qposadr[model.joint("knee").id]
    np.testing.assert_allclose(
        [tree.qpos_lower[knee], tree.qpos_upper[knee]], np.radians([-90, 90])
    )
    assert np.isinf(tree.qpos_lower[model.jnt_qposadr[model.joint("shoulder").id]])
    assert "nq=26" in repr(tree)


def test_batch_shapes_and_float32(backend, compiled):
    model, tree = compiled["hinge_slide"]
    q = random_qpos(model, np.random.default_rng(5), 6)
    ref = mujoco_kinematics(model, q)
    poses = numpy_of(tree.forward_kinematics(native(q.reshape(2, 3, -1), backend)))
    assert_close(poses.reshape(6, -1, 4, 4)[..., :3, 3], ref["xpos"])
    jac = numpy_of(tree.jacobian(native(q.reshape(2, 3, -1), backend), "b3"))
    assert_close(jac.reshape(6, 6, -1), mujoco_jacobians(model, q, "body", 3))
    single32 = tree.forward_kinematics(native(q[0].astype(np.float32), backend))
    assert str(numpy_of(single32).dtype) == "float32"
    assert_close(numpy_of(single32)[:, :3, 3], ref["xpos"][0], rtol=1e-5, atol=2e-5)


@pytest.mark.parametrize("name", ["hinge_slide"])
def test_jacobian_equals_autodiff_of_fk(name, diff_backend, compiled):
    model, tree = compiled[name]
    q = random_qpos(model, np.random.default_rng(11), 1)[0]
    bodies = range(1, model.nbody)

    def positions(x):
        return tree.forward_kinematics(x)[..., :3, 3]

    def rotations(x):
        return tree.forward_kinematics(x)[..., :3, :3]

    dpos = autodiff_jacobian(diff_backend, positions, q)  # [nbody, 3, nq]
    drot = autodiff_jacobian(diff_backend, rotations, q)  # [nbody, 3, 3, nq]
    rot = numpy_of(rotations(native(q, diff_backend)))
    for b in bodies:
        jac = numpy_of(tree.jacobian(native(q, diff_backend), b))
        assert_close(jac[:3], dpos[b], rtol=1e-10, atol=1e-10)
        # angular columns: dR/dq_i R^T is the cross-product matrix of the angular velocity
        for i in range(model.nv):
            omega = drot[b, :, :, i] @ rot[b].T
            assert_close(np.array([omega[2, 1], omega[0, 2], omega[1, 0]]), jac[3:, i], atol=1e-10)
    site = numpy_of(tree.jacobian(native(q, diff_backend), site=0))
    dsite = autodiff_jacobian(diff_backend, lambda x: tree.site_poses(x)[0, :3, 3], q)
    assert_close(site[:3], dsite, rtol=1e-10, atol=1e-10)


def test_fk_gradient_with_ball_and_free_joints(diff_backend, compiled):
    """Gradients through quaternion joints (normalisation included) equal finite differences."""
    from tests.helpers import check_gradients

    model, tree = compiled["all_features"]
    q = random_qpos(model, np.random.default_rng(13), 2)
    check_gradients(diff_backend, lambda x: tree.site_poses(x), [q], n_directions=2)


def test_compiled_equals_eager(graph_backend, compiled):
    model, tree = compiled["all_features"]
    q = native(random_qpos(model, np.random.default_rng(17), BATCH), graph_backend)

    def everything(x):
        return tree.forward_kinematics(x), tree.site_poses(x), tree.jacobian(x, "hand")

    fast = ivy.compile_fn(everything)
    for got, want in zip(fast(q), everything(q)):
        assert_close(numpy_of(got), numpy_of(want))


def test_transform_points_and_collision_spheres(backend, compiled):
    model, tree = compiled["panda"]
    q = random_qpos(model, np.random.default_rng(19), 2)
    ref = mujoco.MjData(model)
    spheres = tree.collision_spheres(0.04)
    assert set(np.unique(spheres.body_ids)) == {tree.body_id(f"link{i}") for i in range(1, 8)} | {
        tree.body_id("hand")
    }
    centres = numpy_of(tree.transform_points(native(q, backend), spheres.body_ids, spheres.centres))
    for k, qk in enumerate(q):
        ref.qpos[:] = qk
        mujoco.mj_kinematics(model, ref)
        for g in range(model.ngeom):
            if model.geom_type[g] != mujoco.mjtGeom.mjGEOM_CAPSULE or model.geom_bodyid[g] == 1:
                continue
            axis = ref.geom_xmat[g].reshape(3, 3)[:, 2] * model.geom_size[g, 1]
            ends = np.stack([ref.geom_xpos[g] - axis, ref.geom_xpos[g] + axis])
            mine = centres[k][np.flatnonzero(np.isclose(spheres.radii, model.geom_size[g, 0]))]
            for end in ends:  # both ends of every capsule are sphere centres
                assert np.min(np.linalg.norm(mine - end, axis=-1)) < 1e-12
    names = tree.transform_points(native(q, backend), ["hand"], np.zeros((1, 3)))
    fk = numpy_of(tree.forward_kinematics(native(q, backend)))
    assert_close(numpy_of(names)[:, 0], fk[:, tree.body_id("hand"), :3, 3])


# ----------------------------------------------------------------------------------------------
# Bad input
# ----------------------------------------------------------------------------------------------

UNIVERSAL = """<mujoco><worldbody><body name="b">
  <joint name="u" type="universal"/><geom size=".1"/>
</body></worldbody></mujoco>"""


def test_unsupported_joint_type():
    with pytest.raises(ValueError, match=r"joint 'u' has type 'universal'.*hinge"):
        ivy_robot.KinematicTree.from_mjcf(UNIVERSAL)


def test_bad_sources(tmp_path):
    with pytest.raises(ValueError, match="neither an existing file nor an MJCF XML string"):
        ivy_robot.KinematicTree.from_mjcf("no/such/file.xml")
    with pytest.raises(ValueError, match="MuJoCo could not compile"):
        ivy_robot.KinematicTree.from_mjcf("<mujoco><worldbody><body><geom/></body>")
    with pytest.raises(TypeError, match="expected a path"):
        ivy_robot.KinematicTree.from_mjcf(3)
    path = tmp_path / "universal.xml"
    path.write_text(UNIVERSAL)
    with pytest.raises(ValueError, match="universal"):
        ivy_robot.KinematicTree.from_mjcf(path)


def test_the_device_is_the_inputs(backend, compiled):
    """The tree holds no arrays: from_mjcf takes no device (a clear error says where it goes),
    and the results are on the inputs' device."""
    with pytest.raises(TypeError, match=r"takes only the model, got \['device'\].*device="):
        ivy_robot.KinematicTree.from_mjcf(MODELS["all_features"], device="gpu:0")
    _, tree = compiled["all_features"]
    q = ivy.asarray(np.zeros((2, tree.nq)), device=device_for(backend), f=backend)
    assert ivy.dev(tree.forward_kinematics(q)) == ivy.dev(q)


def test_bad_qpos_and_names(backend, compiled):
    model, tree = compiled["all_features"]
    with pytest.raises(ValueError, match=r"qpos has shape \(3, 25\).*nq=26"):
        tree.forward_kinematics(native(np.zeros((3, 25)), backend))
    with pytest.raises(ValueError, match="nq=26"):
        tree.jacobian(native(np.zeros(27), backend), "hand")
    with pytest.raises(TypeError, match="floating"):
        tree.site_poses(native(np.zeros(26, dtype=np.int64), backend))
    q = native(model.qpos0, backend)
    with pytest.raises(
        ValueError, match=r"unknown body 'fingertip'; the model's bodies are: 'world'"
    ):
        tree.jacobian(q, "fingertip")
    with pytest.raises(ValueError, match="unknown site 'nose'; the model's sites are"):
        tree.jacobian(q, site="nose")
    with pytest.raises(ValueError, match="exactly one of body= or site="):
        tree.jacobian(q, "hand", site="tip")
    with pytest.raises(ValueError, match=r"out of range: the model has \d+ bodies \(indices 0 to"):
        tree.body_id(99)
