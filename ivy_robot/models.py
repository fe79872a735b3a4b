"""MJCF models shipped with ivy_robot, as XML strings.

``panda_mjcf`` is a kinematic model of the Franka Emika Panda arm written from the joint origins
of Franka's published kinematics (the same as its modified DH table: link offsets and
plus/minus 90 degree twists), with capsule geoms roughly covering its links, joint ranges, and a
``flange`` site 0.107 m beyond joint 7. Collision classes: the moving links collide with
obstacles (``contype=1, conaffinity=0``), the base collides with nothing; obstacles added to the
scene should use ``contype=0, conaffinity=1`` so that MuJoCo reports exactly the arm-obstacle
contacts.
"""

from __future__ import annotations

__all__ = ["panda_mjcf"]

_PANDA_BODIES = """
    <body name="link0" pos="{base_pos}">
      <geom name="link0_geom" type="capsule" fromto="0 0 0.03 0 0 0.2" size="0.07"
            contype="0" conaffinity="0"/>
      <body name="link1" pos="0 0 0.333">
        <joint name="joint1" range="-2.8973 2.8973"/>
        <geom class="link" fromto="0 0 -0.13 0 0 0"/>
        <body name="link2" quat="0.7071067811865476 -0.7071067811865476 0 0">
          <joint name="joint2" range="-1.7628 1.7628"/>
          <geom class="link" fromto="0 0 0 0 -0.2 0"/>
          <body name="link3" pos="0 -0.316 0" quat="0.7071067811865476 0.7071067811865476 0 0">
            <joint name="joint3" range="-2.8973 2.8973"/>
            <geom class="link" fromto="0 0 -0.1 0.0825 0 0"/>
            <body name="link4" pos="0.0825 0 0" quat="0.7071067811865476 0.7071067811865476 0 0">
              <joint name="joint4" range="-3.0718 -0.0698"/>
              <geom class="link" fromto="0 0 0 -0.0825 0.2 0"/>
              <body name="link5" pos="-0.0825 0.384 0"
                    quat="0.7071067811865476 -0.7071067811865476 0 0">
                <joint name="joint5" range="-2.8973 2.8973"/>
                <geom class="link" fromto="0 0 -0.18 0 0 -0.05" size="0.05"/>
                <body name="link6" quat="0.7071067811865476 0.7071067811865476 0 0">
                  <joint name="joint6" range="-0.0175 3.7525"/>
                  <geom class="link" fromto="0 0 0 0.088 0 0" size="0.045"/>
                  <body name="link7" pos="0.088 0 0"
                        quat="0.7071067811865476 0.7071067811865476 0 0">
                    <joint name="joint7" range="-2.8973 2.8973"/>
                    <geom class="link" fromto="0 0 0 0 0 0.107" size="0.04"/>
                    <site name="flange" pos="0 0 0.107"/>
                    <body name="hand" pos="0 0 0.107">
                      <geom class="link" type="sphere" pos="0 0 0.05" size="0.05"/>
                      <site name="grasp" pos="0 0 0.1034"/>
                    </body>
                  </body>
                </body>
              </body>
            </body>
          </body>
        </body>
      </body>
    </body>
"""


def panda_mjcf(world: str = "", *, base_pos: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> str:
    """MJCF of a Panda arm, optionally with more of a scene.

    Args:
        world: extra XML placed in ``<worldbody>`` (obstacles, a floor, targets).
        base_pos: the position of the arm's base in the world.

    Returns:
        The MJCF XML string (angles in radians).

    Example:
        >>> tree = KinematicTree.from_mjcf(panda_mjcf())
        >>> tree.nq, tree.site_names
        (7, ('flange', 'grasp'))
    """
    pos = " ".join(repr(float(v)) for v in base_pos)
    return f"""<mujoco model="panda">
  <compiler angle="radian"/>
  <default>
    <joint type="hinge" axis="0 0 1" limited="true"/>
    <default class="link">
      <geom type="capsule" size="0.06" contype="1" conaffinity="0" rgba="0.9 0.9 0.9 1"/>
    </default>
  </default>
  <worldbody>
{world}
{_PANDA_BODIES.format(base_pos=pos)}
  </worldbody>
</mujoco>
"""
