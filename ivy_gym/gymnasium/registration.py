"""Gymnasium ids of the ivy_gym tasks, registered on ``import ivy_gym.gymnasium`` (and on
``import ivy_gym`` when gymnasium is already imported).

``gymnasium.make("ivy_gym/Pendulum-v1", framework="torch", dtype="float64", device="gpu:0")``
builds a :class:`~ivy_gym.gymnasium.GymnasiumEnv`; ``gymnasium.make("ivy_gym:ivy_gym/Pendulum-v1")``
imports ivy_gym first, so it works with nothing imported by hand. ``gymnasium.make_vec(id,
num_envs=N, vectorization_mode="vector_entry_point", framework=...)`` builds a native
:class:`~ivy_gym.gymnasium.GymnasiumVectorEnv`. Further keyword arguments go to the core
(physical parameters, ``smooth=True``, ``num_joints=3``...).
"""

from __future__ import annotations

from typing import Any

import gymnasium

from ivy.typing import Dtype, Framework
from ivy_gym.acrobot import Acrobot
from ivy_gym.ant import Ant
from ivy_gym.cartpole import CartPole, CartPoleSwingUp
from ivy_gym.gymnasium.facades import GymnasiumEnv, GymnasiumVectorEnv
from ivy_gym.humanoid import Humanoid
from ivy_gym.inverted_double_pendulum import InvertedDoublePendulum
from ivy_gym.inverted_pendulum import InvertedPendulum
from ivy_gym.locomotion import HalfCheetah, Hopper, SwimmerMuJoCo, Walker2d
from ivy_gym.mountain_car import MountainCar, MountainCarContinuous, MountainCarShaped
from ivy_gym.pendulum import Pendulum, PendulumSmooth
from ivy_gym.reacher import Reacher
from ivy_gym.reacher_mujoco import ReacherMuJoCo
from ivy_gym.swimmer import Swimmer

__all__ = ["TASKS", "make_env", "make_vector_env", "register_envs"]

#: Gymnasium id (without the ``ivy_gym/`` namespace) -> (core class, discrete actions,
#: reward threshold).
TASKS: dict[str, tuple[type, bool, float | None]] = {
    "CartPole-v1": (CartPole, True, 475.0),
    "CartPoleSwingUp-v0": (CartPoleSwingUp, False, None),
    "Pendulum-v1": (Pendulum, False, None),
    "PendulumSmooth-v0": (PendulumSmooth, False, None),
    "MountainCarContinuous-v0": (MountainCarContinuous, False, 90.0),
    "MountainCarShaped-v0": (MountainCarShaped, False, None),
    "Reacher-v0": (Reacher, False, None),
    "Swimmer-v0": (Swimmer, False, None),
    "Acrobot-v1": (Acrobot, True, -100.0),
    "MountainCar-v0": (MountainCar, True, -110.0),
    "InvertedPendulum-v5": (InvertedPendulum, False, 950.0),
    "Reacher-v5": (ReacherMuJoCo, False, -3.75),
    "InvertedDoublePendulum-v5": (InvertedDoublePendulum, False, 9100.0),
    "Hopper-v5": (Hopper, False, 3800.0),
    "Walker2d-v5": (Walker2d, False, None),
    "HalfCheetah-v5": (HalfCheetah, False, 4800.0),
    "Ant-v5": (Ant, False, 6000.0),
    "Humanoid-v5": (Humanoid, False, None),
    "Swimmer-v5": (SwimmerMuJoCo, False, 360.0),
}


def make_env(
    task: str,
    *,
    framework: Framework = "numpy",
    dtype: Dtype | None = None,
    render_mode: str | None = None,
    device: str | None = None,
    compile: bool | None = None,
    **core_kwargs: Any,
) -> GymnasiumEnv:
    """The Gymnasium entry point of ``ivy_gym/<task>``.

    Example:
        >>> env = make_env("Pendulum-v1", framework="jax", g=9.81)
        >>> env = make_env("Hopper-v5", framework="torch", healthy_reward=2.0)  # float64
    """
    cls, discrete, _ = TASKS[task]
    return GymnasiumEnv(
        cls(**core_kwargs),
        framework=framework,
        dtype=dtype,
        render_mode=render_mode,
        discrete=discrete,
        device=device,
        compile=compile,
    )


def make_vector_env(
    task: str,
    num_envs: int = 1,
    *,
    framework: Framework = "numpy",
    dtype: Dtype | None = None,
    render_mode: str | None = None,
    max_episode_steps: int | None = None,
    compile: bool | None = None,
    device: str | None = None,
    autoreset_mode: Any = "NextStep",
    **core_kwargs: Any,
) -> GymnasiumVectorEnv:
    """The Gymnasium vector entry point of ``ivy_gym/<task>``.

    Example:
        >>> envs = make_vector_env("CartPole-v1", 64, framework="torch", max_episode_steps=500)
    """
    cls, discrete, _ = TASKS[task]
    return GymnasiumVectorEnv(
        cls(**core_kwargs),
        num_envs,
        framework=framework,
        dtype=dtype,
        max_episode_steps=max_episode_steps,
        render_mode=render_mode,
        discrete=discrete,
        compile=compile,
        device=device,
        autoreset_mode=autoreset_mode,
    )


def register_envs() -> None:
    """Register every ``ivy_gym/<task>`` id with Gymnasium (done by ``import ivy_gym.gymnasium``;
    ids already registered are left as they are)."""
    for task, (cls, _, threshold) in TASKS.items():
        env_id = f"ivy_gym/{task}"
        if env_id in gymnasium.registry:
            continue
        gymnasium.register(
            id=env_id,
            entry_point="ivy_gym.gymnasium.registration:make_env",
            vector_entry_point="ivy_gym.gymnasium.registration:make_vector_env",
            max_episode_steps=cls.max_episode_steps,
            reward_threshold=threshold,
            kwargs={"task": task},
        )
