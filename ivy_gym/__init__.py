"""ivy_gym: differentiable, batched environments written once for every ivy backend.

Each environment is a pure, batched core (``ivy_gym.Env``): ``state = env.reset(batch_shape,
f=...)`` and ``state, obs, reward, terminated = env.step(state, action)``, differentiable and
compilable on torch, jax and tensorflow (numpy runs them too). ``ivy_gym.rollout`` runs many
steps as one ``ivy.scan``; :mod:`ivy_gym.optimise` optimises actions and policies through
rollouts. The Gymnasium facades live in :mod:`ivy_gym.gymnasium` (which imports gymnasium);
``import ivy_gym`` needs neither gymnasium nor a framework, and registers the
``ivy_gym/<Task>-v<N>`` ids only when gymnasium is already imported.

Example:
    >>> import ivy_gym
    >>> env = ivy_gym.Pendulum()
    >>> state = env.reset((64,), f="torch")
    >>> traj = ivy_gym.rollout(env, state, torch.zeros(100, 64, 1))
"""

import sys

from ivy_gym import (
    acrobot,
    ant,
    cartpole,
    humanoid,
    inverted_double_pendulum,
    inverted_pendulum,
    locomotion,
    mountain_car,
    mujoco_env,
    optimise,
    pendulum,
    reacher,
    reacher_mujoco,
    rendering,
    rollouts,
    swimmer,
)
from ivy_gym.acrobot import *  # noqa: F403
from ivy_gym.ant import *  # noqa: F403
from ivy_gym.base import Env
from ivy_gym.cartpole import *  # noqa: F403
from ivy_gym.humanoid import *  # noqa: F403
from ivy_gym.inverted_double_pendulum import *  # noqa: F403
from ivy_gym.inverted_pendulum import *  # noqa: F403
from ivy_gym.locomotion import *  # noqa: F403
from ivy_gym.mountain_car import *  # noqa: F403
from ivy_gym.mujoco_env import *  # noqa: F403
from ivy_gym.optimise import *  # noqa: F403
from ivy_gym.pendulum import *  # noqa: F403
from ivy_gym.reacher import *  # noqa: F403
from ivy_gym.reacher_mujoco import *  # noqa: F403
from ivy_gym.rendering import *  # noqa: F403
from ivy_gym.rollouts import *  # noqa: F403
from ivy_gym.swimmer import *  # noqa: F403

#: Names of :mod:`ivy_gym.gymnasium` also reachable as ``ivy_gym.<name>`` (importing gymnasium
#: on first use), as before the facades moved there.
_GYMNASIUM_NAMES = (
    "GymnasiumEnv",
    "GymnasiumVectorEnv",
    "TASKS",
    "make_env",
    "make_vector_env",
    "register_envs",
)

__all__ = [
    "Env",
    *acrobot.__all__,
    *cartpole.__all__,
    *pendulum.__all__,
    *mountain_car.__all__,
    *reacher.__all__,
    *swimmer.__all__,
    *inverted_pendulum.__all__,
    *reacher_mujoco.__all__,
    *inverted_double_pendulum.__all__,
    *mujoco_env.__all__,
    *locomotion.__all__,
    *ant.__all__,
    *humanoid.__all__,
    *rollouts.__all__,
    *optimise.__all__,
    *rendering.__all__,
]


def __getattr__(name: str):
    if name in _GYMNASIUM_NAMES:
        import ivy_gym.gymnasium as facades

        return getattr(facades, name)
    raise AttributeError(f"module 'ivy_gym' has no attribute {name!r}")


if "gymnasium" in sys.modules:  # gymnasium.make("ivy_gym:ivy_gym/...") imports ivy_gym
    import ivy_gym.gymnasium  # noqa: F401  (registers the ids)
