"""ReacherMuJoCo: Gymnasium's Reacher-v5 on ``ivy_robot.physics``.

Gymnasium's ``reacher.xml`` is a two-link planar arm (hinges ``joint0``, unlimited, and
``joint1``, the elbow, limited to [-3, 3] rad; each with armature 1 and damping 1, driven by
motors of gear 200 whose controls are clamped to [-1, 1]) and a target body on two slide joints
(``target_x``, ``target_y``, limited to [-0.27, 0.27]; no armature, damping or stiffness, so a
target at rest stays where the reset put it). The model asks for MuJoCo's RK4 integrator with
``timestep = 0.01``; Gymnasium runs ``frame_skip = 2`` of them per environment step, and so does
:class:`ivy_gym.MuJoCoEnv`. The elbow's limit is MuJoCo's soft limit constraint (Newton's
solver): an arm driven into it stops there as in Gymnasium. The model's geoms do not collide
(``contype`` 0 throughout).

Gymnasium's observation and reward read more than the new state: after ``mj_step`` with RK4,
MuJoCo's body positions (``data.xpos``, Gymnasium's ``get_body_com``) are those its last stage
computed, at ``qpos + timestep * v3`` (``v3`` the third stage's velocity), not at the new
``qpos``. Gymnasium's ``fingertip - target`` (in the observation and in the distance cost, both
after the step) is that stale vector, and so is this core's; :meth:`ReacherMuJoCo.observe` of a
state computes it at the state itself (as Gymnasium's reset does, after ``mj_forward``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

import ivy
from ivy_gym.base import _shape
from ivy_gym.mujoco_env import MuJoCoEnv, control_cost, mujoco_tree

__all__ = ["ReacherMuJoCo", "ReacherMuJoCoParams", "reacher_tree"]

# the bodies whose positions the observation and the reward read
_FINGERTIP, _TARGET = "fingertip", "target"


def reacher_tree():
    """The :class:`ivy_robot.KinematicTree` of Gymnasium's ``reacher.xml``, parsed once
    (through MuJoCo).

    Example:
        >>> tree = ivy_gym.reacher_tree()
        >>> tree.nq, tree.nv, tree.nu, tree.integrator
        (4, 4, 2, 'RK4')
    """
    return mujoco_tree("reacher.xml")


@dataclass(frozen=True)
class ReacherMuJoCoParams:
    """Gymnasium's Reacher-v5 arguments (``frame_skip``, the reward weights: the defaults of
    its code, where the control weight is 1 although its docstring says 0.1), and the constants
    its reset hard-codes (noise half-widths, the goal's disc radius)."""

    xml_file: str = "reacher.xml"
    frame_skip: int = 2
    reward_dist_weight: float = 1.0
    reward_control_weight: float = 1.0
    reset_noise_scale: float = 0.1  # arm angles: qpos0 + U(-0.1, 0.1)
    goal_radius: float = 0.2  # the goal: uniform in the open disc of this radius
    velocity_noise_scale: float = 0.005  # arm velocities: U(-0.005, 0.005); the target's: 0


class ReacherMuJoCo(MuJoCoEnv):
    """Gymnasium's Reacher-v5, step for step: a two-link arm reaches a target.

    State ``[joint0, joint1, target_x, target_y, joint0_vel, joint1_vel, target_x_vel,
    target_y_vel]``: MuJoCo's ``qpos`` then ``qvel`` (the target's slide joints included). The
    action (the two motors' controls, in the XML's ``ctrlrange`` [-1, 1]; the actuators clamp
    it) is held for ``frame_skip`` steps of RK4. Observation, as Gymnasium's ``_get_obs``:
    ``[cos(joint0), cos(joint1), sin(joint0), sin(joint1), target_x, target_y, joint0_vel,
    joint1_vel, (fingertip - target)_x, (fingertip - target)_y]``. Reward, after the step:
    ``-reward_dist_weight * |fingertip - target| - reward_control_weight * |action|^2`` (the
    control cost of the action as given, in its dtype: Gymnasium's float32 arithmetic for
    float32 actions). After a step the fingertip and target positions are MuJoCo's stale ones
    of the last RK4 stage (see the module's docstring); :meth:`observe` computes them at the
    state. Never terminates; time limit (registered task): 50 steps.

    Initial state (Gymnasium's ``reset_model``): arm angles ``qpos0 + U(-0.1, 0.1)``, the goal
    uniform in the disc of radius 0.2 (Gymnasium draws it by rejection from the square, which the
    Gymnasium facades repeat draw for draw; :meth:`reset` maps uniform draws onto the disc, the
    same distribution), arm velocities ``U(-0.005, 0.005)``, the target's 0.
    :meth:`reset_bounds` is the bounding box of that set. Info (Gymnasium's): ``reward_dist,
    reward_ctrl``.

    Args:
        **params: fields of :class:`ReacherMuJoCoParams`.

    Example:
        >>> env = ivy_gym.ReacherMuJoCo()
        >>> s = env.reset((16,), dtype="float64", f="numpy")
        >>> s, obs, reward, terminated = env.step(s, np.zeros((16, 2)))
    """

    Params = ReacherMuJoCoParams
    max_episode_steps = 50
    data_fields = ("xpos",)
    reset_stage = "kinematics"
    info_types = {"reward_ctrl": "action"}

    def __init__(self, **params) -> None:
        super().__init__(**params)
        tree = self.tree
        if tree.integrator != "RK4" or set(tree.joint_types) - {"hinge", "slide"}:
            raise ValueError(
                "ReacherMuJoCo: the model must integrate with RK4 and have only hinge and slide "
                f"joints (Gymnasium's reacher.xml); got {tree.integrator}, {tree.joint_types}."
            )

    def _observation_names(self):
        return (
            "cos_joint0",
            "cos_joint1",
            "sin_joint0",
            "sin_joint1",
            "target_x",
            "target_y",
            "joint0_vel",
            "joint1_vel",
            "fingertip_minus_target_x",
            "fingertip_minus_target_y",
        )

    # ------------------------------------------------------------------------------------------
    # Boxes and resets
    # ------------------------------------------------------------------------------------------

    def reset_bounds(self):
        p, tree = self.params, self.tree
        qpos0 = np.asarray(tree.qpos0, dtype=np.float64)
        centre = np.concatenate([qpos0[:2], np.zeros(2), np.zeros(tree.nv)])
        half = np.array(
            [p.reset_noise_scale] * 2 + [p.goal_radius] * 2 + [p.velocity_noise_scale] * 2 + [0, 0],
            dtype=np.float64,
        )
        return centre - half, centre + half

    def _reset_scales(self):
        """``(centre, half)`` of the initial box: qpos then qvel (see :meth:`narrowed`)."""
        low, high = self.initial_bounds()
        return (high + low) / 2, (high - low) / 2

    def draw_initial(self, rng: np.random.Generator, batch_shape=()) -> np.ndarray:
        """Gymnasium's ``reset_model``, draw for draw with ``rng``, for each member of the batch
        in turn: ``qpos = U(-0.1, 0.1, nq) + qpos0``; the goal ``U(-0.2, 0.2, 2)`` until its
        norm is below 0.2, into ``qpos[2:]``; ``qvel = U(-0.005, 0.005, nv)`` with the target's
        set to 0 (the half-widths shrink with :meth:`narrowed`)."""
        tree = self.tree
        centre, half = self._reset_scales()
        qpos0 = np.asarray(tree.qpos0, dtype=np.float64)
        arm, radius, vel = half[0], half[2], half[tree.nq]
        goal_centre = centre[2:4]
        batch = _shape(batch_shape)
        out = np.empty((*batch, self.state_dim))
        for index in np.ndindex(*batch):
            qpos = rng.uniform(low=-arm, high=arm, size=tree.nq) + qpos0
            while True:
                goal = rng.uniform(low=-radius, high=radius, size=2)
                if np.linalg.norm(goal) < radius:
                    break
            qpos[2:] = goal + goal_centre
            qvel = centre[tree.nq :] + rng.uniform(low=-vel, high=vel, size=tree.nv)
            qvel[2:] = 0.0
            out[index] = np.concatenate([qpos, qvel])
        return out

    def reset(self, batch_shape=(), *, dtype="float32", device=None, f=None):
        """A batch of initial states drawn with ivy's random functions (see :meth:`Env.reset`):
        uniform in the box for the arm, the goal uniform in its disc (radius ``sqrt(u)``, angle
        ``2 pi v``), the target at rest.

        Example:
            >>> ivy.seed(0)
            >>> ivy_gym.ReacherMuJoCo().reset((64,), f="torch").shape
            torch.Size([64, 8])
        """
        xp = ivy.get_framework(f=f)
        batch = _shape(batch_shape)
        low = xp.constant(self._constants["reset_low"], dtype=dtype, device=device)
        width = xp.constant(self._constants["reset_width"], dtype=dtype, device=device)
        u = xp.random_uniform(shape=(*batch, self.state_dim), dtype=dtype, device=device)
        box = low + width * u
        centre, half = self._reset_scales()
        radius = half[2] * xp.sqrt(u[..., 2])
        angle = (2 * math.pi) * u[..., 3]
        goal = [centre[2] + radius * xp.cos(angle), centre[3] + radius * xp.sin(angle)]
        state = xp.concat([box[..., :2], xp.stack(goal, axis=-1), box[..., 4:]], axis=-1)
        return self.kernel_initial(xp, state)

    # ------------------------------------------------------------------------------------------
    # Kernels
    # ------------------------------------------------------------------------------------------

    def _fingertip_minus_target(self, xp, data):
        """``fingertip - target`` in the world (3 components) from the data's body positions."""
        fingertip, target = (self.tree.body_id(b) for b in (_FINGERTIP, _TARGET))
        return data.xpos[..., fingertip, :] - data.xpos[..., target, :]

    def observation(self, xp, data):
        qpos, vec = data.qpos, self._fingertip_minus_target(xp, data)
        angles = qpos[..., :2]
        return xp.concat(
            [xp.cos(angles), xp.sin(angles), qpos[..., 2:], data.qvel[..., :2], vec[..., :2]],
            axis=-1,
        )

    def reward(self, xp, t):
        p = self.params
        vec = self._fingertip_minus_target(xp, t.data)
        # Gymnasium: -|vec| * w_dist + (-sum(action^2) * w_control)
        dist = -xp.safe_norm(vec, axis=-1) * p.reward_dist_weight
        ctrl = -control_cost(xp, t.action, p.reward_control_weight, dist)
        info = {"reward_dist": dist, "reward_ctrl": ctrl}
        return dist + ctrl, dist > np.inf, info

    # ------------------------------------------------------------------------------------------
    # Rendering
    # ------------------------------------------------------------------------------------------

    def _view(self, s):
        return (-0.32, 0.32, -0.32, 0.32)

    def _draw(self, canvas, s):
        poses = np.asarray(self.tree.forward_kinematics(s[: self.tree.nq]))
        xy = {name: poses[self.tree.body_id(name), :2, 3] for name in self.tree.body_names[1:]}
        corners = [(-0.3, -0.3), (0.3, -0.3), (0.3, 0.3), (-0.3, 0.3)]
        for a, b in zip(corners, corners[1:] + corners[:1]):  # the arena's walls
            canvas.line(a, b, 0.02, (230, 102, 153))
        canvas.disc(xy[_TARGET], 0.009 * 2, (230, 51, 51))
        canvas.line(xy["body0"], xy["body1"], 0.02, (0, 102, 153))
        canvas.line(xy["body1"], xy[_FINGERTIP], 0.02, (0, 102, 153))
        canvas.disc(xy[_FINGERTIP], 0.01, (0, 204, 153))
        canvas.disc(xy["body0"], 0.011, (230, 102, 153))
