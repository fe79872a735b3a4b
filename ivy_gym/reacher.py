"""Reacher: the original ivy_gym's planar arm of N joints that reaches a goal (not Gymnasium's
MuJoCo Reacher, a different task)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ivy_gym.base import Env, cast_like, unstack_last
from ivy_gym.rendering import reward_color

__all__ = ["Reacher", "ReacherParams"]


@dataclass(frozen=True)
class ReacherParams:
    """The original ivy_gym reacher's constants."""

    dt: float = 0.05
    torque_scale: float = 1.0


class Reacher(Env):
    """A planar arm of ``num_joints`` unit links, driven by angular accelerations, reaching a goal.

    ``angles`` are the absolute angles of the links (from the x axis), so the end effector is
    at ``(sum(cos(angles)), sum(sin(angles)))``. Each step, semi-implicit Euler:

        angle_vels += dt * torque_scale * action;   angles += dt * angle_vels

    Reward, of the new state, smooth and in [0, 1]: ``exp(-|end_effector - goal|**2)``.
    State ``[angles (N), angle_vels (N), goal_xy (2)]``; observation
    ``[cos(angles) (N), sin(angles) (N), angle_vels (N), goal_xy (2)]``. Initial state: angles
    uniform in [-pi, pi], velocities in [-1, 1], the goal uniform in ``[-N, N]^2``. Actions in
    [-1, 1] (not clipped by the core). Never terminates; time limit (registered task): 200 steps.

    Args:
        num_joints: number of links (2 by default).
        **params: fields of :class:`ReacherParams`.

    Example:
        >>> env = ivy_gym.Reacher(num_joints=3)
        >>> s = env.reset((16,), f="jax")
        >>> s, obs, reward, terminated = env.step(s, jnp.zeros((16, 3)))
    """

    Params = ReacherParams

    def __init__(self, num_joints: int = 2, **params) -> None:
        if int(num_joints) < 1:
            raise ValueError(f"Reacher: num_joints must be at least 1, got {num_joints}.")
        self.num_joints = n = int(num_joints)
        self.state_names = (
            *(f"angle_{i}" for i in range(n)),
            *(f"angle_vel_{i}" for i in range(n)),
            "goal_x",
            "goal_y",
        )
        self.observation_names = (
            *(f"cos_angle_{i}" for i in range(n)),
            *(f"sin_angle_{i}" for i in range(n)),
            *(f"angle_vel_{i}" for i in range(n)),
            "goal_x",
            "goal_y",
        )
        super().__init__(**params)

    def __repr__(self) -> str:
        return f"Reacher(num_joints={self.num_joints}, {self.params})"

    def reset_bounds(self):
        n = self.num_joints
        high = np.concatenate([np.full(n, np.pi), np.ones(n), np.full(2, float(n))])
        return -high, high

    def action_bounds(self):
        return -np.ones(self.num_joints), np.ones(self.num_joints)

    def observation_bounds(self):
        n = self.num_joints
        high = np.concatenate([np.ones(2 * n), np.full(n, np.inf), np.full(2, np.inf)])
        return -high, high

    def kernel_step(self, xp, state, action):
        p, n = self.params, self.num_joints
        angles, vels, goal = xp.split(state, [n, n, 2], axis=-1)
        vels = vels + p.dt * (p.torque_scale * cast_like(xp, action, state))
        angles = angles + p.dt * vels
        cos, sin = xp.cos(angles), xp.sin(angles)
        goal_x, goal_y = unstack_last(xp, goal)
        dx = xp.sum(cos, axis=-1) - goal_x
        dy = xp.sum(sin, axis=-1) - goal_y
        reward = xp.exp(-(dx * dx + dy * dy))
        state = xp.concat([angles, vels, goal], axis=-1)
        obs = xp.concat([cos, sin, vels, goal], axis=-1)
        return state, obs, reward, xp.zeros_like(dx) > 0

    def kernel_observe(self, xp, state):
        n = self.num_joints
        angles, rest = xp.split(state, [n, n + 2], axis=-1)
        return xp.concat([xp.cos(angles), xp.sin(angles), rest], axis=-1)

    def _view(self, s):
        bound = self.num_joints + 0.2
        return (-bound, bound, -bound, bound)

    def _draw(self, canvas, s):
        n = self.num_joints
        angles, goal = s[:n], s[2 * n :]
        joints = np.concatenate(
            [[[0.0, 0.0]], np.cumsum(np.stack([np.cos(angles), np.sin(angles)], -1), 0)]
        )
        reward = math.exp(-float(np.sum((joints[-1] - goal) ** 2)))
        canvas.disc(goal, 0.15, (30, 120, 230))
        for a, b in zip(joints[:-1], joints[1:]):
            canvas.line(a, b, 0.2, reward_color(reward))
        for j in joints[:-1]:
            canvas.disc(j, 0.08, (0, 0, 0))
        canvas.disc(joints[-1], 0.1, (80, 80, 80))
