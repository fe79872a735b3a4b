"""InvertedDoublePendulum: Gymnasium's InvertedDoublePendulum-v5 on ``ivy_robot.physics``, and a
swing-up variant for gradient-based optimisation.

Gymnasium's ``inverted_double_pendulum.xml`` (a cart on a slider of range [-1, 1], two unlimited
hinges, RK4 with ``timestep = 0.01``) on :class:`ivy_gym.MuJoCoEnv`: ``frame_skip = 5`` calls of
``mj_step`` per environment step, with the action held as the motor's control (clamped to its
control range [-1, 1] by the actuator, as MuJoCo clamps ``ctrl``; gear 500).

**What Gymnasium reads after the step.** Gymnasium computes the reward and the termination from
``data.site_xpos`` after ``mj_step``, and the observation's last component from
``data.qfrc_constraint``. MuJoCo's RK4 evaluates the dynamics (``mj_forward``, which also places
the sites and solves the constraints) at four stages and then advances ``qpos`` and ``qvel``
without evaluating them again, so after the step ``site_xpos`` is the tip at the last stage's
positions, ``qpos + h * (qvel + h / 2 * qacc_2)`` (``qacc_2`` the acceleration of the second
stage), not at the new ``qpos``: up to ~1e-6 m apart in a step; ``ivy_robot.physics.step``
returns the last stage's data as MuJoCo leaves it, and the task reads it there.

**The slider's limit** is MuJoCo's soft limit constraint (margin 0.01, Newton's solver):
``qfrc_constraint[0]`` is its force on the cart, zero while the cart is inside its range, and
the observation's last component is Gymnasium's ``clip(qfrc_constraint[0], -10, 10)``. The
model's geoms do not collide (``contype = 0``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

import ivy
from ivy.typing import Array, Framework
from ivy_gym.mujoco_env import MuJoCoEnv, mujoco_tree
from ivy_gym.rendering import reward_color

__all__ = [
    "InvertedDoublePendulum",
    "InvertedDoublePendulumParams",
    "inverted_double_pendulum_tree",
]

#: Length of each pole (the model's capsules from 0 to 0.6 along the body's z axis).
_POLE = 0.6


def inverted_double_pendulum_tree():
    """The :class:`ivy_robot.KinematicTree` of Gymnasium's ``inverted_double_pendulum.xml``,
    parsed once (through MuJoCo).

    Example:
        >>> tree = ivy_gym.inverted_double_pendulum_tree()
        >>> tree.nq, tree.nv, tree.nu, tree.site_names
        (3, 3, 1, ('tip',))
    """
    return mujoco_tree("inverted_double_pendulum.xml")


@dataclass(frozen=True)
class InvertedDoublePendulumParams:
    """Gymnasium's InvertedDoublePendulum-v5 arguments, and the swing-up variant's.

    ``swing_up=True``: start hanging down, smooth reward, no termination (see
    :class:`InvertedDoublePendulum`); the ``swing_up_*`` and ``slider_*`` fields shape its
    reward and are unused otherwise.
    """

    xml_file: str = "inverted_double_pendulum.xml"
    frame_skip: int = 5
    healthy_reward: float = 10.0
    reset_noise_scale: float = 0.1
    swing_up: bool = False
    swing_up_velocity_cost: float = 1e-3
    swing_up_action_cost: float = 1e-2
    slider_barrier_start: float = 0.8
    slider_barrier_weight: float = 10.0


class InvertedDoublePendulum(MuJoCoEnv):
    """Gymnasium's InvertedDoublePendulum-v5, step for step: balance two poles on a cart; with
    ``swing_up=True``, swing them up from hanging down.

    State ``[slider, hinge, hinge2, slider_vel, hinge_vel, hinge2_vel]`` (MuJoCo's ``qpos`` then
    ``qvel``; ``hinge2`` is the second pole's angle relative to the first). The action, the
    motor's control in [-1, 1] (force ``500 * action`` on the cart), is held for ``frame_skip``
    steps of the model's RK4 integrator. Observation (Gymnasium's): ``[slider, sin(hinge),
    sin(hinge2), cos(hinge), cos(hinge2), clip(qvel, -10, 10), clip(qfrc_constraint[0], -10,
    10)]``, the last the slider limit's force as MuJoCo leaves it after the step (see the
    module's docstring).

    Gymnasium's task (``swing_up=False``), with ``(x, y)`` the tip's horizontal position and
    height where MuJoCo's ``site_xpos`` leaves them after the step (the last RK4 stage, see the
    module's docstring)::

        terminated = y <= 1 or the state is not finite
        reward = healthy_reward * (not terminated) - 0.01 x**2 - (y - 2)**2
                 - 1e-3 hinge_vel**2 - 5e-3 hinge2_vel**2

    (Gymnasium does not test finiteness; MuJoCo itself resets a non-finite state with a warning,
    so that case is where ivy_gym ends the episode instead.) Info (Gymnasium's):
    ``reward_survive, distance_penalty, velocity_penalty``. Initial state: ``qpos`` uniform in
    ``[-reset_noise_scale, reset_noise_scale]`` about zero, ``qvel`` normal with standard
    deviation ``reset_noise_scale`` (:meth:`reset` with ivy's generators; :meth:`draw_initial`
    for the Gymnasium facades, draw for draw as Gymnasium's ``reset_model``). Time limit
    (registered task): 1000 steps.

    Swing-up (``swing_up=True``): the initial state hangs down, ``hinge = pi``, ``hinge2 = 0``
    (the second pole continues the first), with the same noise; it never terminates, and the
    reward of the new state is smooth::

        reward = tip_height / 1.2 - swing_up_velocity_cost * |qvel|**2
                 - swing_up_action_cost * action**2 - barrier(slider)
        barrier(x) = slider_barrier_weight * ((relu(x - b)**2 + relu(-x - b)**2) / (1 - b)**2)

    with ``b = slider_barrier_start``: ``tip_height / 1.2`` goes from -1 hanging to 1 upright,
    and the barrier (zero for ``|x| <= b``, ``slider_barrier_weight`` at the slider's range
    ``|x| = 1``, growing beyond) keeps the cart off the slider's limit, where the dynamics stay
    smooth. ``tip_height`` is the tip's height at the new ``qpos``.

    Args:
        **params: fields of :class:`InvertedDoublePendulumParams`.

    Example:
        >>> env = ivy_gym.InvertedDoublePendulum()
        >>> s = env.reset((16,), dtype="float64", f="torch")
        >>> s, obs, reward, terminated = env.step(s, torch.zeros(16, 1))
        >>> swing = ivy_gym.InvertedDoublePendulum(swing_up=True)
    """

    Params = InvertedDoublePendulumParams
    max_episode_steps = 1000
    velocity_noise = "normal"
    data_fields = ("site_xpos", "qfrc_constraint")
    reset_stage = "forward"
    info_types = {"reward_survive": float}
    view_width = 3.2

    def __init__(self, **params) -> None:
        super().__init__(**params)
        if self.model.integrator != "RK4":  # the reward's tip is read at an RK4 stage
            raise ValueError(
                "InvertedDoublePendulum follows Gymnasium's inverted_double_pendulum.xml, whose "
                f"integrator is RK4; the installed model asks for {self.model.integrator}. "
                "Install a gymnasium whose model is RK4 (Gymnasium 1.x)."
            )
        p = self.params
        if not 0.0 <= float(p.slider_barrier_start) < 1.0:
            raise ValueError(
                "InvertedDoublePendulum: slider_barrier_start must be in [0, 1) (the slider's "
                f"range is [-1, 1]), got {p.slider_barrier_start!r}."
            )

    @property
    def can_terminate(self) -> bool:  # type: ignore[override]
        """Gymnasium's task terminates; the swing-up never does."""
        return not self.params.swing_up

    def _observation_names(self):
        return (
            "slider",
            "sin_hinge",
            "sin_hinge2",
            "cos_hinge",
            "cos_hinge2",
            "slider_vel",
            "hinge_vel",
            "hinge2_vel",
            "slider_constraint_force",
        )

    def _centre(self) -> np.ndarray:
        centre = super()._centre()
        if self.params.swing_up:
            centre[1] += np.pi  # the first pole hangs down; hinge2 is relative to it
        return centre

    # ------------------------------------------------------------------------------------------
    # Kernels
    # ------------------------------------------------------------------------------------------

    def observation(self, xp, data):
        qpos = data.qpos
        angles = qpos[..., 1:]
        return xp.concat(
            [
                qpos[..., :1],
                xp.sin(angles),
                xp.cos(angles),
                xp.clip(data.qvel, -10.0, 10.0),
                xp.clip(data.qfrc_constraint[..., :1], -10.0, 10.0),
            ],
            axis=-1,
        )

    def _tip(self, xp, qpos):
        """The tip's world position (MuJoCo's ``site_xpos[0]``) at ``qpos``."""
        return self.tree.site_poses(qpos, f=xp)[..., 0, :3, 3]

    def reward(self, xp, t):
        p, data = self.params, t.data
        if p.swing_up:
            reward = self._swing_up_reward(xp, data, t.action)
            return reward, reward > np.inf, {}
        tip = data.site_xpos[..., 0, :]  # where Gymnasium reads it: the last RK4 stage
        x, y = tip[..., 0], tip[..., 2]
        state = xp.concat([data.qpos, data.qvel], axis=-1)
        finite = xp.all(xp.isfinite(state), axis=-1)
        terminated = xp.logical_or(y <= 1.0, xp.logical_not(finite))
        alive = p.healthy_reward * xp.astype(xp.logical_not(terminated), x.dtype)
        distance = 0.01 * x**2 + (y - 2.0) ** 2
        v1, v2 = data.qvel[..., 1], data.qvel[..., 2]
        velocity = 1e-3 * v1**2 + 5e-3 * v2**2
        info = {
            "reward_survive": alive,
            "distance_penalty": -distance,
            "velocity_penalty": -velocity,
        }
        return alive - distance - velocity, terminated, info

    def _swing_up_reward(self, xp, data, action):
        p = self.params
        ctrl = data.ctrl
        height = self._tip(xp, data.qpos)[..., 2] / (2 * _POLE)
        velocity = p.swing_up_velocity_cost * xp.sum(data.qvel**2, axis=-1)
        effort = p.swing_up_action_cost * ctrl[..., 0] ** 2
        return height - velocity - effort - self._barrier_root(xp, data.qpos[..., 0]) ** 2

    def _barrier_root(self, xp, x):
        """The slider barrier's square root, ``sqrt(weight) / (1 - b) * (relu(x - b) +
        relu(-x - b))``: its square is the barrier, since ``b >= 0`` keeps one side zero."""
        p = self.params
        b = float(p.slider_barrier_start)
        return (math.sqrt(p.slider_barrier_weight) / (1.0 - b)) * (xp.relu(x - b) + xp.relu(-x - b))

    def swing_up_residuals(self, trajectory, hold: int = 20, *, f: Framework = None) -> Array:
        """Least-squares residuals of a swing-up that ends held upright, for
        :func:`ivy_gym.optimise_actions_least_squares`: per initial state, over the last
        ``hold`` states of ``trajectory`` (the poles upright, still, the cart centred)

            slider, sin(phi1), 1 - cos(phi1), sin(phi2), 1 - cos(phi2), 0.2 * qvel

        with ``phi1 = hinge`` and ``phi2 = hinge + hinge2`` the poles' absolute angles from
        upright (zero at any whole turn), then, over every state, the slider barrier's square
        root ``sqrt(slider_barrier_weight) / (1 - b) * (relu(x - b) + relu(-x - b))`` (``b =
        slider_barrier_start``), so that the cart stays where the dynamics are faithful.

        Args:
            trajectory: a :class:`ivy_gym.Trajectory` of ``T >= hold`` steps, ``states``
                ``(T, *B, 6)``.
            hold: how many of the last states to hold upright.
            f: framework; by default that of the states.

        Returns:
            ``(*B, 8 * hold + T)``.

        Example:
            >>> env = ivy_gym.InvertedDoublePendulum(swing_up=True)
            >>> traj = ivy_gym.rollout(env, env.reset((2,), f="torch"), ivy.torch.zeros((10, 2, 1)))
            >>> tuple(env.swing_up_residuals(traj, hold=3).shape)  # 8 * hold + T
            (2, 34)

            They are what :func:`ivy_gym.optimise_actions_least_squares` minimises to swing
            the poles up (``docs/ivy_gym.md``).
        """
        states = trajectory.states
        xp = ivy.get_framework(states, f=f)
        steps = int(states.shape[0])
        if not 1 <= int(hold) <= steps:
            raise ValueError(
                f"swing_up_residuals: hold must be in [1, {steps}] (the trajectory's steps), "
                f"got {hold!r}."
            )
        hold, nb = int(hold), len(states.shape) - 2
        last = states[steps - hold :]
        x, hinge, hinge2 = last[..., 0], last[..., 1], last[..., 2]
        phi2 = hinge + hinge2
        upright = xp.stack(
            [x, xp.sin(hinge), 1.0 - xp.cos(hinge), xp.sin(phi2), 1.0 - xp.cos(phi2)], axis=-1
        )
        upright = xp.concat([upright, 0.2 * last[..., 3:]], axis=-1)  # (hold, *B, 8)
        barrier = self._barrier_root(xp, states[..., 0])  # (T, *B)
        batch_first = (*range(1, nb + 1), 0)
        upright = xp.permute_dims(upright, (*range(1, nb + 1), 0, nb + 1))
        upright = xp.reshape(upright, (*states.shape[1:-1], 8 * hold))
        return xp.concat([upright, xp.permute_dims(barrier, batch_first)], axis=-1)

    # ------------------------------------------------------------------------------------------
    # Rendering
    # ------------------------------------------------------------------------------------------

    def _view(self, s):
        return (-1.6, 1.6, -1.4, 1.4)

    def _draw(self, canvas, s):
        x, a1, a2 = float(s[0]), float(s[1]), float(s[2])
        elbow = (x + _POLE * math.sin(a1), _POLE * math.cos(a1))
        tip = (elbow[0] + _POLE * math.sin(a1 + a2), elbow[1] + _POLE * math.cos(a1 + a2))
        canvas.line((-1.0, 0.0), (1.0, 0.0), 0.04, (77, 77, 179))
        color = reward_color((tip[1] / (2 * _POLE) + 1) / 2)
        canvas.line((x, 0.0), elbow, 0.09, (0, 179, 179))
        canvas.line(elbow, tip, 0.09, color)
        canvas.disc((x, 0.0), 0.1, (179, 179, 0))
