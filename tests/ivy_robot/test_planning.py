"""CHOMP-style trajectory optimisation: cost functions against numpy formulas; an arm (joint
space) and a drone (pose space) plan around obstacles: their cost decreases and MuJoCo finds no
contact on a dense resampling of the optimised path, while the straight-line path collides;
compiled steps equal eager steps; numpy (no gradients) raises."""

from __future__ import annotations

import importlib.util

import numpy as np
import pytest

import ivy
import ivy_robot
from tests.helpers import assert_close, native, numpy_of
from tests.ivy_robot._models import (
    ARM_GOAL,
    ARM_OBSTACLES,
    ARM_START,
    DRONE_GOAL,
    DRONE_POINTS,
    DRONE_RADIUS,
    DRONE_SCENE,
    DRONE_START,
)

mujoco = pytest.importorskip("mujoco")
ARM_XML = ivy_robot.panda_mjcf(ARM_OBSTACLES)
DENSE = 400


def test_cost_functions(backend):
    rng = np.random.default_rng(0)
    path = rng.normal(size=(2, 9, 3))
    want = np.sum(np.diff(path, axis=-2) ** 2, axis=(-2, -1)) * 8
    assert_close(numpy_of(ivy_robot.smoothness_cost(native(path, backend))), want)
    d = np.array([-0.3, -0.01, 0.0, 0.02, 0.05, 0.1, 0.7])
    eps = 0.05
    want = np.where(d < 0, -d + eps / 2, np.where(d <= eps, (d - eps) ** 2 / (2 * eps), 0.0))
    assert_close(numpy_of(ivy_robot.obstacle_cost(native(d, backend), eps)), want)
    q = rng.normal(size=(4, 3))
    lower, upper = np.array([-0.5, -np.inf, 0.0]), np.array([0.5, 0.2, np.inf])
    viol = np.maximum(lower - q, 0) ** 2 + np.maximum(q - upper, 0) ** 2
    got = ivy_robot.joint_limit_cost(native(q, backend), lower, upper)
    assert_close(numpy_of(got), viol.sum(-1))
    with pytest.raises(ValueError, match="margin must be positive"):
        ivy_robot.obstacle_cost(native(d, backend), 0.0)


def _arm_contacts(path):
    model = mujoco.MjModel.from_xml_string(ARM_XML)
    data = mujoco.MjData(model)
    count = 0
    for q in path:
        data.qpos[:] = q
        mujoco.mj_forward(model, data)
        count += data.ncon > 0
    return count


def _drone_contacts(path):
    from scipy.spatial.transform import Rotation

    model = mujoco.MjModel.from_xml_string(DRONE_SCENE)
    data = mujoco.MjData(model)
    count = 0
    for pose in np.array(path):  # a writable copy (scipy's Cython needs one)
        quat = Rotation.from_rotvec(pose[3:]).as_quat()  # [x, y, z, w]
        data.qpos[:] = np.concatenate([pose[:3], quat[3:], quat[:3]])  # MuJoCo: [w, x, y, z]
        mujoco.mj_forward(model, data)
        count += data.ncon > 0
    return count


@pytest.fixture(scope="module")
def arm_planner():
    tree = ivy_robot.KinematicTree.from_mjcf(ARM_XML)
    scene = ivy_robot.SceneSDF.from_mjcf(ARM_XML, exclude=["link0"])
    return ivy_robot.ArmPlanner(tree, scene, num_samples=40)


@pytest.fixture(scope="module")
def drone_planner():
    scene = ivy_robot.SceneSDF.from_mjcf(DRONE_SCENE, exclude=["drone"])
    body = ivy_robot.RigidMobile(DRONE_POINTS)
    return ivy_robot.DronePlanner(body, scene, body_radius=DRONE_RADIUS, num_samples=40)


def test_arm_plans_around_obstacles(graph_backend, arm_planner):
    start, goal = native(ARM_START, graph_backend), native(ARM_GOAL, graph_backend)
    straight = arm_planner.path(arm_planner.initial_anchors(start, goal), start, goal, DENSE)
    assert _arm_contacts(numpy_of(straight)) > 0  # the problem is not trivial
    result = arm_planner.optimise(start, goal, 150, lr=0.05)
    assert result.costs.shape == (150,)
    assert result.costs[-1] < 0.5 * result.costs[0]
    dense = numpy_of(arm_planner.path(result.anchors, start, goal, DENSE))
    assert_close(dense[0], ARM_START)
    assert_close(dense[-1], ARM_GOAL)
    assert _arm_contacts(dense) == 0
    tree = arm_planner.robot
    assert np.all(dense >= tree.qpos_lower - 1e-3) and np.all(dense <= tree.qpos_upper + 1e-3)


