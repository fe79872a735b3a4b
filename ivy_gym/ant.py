"""Gymnasium's Ant-v5 on ``ivy_robot.physics``, with all its v5 constructor arguments.

**The torso position that Gymnasium reads.** Ant-v5's forward reward is the change of
``data.body(main_body).xpos[:2]`` over ``do_simulation``, divided by ``dt``. MuJoCo's RK4
computes the body positions at each of its four stages and advances ``qpos`` after the last one
without computing them again, so after ``mj_step`` ``xpos`` is the torso at the last stage's
positions, not at the new ``qpos`` (up to ~1e-4 m apart); Gymnasium reads it after the step
(``xy_position_after``) and, at the next step, again before it (``xy_position_before``: what the
previous step left, or the reset's ``mj_forward``). The state therefore carries the torso's x-y
position as the last step left it: ``[qpos (15), qvel (14), torso_x, torso_y]``; the reset and
:meth:`~ivy_gym.MuJoCoEnv.kernel_set_state` put it at ``qpos`` (``mj_forward``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ivy_gym.mujoco_env import MuJoCoEnv, control_cost

__all__ = ["Ant", "AntParams"]


@dataclass(frozen=True)
class AntParams:
    """Gymnasium's Ant-v5 arguments (its defaults)."""

    xml_file: str = "ant.xml"
    frame_skip: int = 5
    forward_reward_weight: float = 1.0
    ctrl_cost_weight: float = 0.5
    contact_cost_weight: float = 5e-4
    healthy_reward: float = 1.0
    main_body: int | str = 1
    terminate_when_unhealthy: bool = True
    healthy_z_range: tuple = (0.2, 1.0)
    contact_force_range: tuple = (-1.0, 1.0)
    reset_noise_scale: float = 0.1
    exclude_current_positions_from_observation: bool = True
    include_cfrc_ext_in_observation: bool = True


class Ant(MuJoCoEnv):
    """Gymnasium's Ant-v5, step for step: a four-legged robot walks forward.

    State ``[qpos (15), qvel (14), torso_x, torso_y]``: the torso's free joint (position,
    quaternion ``[w, x, y, z]``; linear and angular velocity), the eight leg hinges, and the
    ``main_body``'s x-y position where the last step left MuJoCo's ``xpos`` (see the module's
    docstring). The action (eight motors' controls in [-1, 1]) is held for ``frame_skip`` steps
    of RK4 (``timestep`` 0.01). Observation ``[qpos[2:], qvel, clip(cfrc_ext[1:],
    *contact_force_range)]`` (the external forces on the 13 bodies, as ``mj_rnePostConstraint``
    gives them after the step; zero after a reset, as Gymnasium's). Reward::

        forward_reward_weight * x_velocity + healthy_reward * healthy
            - ctrl_cost_weight * |action|^2 - contact_cost_weight * |clip(cfrc_ext)|^2

    healthy: the state finite and the torso height ``qpos[2]`` in ``healthy_z_range`` (closed);
    terminated when unhealthy (``terminate_when_unhealthy``). Reset: ``qpos`` uniform in
    ``init_qpos +- reset_noise_scale``, ``qvel`` normal with standard deviation
    ``reset_noise_scale``. Info: ``x_position, y_position, distance_from_origin, x_velocity,
    y_velocity, reward_forward, reward_ctrl, reward_contact, reward_survive``. Time limit
    (registered task): 1000 steps.

    Args:
        **params: fields of :class:`AntParams`.

    Example:
        >>> env = ivy_gym.Ant()
        >>> s = env.reset((16,), dtype="float64", f="torch")
        >>> s, obs, reward, terminated = env.step(s, torch.zeros(16, 8))
    """

    Params = AntParams
    max_episode_steps = 1000
    velocity_noise = "normal"
    position_dim = 2
    position_stale = True
    data_fields = ("xpos", "cfrc_ext")
    info_types = {"reward_ctrl": "action"}
    camera = "top"
    view_width = 6.0

    @property
    def can_terminate(self) -> bool:  # type: ignore[override]
        return bool(self.params.terminate_when_unhealthy)

    def _skipped(self) -> int:
        return 2 if self.params.exclude_current_positions_from_observation else 0

    def _observation_names(self):
        names = self.qpos_names()[self._skipped() :] + self.qvel_names()
        if self.params.include_cfrc_ext_in_observation:
            bodies = self.model.body_names[1:]
            names += [f"cfrc_ext_{b}_{k}" for b in bodies for k in range(6)]
        return tuple(names)

    def position(self, xp, data):
        return data.xpos[..., self.tree.body_id(self.params.main_body), :2]

    def _contact_forces(self, xp, data):
        lo, hi = self.params.contact_force_range
        return xp.clip(data.cfrc_ext, float(lo), float(hi))

    def observation(self, xp, data):
        parts = [data.qpos[..., self._skipped() :], data.qvel]
        if self.params.include_cfrc_ext_in_observation:
            forces = self._contact_forces(xp, data)[..., 1:, :]
            shape = (*forces.shape[:-2], (self.model.nbody - 1) * 6)
            parts.append(xp.reshape(forces, shape))
        return xp.concat(parts, axis=-1)

    def reward(self, xp, t):
        p, data = self.params, t.data
        state = xp.concat([data.qpos, data.qvel], axis=-1)
        z = data.qpos[..., 2]
        lo, hi = p.healthy_z_range
        healthy = xp.all(xp.isfinite(state), axis=-1) & (z >= lo) & (z <= hi)
        x_velocity, y_velocity = t.velocity[..., 0], t.velocity[..., 1]
        forward = x_velocity * p.forward_reward_weight
        survive = p.healthy_reward * xp.astype(healthy, z.dtype)
        ctrl = control_cost(xp, t.action, p.ctrl_cost_weight, z)
        forces = self._contact_forces(xp, data)
        contact = p.contact_cost_weight * xp.sum(forces * forces, axis=(-2, -1))
        reward = (forward + survive) - (ctrl + contact)
        terminated = xp.logical_not(healthy) if p.terminate_when_unhealthy else z > np.inf
        info = {
            **self.reset_info(xp, data),
            "x_velocity": x_velocity,
            "y_velocity": y_velocity,
            "reward_forward": forward,
            "reward_ctrl": -ctrl,
            "reward_contact": -contact,
            "reward_survive": survive,
        }
        return reward, terminated, info

    def reset_info(self, xp, data):
        xy = data.qpos[..., :2]
        return {
            "x_position": xy[..., 0],
            "y_position": xy[..., 1],
            "distance_from_origin": xp.safe_norm(xy, axis=-1),
        }
