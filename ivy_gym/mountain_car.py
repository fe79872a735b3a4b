"""Mountain car: Gymnasium's MountainCar-v0 and MountainCarContinuous-v0, and the original
ivy_gym's shaped task.

A car on the track of height ``sin(3 x)`` must climb to the flag at ``x = 0.45``; its engine
is too weak to drive straight up, so it must swing back and forth.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ivy_gym.base import Env, cast_like, scalar_action, unstack_last
from ivy_gym.rendering import reward_color

__all__ = [
    "MountainCar",
    "MountainCarContinuous",
    "MountainCarShaped",
    "MountainCarParams",
    "MountainCarDiscreteParams",
    "MountainCarShapedParams",
]


@dataclass(frozen=True)
class MountainCarParams:
    """Gymnasium's MountainCarContinuous-v0 constants."""

    min_action: float = -1.0
    max_action: float = 1.0
    min_position: float = -1.2
    max_position: float = 0.6
    max_speed: float = 0.07
    goal_position: float = 0.45
    goal_velocity: float = 0.0
    power: float = 0.0015


@dataclass(frozen=True)
class MountainCarDiscreteParams:
    """Gymnasium's MountainCar-v0 constants."""

    min_position: float = -1.2
    max_position: float = 0.6
    max_speed: float = 0.07
    goal_position: float = 0.5
    goal_velocity: float = 0.0
    force: float = 0.001
    gravity: float = 0.0025


@dataclass(frozen=True)
class MountainCarShapedParams:
    """The original ivy_gym mountain car's constants."""

    g: float = 9.8
    dt: float = 0.02
    torque_scale: float = 3.0
    goal_position: float = 0.45


def _height(x):
    return np.sin(3 * x) * 0.45 + 0.55


class _MountainCarBase(Env):
    state_names = ("position", "velocity")
    observation_names = ("position", "velocity")

    def action_bounds(self):
        return np.array([-1.0]), np.array([1.0])

    def kernel_observe(self, xp, state):
        return state

    def _view(self, s):
        return (-1.2, 0.6, -0.2, 1.6)

    def _draw_scene(self, canvas, position, goal, color):
        xs = np.linspace(-1.2, 0.6, 100)
        canvas.polyline(np.stack([xs, _height(xs)], -1), 0.01, (0, 0, 0))
        base = np.array([position, _height(position)])
        angle = math.atan(3 * 0.45 * math.cos(3 * position))
        along = np.array([math.cos(angle), math.sin(angle)])
        up = np.array([-along[1], along[0]])
        w, h, clearance = 0.12, 0.06, 0.03
        corners = [
            base + up * clearance + along * sx * w / 2 + up * sy * h
            for sx, sy in [(-1, 0), (1, 0), (1, 1), (-1, 1)]
        ]
        canvas.polygon(corners, color)
        for sx in (-1, 1):
            canvas.disc(base + up * clearance + along * sx * w / 4, 0.02, (128, 128, 128))
        flag = np.array([goal, _height(goal)])
        canvas.line(flag, flag + (0, 0.15), 0.006, (0, 0, 0))
        canvas.polygon([flag + (0, 0.15), flag + (0, 0.12), flag + (0.07, 0.135)], (204, 204, 0))


class MountainCar(_MountainCarBase):
    """Gymnasium's MountainCar-v0, step for step (in float64, as Gymnasium computes it).

    State ``[position, velocity]``, observation the same. The action ``u``, ``(..., 1)`` in
    [-1, 1], pushes with ``u * force``; the Gymnasium facade takes Gymnasium's discrete
    actions {0, 1, 2} (``u = action - 1``: left, none, right):

        velocity += u * force + cos(3 * position) * (-gravity)
        velocity  = clip(velocity, -max_speed, max_speed)
        position += velocity;  position = clip(position, min_position, max_position)
        velocity  = 0 if position == min_position and velocity < 0   (the wall)

    Terminated when ``position >= goal_position`` and ``velocity >= goal_velocity``; reward -1
    at every step, the terminating one included (so it has no gradient). Initial state:
    position uniform in [-0.6, -0.4], velocity 0. Time limit (registered task): 200 steps.

    Example:
        >>> env = ivy_gym.MountainCar()
        >>> s = env.reset((32,), f="torch")
        >>> s, obs, reward, terminated = env.step(s, torch.ones(32, 1))
    """

    Params = MountainCarDiscreteParams
    # Gymnasium computes in float64 and observes in float32
    gymnasium_dtype = "float64"
    gymnasium_observation_dtype = "float32"
    can_terminate = True
    max_episode_steps = 200
    #: The core actions of Gymnasium's discrete actions {0, 1, 2}.
    discrete_actions = ((-1.0,), (0.0,), (1.0,))

    def reset_bounds(self):
        return np.array([-0.6, 0.0]), np.array([-0.4, 0.0])

    def observation_bounds(self):
        p = self.params
        return np.array([p.min_position, -p.max_speed]), np.array([p.max_position, p.max_speed])

    def kernel_step(self, xp, state, action):
        p = self.params
        position, velocity = unstack_last(xp, state)
        push = scalar_action(xp, cast_like(xp, action, state))
        velocity = velocity + (push * p.force + xp.cos(3 * position) * (-p.gravity))
        velocity = xp.clip(velocity, -p.max_speed, p.max_speed)
        position = xp.clip(position + velocity, p.min_position, p.max_position)
        at_wall = xp.logical_and(position == p.min_position, velocity < 0)
        velocity = xp.where(at_wall, xp.zeros_like(velocity), velocity)
        terminated = xp.logical_and(position >= p.goal_position, velocity >= p.goal_velocity)
        state = xp.stack([position, velocity], axis=-1)
        return state, state, -xp.ones_like(position), terminated

    def _draw(self, canvas, s):
        self._draw_scene(canvas, s[0], self.params.goal_position, (0, 0, 0))


