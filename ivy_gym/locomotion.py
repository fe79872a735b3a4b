"""Gymnasium's planar MuJoCo locomotion tasks on ``ivy_robot.physics``: Hopper-v5, Walker2d-v5,
HalfCheetah-v5 and Swimmer-v5, with all their v5 constructor arguments.

Each is Gymnasium's model, its observation and its reward on :class:`ivy_gym.MuJoCoEnv` (frame
skip, resets, ``info``, rendering). The robots move in the x-z plane (Swimmer: x-y), forward is
+x, and the reward's velocity is the change of ``qpos[0]`` over the step divided by ``dt`` (of
``qpos[0:2]`` for Swimmer). Contacts with the floor, joint limits and (Swimmer's) fluid drag are
MuJoCo's, as ``ivy_robot.physics`` models them; the state is ``[qpos, qvel]`` (the models use
Newton's solver, whose result does not depend on the warm start).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ivy_gym.mujoco_env import MuJoCoEnv, control_cost, never

__all__ = [
    "HalfCheetah",
    "HalfCheetahParams",
    "Hopper",
    "HopperParams",
    "SwimmerMuJoCo",
    "SwimmerMuJoCoParams",
    "Walker2d",
    "Walker2dParams",
]

_INF = math.inf


def _flag(xp, condition, like):
    """A bool array as 0.0 / 1.0 in ``like``'s dtype."""
    return xp.astype(condition, like.dtype)


def _between(lo, x, hi):
    """``lo < x < hi`` elementwise (Gymnasium's chained comparison)."""
    return (x > lo) & (x < hi)


class _Runner(MuJoCoEnv):
    """What Hopper and Walker2d share: observation ``[qpos[1:], clip(qvel, -10, 10)]``, reward
    ``forward + healthy - control``, termination when unhealthy."""

    position_dim = 1

    @property
    def can_terminate(self) -> bool:  # type: ignore[override]
        return bool(self.params.terminate_when_unhealthy)

    def _skipped(self) -> int:
        return 1 if self.params.exclude_current_positions_from_observation else 0

    def _observation_names(self):
        return tuple(self.qpos_names()[self._skipped() :] + self.qvel_names())

    def position(self, xp, data):
        return data.qpos[..., :1]

    def observation(self, xp, data):
        qvel = xp.clip(data.qvel, -10.0, 10.0)
        return xp.concat([data.qpos[..., self._skipped() :], qvel], axis=-1)

    def healthy(self, xp, qpos, qvel):
        """Gymnasium's ``is_healthy`` of a state (bool ``(*B,)``)."""
        raise NotImplementedError

    def reward(self, xp, t):
        p, qpos = self.params, t.data.qpos
        x_velocity = t.velocity[..., 0]
        healthy = self.healthy(xp, qpos, t.data.qvel)
        forward = p.forward_reward_weight * x_velocity
        survive = p.healthy_reward * _flag(xp, healthy, x_velocity)
        ctrl = control_cost(xp, t.action, p.ctrl_cost_weight, x_velocity)
        reward = (forward + survive) - ctrl
        if p.terminate_when_unhealthy:
            terminated = xp.logical_not(healthy)
        else:
            terminated = never(xp, reward)
        info = {
            "x_position": qpos[..., 0],
            "z_distance_from_origin": qpos[..., 1] - float(self.init_qpos[1]),
            "x_velocity": x_velocity,
            "reward_forward": forward,
            "reward_ctrl": -ctrl,
            "reward_survive": survive,
        }
        return reward, terminated, info

    def reset_info(self, xp, data):
        qpos = data.qpos
        return {
            "x_position": qpos[..., 0],
            "z_distance_from_origin": qpos[..., 1] - float(self.init_qpos[1]),
        }


@dataclass(frozen=True)
class HopperParams:
    """Gymnasium's Hopper-v5 arguments (its defaults)."""

    xml_file: str = "hopper.xml"
    frame_skip: int = 4
    forward_reward_weight: float = 1.0
    ctrl_cost_weight: float = 1e-3
    healthy_reward: float = 1.0
    terminate_when_unhealthy: bool = True
    healthy_state_range: tuple = (-100.0, 100.0)
    healthy_z_range: tuple = (0.7, _INF)
    healthy_angle_range: tuple = (-0.2, 0.2)
    reset_noise_scale: float = 5e-3
    exclude_current_positions_from_observation: bool = True


