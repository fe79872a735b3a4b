"""Signed distances against MuJoCo: ``mj_geomDistance`` between a small probe sphere and each
primitive (plus the probe's radius) equals the SDF, inside and outside, on every backend;
gradients against finite differences; scene SDFs from MJCF; bad input raises."""

from __future__ import annotations

import numpy as np
import pytest

import ivy
import ivy_robot
from tests.helpers import assert_close, check_gradients, native, numpy_of

mujoco = pytest.importorskip("mujoco")

PROBE = 0.005
SCENE = f"""<mujoco><worldbody>
  <geom name="ball" type="sphere" size="0.3" pos="0.1 0.2 0.3"/>
  <geom name="crate" type="box" size="0.2 0.3 0.4" pos="-0.5 0.1 0.2" euler="0.3 0.5 0.7"/>
  <geom name="pill" type="capsule" size="0.15 0.3" pos="0.4 -0.5 0.1" euler="1.0 0.2 0.1"/>
  <geom name="drum" type="cylinder" size="0.2 0.25" pos="-0.3 -0.6 0.4" euler="0.2 1.1 0.4"/>
  <geom name="ground" type="plane" size="1 1 1" pos="0 0 -0.5" euler="0.1 0.2 0"/>
  <body name="shelf" pos="0 0 1" euler="0 0 0.5">
    <geom name="board" type="box" size="0.3 0.1 0.02" pos="0.1 0 0"/>
  </body>
  <body name="arm" pos="1 1 0">
    <joint type="hinge"/>
    <geom name="moving" type="capsule" size="0.05 0.2"/>
  </body>
  <body name="probe" mocap="true"><geom name="probe" type="sphere" size="{PROBE}"/></body>
</worldbody></mujoco>"""


@pytest.fixture(scope="module")
def reference():
    """MuJoCo's model, each static geom's pose and size, and query points around each geom
    (about half of them inside) with ``mj_geomDistance + probe radius`` per geom."""
    model = mujoco.MjModel.from_xml_string(SCENE)
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    probe = model.geom("probe").id
    rng = np.random.default_rng(0)
    geoms = {}
    for name in ("ball", "crate", "pill", "drum", "ground", "board"):
        g = model.geom(name).id
        pose = np.eye(4)
        pose[:3, :3], pose[:3, 3] = data.geom_xmat[g].reshape(3, 3), data.geom_xpos[g]
        r, h = model.geom_size[g, 0], model.geom_size[g, 1]
        extent = {
            "ball": [r, r, r],
            "crate": model.geom_size[g],
            "board": model.geom_size[g],
            "pill": [r, r, h + r],
            "drum": [r, r, h],
            "ground": [0.5, 0.5, 0.3],
        }[name]
        local = rng.uniform(-1.3, 1.3, size=(40, 3)) * np.asarray(extent)
        points = local @ pose[:3, :3].T + pose[:3, 3]
        want = []
        for p in points:
            data.mocap_pos[0] = p
            mujoco.mj_kinematics(model, data)
            want.append(mujoco.mj_geomDistance(model, data, probe, g, 10.0, None) + PROBE)
        geoms[name] = dict(
            pose=pose, size=model.geom_size[g].copy(), points=points, want=np.array(want)
        )
    return model, geoms


def _primitive(name, pts, geom, backend):
    size, pose = geom["size"], native(geom["pose"], backend)
    if name == "ball":
        return ivy_robot.sphere_sdf(pts, native(geom["pose"][:3, 3], backend), size[0])
    if name in ("crate", "board"):
        return ivy_robot.box_sdf(pts, native(size, backend), pose)
    if name == "pill":
        return ivy_robot.capsule_sdf(pts, size[0], size[1], pose)
    if name == "drum":
        return ivy_robot.cylinder_sdf(pts, size[0], size[1], pose)
    return ivy_robot.plane_sdf(pts, pose)


def test_primitives_match_mujoco(backend, reference):
    _, geoms = reference
    for name, geom in geoms.items():
        assert (geom["want"] < 0).sum() >= 5 and (geom["want"] > 0).sum() >= 5, name
        got = numpy_of(_primitive(name, native(geom["points"], backend), geom, backend))
        assert_close(got, geom["want"], err_msg=name)