class MountainCarContinuous(_MountainCarBase):
    """Gymnasium's MountainCarContinuous-v0, step for step.

    State ``[position, velocity]`` (Gymnasium's layout), observation the same. With the force
    ``clip(action, min_action, max_action)``:

        velocity += force * power - 0.0025 * cos(3 * position)
        velocity  = clip(velocity, -max_speed, max_speed)
        position += velocity;  position = clip(position, min_position, max_position)
        velocity  = 0 if position == min_position and velocity < 0   (the wall)

    Terminated when ``position >= goal_position`` and ``velocity >= goal_velocity``. Reward:
    100 at termination, minus ``0.1 * action**2`` (of the action as given). Initial state:
    position uniform in [-0.6, -0.4], velocity 0. Time limit (registered task): 999 steps.

    Gymnasium draws its initial state in float64 and stores the state in float32 after every
    step; numpy 2's scalar types then decide the precision of each operation, from the state's
    and the action's dtypes (float32 for its action space's samples). With
    ``float32_state=True`` (the default) a float64 core rounds at the same places, so that it
    follows Gymnasium exactly for float32 and float64 actions (see ``_gymnasium_step``; a
    float32 core computes in float32 throughout).
    ``smooth=True`` drops the speed clip, the position clip and the wall (the track continues),
    so that the dynamics are smooth; set ``float32_state=False`` too for exact float64
    gradients.

    Args:
        smooth: drop the clips and the wall.
        float32_state: round the state to float32 after each step, as Gymnasium does.
        **params: fields of :class:`MountainCarParams`.

    Example:
        >>> env = ivy_gym.MountainCarContinuous()
        >>> s = env.reset((32,), f="tensorflow")
        >>> s, obs, reward, terminated = env.step(s, tf.ones((32, 1)))
    """

    Params = MountainCarParams
    # Gymnasium computes in float64 (rounding its state to float32 after every step, as the
    # core does), observes and acts in float32
    gymnasium_dtype = "float64"
    gymnasium_observation_dtype = "float32"
    gymnasium_action_dtype = "float32"
    can_terminate = True
    max_episode_steps = 999

    def __init__(self, *, smooth: bool = False, float32_state: bool = True, **params) -> None:
        self.smooth = bool(smooth)
        self.float32_state = bool(float32_state)
        super().__init__(**params)

    def __repr__(self) -> str:
        return (
            f"MountainCarContinuous(smooth={self.smooth}, float32_state={self.float32_state}, "
            f"{self.params})"
        )

    def reset_bounds(self):
        return np.array([-0.6, 0.0]), np.array([-0.4, 0.0])

    def action_bounds(self):
        return np.array([self.params.min_action]), np.array([self.params.max_action])

    def observation_bounds(self):
        p = self.params
        if self.smooth:
            return np.full(2, -np.inf), np.full(2, np.inf)
        return np.array([p.min_position, -p.max_speed]), np.array([p.max_position, p.max_speed])

    def _round(self, xp, x):
        """``x`` rounded to float32, in ``x``'s dtype."""
        return xp.astype(xp.astype(x, "float32"), x.dtype)

    def kernel_step(self, xp, state, action):
        p = self.params
        position, velocity = unstack_last(xp, state)
        a = scalar_action(xp, action)
        if self.float32_state and state.dtype != xp.float32:
            return self._gymnasium_step(xp, p, position, velocity, a)
        a = cast_like(xp, a, position)
        force = xp.clip(a, p.min_action, p.max_action)
        velocity = velocity + (force * p.power - 0.0025 * xp.cos(3 * position))
        if not self.smooth:
            velocity = xp.clip(velocity, -p.max_speed, p.max_speed)
        state, reward, terminated = self._finish(xp, p, position + velocity, velocity, a)
        return state, state, reward, terminated

    def _gymnasium_step(self, xp, p, position, velocity, a):
        """The step as Gymnasium computes it with numpy 2's scalar types, on a float64 core.

        Gymnasium's state is float64 after ``reset`` and float32 after every step; a state
        whose position is a float32 number is taken as float32 (a float64 draw is one with
        probability 2**-29). Python floats (a clipped action or speed, the cosine's term) take
        the dtype of the array they meet; float32 meets float64 in float64. So the velocity
        update rounds to float32 on a float32 state when the action is float32 or clipped, and
        the position update when the velocity was rounded or clipped; the stored state is
        rounded to float32 (at every step, as Gymnasium stores it).
        """
        r = self._round
        typed32 = r(xp, position) == position  # Gymnasium's state is float32 (after a step)
        action32 = a.dtype == xp.float32  # Gymnasium's action space samples float32
        a = cast_like(xp, a, position)  # exact
        clipped_action = xp.logical_or(a < p.min_action, a > p.max_action)
        force = xp.clip(a, p.min_action, p.max_action)  # a clipped action: a Python float
        cos_term = 0.0025 * xp.cos(xp.where(typed32, r(xp, 3 * position), 3 * position))
        increment = force * p.power - cos_term  # float64: a float64 or a clipped action
        if action32:  # a float32 action: float32 * power - cos_term, all in float32
            power32 = float(np.float32(p.power))
            in_float32 = r(xp, r(xp, a * power32) - r(xp, cos_term))
            increment = xp.where(clipped_action, increment, in_float32)
            rounded_velocity = typed32
        else:
            rounded_velocity = xp.logical_and(typed32, clipped_action)
        velocity = xp.where(
            rounded_velocity, r(xp, velocity + r(xp, increment)), velocity + increment
        )
        rounded_position = rounded_velocity
        if not self.smooth:
            clipped_speed = xp.logical_or(velocity > p.max_speed, velocity < -p.max_speed)
            velocity = xp.clip(velocity, -p.max_speed, p.max_speed)
            rounded_position = xp.logical_or(
                rounded_velocity, xp.logical_and(typed32, clipped_speed)
            )
        position = xp.where(
            rounded_position, r(xp, position + r(xp, velocity)), position + velocity
        )
        state, reward, terminated = self._finish(xp, p, position, velocity, a)
        return state, state, reward, terminated

    def _finish(self, xp, p, position, velocity, a):
        """The position clip, the wall, termination, reward and the stored state."""
        if not self.smooth:
            position = xp.clip(position, p.min_position, p.max_position)
            at_wall = xp.logical_and(position == p.min_position, velocity < 0)
            velocity = xp.where(at_wall, xp.zeros_like(velocity), velocity)
        terminated = xp.logical_and(position >= p.goal_position, velocity >= p.goal_velocity)
        reward = xp.where(terminated, xp.full_like(a, 100.0), xp.zeros_like(a)) - (a * a) * 0.1
        state = xp.stack([position, velocity], axis=-1)
        if self.float32_state and state.dtype != xp.float32:
            state = self._round(xp, state)
        return state, reward, terminated

    def _draw(self, canvas, s):
        self._draw_scene(canvas, s[0], self.params.goal_position, (0, 0, 0))