class Hopper(_Runner):
    """Gymnasium's Hopper-v5, step for step: a one-legged robot hops forward.

    State ``[qpos (6), qvel (6)]``: ``rootx, rootz, rooty`` (the torso's planar position and
    angle), then the thigh, leg and foot hinges. The action (three motors' controls in [-1, 1])
    is held for ``frame_skip`` steps of the model's RK4 (``timestep`` 0.002). Observation
    ``[qpos[1:], clip(qvel, -10, 10)]`` (``qpos`` whole when
    ``exclude_current_positions_from_observation`` is False). Reward::

        forward_reward_weight * x_velocity + healthy_reward * healthy
            - ctrl_cost_weight * |action|^2

    with ``x_velocity`` the change of ``rootx`` over ``dt = 0.008``; ``healthy``: every
    component of ``[qpos[2:], qvel]`` inside ``healthy_state_range``, ``rootz`` inside
    ``healthy_z_range`` and ``rooty`` inside ``healthy_angle_range`` (open intervals).
    Terminated when unhealthy (``terminate_when_unhealthy``). Reset: ``init_qpos`` and zero
    velocity plus noise uniform in ``[-reset_noise_scale, reset_noise_scale]``. Info (as
    Gymnasium's): ``x_position, z_distance_from_origin, x_velocity, reward_forward,
    reward_ctrl, reward_survive``. Time limit (registered task): 1000 steps.

    Args:
        **params: fields of :class:`HopperParams`.

    Example:
        >>> env = ivy_gym.Hopper()
        >>> s = env.reset((16,), dtype="float64", f="torch")
        >>> s, obs, reward, terminated = env.step(s, torch.zeros(16, 3))
    """

    Params = HopperParams
    max_episode_steps = 1000
    info_types = {"reward_survive": float, "reward_ctrl": "action"}
    view_width = 4.0

    def healthy(self, xp, qpos, qvel):
        p = self.params
        state = xp.concat([qpos[..., 2:], qvel], axis=-1)
        lo, hi = p.healthy_state_range
        healthy = xp.all(_between(lo, state, hi), axis=-1)
        healthy = healthy & _between(p.healthy_z_range[0], qpos[..., 1], p.healthy_z_range[1])
        lo, hi = p.healthy_angle_range
        return healthy & _between(lo, qpos[..., 2], hi)


@dataclass(frozen=True)
class Walker2dParams:
    """Gymnasium's Walker2d-v5 arguments (its defaults)."""

    xml_file: str = "walker2d_v5.xml"
    frame_skip: int = 4
    forward_reward_weight: float = 1.0
    ctrl_cost_weight: float = 1e-3
    healthy_reward: float = 1.0
    terminate_when_unhealthy: bool = True
    healthy_z_range: tuple = (0.8, 2.0)
    healthy_angle_range: tuple = (-1.0, 1.0)
    reset_noise_scale: float = 5e-3
    exclude_current_positions_from_observation: bool = True


class Walker2d(_Runner):
    """Gymnasium's Walker2d-v5, step for step: a two-legged planar walker.

    State ``[qpos (9), qvel (9)]``: ``rootx, rootz, rooty``, then the right and the left leg's
    thigh, leg and foot hinges. The action (six motors' controls in [-1, 1]) is held for
    ``frame_skip`` steps of RK4 (``timestep`` 0.002). Observation ``[qpos[1:], clip(qvel, -10,
    10)]``. Reward ``forward_reward_weight * x_velocity + healthy_reward * healthy -
    ctrl_cost_weight * |action|^2``; healthy: ``rootz`` inside ``healthy_z_range`` and
    ``rooty`` inside ``healthy_angle_range`` (open intervals); terminated when unhealthy
    (``terminate_when_unhealthy``). Reset, info and time limit as :class:`Hopper`'s.

    Args:
        **params: fields of :class:`Walker2dParams`.

    Example:
        >>> env = ivy_gym.Walker2d()
        >>> s = env.reset((16,), dtype="float64", f="numpy")
        >>> s, obs, reward, terminated = env.step(s, np.zeros((16, 6)))
    """

    Params = Walker2dParams
    max_episode_steps = 1000
    info_types = {"reward_ctrl": "action"}
    view_width = 5.0

    def healthy(self, xp, qpos, qvel):
        p = self.params
        return _between(p.healthy_z_range[0], qpos[..., 1], p.healthy_z_range[1]) & _between(
            p.healthy_angle_range[0], qpos[..., 2], p.healthy_angle_range[1]
        )


@dataclass(frozen=True)
class HalfCheetahParams:
    """Gymnasium's HalfCheetah-v5 arguments (its defaults)."""

    xml_file: str = "half_cheetah.xml"
    frame_skip: int = 5
    forward_reward_weight: float = 1.0
    ctrl_cost_weight: float = 0.1
    reset_noise_scale: float = 0.1
    exclude_current_positions_from_observation: bool = True


