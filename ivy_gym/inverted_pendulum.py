"""InvertedPendulum: Gymnasium's InvertedPendulum-v5 on the kinematic tree of its own MJCF model.

The dynamics are :class:`ivy_robot.KinematicTree`'s (``step``: MuJoCo's integrator as the model
asks, RK4 with ``timestep = 0.02``), run ``frame_skip = 2`` times per environment step as
Gymnasium does, with the action held as the motor's control (clamped to its control range by the
actuator, as MuJoCo clamps ``ctrl``). Joint limits and contacts are out of the tree's scope: the
cart's slider has range [-1, 1], and a state that reaches it (``tree.constraint_free`` is False)
is where MuJoCo would add a limit force that these dynamics leave out. The pole's hinge range
(+-90 degrees) lies far beyond the termination angle (0.2 rad), and the model's geoms do not
collide.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from ivy_gym.base import Env, cast_like

__all__ = ["InvertedPendulum", "InvertedPendulumParams", "inverted_pendulum_tree"]


def _gymnasium_asset(name: str) -> str:
    import importlib.util
    import os

    spec = importlib.util.find_spec("gymnasium")
    if spec is None or spec.origin is None:
        raise ImportError(
            f"ivy_gym's MuJoCo tasks read Gymnasium's model {name!r}: install gymnasium "
            "(pip install 'ivy[gym]')."
        )
    return os.path.join(os.path.dirname(spec.origin), "envs", "mujoco", "assets", name)


@functools.cache
def inverted_pendulum_tree():
    """The :class:`ivy_robot.KinematicTree` of Gymnasium's ``inverted_pendulum.xml``, parsed
    once (through MuJoCo).

    Example:
        >>> tree = ivy_gym.inverted_pendulum_tree()
        >>> tree.nq, tree.nv, tree.nu
        (2, 2, 1)
    """
    from ivy_robot import KinematicTree

    return KinematicTree.from_mjcf(_gymnasium_asset("inverted_pendulum.xml"))


@dataclass(frozen=True)
class InvertedPendulumParams:
    """Gymnasium's InvertedPendulum-v5 arguments."""

    frame_skip: int = 2
    reset_noise_scale: float = 0.01


class InvertedPendulum(Env):
    """Gymnasium's InvertedPendulum-v5, step for step: balance a pole on a cart.

    State ``[slider, hinge, slider_vel, hinge_vel]`` (MuJoCo's ``qpos`` then ``qvel``), which is
    also the observation. The action (the motor's control, in [-3, 3]) is held for
    ``frame_skip`` steps of the model's integrator. Reward 1 while not terminated; terminated
    when the state is not finite or ``|hinge| > 0.2``. Initial state: the model's ``qpos0``
    and zero velocity plus noise uniform in ``[-reset_noise_scale, reset_noise_scale]``.
    Time limit (registered task): 1000 steps. Faithful while ``tree.constraint_free`` holds
    (the cart within its slider's range), see the module's docstring.

    Args:
        **params: fields of :class:`InvertedPendulumParams`.

    Example:
        >>> env = ivy_gym.InvertedPendulum()
        >>> s = env.reset((16,), dtype="float64", f="torch")
        >>> s, obs, reward, terminated = env.step(s, torch.zeros(16, 1))
    """

    Params = InvertedPendulumParams
    state_names = ("slider", "hinge", "slider_vel", "hinge_vel")
    observation_names = state_names
    can_terminate = True
    max_episode_steps = 1000
    render_fps = 25

    def __init__(self, **params) -> None:
        self.tree = inverted_pendulum_tree()
        super().__init__(**params)
        if int(self.params.frame_skip) < 1:
            raise ValueError(
                f"InvertedPendulum: frame_skip must be an integer >= 1, got "
                f"{self.params.frame_skip!r}."
            )

    def reset_bounds(self):
        tree, noise = self.tree, float(self.params.reset_noise_scale)
        qpos0 = np.asarray(tree.qpos0, dtype=np.float64).reshape(tree.nq)
        centre = np.concatenate([qpos0, np.zeros(tree.nv)])
        return centre - noise, centre + noise

    def action_bounds(self):
        return np.array([-3.0]), np.array([3.0])

    def kernel_observe(self, xp, state):
        return state

    def kernel_step(self, xp, state, action):
        tree = self.tree
        nq = tree.nq
        qpos, qvel = state[..., :nq], state[..., nq:]
        ctrl = cast_like(xp, action, state)
        for _ in range(int(self.params.frame_skip)):
            qpos, qvel = tree.step(qpos, qvel, ctrl, f=xp)
        state = xp.concat([qpos, qvel], axis=-1)
        finite = xp.all(xp.isfinite(state), axis=-1)
        upright = xp.abs(qpos[..., 1]) <= 0.2
        terminated = xp.logical_not(xp.logical_and(finite, upright))
        reward = cast_like(xp, xp.logical_not(terminated), state)
        return state, state, reward, terminated

    def _view(self, s):
        return (-1.5, 1.5, -0.6, 1.2)

    def _draw(self, canvas, s):
        x, theta = float(s[0]), float(s[1])
        tip = (x + 0.6 * np.sin(theta), 0.6 * np.cos(theta))
        canvas.line((-1.0, 0.0), (1.0, 0.0), 0.04, (77, 77, 179))
        canvas.line((x, 0.0), tip, 0.1, (0, 179, 179))
        canvas.disc((x, 0.0), 0.1, (179, 179, 0))