class MountainCarShaped(_MountainCarBase):
    """The original ivy_gym's mountain car: a smooth reward for nearing the flag.

    ``acc = torque_scale * action - g * cos(3 x)``, semi-implicit Euler with ``dt`` (velocity
    first), no speed limit and no walls; the action in [-1, 1] is not clipped by the core.
    Reward, of the new state, smooth and in [0, 1]: ``exp(-5 (x - goal_position)**2)``.
    Initial state: ``x`` uniform in [-0.9, -0.2], velocity 0. Never terminates; time limit
    (registered task): 500 steps.

    Example:
        >>> env = ivy_gym.MountainCarShaped()
        >>> traj = ivy_gym.rollout(env, env.reset((8,), f="torch"), torch.zeros(100, 8, 1))
    """

    Params = MountainCarShapedParams
    max_episode_steps = 500

    def reset_bounds(self):
        return np.array([-0.9, 0.0]), np.array([-0.2, 0.0])

    def kernel_step(self, xp, state, action):
        p = self.params
        x, v = unstack_last(xp, state)
        acc = p.torque_scale * scalar_action(xp, cast_like(xp, action, state)) - p.g * xp.cos(3 * x)
        v = v + p.dt * acc
        x = x + p.dt * v
        d = x - p.goal_position
        state = xp.stack([x, v], axis=-1)
        return state, state, xp.exp(-5.0 * (d * d)), xp.zeros_like(x) > 0

    def _draw(self, canvas, s):
        reward = math.exp(-5 * (s[0] - self.params.goal_position) ** 2)
        self._draw_scene(canvas, s[0], self.params.goal_position, reward_color(reward))
