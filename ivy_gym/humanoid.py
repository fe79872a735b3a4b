"""Gymnasium's Humanoid-v5 on ``ivy_robot.physics``, with all its v5 constructor arguments.

**What MuJoCo keeps between steps.** The model's solver is PGS, which stops at a tolerance, so
its result depends on where it starts: MuJoCo's warm start, the ``qacc`` of the previous step.
Gymnasium's forward reward is the change over ``do_simulation`` of the centre of mass computed
from ``data.xipos``, read before the step from what the previous step left (RK4's last stage,
not the state's own positions) and after it likewise. The state therefore carries both:
``[qpos (24), qvel (23), qacc_warmstart (23), com_x, com_y]``; the reset gives a cold warm start
and the centre of mass at ``qpos`` (``mj_resetData``, then ``mj_forward``), and
:meth:`~ivy_gym.MuJoCoEnv.kernel_set_state` keeps the warm start as Gymnasium's ``set_state``.

**Tendons in the info.** Gymnasium's ``info`` holds ``ten_length`` and ``ten_velocity`` of the
model's two fixed tendons after the step: MuJoCo computes them at RK4's last stage, whose joint
positions and velocities the step does not return. Each tendon joint of this model is limited,
so its last-stage position and velocity are read back from its limit row (``efc_pos = side *
(bound - q)``, ``efc_vel = J qvel``), exactly; a tendon on an unlimited joint would be computed
at the new state instead.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from ivy_gym.mujoco_env import MuJoCoEnv, _mujoco_extras

__all__ = ["Humanoid", "HumanoidParams"]


@dataclass(frozen=True)
class HumanoidParams:
    """Gymnasium's Humanoid-v5 arguments (its defaults)."""

    xml_file: str = "humanoid.xml"
    frame_skip: int = 5
    forward_reward_weight: float = 1.25
    ctrl_cost_weight: float = 0.1
    contact_cost_weight: float = 5e-7
    contact_cost_range: tuple = (-math.inf, 10.0)
    healthy_reward: float = 5.0
    terminate_when_unhealthy: bool = True
    healthy_z_range: tuple = (1.0, 2.0)
    reset_noise_scale: float = 1e-2
    exclude_current_positions_from_observation: bool = True
    include_cinert_in_observation: bool = True
    include_cvel_in_observation: bool = True
    include_qfrc_actuator_in_observation: bool = True
    include_cfrc_ext_in_observation: bool = True


