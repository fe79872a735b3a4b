"""MJCF models written for the tests: every joint type, orientation attribute and frame
arrangement that MuJoCo resolves, plus the paths of the models Gymnasium ships."""

from __future__ import annotations

import glob
import os

import numpy as np

# Every joint type (hinge, slide, ball, free), joints with offsets (pos) and references (ref),
# several joints in one body, rigid bodies under moving ones, a mocap body, sites, and every
# orientation attribute (quat, euler with a custom sequence, axisangle, xyaxes, zaxis) in degrees.
ALL_FEATURES = """
<mujoco model="all_features">
  <compiler angle="degree" eulerseq="zyx" boundmass="0.01" boundinertia="0.001"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 .1"/>
    <body name="base" pos="0.1 -0.2 0.3" euler="10 20 30">
      <geom type="box" size=".1 .1 .1"/>
      <body name="upper" pos="0 0 0.2" axisangle="1 1 0 35">
        <joint name="shoulder" type="hinge" axis="0 1 0.3" pos="0.05 0 -0.02" ref="15"/>
        <geom type="capsule" fromto="0 0 0 0.3 0 0" size="0.04"/>
        <site name="elbow_site" pos="0.3 0 0" xyaxes="0 1 0 -1 0 0"/>
        <body name="fore" pos="0.3 0 0" quat="0.9 0.1 -0.3 0.2">
          <joint name="twist" type="hinge" axis="1 0 0"/>
          <joint name="extend" type="slide" axis="1 0.2 0" pos="0.1 0 0" ref="0.05"/>
          <joint name="wrist" type="ball" pos="0.02 0.01 0"/>
          <geom type="capsule" fromto="0 0 0 0.25 0 0" size="0.03"/>
          <body name="hand" pos="0.25 0 0" zaxis="0 1 1">
            <geom type="sphere" size="0.05"/>
            <site name="tip" pos="0.05 0.01 0.02" euler="5 -40 60"/>
          </body>
        </body>
      </body>
      <body name="slider" pos="-0.2 0 0">
        <joint name="rail" type="slide" axis="0 0 1"/>
        <geom type="box" size=".02 .02 .02"/>
        <body name="spinner" pos="0 0.1 0">
          <joint name="spin_slide" type="slide" axis="0 1 0" pos="0 0 0.05"/>
          <joint name="spin_ball" type="ball"/>
          <geom type="cylinder" size=".02 .05"/>
        </body>
      </body>
    </body>
    <body name="drone" pos="1 1 1">
      <freejoint name="drone_free"/>
      <geom type="box" size=".1 .1 .02"/>
      <site name="drone_cam" pos="0.1 0 0" axisangle="0 1 0 -30"/>
      <body name="rotor" pos="0.1 0.1 0.03" euler="0 0 45">
        <joint name="rotor_spin" type="hinge" axis="0 0 1"/>
        <geom type="cylinder" size=".05 .005"/>
      </body>
    </body>
    <body name="target" mocap="true" pos="0.5 0.5 0.5" euler="0 30 0">
      <geom type="sphere" size=".02" contype="0" conaffinity="0"/>
    </body>
    <body name="ball_top" pos="0 1 0.5">
      <joint name="pivot" type="ball" pos="0 0 0.1"/>
      <geom type="capsule" fromto="0 0 0 0 0 -0.3" size="0.02"/>
      <body name="ball_child" pos="0 0 -0.3">
        <joint name="knee" type="hinge" axis="1 0 0" range="-90 90"/>
        <geom type="capsule" fromto="0 0 0 0 0 -0.3" size="0.02"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""

# A chain of hinges and slides only (nq == nv), for autodiff comparisons with the FK.
HINGE_SLIDE = """
<mujoco model="hinge_slide">
  <worldbody>
    <body name="b1" pos="0 0 0.1" euler="0.1 0.2 0.3">
      <joint name="j1" type="hinge" axis="0 0 1"/>
      <geom type="capsule" fromto="0 0 0 0.2 0 0" size="0.02"/>
      <body name="b2" pos="0.2 0 0">
        <joint name="j2" type="hinge" axis="0 1 0" pos="0.01 0 0.02" ref="0.3"/>
        <joint name="j3" type="slide" axis="1 0 0"/>
        <geom type="capsule" fromto="0 0 0 0.2 0 0" size="0.02"/>
        <body name="b3" pos="0.2 0 0" quat="0.8 0.2 0.1 0.3">
          <joint name="j4" type="slide" axis="0 0.6 0.8" ref="0.1"/>
          <joint name="j5" type="hinge" axis="1 0 0"/>
          <geom type="sphere" size="0.03"/>
          <site name="s" pos="0.05 0 0.01" euler="0.3 0 0.1"/>
        </body>
      </body>
    </body>
  </worldbody>
