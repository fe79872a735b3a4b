"""Swimmer: the original ivy_gym's point fish that swims to a goal among urchins it must avoid
(not Gymnasium's MuJoCo Swimmer, a different task)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ivy_gym.base import Env, cast_like
from ivy_gym.rendering import reward_color

__all__ = ["Swimmer", "SwimmerParams"]


@dataclass(frozen=True)
class SwimmerParams:
    """The original ivy_gym swimmer's constants."""

    dt: float = 0.05
    goal_sharpness: float = 0.5
    urchin_sharpness: float = 30.0


class Swimmer(Env):
    """A point fish in the plane, accelerated by the action, that must reach a goal and keep away
    from ``num_urchins`` fixed urchins.

    Semi-implicit Euler: ``xy_vel += dt * action;  xy += dt * xy_vel``. Reward, of the new state,
    smooth and in [0, 1]::

        exp(-goal_sharpness |xy - goal|**2) * prod_i (1 - exp(-urchin_sharpness |xy - urchin_i|**2))

    State = observation = ``[urchin_xys (2U), xy (2), xy_vel (2), goal_xy (2)]``. Initial state:
    urchins, fish and goal uniform in ``[-1, 1]^2``, velocity 0. Actions in [-1, 1]^2 (not
    clipped by the core). Never terminates; time limit (registered task): 200 steps.

    Args:
        num_urchins: number of urchins (5 by default).
        **params: fields of :class:`SwimmerParams`.

    Example:
        >>> env = ivy_gym.Swimmer()
        >>> s = env.reset((16,), f="torch")
        >>> s, obs, reward, terminated = env.step(s, torch.zeros(16, 2))
    """

    Params = SwimmerParams

    def __init__(self, num_urchins: int = 5, **params) -> None:
        if int(num_urchins) < 0:
            raise ValueError(f"Swimmer: num_urchins must be non-negative, got {num_urchins}.")
        self.num_urchins = int(num_urchins)
        names = (
            *(f"urchin_{i}_{c}" for i in range(self.num_urchins) for c in "xy"),
            "x",
            "y",
            "x_vel",
            "y_vel",
            "goal_x",
            "goal_y",
        )
        self.state_names = self.observation_names = names
        super().__init__(**params)

    def __repr__(self) -> str:
        return f"Swimmer(num_urchins={self.num_urchins}, {self.params})"

    def reset_bounds(self):
        u = 2 * self.num_urchins
        high = np.concatenate([np.ones(u + 2), np.zeros(2), np.ones(2)])
        low = np.concatenate([-np.ones(u + 2), np.zeros(2), -np.ones(2)])
        return low, high

    def action_bounds(self):
        return -np.ones(2), np.ones(2)

    def kernel_step(self, xp, state, action):
        p, u = self.params, 2 * self.num_urchins
        if u:
            urchins, xy, vel, goal = xp.split(state, [u, 2, 2, 2], axis=-1)
        else:
            urchins, (xy, vel, goal) = None, xp.split(state, [2, 2, 2], axis=-1)
        vel = vel + p.dt * cast_like(xp, action, state)
        xy = xy + p.dt * vel
        state = xp.concat([urchins, xy, vel, goal] if u else [xy, vel, goal], axis=-1)
        to_goal = xy - goal
        reward = xp.exp(-p.goal_sharpness * xp.sum(to_goal * to_goal, axis=-1))
        if self.num_urchins:
            shape = (*urchins.shape[:-1], self.num_urchins, 2)
            to_urchins = xp.expand_dims(xy, axis=-2) - xp.reshape(urchins, shape)
            near = xp.exp(-p.urchin_sharpness * xp.sum(to_urchins * to_urchins, axis=-1))
            reward = reward * xp.prod(1.0 - near, axis=-1)
        return state, state, reward, xp.zeros_like(reward) > 0

    def kernel_observe(self, xp, state):
        return state

    def _view(self, s):
        return (-1.6, 1.6, -1.6, 1.6)

    def _draw(self, canvas, s):
        u = 2 * self.num_urchins
        urchins, xy, goal = s[:u].reshape(-1, 2), s[u : u + 2], s[u + 4 :]
        p = self.params
        reward = math.exp(-p.goal_sharpness * float(np.sum((xy - goal) ** 2)))
        if self.num_urchins:
            near = np.exp(-p.urchin_sharpness * np.sum((xy - urchins) ** 2, -1))
            reward *= float(np.prod(1 - near))
        canvas.disc(goal, 0.08, (30, 120, 230))
        for c in urchins:
            for k in range(8):
                a = k * math.pi / 4
                canvas.line(c, c + 0.12 * np.array([math.cos(a), math.sin(a)]), 0.015, (60, 20, 60))
            canvas.disc(c, 0.06, (90, 30, 90))
        vel = s[u + 2 : u + 4]
        heading = math.atan2(vel[1], vel[0]) if np.any(vel) else 0.0
        along = np.array([math.cos(heading), math.sin(heading)])
        side = np.array([-along[1], along[0]])
        body = [xy + along * 0.1, xy + side * 0.05, xy - along * 0.08, xy - side * 0.05]
        canvas.polygon(body, reward_color(reward))
        canvas.polygon(
            [xy - along * 0.06, xy - along * 0.14 + side * 0.05, xy - along * 0.14 - side * 0.05],
            reward_color(reward),
        )
