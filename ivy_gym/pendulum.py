"""Pendulum: Gymnasium's Pendulum-v1, and the original ivy_gym's pendulum with a smooth reward.

A rod of mass ``m`` and length ``l`` on a motor; ``theta`` is its angle from upright, so that

    theta_acc = 3 g / (2 l) * sin(theta) + 3 / (m l**2) * torque

and one step of ``dt`` is semi-implicit Euler (velocity first, then the angle from the new
velocity).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ivy_gym.base import Env, cast_like, scalar_action, unstack_last
from ivy_gym.rendering import reward_color

__all__ = ["Pendulum", "PendulumSmooth", "PendulumParams", "PendulumSmoothParams"]


@dataclass(frozen=True)
class PendulumParams:
    """Gymnasium's Pendulum-v1 constants."""

    g: float = 10.0
    m: float = 1.0
    l: float = 1.0  # noqa: E741 - Gymnasium's name
    dt: float = 0.05
    max_speed: float = 8.0
    max_torque: float = 2.0


@dataclass(frozen=True)
class PendulumSmoothParams:
    """The original ivy_gym pendulum's constants (its action is scaled by ``torque_scale``)."""

    g: float = 9.8
    m: float = 1.0
    l: float = 1.0  # noqa: E741
    dt: float = 0.05
    torque_scale: float = 1.0


def _numbers(*values) -> bool:
    return all(isinstance(v, (int, float)) for v in values)


class _PendulumBase(Env):
    state_names = ("theta", "theta_dot")
    observation_names = ("cos_theta", "sin_theta", "theta_dot")

    def kernel_observe(self, xp, state):
        theta, theta_dot = unstack_last(xp, state)
        return xp.stack([xp.cos(theta), xp.sin(theta), theta_dot], axis=-1)

    def _view(self, s):
        return (-2.2, 2.2, -2.2, 2.2)

    def _draw_rod(self, canvas, theta, color):
        tip = (math.sin(theta), math.cos(theta))
        canvas.line((0.0, 0.0), tip, 0.2, color)
        canvas.disc(tip, 0.1, color)
        canvas.disc((0.0, 0.0), 0.1, color)
        canvas.disc((0.0, 0.0), 0.05, (0, 0, 0))