</mujoco>
"""


def gymnasium_models() -> list[str]:
    """Paths of the MJCF models that Gymnasium ships (empty if gymnasium is absent)."""
    try:
        import gymnasium
    except ImportError:
        return []
    folder = os.path.join(os.path.dirname(gymnasium.__file__), "envs", "mujoco", "assets")
    return sorted(glob.glob(os.path.join(folder, "*.xml")))


def random_qpos(model, rng: np.random.Generator, batch: int) -> np.ndarray:
    """Random joint positions *[batch, nq]*: hinges and slides around qpos0, unit (and some
    non-unit) quaternions for ball and free joints, free positions anywhere near the origin."""
    q = np.tile(model.qpos0, (batch, 1)) + rng.normal(scale=1.0, size=(batch, model.nq))
    for j in range(model.njnt):
        adr, kind = model.jnt_qposadr[j], model.jnt_type[j]
        if kind in (0, 1):  # free, ball: a quaternion at adr (+3 for free)
            qa = adr + (3 if kind == 0 else 0)
            quat = rng.normal(size=(batch, 4))
            q[:, qa : qa + 4] = quat * rng.uniform(0.5, 2.0, size=(batch, 1))
    return q


# Obstacles for the Panda of ivy_robot.panda_mjcf: a post in front of the arm that the straight
# joint-space path from START to GOAL sweeps through, and the floor.
ARM_OBSTACLES = """
    <geom name="floor" type="plane" size="2 2 .1" contype="0" conaffinity="1"/>
    <geom name="post" type="box" pos="0.6 0 0.2" size="0.06 0.06 0.2" contype="0" conaffinity="1"/>
"""
ARM_START = np.array([-1.2, 0.5, 0.0, -1.8, 0.0, 2.3, 0.8])
ARM_GOAL = np.array([1.2, 0.5, 0.0, -1.8, 0.0, 2.3, 0.8])

# A drone (five spheres on a cross) and pillars between its start and goal.
DRONE_POINTS = np.array(
    [[0.0, 0.0, 0.0], [0.15, 0.0, 0.0], [-0.15, 0.0, 0.0], [0.0, 0.15, 0.0], [0.0, -0.15, 0.0]]
)
DRONE_RADIUS = 0.05
DRONE_START = np.array([-1.0, -1.0, 0.6, 0.0, 0.0, 0.0])
DRONE_GOAL = np.array([1.0, 1.0, 0.6, 0.0, 0.0, 1.0])
DRONE_SCENE = """
<mujoco model="drone_scene">
  <worldbody>
    <geom name="floor" type="plane" size="3 3 .1" contype="0" conaffinity="1"/>
    <geom name="pillar" type="cylinder" pos="0.08 -0.05 0.6" size="0.3 0.6" contype="0" conaffinity="1"/>
    <geom name="crate" type="box" pos="0.5 -0.4 0.4" size="0.2 0.2 0.4" euler="0 0 0.4"
          contype="0" conaffinity="1"/>
    <geom name="beam" type="capsule" fromto="-0.8 0.6 0.2 -0.2 0.9 1.2" size="0.1"
          contype="0" conaffinity="1"/>
    <body name="drone">
      <freejoint/>
      <geom type="sphere" size="{r}" pos="0 0 0" contype="1" conaffinity="0"/>
      <geom type="sphere" size="{r}" pos="0.15 0 0" contype="1" conaffinity="0"/>
      <geom type="sphere" size="{r}" pos="-0.15 0 0" contype="1" conaffinity="0"/>
      <geom type="sphere" size="{r}" pos="0 0.15 0" contype="1" conaffinity="0"/>
      <geom type="sphere" size="{r}" pos="0 -0.15 0" contype="1" conaffinity="0"/>
    </body>
  </worldbody>
</mujoco>
""".replace("{r}", str(DRONE_RADIUS))