class Humanoid(MuJoCoEnv):
    """Gymnasium's Humanoid-v5, step for step: a 3-D humanoid walks forward.

    State ``[qpos (24), qvel (23), qacc_warmstart (23), com_x, com_y]`` (see the module's
    docstring). The action (17 motors' controls in [-0.4, 0.4]) is held for ``frame_skip``
    steps of RK4 (``timestep`` 0.003, PGS). Observation, by default: ``[qpos[2:], qvel,
    cinert[1:], cvel[1:], qfrc_actuator[6:], cfrc_ext[1:]]``, the body inertias, velocities,
    actuator forces and external forces as MuJoCo leaves them after the step (after a reset:
    ``mj_forward``'s, with zero controls and zero ``cfrc_ext``). Reward::

        forward_reward_weight * x_velocity + healthy_reward * healthy
            - ctrl_cost_weight * |ctrl|^2 - clip(contact_cost_weight * |cfrc_ext|^2,
                                                 *contact_cost_range)

    ``x_velocity`` the change of the centre of mass over ``dt``; healthy: ``qpos[2]`` inside
    ``healthy_z_range`` (open); terminated when unhealthy (``terminate_when_unhealthy``). Reset:
    ``init_qpos`` and zero velocity plus noise uniform in ``[-reset_noise_scale,
    reset_noise_scale]``. Info: ``x_position, y_position, tendon_length, tendon_velocity,
    distance_from_origin, x_velocity, y_velocity, reward_survive, reward_forward, reward_ctrl,
    reward_contact``. Time limit (registered task): 1000 steps.

    Args:
        **params: fields of :class:`HumanoidParams`.

    Example:
        >>> env = ivy_gym.Humanoid()
        >>> s = env.reset((4,), dtype="float64", f="numpy")
        >>> s, obs, reward, terminated = env.step(s, np.zeros((4, 17)))
    """

    Params = HumanoidParams
    max_episode_steps = 1000
    position_dim = 2
    position_stale = True
    carries_warmstart = True
    data_fields = ("xipos", "cinert", "cvel", "qfrc_actuator", "cfrc_ext", "efc_pos", "efc_vel")
    camera = "side"
    view_width = 3.0

    @property
    def can_terminate(self) -> bool:  # type: ignore[override]
        return bool(self.params.terminate_when_unhealthy)

    @property
    def reset_stage(self) -> str:  # type: ignore[override]
        """``mj_forward`` where the observation reads inertias, velocities or actuator forces."""
        p = self.params
        reads = (
            p.include_cinert_in_observation
            or p.include_cvel_in_observation
            or p.include_qfrc_actuator_in_observation
        )
        return "forward" if reads else "state"

    def _skipped(self) -> int:
        return 2 if self.params.exclude_current_positions_from_observation else 0

    def _observation_names(self):
        p, bodies = self.params, self.model.body_names[1:]
        names = self.qpos_names()[self._skipped() :] + self.qvel_names()
        if p.include_cinert_in_observation:
            names += [f"cinert_{b}_{k}" for b in bodies for k in range(10)]
        if p.include_cvel_in_observation:
            names += [f"cvel_{b}_{k}" for b in bodies for k in range(6)]
        if p.include_qfrc_actuator_in_observation:
            names += [f"qfrc_actuator_{n}" for n in self.qvel_names()[6:]]
        if p.include_cfrc_ext_in_observation:
            names += [f"cfrc_ext_{b}_{k}" for b in bodies for k in range(6)]
        return tuple(names)

    def position(self, xp, data):
        """The centre of mass' x-y from ``xipos`` (Gymnasium's ``mass_center``)."""
        mass = np.asarray(self.model.body_mass, np.float64)
        xy = data.xipos[..., :2]
        weights = xp.constant(mass / mass.sum(), dtype=xy.dtype, device=xp.dev(xy))
        return xp.sum(weights[:, None] * xy, axis=-2)

    def observation(self, xp, data):
        p = self.params
        parts = [data.qpos[..., self._skipped() :], data.qvel]

        def bodies(x):
            x = x[..., 1:, :]
            return xp.reshape(x, (*x.shape[:-2], x.shape[-2] * x.shape[-1]))

        if p.include_cinert_in_observation:
            parts.append(bodies(data.cinert))
        if p.include_cvel_in_observation:
            parts.append(bodies(data.cvel))
        if p.include_qfrc_actuator_in_observation:
            parts.append(data.qfrc_actuator[..., 6:])
        if p.include_cfrc_ext_in_observation:
            parts.append(bodies(data.cfrc_ext))
        return xp.concat(parts, axis=-1)

    def reward(self, xp, t):
        p, data = self.params, t.data
        z = data.qpos[..., 2]
        healthy = (z > p.healthy_z_range[0]) & (z < p.healthy_z_range[1])
        x_velocity, y_velocity = t.velocity[..., 0], t.velocity[..., 1]
        forward = p.forward_reward_weight * x_velocity
        survive = p.healthy_reward * xp.astype(healthy, z.dtype)
        ctrl = p.ctrl_cost_weight * xp.sum(data.ctrl * data.ctrl, axis=-1)
        forces = data.cfrc_ext
        contact = p.contact_cost_weight * xp.sum(forces * forces, axis=(-2, -1))
        lo, hi = p.contact_cost_range
        contact = xp.minimum(xp.maximum(contact, float(lo)), float(hi))
        reward = (forward + survive) - (ctrl + contact)
        terminated = xp.logical_not(healthy) if p.terminate_when_unhealthy else z > np.inf
        length, velocity = self._last_stage_tendons(xp, data)
        xy = data.qpos[..., :2]
        info = {
            "x_position": xy[..., 0],
            "y_position": xy[..., 1],
            "tendon_length": length,
            "tendon_velocity": velocity,
            "distance_from_origin": xp.safe_norm(xy, axis=-1),
            "x_velocity": x_velocity,
            "y_velocity": y_velocity,
            "reward_survive": survive,
            "reward_forward": forward,
            "reward_ctrl": -ctrl,
            "reward_contact": -contact,
        }
        return reward, terminated, info

    def reset_info(self, xp, data):
        xy = data.qpos[..., :2]
        length, velocity = self._tendons(xp, data.qpos, data.qvel)
        return {
            "x_position": xy[..., 0],
            "y_position": xy[..., 1],
            "tendon_length": length,
            "tendon_velocity": velocity,
            "distance_from_origin": xp.safe_norm(xy, axis=-1),
        }

    # ------------------------------------------------------------------------------------------
    # Tendons
    # ------------------------------------------------------------------------------------------

    def _tendons(self, xp, qpos, qvel):
        """The fixed tendons' lengths and velocities at ``(qpos, qvel)``."""
        extras = _mujoco_extras(self.params.xml_file)
        like = qpos
        length_map = xp.constant(extras["tendon_qpos"].T, dtype=like.dtype, device=xp.dev(like))
        velocity_map = xp.constant(extras["tendon_dof"].T, dtype=like.dtype, device=xp.dev(like))
        return xp.matmul(qpos, length_map), xp.matmul(qvel, velocity_map)

    def _last_stage_tendons(self, xp, data):
        """The tendons at the last frame's last evaluation (see the module's docstring)."""
        maps = _tendon_rows(self.params.xml_file)
        if maps is None:
            return self._tendons(xp, data.qpos, data.qvel)
        rows, offset = maps
        like = data.efc_pos
        rows = xp.constant(rows, dtype=like.dtype, device=xp.dev(like))
        offset = xp.constant(offset, dtype=like.dtype, device=xp.dev(like))
        return xp.matmul(data.efc_pos, rows) + offset, xp.matmul(data.efc_vel, rows)


@functools.cache
def _tendon_rows(xml_file: str):
    """``(rows [nefc, ntendon], offset [ntendon])`` with ``ten_length = efc_pos @ rows +
    offset`` and ``ten_velocity = efc_vel @ rows`` from each tendon joint's lower limit row, or
    None if a tendon is not fixed or has an unlimited joint."""
    from ivy_gym.mujoco_env import mujoco_tree

    extras = _mujoco_extras(xml_file)
    model = mujoco_tree(xml_file).physics
    layout = model.rows
    if not extras["tendons_fixed"]:
        return None
    ntendon = extras["tendon_qpos"].shape[0]
    rows, offset = np.zeros((layout.nefc, ntendon)), np.zeros(ntendon)
    for t, joints in enumerate(extras["tendon_joints"]):
        for j in set(joints):
            dof, qadr = int(model.jnt_dofadr[j]), int(model.jnt_qposadr[j])
            found = np.flatnonzero(np.asarray(layout.limit_dof) == dof)
            if not found.size:
                return None
            k = int(found[0])
            side, bound = float(layout.limit_side[k]), float(layout.limit_bound[k])
            coef = extras["tendon_qpos"][t, qadr]
            # efc_pos = side (bound - q): q = bound - side efc_pos; efc_vel = -side qvel
            rows[layout.nf + k, t] += -side * coef
            offset[t] += coef * bound
    return rows, offset
