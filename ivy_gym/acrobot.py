"""Acrobot: Gymnasium's Acrobot-v1, step for step.

Two links hang from a fixed joint; only the joint between them is driven. Swing the free end
above the bar at height one link's length above the fixed joint (Sutton and Barto, 1998).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ivy_gym.base import Env, cast_like, scalar_action, unstack_last

__all__ = ["Acrobot", "AcrobotParams"]


@dataclass(frozen=True)
class AcrobotParams:
    """Gymnasium's Acrobot-v1 constants (``book_or_nips``: ``"book"`` or ``"nips"``)."""

    dt: float = 0.2
    link_length_1: float = 1.0
    link_mass_1: float = 1.0
    link_mass_2: float = 1.0
    link_com_pos_1: float = 0.5
    link_com_pos_2: float = 0.5
    link_moi: float = 1.0
    max_vel_1: float = 4 * math.pi
    max_vel_2: float = 9 * math.pi
    gravity: float = 9.8
    book_or_nips: str = "book"


def _wrap(xp, x, low, high, times=3):
    """Gymnasium's ``wrap``: subtract (add) ``high - low`` while above ``high`` (below ``low``),
    one subtraction at a time as it does (``times`` of them reach every reachable state)."""
    diff = high - low
    for _ in range(times):
        x = xp.where(x > high, x - diff, x)
    for _ in range(times):
        x = xp.where(x < low, x + diff, x)
    return x


