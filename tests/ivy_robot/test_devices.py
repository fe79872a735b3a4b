"""Arrays stay on the device of the inputs: the kinematic tree's constants, the DH
manipulator's, the scene SDF's and the planners', on the device the test run targets
(``IVY_TEST_DEVICE``). Model constants come through ``xp.constant``: converted once per dtype and
device, so a loop over steps copies nothing from the host."""

from __future__ import annotations

import numpy as np

import ivy_robot


def _device(xp, target_device):
    """The test run's device where the backend has that kind of device, else the CPU."""
    return target_device if target_device.split(":")[0] in xp.capabilities.devices else "cpu"


SCENE = """<mujoco><worldbody>
  <geom name="post" type="box" pos="0.6 0 0.2" size="0.06 0.06 0.2"/>
</worldbody></mujoco>"""


def test_results_stay_on_the_inputs_device(xp, target_device):
    device = _device(xp, target_device)

    def on(x):
        return xp.asarray(np.asarray(x, dtype=np.float64), device=device)

    tree = ivy_robot.KinematicTree.from_mjcf(ivy_robot.panda_mjcf())
    arm = ivy_robot.PandaModel()
    scene = ivy_robot.SceneSDF.from_mjcf(SCENE)
    q = on(np.full((2, 7), 0.3))
    drone = ivy_robot.DronePlanner(ivy_robot.RigidMobile([[0.0, 0.0, 0.0]]), scene, num_samples=8)
    start, goal = on([-1.0, -1.0, 0.5, 0, 0, 0]), on([1.0, 1.0, 0.5, 0, 0, 0])
    outputs = {
        "forward_kinematics": tree.forward_kinematics(q),
        "site_poses": tree.site_poses(q),
        "link_matrices": arm.link_matrices(q),
        "scene sdf": scene(on(np.zeros((4, 3)))),
        "planner path": drone.path(drone.initial_anchors(start, goal), start, goal),
        "planner cost": drone.cost(drone.initial_anchors(start, goal), start, goal),
    }
    for name, out in outputs.items():
        assert xp.dev(out) == device, f"{name} is on {xp.dev(out)}, not {device}"