def test_scene_matches_mujoco(backend, reference):
    model, geoms = reference
    scene = ivy_robot.SceneSDF.from_mjcf(model, exclude=["probe"])
    assert set(scene.names) == set(geoms)  # static geoms only: not the hinge's, not the mocap's
    points = np.concatenate([g["points"] for g in geoms.values()])
    dists = numpy_of(scene.distances(native(points.reshape(6, 40, 3), backend)))
    assert dists.shape == (6, 40, scene.num_shapes)
    for k, name in enumerate(geoms):
        column = scene.names.index(name)
        assert_close(dists[k, :, column], geoms[name]["want"], err_msg=name)
    brute = np.stack([_ref_min(p, geoms, model) for p in points[:12]])
    assert_close(numpy_of(scene(native(points[:12], backend))), brute)


def _ref_min(point, geoms, model):
    data = mujoco.MjData(model)
    data.mocap_pos[0] = point
    mujoco.mj_kinematics(model, data)
    probe = model.geom("probe").id
    return min(
        mujoco.mj_geomDistance(model, data, probe, model.geom(n).id, 10.0, None) + PROBE
        for n in geoms
    )


def test_gradients(diff_backend, reference):
    _, geoms = reference
    for name, geom in geoms.items():
        pts = geom["points"][:10]
        check_gradients(
            diff_backend, lambda p, n=name, g=geom: _primitive(n, p, g, diff_backend), [pts]
        )
    scene = ivy_robot.SceneSDF.from_mjcf(SCENE, exclude=["probe"])
    check_gradients(diff_backend, lambda p: scene(p), [geoms["crate"]["points"][:10]])


def test_gradients_finite_at_singular_points(diff_backend):
    from tests.ivy_robot._utils import autodiff_jacobian

    zero = np.zeros(3)
    cases = {
        "sphere centre": lambda p: ivy_robot.sphere_sdf(p, np.zeros(3), 1.0),
        "box centre": lambda p: ivy_robot.box_sdf(p, np.ones(3)),
        "capsule axis": lambda p: ivy_robot.capsule_sdf(p, 0.5, 1.0),
        "cylinder axis": lambda p: ivy_robot.cylinder_sdf(p, 0.5, 1.0),
    }
    for what, fn in cases.items():
        jac = autodiff_jacobian(diff_backend, fn, zero)
        assert np.all(np.isfinite(jac)), what


def test_batched_poses_and_float32(backend):
    rng = np.random.default_rng(1)
    poses = np.tile(np.eye(4), (4, 1, 1))
    poses[:, :3, 3] = rng.normal(size=(4, 3))
    points = rng.normal(size=(4, 3))
    got = numpy_of(ivy_robot.box_sdf(native(points, backend), native(np.ones(3), backend),
                                     native(poses, backend)))  # fmt: skip
    want = [numpy_of(ivy_robot.box_sdf(points[k] - poses[k, :3, 3], np.ones(3))) for k in range(4)]
    assert_close(got, np.array(want))
    got32 = ivy_robot.sphere_sdf(native(points.astype(np.float32), backend), np.zeros(3), 0.5)
    assert str(numpy_of(got32).dtype) == "float32"
    assert_close(numpy_of(got32), np.linalg.norm(points, axis=-1) - 0.5, rtol=1e-5, atol=1e-6)


def test_compiled_equals_eager(graph_backend, reference):
    _, geoms = reference
    scene = ivy_robot.SceneSDF.from_mjcf(SCENE, exclude=["probe"])
    pts = native(geoms["pill"]["points"], graph_backend)
    assert_close(numpy_of(ivy.compile_fn(lambda p: scene(p))(pts)), numpy_of(scene(pts)))


def test_bad_input(backend):
    with pytest.raises(ValueError, match=r"unsupported types: \['egg \(mjGEOM_ELLIPSOID\)'\]"):
        ivy_robot.SceneSDF.from_mjcf(
            '<mujoco><worldbody><geom name="egg" type="ellipsoid" size=".1 .2 .3"/>'
            "</worldbody></mujoco>"
        )
    with pytest.raises(ValueError, match="exclude names no geom or body"):
        ivy_robot.SceneSDF.from_mjcf(SCENE, exclude=["nothing"])
    with pytest.raises(ValueError, match="no static geom"):
        ivy_robot.SceneSDF.from_mjcf(SCENE, exclude=["ball", "crate", "pill", "drum", "ground",
                                                     "shelf", "probe"])  # fmt: skip
    with pytest.raises(ValueError, match="unsupported shape types"):
        ivy_robot.SceneSDF(["x"], ["torus"], np.ones((1, 3)), np.eye(4)[None])
    with pytest.raises(ValueError, match=r"points must have shape \[\.\.\., 3\]"):
        ivy_robot.box_sdf(native(np.zeros((4, 2)), backend), np.ones(3))
    with pytest.raises(TypeError, match="floating"):
        ivy_robot.plane_sdf(native(np.zeros((4, 3), dtype=np.int32), backend))