class Acrobot(Env):
    """Gymnasium's Acrobot-v1, step for step.

    State ``[theta1, theta2, dtheta1, dtheta2]`` (Gymnasium's layout: ``theta1`` of the first
    link from hanging down, ``theta2`` of the second relative to the first). Observation
    ``[cos theta1, sin theta1, cos theta2, sin theta2, dtheta1, dtheta2]``. The action is the
    torque on the middle joint, ``(..., 1)`` in [-1, 1]; the Gymnasium facade takes
    Gymnasium's discrete actions {0, 1, 2} (torques -1, 0, +1). Gymnasium's
    ``torque_noise_max`` (0 in Acrobot-v1) is noise on this torque: add it to the action.

    One step: one fourth-order Runge-Kutta step of ``dt`` with the torque held (Gymnasium's
    ``rk4`` and ``_dsdt``, with its order of floating-point operations; ``book_or_nips``
    picks the book's or the NIPS paper's dynamics), then the angles wrapped into [-pi, pi]
    and the speeds clipped to ``max_vel_1`` and ``max_vel_2``. Terminated when
    ``-cos(theta1) - cos(theta1 + theta2) > 1``; reward -1, and 0 at termination. Initial
    state: uniform in [-0.1, 0.1]^4, rounded to float32 numbers (as Gymnasium stores it).
    Time limit (registered task): 500 steps.

    Example:
        >>> env = ivy_gym.Acrobot()
        >>> s = env.reset((16,), f="jax")
        >>> s, obs, reward, terminated = env.step(s, jnp.ones((16, 1)))
    """

    Params = AcrobotParams
    # Gymnasium computes in float64 and observes in float32
    gymnasium_dtype = "float64"
    gymnasium_observation_dtype = "float32"
    state_names = ("theta1", "theta2", "dtheta1", "dtheta2")
    observation_names = ("cos_theta1", "sin_theta1", "cos_theta2", "sin_theta2")
    observation_names += ("dtheta1", "dtheta2")
    can_terminate = True
    max_episode_steps = 500
    render_fps = 15
    #: The core actions of Gymnasium's discrete actions {0, 1, 2}.
    discrete_actions = ((-1.0,), (0.0,), (1.0,))

    def __init__(self, **params) -> None:
        super().__init__(**params)
        if self.params.book_or_nips not in ("book", "nips"):
            raise ValueError(
                f"Acrobot: book_or_nips must be 'book' or 'nips', got {self.params.book_or_nips!r}."
            )

    def reset_bounds(self):
        return np.full(4, -0.1), np.full(4, 0.1)

    def action_bounds(self):
        return np.array([-1.0]), np.array([1.0])

    def observation_bounds(self):
        p = self.params
        high = np.array([1.0, 1.0, 1.0, 1.0, p.max_vel_1, p.max_vel_2])
        return -high, high

    def kernel_initial(self, xp, state):
        return xp.astype(xp.astype(state, "float32"), state.dtype)

    def _derivatives(self, xp, theta1, theta2, dtheta1, dtheta2, torque):
        """Gymnasium's ``_dsdt``, with its order of floating-point operations."""
        p = self.params
        m1, m2, l1 = p.link_mass_1, p.link_mass_2, p.link_length_1
        lc1, lc2, i1, i2, g = p.link_com_pos_1, p.link_com_pos_2, p.link_moi, p.link_moi, p.gravity
        cos2, sin2 = xp.cos(theta2), xp.sin(theta2)
        d1 = m1 * lc1**2 + m2 * (l1**2 + lc2**2 + 2 * l1 * lc2 * cos2) + i1 + i2
        d2 = m2 * (lc2**2 + l1 * lc2 * cos2) + i2
        phi2 = m2 * lc2 * g * xp.cos(theta1 + theta2 - math.pi / 2.0)
        phi1 = (
            -m2 * l1 * lc2 * (dtheta2 * dtheta2) * sin2
            - 2 * m2 * l1 * lc2 * dtheta2 * dtheta1 * sin2
            + (m1 * lc1 + m2 * l1) * g * xp.cos(theta1 - math.pi / 2)
            + phi2
        )
        inertia = m2 * lc2**2 + i2 - (d2 * d2) / d1
        if p.book_or_nips == "nips":
            ddtheta2 = (torque + d2 / d1 * phi1 - phi2) / inertia
        else:
            coriolis = m2 * l1 * lc2 * (dtheta1 * dtheta1) * sin2
            ddtheta2 = (torque + d2 / d1 * phi1 - coriolis - phi2) / inertia
        ddtheta1 = -(d2 * ddtheta2 + phi1) / d1
        return dtheta1, dtheta2, ddtheta1, ddtheta2

    def kernel_step(self, xp, state, action):
        p = self.params
        torque = scalar_action(xp, cast_like(xp, action, state))
        y = unstack_last(xp, state)
        dt = p.dt - 0.0
        dt2 = dt / 2.0

        def moved(k, h):
            return [yi + h * ki for yi, ki in zip(y, k)]

        k1 = self._derivatives(xp, *y, torque)
        k2 = self._derivatives(xp, *moved(k1, dt2), torque)
        k3 = self._derivatives(xp, *moved(k2, dt2), torque)
        k4 = self._derivatives(xp, *moved(k3, dt), torque)
        theta1, theta2, dtheta1, dtheta2 = [
            yi + dt / 6.0 * (a + 2 * b + 2 * c + d) for yi, a, b, c, d in zip(y, k1, k2, k3, k4)
        ]
        theta1 = _wrap(xp, theta1, -math.pi, math.pi)
        theta2 = _wrap(xp, theta2, -math.pi, math.pi)
        dtheta1 = xp.clip(dtheta1, -p.max_vel_1, p.max_vel_1)
        dtheta2 = xp.clip(dtheta2, -p.max_vel_2, p.max_vel_2)
        state = xp.stack([theta1, theta2, dtheta1, dtheta2], axis=-1)
        terminated = -xp.cos(theta1) - xp.cos(theta2 + theta1) > 1.0
        reward = xp.where(terminated, xp.zeros_like(theta1), -xp.ones_like(theta1))
        return state, self._observe(xp, theta1, theta2, dtheta1, dtheta2), reward, terminated

    def _observe(self, xp, theta1, theta2, dtheta1, dtheta2):
        return xp.stack(
            [xp.cos(theta1), xp.sin(theta1), xp.cos(theta2), xp.sin(theta2), dtheta1, dtheta2],
            axis=-1,
        )

    def kernel_observe(self, xp, state):
        return self._observe(xp, *unstack_last(xp, state))

    def _view(self, s):
        return (-2.2, 2.2, -2.2, 2.2)

    def _draw(self, canvas, s):
        theta1, theta2 = s[0], s[1]
        length = self.params.link_length_1
        canvas.line((-2.2, length), (2.2, length), 0.02, (0, 0, 0))
        elbow = (length * math.sin(theta1), -length * math.cos(theta1))
        tip = (
            elbow[0] + length * math.sin(theta1 + theta2),
            elbow[1] - length * math.cos(theta1 + theta2),
        )
        canvas.line((0.0, 0.0), elbow, 0.1, (0, 204, 204))
        canvas.line(elbow, tip, 0.1, (0, 204, 204))
        canvas.disc((0.0, 0.0), 0.08, (204, 204, 0))
        canvas.disc(elbow, 0.08, (204, 204, 0))
