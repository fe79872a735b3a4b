"""Cart-pole: Gymnasium's CartPole-v1, and the original ivy_gym's swing-up task.

Both share the dynamics of a pole hinged on a cart (Barto, Sutton and Anderson, 1983, as in
Gymnasium): with ``theta`` the pole's angle from upright and ``F = force_mag * u`` the force on
the cart,

    temp        = (F + m_p * l * theta_dot**2 * sin(theta)) / (m_c + m_p)
    theta_acc   = (g * sin(theta) - cos(theta) * temp)
                  / (l * (4/3 - m_p * cos(theta)**2 / (m_c + m_p)))
    x_acc       = temp - m_p * l * theta_acc * cos(theta) / (m_c + m_p)

where ``l`` is half the pole's length. The action is continuous, ``u`` in [-1, 1] (shape
``(..., 1)``): ``u = +-1`` is Gymnasium's push right / left, and the Gymnasium facade of
CartPole-v1 takes Gymnasium's discrete actions {0, 1}.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ivy_gym.base import Env, cast_like, scalar_action, unstack_last
from ivy_gym.rendering import reward_color

__all__ = ["CartPole", "CartPoleSwingUp", "CartPoleParams"]


@dataclass(frozen=True)
class CartPoleParams:
    """Physical constants of the cart-pole (Gymnasium's values)."""

    gravity: float = 9.8
    masscart: float = 1.0
    masspole: float = 0.1
    length: float = 0.5  # half the pole's length
    force_mag: float = 10.0
    tau: float = 0.02  # seconds per step
    x_threshold: float = 2.4
    theta_threshold_radians: float = 12 * 2 * math.pi / 360


def _accelerations(xp, p, x_dot, theta, theta_dot, force):
    """Gymnasium's cart-pole accelerations, with its order of floating-point operations."""
    total_mass = p.masspole + p.masscart
    polemass_length = p.masspole * p.length
    costheta, sintheta = xp.cos(theta), xp.sin(theta)
    temp = (force + polemass_length * (theta_dot * theta_dot) * sintheta) / total_mass
    thetaacc = (p.gravity * sintheta - costheta * temp) / (
        p.length * (4.0 / 3.0 - p.masspole * (costheta * costheta) / total_mass)
    )
    xacc = temp - polemass_length * thetaacc * costheta / total_mass
    return xacc, thetaacc


class _CartPoleBase(Env):
    Params = CartPoleParams
    state_names = ("x", "x_dot", "theta", "theta_dot")
    render_fps = 50

    def action_bounds(self):
        return np.array([-1.0]), np.array([1.0])

    def _view(self, s):
        return (-2.4 * 1.5, 2.4 * 1.5, -1.6, 2.0)

    def _draw_cart(self, canvas, x, theta, color):
        p = self.params
        canvas.line((-10, 0), (10, 0), 0.02, (0, 0, 0))
        w, h = 0.5, 0.3
        canvas.polygon(
            [(x - w / 2, -h / 2), (x + w / 2, -h / 2), (x + w / 2, h / 2), (x - w / 2, h / 2)],
            (0, 0, 0),
        )
        tip = (x + 2 * float(p.length) * math.sin(theta), 2 * float(p.length) * math.cos(theta))
        canvas.line((x, 0.0), tip, 0.1, color)
        canvas.disc((x, 0.0), 0.05, (129, 132, 203))


class CartPole(_CartPoleBase):
    """Gymnasium's CartPole-v1, step for step: balance the pole; terminate when it falls.

    State ``[x, x_dot, theta, theta_dot]`` (Gymnasium's layout), observation the same.
    Integrator: explicit Euler with ``tau`` (Gymnasium's ``"euler"``), positions first from the
    old velocities. Reward 1 at every step, the terminating one included. Terminated when
    ``|x| > x_threshold`` or ``|theta| > theta_threshold_radians`` (12 degrees). Initial state
    uniform in [-0.05, 0.05]^4. Time limit (registered task): 500 steps.

    The reward is constant, so it has no gradient: optimise :class:`CartPoleSwingUp`, or a
    function of the states, through rollouts.

    Example:
        >>> env = ivy_gym.CartPole()
        >>> s = env.reset((16,), f="jax")
        >>> s, obs, reward, terminated = env.step(s, jnp.ones((16, 1)))
    """

    # Gymnasium computes in float64 and observes in float32
    gymnasium_dtype = "float64"
    gymnasium_observation_dtype = "float32"

    observation_names = state_names = _CartPoleBase.state_names
    can_terminate = True
    max_episode_steps = 500

    def reset_bounds(self):
        return np.full(4, -0.05), np.full(4, 0.05)

    def observation_bounds(self):
        p = self.params
        high = np.array([p.x_threshold * 2, np.inf, p.theta_threshold_radians * 2, np.inf])
        return -high, high

    def kernel_step(self, xp, state, action):
        p = self.params
        x, x_dot, theta, theta_dot = unstack_last(xp, state)
        force = p.force_mag * scalar_action(xp, cast_like(xp, action, state))
        xacc, thetaacc = _accelerations(xp, p, x_dot, theta, theta_dot, force)
        x = x + p.tau * x_dot
        x_dot = x_dot + p.tau * xacc
        theta = theta + p.tau * theta_dot
        theta_dot = theta_dot + p.tau * thetaacc
        state = xp.stack([x, x_dot, theta, theta_dot], axis=-1)
        # |x| > t is Gymnasium's x < -t or x > t (both False for NaN)
        terminated = (xp.abs(x) > p.x_threshold) | (xp.abs(theta) > p.theta_threshold_radians)
        return state, state, xp.ones_like(x), terminated

    def kernel_observe(self, xp, state):
        return state

    def _draw(self, canvas, s):
        self._draw_cart(canvas, s[0], s[2], (202, 152, 101))


class CartPoleSwingUp(_CartPoleBase):
    """The original ivy_gym's cart-pole: swing the pole up from anywhere and keep it centred.

    The cart-pole's dynamics and constants, integrated semi-implicitly (velocities first, then
    positions from the new velocities), with no track limits and no termination.

    Reward (of the new state), smooth and in [0, 1]: ``exp(-x**2) * (cos(theta) + 1) / 2``.
    Observation ``[x, x_dot, cos(theta), sin(theta), theta_dot]``. Initial state uniform in
    ``x in [-1, 1]``, ``x_dot in [-0.3, 0.3]``, ``theta in [-pi, pi]``,
    ``theta_dot in [-0.3, 0.3]``. Time limit (registered task): 500 steps.

    Example:
        >>> env = ivy_gym.CartPoleSwingUp()
        >>> traj = ivy_gym.rollout(env, env.reset((4,), f="torch"), torch.zeros(100, 4, 1))
    """

    observation_names = ("x", "x_dot", "cos_theta", "sin_theta", "theta_dot")
    max_episode_steps = 500

    def reset_bounds(self):
        high = np.array([1.0, 0.3, np.pi, 0.3])
        return -high, high

    def observation_bounds(self):
        high = np.array([np.inf, np.inf, 1.0, 1.0, np.inf])
        return -high, high

    def kernel_step(self, xp, state, action):
        p = self.params
        x, x_dot, theta, theta_dot = unstack_last(xp, state)
        force = p.force_mag * scalar_action(xp, cast_like(xp, action, state))
        xacc, thetaacc = _accelerations(xp, p, x_dot, theta, theta_dot, force)
        x_dot = x_dot + p.tau * xacc
        x = x + p.tau * x_dot
        theta_dot = theta_dot + p.tau * thetaacc
        theta = theta + p.tau * theta_dot
        state = xp.stack([x, x_dot, theta, theta_dot], axis=-1)
        cos, sin = xp.cos(theta), xp.sin(theta)
        reward = xp.exp(-(x * x)) * (cos + 1.0) * 0.5
        obs = xp.stack([x, x_dot, cos, sin, theta_dot], axis=-1)
        return state, obs, reward, xp.zeros_like(x) > 0

    def kernel_observe(self, xp, state):
        x, x_dot, theta, theta_dot = unstack_last(xp, state)
        return xp.stack([x, x_dot, xp.cos(theta), xp.sin(theta), theta_dot], axis=-1)

    def _draw(self, canvas, s):
        reward = math.exp(-(s[0] ** 2)) * (math.cos(s[2]) + 1) / 2
        self._draw_cart(canvas, s[0], s[2], reward_color(reward))
