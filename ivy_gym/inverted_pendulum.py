"""InvertedPendulum: Gymnasium's InvertedPendulum-v5 on ``ivy_robot.physics``.

Gymnasium's ``inverted_pendulum.xml`` (a cart on a slider of range [-1, 1], a pole on a hinge of
range +-90 degrees, RK4 with ``timestep = 0.02``) on :class:`ivy_gym.MuJoCoEnv`: ``frame_skip =
2`` calls of ``mj_step`` per environment step, with the action held as the motor's control
(clamped to its control range by the actuator, as MuJoCo clamps ``ctrl``). The slider's limit is
MuJoCo's soft limit constraint (Newton's solver), so a cart driven into the end of its rail stops
there as in Gymnasium; the model's geoms do not collide.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ivy_gym.mujoco_env import MuJoCoEnv, gymnasium_asset, mujoco_tree

__all__ = ["InvertedPendulum", "InvertedPendulumParams", "inverted_pendulum_tree"]

#: The earlier name of :func:`ivy_gym.gymnasium_asset`.
_gymnasium_asset = gymnasium_asset


def inverted_pendulum_tree():
    """The :class:`ivy_robot.KinematicTree` of Gymnasium's ``inverted_pendulum.xml``, parsed
    once (through MuJoCo).

    Example:
        >>> tree = ivy_gym.inverted_pendulum_tree()
        >>> tree.nq, tree.nv, tree.nu
        (2, 2, 1)
    """
    return mujoco_tree("inverted_pendulum.xml")


@dataclass(frozen=True)
class InvertedPendulumParams:
    """Gymnasium's InvertedPendulum-v5 arguments."""

    xml_file: str = "inverted_pendulum.xml"
    frame_skip: int = 2
    reset_noise_scale: float = 0.01


class InvertedPendulum(MuJoCoEnv):
    """Gymnasium's InvertedPendulum-v5, step for step: balance a pole on a cart.

    State ``[slider, hinge, slider_vel, hinge_vel]`` (MuJoCo's ``qpos`` then ``qvel``), which is
    also the observation. The action (the motor's control, in [-3, 3]) is held for
    ``frame_skip`` steps of the model's integrator. Reward 1 while not terminated (an ``int``
    in the Gymnasium facades, as Gymnasium's); terminated when the state is not finite or
    ``|hinge| > 0.2``. Info: ``reward_survive``, the reward. Initial state: the model's
    ``qpos0`` and zero velocity plus noise uniform in ``[-reset_noise_scale,
    reset_noise_scale]``. Time limit (registered task): 1000 steps.

    Args:
        **params: fields of :class:`InvertedPendulumParams`.

    Example:
        >>> env = ivy_gym.InvertedPendulum()
        >>> s = env.reset((16,), dtype="float64", f="torch")
        >>> s, obs, reward, terminated = env.step(s, torch.zeros(16, 1))
    """

    Params = InvertedPendulumParams
    can_terminate = True
    max_episode_steps = 1000
    reward_type = int
    info_types = {"reward_survive": int}
    view_width = 3.0

    def _observation_names(self):
        return ("slider", "hinge", "slider_vel", "hinge_vel")

    def observation(self, xp, data):
        return xp.concat([data.qpos, data.qvel], axis=-1)

    def reward(self, xp, t):
        obs = self.observation(xp, t.data)
        finite = xp.all(xp.isfinite(obs), axis=-1)
        upright = xp.abs(obs[..., 1]) <= 0.2
        terminated = xp.logical_not(xp.logical_and(finite, upright))
        reward = xp.astype(xp.logical_not(terminated), obs.dtype)
        return reward, terminated, {"reward_survive": reward}

    def _view(self, s):
        return (-1.5, 1.5, -0.6, 1.2)

    def _draw(self, canvas, s):
        x, theta = float(s[0]), float(s[1])
        tip = (x + 0.6 * np.sin(theta), 0.6 * np.cos(theta))
        canvas.line((-1.0, 0.0), (1.0, 0.0), 0.04, (77, 77, 179))
        canvas.line((x, 0.0), tip, 0.1, (0, 179, 179))
        canvas.disc((x, 0.0), 0.1, (179, 179, 0))
