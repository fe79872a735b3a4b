"""InvertedDoublePendulum: Gymnasium's InvertedDoublePendulum-v5 on the kinematic tree of its own
MJCF model, and a swing-up variant for gradient-based optimisation.

The dynamics are :class:`ivy_robot.KinematicTree`'s: the model's integrator (RK4, ``timestep =
0.01``) run ``frame_skip = 5`` times per environment step as Gymnasium does, with the action held
as the motor's control (clamped to its control range [-1, 1] by the actuator, as MuJoCo clamps
``ctrl``; gear 500).

**The tip that Gymnasium reads.** Gymnasium computes the reward and the termination from
``data.site_xpos`` after ``mj_step``. MuJoCo's RK4 evaluates the dynamics (``mj_forward``, which
also places the sites) at four stages and then advances ``qpos`` and ``qvel`` without evaluating
them again, so after the step ``site_xpos`` is the tip at the last stage's positions,
``qpos + h * (qvel + h / 2 * qacc_2)`` (``qacc_2`` the acceleration of the second stage), not at
the new ``qpos``: up to ~1e-6 m apart in a step. The integrator's step is therefore written out
here (:func:`rk4_step_with_last_stage`: MuJoCo's tableau, the same arithmetic as ``tree.step``
for these hinge and slide joints, its four stages one ``xp.scan`` and the ``frame_skip`` steps
another, so that compilers trace the dynamics once) and the last stage's positions come out of
the step at no extra cost; the stale tip is a function of the state before the step
and the action, so nothing beyond ``[qpos, qvel]`` is carried in the state.

**Scope.** Joint limits and contacts are out of the tree's scope. The poles' hinges are unlimited
and the geoms do not collide (``contype = 0``), so the only constraint MuJoCo can add is the
cart's slider limit (range [-1, 1], margin 0.01): ``qfrc_constraint`` is zero while it is inactive,
and the observation's last component, Gymnasium's clipped ``qfrc_constraint[0]``, is that zero.
A state where the limit is active (``tree.constraint_free(qpos)`` is False) is where MuJoCo adds a
limit force that these dynamics leave out and the trajectories part.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

import ivy
from ivy.typing import Array, Dtype, Framework, Shape
from ivy_gym.base import Env, _shape, cast_like
from ivy_gym.inverted_pendulum import _gymnasium_asset
from ivy_gym.rendering import reward_color

__all__ = [
    "InvertedDoublePendulum",
    "InvertedDoublePendulumParams",
    "inverted_double_pendulum_tree",
    "rk4_step_with_last_stage",
]

#: Length of each pole (the model's capsules from 0 to 0.6 along the body's z axis).
_POLE = 0.6


@functools.cache
def inverted_double_pendulum_tree():
    """The :class:`ivy_robot.KinematicTree` of Gymnasium's ``inverted_double_pendulum.xml``,
    parsed once (through MuJoCo).

    Example:
        >>> tree = ivy_gym.inverted_double_pendulum_tree()
        >>> tree.nq, tree.nv, tree.nu, tree.site_names
        (3, 3, 1, ('tip',))
    """
    from ivy_robot import KinematicTree

    return KinematicTree.from_mjcf(_gymnasium_asset("inverted_double_pendulum.xml"))


def rk4_step_with_last_stage(xp, tree, qpos: Array, qvel: Array, ctrl: Array) -> tuple:
    """One RK4 step of a tree of hinge and slide joints, as MuJoCo's ``mj_RungeKutta`` takes it,
    returning also the positions of its last stage (where MuJoCo's ``site_xpos`` and the other
    position-dependent quantities of ``mjData`` stand after ``mj_step``).

    Stages at ``0, h/2, h/2, h`` (each from the previous stage's velocity and acceleration),
    weights ``1/6, 1/3, 1/3, 1/6``: four calls of ``tree.forward_dynamics``, the same as
    ``tree.step``, whose result this equals (positions integrate as ``q + h v`` for hinges and
    slides; ball and free joints would need ``tree.step``'s group integration).

    Args:
        xp: the backend namespace.
        tree: the :class:`ivy_robot.KinematicTree` (RK4, hinge and slide joints only).
        qpos, qvel: *[batch_shape, nq]* and *[batch_shape, nv]*, of one batch shape (the
            stages are one ``xp.scan``, whose carry keeps its shape).
        ctrl: *[batch_shape, nu]* in their dtype (broadcasting against the batch).

    Returns:
        ``(qpos, qvel, stage_qpos)`` after one ``tree.timestep``.
    """
    tree_h = tree.timestep
    dtype, device = qpos.dtype, xp.dev(qpos)
    # stage k starts a fraction c_k of the step from the start along the previous stage's
    # velocity and acceleration; the step averages the stages with weights w_k
    fractions = xp.constant(np.array([0.0, 0.5, 0.5, 1.0]), dtype=dtype, device=device)
    weights = xp.constant(np.array([1.0, 2.0, 2.0, 1.0]) / 6.0, dtype=dtype, device=device)

    def stage(carry, x):
        velocity, acceleration, mean_vel, mean_acc, _ = carry
        fraction, weight = x
        q = qpos + (tree_h * fraction) * velocity
        v = qvel + (tree_h * fraction) * acceleration
        a = tree.forward_dynamics(q, v, ctrl, f=xp)
        return (v, a, mean_vel + weight * v, mean_acc + weight * a, q), None

    zero = qvel * 0.0
    # one loop of the four stages: compilers trace the dynamics once, not four times
    carry = (zero, zero, zero, zero, qpos)
    (_, _, mean_vel, mean_acc, last), _ = xp.scan(stage, carry, (fractions, weights))
    return qpos + tree_h * mean_vel, qvel + tree_h * mean_acc, last


@dataclass(frozen=True)
class InvertedDoublePendulumParams:
    """Gymnasium's InvertedDoublePendulum-v5 arguments, and the swing-up variant's.

    ``swing_up=True``: start hanging down, smooth reward, no termination (see
    :class:`InvertedDoublePendulum`); the ``swing_up_*`` and ``slider_*`` fields shape its
    reward and are unused otherwise.
    """

    frame_skip: int = 5
    healthy_reward: float = 10.0
    reset_noise_scale: float = 0.1
    swing_up: bool = False
    swing_up_velocity_cost: float = 1e-3
    swing_up_action_cost: float = 1e-2
    slider_barrier_start: float = 0.8
    slider_barrier_weight: float = 10.0


class InvertedDoublePendulum(Env):
    """Gymnasium's InvertedDoublePendulum-v5, step for step: balance two poles on a cart; with
    ``swing_up=True``, swing them up from hanging down.

    State ``[slider, hinge, hinge2, slider_vel, hinge_vel, hinge2_vel]`` (MuJoCo's ``qpos`` then
    ``qvel``; ``hinge2`` is the second pole's angle relative to the first). The action, the
    motor's control in [-1, 1] (force ``500 * action`` on the cart), is held for ``frame_skip``
    steps of the model's RK4 integrator. Observation (Gymnasium's): ``[slider, sin(hinge),
    sin(hinge2), cos(hinge), cos(hinge2), clip(qvel, -10, 10), 0]``, the last being Gymnasium's
    clipped slider constraint force, zero in the tree's scope (see the module's docstring).

    Gymnasium's task (``swing_up=False``), with ``(x, y)`` the tip's horizontal position and
    height where MuJoCo's ``site_xpos`` leaves them after the step (the last RK4 stage, see the
    module's docstring):

        terminated = y <= 1 or the state is not finite
        reward = healthy_reward * (not terminated) - 0.01 x**2 - (y - 2)**2
                 - 1e-3 hinge_vel**2 - 5e-3 hinge2_vel**2

    (Gymnasium does not test finiteness; MuJoCo itself resets a non-finite state with a warning,
    so that case is where ivy_gym ends the episode instead.) Initial state: ``qpos`` uniform in
    ``[-reset_noise_scale, reset_noise_scale]`` about zero, ``qvel`` normal with standard
    deviation ``reset_noise_scale`` (:meth:`reset` with ivy's generators; :meth:`draw_initial`
    for the Gymnasium facades, draw for draw as Gymnasium's ``reset_model``). Time limit
    (registered task): 1000 steps. Faithful while ``tree.constraint_free`` holds.

    Swing-up (``swing_up=True``): the initial state hangs down, ``hinge = pi``, ``hinge2 = 0``
    (the second pole continues the first), with the same noise; it never terminates, and the
    reward of the new state is smooth:

        reward = tip_height / 1.2 - swing_up_velocity_cost * |qvel|**2
                 - swing_up_action_cost * action**2 - barrier(slider)
        barrier(x) = slider_barrier_weight * ((relu(x - b)**2 + relu(-x - b)**2) / (1 - b)**2)

    with ``b = slider_barrier_start``: ``tip_height / 1.2`` goes from -1 hanging to 1 upright,
    and the barrier (zero for ``|x| <= b``, ``slider_barrier_weight`` at the slider's range
    ``|x| = 1``, growing beyond) keeps the cart where the dynamics are faithful, since the
    slider's limit is not modelled. ``tip_height`` is the tip's height at the new ``qpos``.

    Args:
        **params: fields of :class:`InvertedDoublePendulumParams`.

    Example:
        >>> env = ivy_gym.InvertedDoublePendulum()
        >>> s = env.reset((16,), dtype="float64", f="torch")
        >>> s, obs, reward, terminated = env.step(s, torch.zeros(16, 1))
        >>> swing = ivy_gym.InvertedDoublePendulum(swing_up=True)
    """

    Params = InvertedDoublePendulumParams
    state_names = ("slider", "hinge", "hinge2", "slider_vel", "hinge_vel", "hinge2_vel")
    observation_names = (
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
    max_episode_steps = 1000
    render_fps = 20

    def __init__(self, **params) -> None:
        self.tree = inverted_double_pendulum_tree()
        super().__init__(**params)
        if self.tree.integrator != "RK4":  # the reward's tip is read at an RK4 stage
            raise ValueError(
                "InvertedDoublePendulum follows Gymnasium's inverted_double_pendulum.xml, whose "
                f"integrator is RK4; the installed model asks for {self.tree.integrator}. "
                "Install a gymnasium whose model is RK4 (Gymnasium 1.x)."
            )
        p = self.params
        if int(p.frame_skip) < 1:
            raise ValueError(
                f"InvertedDoublePendulum: frame_skip must be an integer >= 1, got {p.frame_skip!r}."
            )
        if not 0.0 <= float(p.slider_barrier_start) < 1.0:
            raise ValueError(
                "InvertedDoublePendulum: slider_barrier_start must be in [0, 1) (the slider's "
                f"range is [-1, 1]), got {p.slider_barrier_start!r}."
            )

    @property
    def can_terminate(self) -> bool:  # type: ignore[override]
        """Gymnasium's task terminates; the swing-up never does."""
        return not self.params.swing_up

    # ------------------------------------------------------------------------------------------
    # Spaces and resets
    # ------------------------------------------------------------------------------------------

    def _centre(self) -> np.ndarray:
        tree = self.tree
        qpos = np.asarray(tree.qpos0, dtype=np.float64).reshape(tree.nq).copy()
        if self.params.swing_up:
            qpos[1] += np.pi  # the first pole hangs down; hinge2 is relative to it
        return np.concatenate([qpos, np.zeros(tree.nv)])

    def reset_bounds(self):
        """``qpos``: the box the initial positions are uniform in; ``qvel``: the normal
        draws' mean plus and minus one standard deviation (the velocities are normal, not
        uniform; see :meth:`reset`)."""
        centre, noise = self._centre(), float(self.params.reset_noise_scale)
        return centre - noise, centre + noise

    def action_bounds(self):
        return np.array([-1.0]), np.array([1.0])

    def reset(
        self,
        batch_shape: Shape | int = (),
        *,
        dtype: Dtype = "float32",
        device: str | None = None,
        f: Framework = None,
    ) -> Array:
        """A batch of initial states drawn with ivy's random functions, distributed as
        Gymnasium's: ``qpos`` uniform in its box, ``qvel`` normal about the centre with
        standard deviation ``reset_noise_scale`` (both scaled by :meth:`Env.narrowed`).

        Example:
            >>> ivy.seed(0)
            >>> ivy_gym.InvertedDoublePendulum().reset((64,), f="jax").shape
            (64, 6)
        """
        xp = ivy.get_framework(f=f)
        batch = _shape(batch_shape)
        nq, nv = self.tree.nq, self.tree.nv
        low, high = self.initial_bounds()
        half = (high - low) / 2

        def constant(values):
            return xp.constant(values, dtype=dtype, device=device)

        u = xp.random_uniform(shape=(*batch, nq), dtype=dtype, device=device)
        qpos = constant(low[:nq]) + constant(high[:nq] - low[:nq]) * u
        n = xp.random_normal(shape=(*batch, nv), dtype=dtype, device=device)
        qvel = constant(low[nq:] + half[nq:]) + constant(half[nq:]) * n
        return self.kernel_initial(xp, xp.concat([qpos, qvel], axis=-1))

    def draw_initial(self, rng: np.random.Generator, batch_shape: Shape | int = ()) -> np.ndarray:
        """Gymnasium's ``reset_model``, state by state: ``init_qpos + uniform(-s, s, nq)``,
        then ``init_qvel + standard_normal(nv) * s`` (``s = reset_noise_scale``, scaled by
        :meth:`Env.narrowed`; the swing-up's ``init_qpos`` hangs down)."""
        batch = _shape(batch_shape)
        low, high = self.initial_bounds()
        centre = (low + high) / 2
        noise = float(self.params.reset_noise_scale) * self.reset_scale
        nq, nv = self.tree.nq, self.tree.nv
        states = np.empty((*batch, self.state_dim))
        for index in np.ndindex(batch):
            qpos = centre[:nq] + rng.uniform(low=-noise, high=noise, size=nq)
            qvel = centre[nq:] + rng.standard_normal(nv) * noise
            states[index] = np.concatenate([qpos, qvel])
        return states

    # ------------------------------------------------------------------------------------------
    # Kernels
    # ------------------------------------------------------------------------------------------

    def kernel_observe(self, xp, state):
        nq = self.tree.nq
        qpos, qvel = state[..., :nq], state[..., nq:]
        angles = qpos[..., 1:]
        return xp.concat(
            [
                qpos[..., :1],
                xp.sin(angles),
                xp.cos(angles),
                xp.clip(qvel, -10.0, 10.0),
                xp.zeros_like(qpos[..., :1]),  # qfrc_constraint: no constraint in the scope
            ],
            axis=-1,
        )

    def _tip(self, xp, qpos):
        """The tip's world position (MuJoCo's ``site_xpos[0]``) at ``qpos``."""
        return self.tree.site_poses(qpos, f=xp)[..., 0, :3, 3]

    def kernel_step(self, xp, state, action):
        tree, p = self.tree, self.params
        nq = tree.nq
        ctrl = cast_like(xp, action, state)
        batch = np.broadcast_shapes(tuple(state.shape[:-1]), tuple(ctrl.shape[:-1]))
        if tuple(state.shape[:-1]) != batch:  # the loops' carries keep one shape
            state = xp.broadcast_to(state, (*batch, self.state_dim))
        qpos, qvel = state[..., :nq], state[..., nq:]

        def frame(carry, _):
            return rk4_step_with_last_stage(xp, tree, carry[0], carry[1], ctrl), None

        # the frames as one loop (compilers trace one RK4 step, not frame_skip of them)
        (qpos, qvel, stage), _ = xp.scan(frame, (qpos, qvel, qpos), None, length=int(p.frame_skip))
        state = xp.concat([qpos, qvel], axis=-1)
        if p.swing_up:
            never = xp.zeros_like(qpos[..., 0]) > 0.0
            return (
                state,
                self.kernel_observe(xp, state),
                self._swing_up_reward(xp, state, ctrl),
                never,
            )
        tip = self._tip(xp, stage)  # where Gymnasium reads it: the last RK4 stage
        x, y = tip[..., 0], tip[..., 2]
        finite = xp.all(xp.isfinite(state), axis=-1)
        terminated = xp.logical_or(y <= 1.0, xp.logical_not(finite))
        alive = p.healthy_reward * cast_like(xp, xp.logical_not(terminated), state)
        distance = 0.01 * x**2 + (y - 2.0) ** 2
        velocity = 1e-3 * qvel[..., 1] ** 2 + 5e-3 * qvel[..., 2] ** 2
        reward = alive - distance - velocity
        return state, self.kernel_observe(xp, state), reward, terminated

    def _swing_up_reward(self, xp, state, ctrl):
        p, nq = self.params, self.tree.nq
        height = self._tip(xp, state[..., :nq])[..., 2] / (2 * _POLE)
        qvel = state[..., nq:]
        velocity = p.swing_up_velocity_cost * xp.sum(qvel**2, axis=-1)
        effort = p.swing_up_action_cost * ctrl[..., 0] ** 2
        return height - velocity - effort - self._barrier_root(xp, state[..., 0]) ** 2

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
            >>> r = ivy_gym.optimise_actions_least_squares(
            ...     env, 40, 60, lambda traj: env.swing_up_residuals(traj, hold=1),
            ...     batch_shape=(32,), f="jax")  # reach upright: the first of two stages
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