class Pendulum(_PendulumBase):
    """Gymnasium's Pendulum-v1, step for step: swing the pendulum up and hold it.

    State ``[theta, theta_dot]`` (Gymnasium's layout; ``theta`` is not wrapped), observation
    ``[cos(theta), sin(theta), theta_dot]``. The torque is the action clipped to
    ``[-max_torque, max_torque]`` (as Gymnasium clips), and its terms ``3 / (m l**2) * torque``
    and ``0.001 * torque**2`` are computed in the action's dtype before they meet the state, as
    numpy 2 computes them in Gymnasium (float32 for its action space's samples). Reward, of the state before the step:
    ``-(normalize(theta)**2 + 0.1 * theta_dot**2 + 0.001 * torque**2)`` with ``normalize``
    wrapping to [-pi, pi). The new angular velocity is clipped to ``[-max_speed, max_speed]``
    (Gymnasium's dynamics); ``smooth=True`` drops that clip, so that the dynamics are smooth.
    Initial state uniform in ``[-pi, pi] x [-1, 1]``. Never terminates; time limit (registered
    task): 200 steps.

    Args:
        smooth: drop the speed clip.
        **params: fields of :class:`PendulumParams`, e.g. ``g=9.81``.

    Example:
        >>> env = ivy_gym.Pendulum(g=10.0)
        >>> s = env.reset((64,), f="torch")
        >>> s, obs, reward, terminated = env.step(s, torch.zeros(64, 1))
    """

    Params = PendulumParams
    # Gymnasium computes in float64, observes and acts in float32; its rewards are numpy floats
    gymnasium_dtype = "float64"
    gymnasium_observation_dtype = "float32"
    gymnasium_action_dtype = "float32"
    reward_type = np.float64

    def __init__(self, *, smooth: bool = False, **params) -> None:
        self.smooth = bool(smooth)
        super().__init__(**params)

    def __repr__(self) -> str:
        return f"Pendulum(smooth={self.smooth}, {self.params})"

    def reset_bounds(self):
        high = np.array([np.pi, 1.0])
        return -high, high

    def action_bounds(self):
        return np.array([-self.params.max_torque]), np.array([self.params.max_torque])

    def observation_bounds(self):
        high = np.array([1.0, 1.0, np.inf if self.smooth else self.params.max_speed])
        return -high, high

    def kernel_step(self, xp, state, action):
        p = self.params
        th, thdot = unstack_last(xp, state)
        u = scalar_action(xp, action)
        coef = 3.0 / (p.m * (p.l * p.l))
        if not _numbers(coef, p.max_torque):  # array parameters: all in the state's dtype
            u = cast_like(xp, u, th)
        u = xp.clip(u, -p.max_torque, p.max_torque)
        # Gymnasium (numpy 2) computes the action's terms in the action's dtype (float32 for
        # its action space's samples), then adds them to its float64 state
        torque_acc = cast_like(xp, coef * u, th)
        torque_cost = cast_like(xp, 0.001 * (u * u), th)
        wrapped = xp.remainder(th + math.pi, 2 * math.pi) - math.pi
        costs = wrapped * wrapped + 0.1 * (thdot * thdot) + torque_cost
        newthdot = thdot + (3 * p.g / (2 * p.l) * xp.sin(th) + torque_acc) * p.dt
        if not self.smooth:
            newthdot = xp.clip(newthdot, -p.max_speed, p.max_speed)
        newth = th + newthdot * p.dt
        state = xp.stack([newth, newthdot], axis=-1)
        obs = xp.stack([xp.cos(newth), xp.sin(newth), newthdot], axis=-1)
        return state, obs, -costs, xp.zeros_like(th) > 0

    def _draw(self, canvas, s):
        self._draw_rod(canvas, s[0], (204, 77, 77))


class PendulumSmooth(_PendulumBase):
    """The original ivy_gym's pendulum: a smooth reward for being upright.

    The pendulum's dynamics with ``torque = torque_scale * action`` (action in [-1, 1]; the core
    does not clip, the Gymnasium facade checks the action space), no speed limit.
    Reward, of the new state, smooth and in [0, 1]: ``(cos(theta) + 1) / 2``. Observation
    ``[cos(theta), sin(theta), theta_dot]``. Initial state uniform in ``[-pi, pi] x [-1, 1]``.
    Never terminates; time limit (registered task): 200 steps.

    Example:
        >>> env = ivy_gym.PendulumSmooth()
        >>> traj = ivy_gym.rollout(env, env.reset((8,), f="jax"), jnp.zeros((100, 8, 1)))
    """

    Params = PendulumSmoothParams

    def reset_bounds(self):
        high = np.array([np.pi, 1.0])
        return -high, high

    def action_bounds(self):
        return np.array([-1.0]), np.array([1.0])

    def observation_bounds(self):
        high = np.array([1.0, 1.0, np.inf])
        return -high, high

    def kernel_step(self, xp, state, action):
        p = self.params
        th, thdot = unstack_last(xp, state)
        torque = p.torque_scale * scalar_action(xp, cast_like(xp, action, state))
        thacc = 3 * p.g / (2 * p.l) * xp.sin(th) + 3.0 / (p.m * (p.l * p.l)) * torque
        thdot = thdot + p.dt * thacc
        th = th + p.dt * thdot
        cos, sin = xp.cos(th), xp.sin(th)
        state = xp.stack([th, thdot], axis=-1)
        obs = xp.stack([cos, sin, thdot], axis=-1)
        return state, obs, (cos + 1.0) * 0.5, xp.zeros_like(th) > 0

    def _draw(self, canvas, s):
        self._draw_rod(canvas, s[0], reward_color((math.cos(s[0]) + 1) / 2))