def test_drone_plans_around_obstacles(diff_backend, drone_planner):
    start, goal = native(DRONE_START, diff_backend), native(DRONE_GOAL, diff_backend)
    straight = drone_planner.path(drone_planner.initial_anchors(start, goal), start, goal, DENSE)
    assert _drone_contacts(numpy_of(straight)) > 0
    # torch.compile takes minutes to build this step: torch runs it eagerly here (the graph is
    # checked for breaks in test_torch_step_is_one_graph)
    result = drone_planner.optimise(start, goal, 120, lr=0.05, compile=diff_backend != "torch")
    assert result.costs[-1] < 0.5 * result.costs[0]
    assert _drone_contacts(numpy_of(drone_planner.path(result.anchors, start, goal, DENSE))) == 0


def test_manipulator_planner(graph_backend):
    """A DH arm: points along its links, each with a radius, against the post (the floor is
    left out: the link points start at the base, on the floor)."""
    scene = ivy_robot.SceneSDF.from_mjcf(ARM_XML, exclude=["link0", "floor"])
    planner = ivy_robot.ArmPlanner(ivy_robot.PandaModel(), scene, num_samples=24, link_radius=0.06)
    start, goal = native(ARM_START, graph_backend), native(ARM_GOAL, graph_backend)
    result = planner.optimise(start, goal, 60, lr=0.05)
    assert result.costs[-1] < 0.5 * result.costs[0]
    centres = numpy_of(planner.sphere_centres(result.path))
    assert centres.shape == (24, ivy_robot.PandaModel().num_link_samples(20.0), 3)
    clearance = numpy_of(scene(native(centres, graph_backend))) - planner.radii
    assert clearance.min() > -0.02


def test_compiled_step_equals_eager(graph_backend):
    """A small drone problem (eager jax pays a compilation per primitive and shape)."""
    scene = ivy_robot.SceneSDF(["ball"], ["sphere"], [[0.3, 0, 0]], [np.eye(4)])
    planner = ivy_robot.DronePlanner(
        ivy_robot.RigidMobile(DRONE_POINTS[:2]), scene, num_anchors=2, num_samples=8
    )
    start = native(np.array([-1.0, 0.05, 0.0, 0.1, 0.0, 0.0]), graph_backend)
    goal = native(np.array([1.0, 0.0, 0.0, 0.0, 0.2, 0.3]), graph_backend)
    anchors = planner.initial_anchors(start, goal)
    optimizer = ivy.SGD(1e-3)
    state = optimizer.init({"anchors": anchors})
    eager = planner.step_fn(optimizer, compile=False)(anchors, state, start, goal)
    compiled = planner.step_fn(optimizer)(anchors, state, start, goal)
    assert_close(numpy_of(compiled[0]), numpy_of(eager[0]))
    assert_close(numpy_of(compiled[1]), numpy_of(eager[1]))
    assert not np.allclose(numpy_of(compiled[1]), numpy_of(anchors))  # the step moved them
    terms = planner.cost_terms(anchors, start, goal)
    total = sum(float(numpy_of(v)) for v in terms.values())
    assert np.isclose(total, float(numpy_of(eager[0])), rtol=1e-12)


def test_torch_step_is_one_graph(drone_planner):
    """torch.compile traces the whole step (cost, gradients, update) without a graph break (as
    ivy.compile_fn runs it: with dynamo tracing autograd.grad; dynamo only, no inductor build)."""
    torch = pytest.importorskip("torch")
    start, goal = torch.tensor(DRONE_START), torch.tensor(DRONE_GOAL)
    anchors = drone_planner.initial_anchors(start, goal)
    optimizer = ivy.Adam(0.05)
    step = drone_planner.step_fn(optimizer, compile=False)
    state = optimizer.init({"anchors": anchors})
    # as after other tests: the argument checks have seen every installed library's arrays
    for name in ("numpy", "jax", "tensorflow"):
        if importlib.util.find_spec(name) is not None:
            ivy.checks.check_floating_dtype(getattr(ivy, name).ones((2,)).dtype)
    with torch._dynamo.config.patch(trace_autograd_ops=True):
        explanation = torch._dynamo.explain(step)(anchors, state, start, goal)
    assert explanation.graph_break_count == 0, explanation.break_reasons
    assert explanation.graph_count == 1


def test_numpy_has_no_gradients(drone_planner):
    with pytest.raises(ivy.errors.UnsupportedError):
        drone_planner.optimise(DRONE_START, DRONE_GOAL, 2, compile=False)


def test_bad_input(arm_planner, drone_planner):
    with pytest.raises(ValueError, match=r"start must have shape \(7,\)"):
        arm_planner.initial_anchors(np.zeros(6), np.zeros(7))
    with pytest.raises(ValueError, match=r"goal must have shape \(6,\)"):
        drone_planner.optimise(np.zeros(6), np.zeros(7), 1)
    with pytest.raises(ValueError, match="ball or free joints"):
        ivy_robot.ArmPlanner(ivy_robot.KinematicTree.from_mjcf(DRONE_SCENE), drone_planner.scene)
    with pytest.raises(ValueError, match="unknown cost weights"):
        ivy_robot.DronePlanner(ivy_robot.RigidMobile(DRONE_POINTS), drone_planner.scene,
                               weights={"speed": 1.0})  # fmt: skip
    with pytest.raises(TypeError, match="KinematicTree or a Manipulator"):
        ivy_robot.ArmPlanner("panda", drone_planner.scene)