class HalfCheetah(MuJoCoEnv):
    """Gymnasium's HalfCheetah-v5, step for step: a planar two-legged cat runs forward.

    State ``[qpos (9), qvel (9)]``: ``rootx, rootz, rooty``, then the back and front thigh, shin
    and foot hinges. The action (six motors' controls in [-1, 1]) is held for ``frame_skip``
    steps of the model's semi-implicit Euler (``timestep`` 0.01). Observation ``[qpos[1:],
    qvel]``. Reward ``forward_reward_weight * x_velocity - ctrl_cost_weight * |action|^2``;
    never terminates. Reset: ``qpos`` uniform in ``init_qpos +- reset_noise_scale``, ``qvel``
    normal with standard deviation ``reset_noise_scale``. Info: ``x_position, x_velocity,
    reward_forward, reward_ctrl``. Time limit (registered task): 1000 steps.

    Args:
        **params: fields of :class:`HalfCheetahParams`.

    Example:
        >>> env = ivy_gym.HalfCheetah()
        >>> s = env.reset((16,), dtype="float64", f="numpy")
        >>> s, obs, reward, terminated = env.step(s, np.zeros((16, 6)))
    """

    Params = HalfCheetahParams
    max_episode_steps = 1000
    velocity_noise = "normal"
    position_dim = 1
    info_types = {"reward_ctrl": "action"}
    view_width = 5.0

    def _skipped(self) -> int:
        return 1 if self.params.exclude_current_positions_from_observation else 0

    def _observation_names(self):
        return tuple(self.qpos_names()[self._skipped() :] + self.qvel_names())

    def position(self, xp, data):
        return data.qpos[..., :1]

    def observation(self, xp, data):
        return xp.concat([data.qpos[..., self._skipped() :], data.qvel], axis=-1)

    def reward(self, xp, t):
        p = self.params
        x_velocity = t.velocity[..., 0]
        forward = p.forward_reward_weight * x_velocity
        ctrl = control_cost(xp, t.action, p.ctrl_cost_weight, x_velocity)
        info = {
            "x_position": t.data.qpos[..., 0],
            "x_velocity": x_velocity,
            "reward_forward": forward,
            "reward_ctrl": -ctrl,
        }
        return forward - ctrl, never(xp, forward), info

    def reset_info(self, xp, data):
        return {"x_position": data.qpos[..., 0]}


@dataclass(frozen=True)
class SwimmerMuJoCoParams:
    """Gymnasium's Swimmer-v5 arguments (its defaults)."""

    xml_file: str = "swimmer.xml"
    frame_skip: int = 4
    forward_reward_weight: float = 1.0
    ctrl_cost_weight: float = 1e-4
    reset_noise_scale: float = 0.1
    exclude_current_positions_from_observation: bool = True


class SwimmerMuJoCo(MuJoCoEnv):
    """Gymnasium's Swimmer-v5, step for step: a three-link swimmer in a viscous fluid.

    (``ivy_gym.Swimmer`` is the original ivy_gym's point fish, another task.) State
    ``[qpos (5), qvel (5)]``: ``slider1, slider2, free_body_rot`` (the head's planar position
    and angle), then the two rotors. The action (two motors' controls in [-1, 1]) is held for
    ``frame_skip`` steps of RK4 (``timestep`` 0.01) with MuJoCo's fluid drag. Observation
    ``[qpos[2:], qvel]``. Reward ``forward_reward_weight * x_velocity - ctrl_cost_weight *
    |action|^2``, ``x_velocity`` the change of ``qpos[0]`` over ``dt``; never terminates.
    Reset: ``init_qpos`` and zero velocity plus noise uniform in ``[-reset_noise_scale,
    reset_noise_scale]``. Info: ``x_position, y_position, distance_from_origin, x_velocity,
    y_velocity, reward_forward, reward_ctrl``. Time limit (registered task): 1000 steps.

    Args:
        **params: fields of :class:`SwimmerMuJoCoParams`.

    Example:
        >>> env = ivy_gym.SwimmerMuJoCo()
        >>> s = env.reset((16,), dtype="float64", f="torch")
        >>> s, obs, reward, terminated = env.step(s, torch.zeros(16, 2))
    """

    Params = SwimmerMuJoCoParams
    max_episode_steps = 1000
    position_dim = 2
    info_types = {"reward_ctrl": "action"}
    camera = "top"
    view_width = 4.5

    def _skipped(self) -> int:
        return 2 if self.params.exclude_current_positions_from_observation else 0

    def _observation_names(self):
        return tuple(self.qpos_names()[self._skipped() :] + self.qvel_names())

    def position(self, xp, data):
        return data.qpos[..., :2]

    def observation(self, xp, data):
        return xp.concat([data.qpos[..., self._skipped() :], data.qvel], axis=-1)

    def reward(self, xp, t):
        p = self.params
        x_velocity, y_velocity = t.velocity[..., 0], t.velocity[..., 1]
        forward = p.forward_reward_weight * x_velocity
        ctrl = control_cost(xp, t.action, p.ctrl_cost_weight, x_velocity)
        info = {
            **self.reset_info(xp, t.data),
            "x_velocity": x_velocity,
            "y_velocity": y_velocity,
            "reward_forward": forward,
            "reward_ctrl": -ctrl,
        }
        return forward - ctrl, never(xp, forward), info

    def reset_info(self, xp, data):
        xy = data.qpos[..., :2]
        return {
            "x_position": xy[..., 0],
            "y_position": xy[..., 1],
            "distance_from_origin": xp.safe_norm(xy, axis=-1),
        }
