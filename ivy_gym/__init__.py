"""ivy_gym: differentiable, batched environments written once for every ivy backend.

Each environment is a pure, batched core (``ivy_gym.Env``): ``state = env.reset(batch_shape,
f=...)`` and ``state, obs, reward, terminated = env.step(state, action)``, differentiable and
compilable on torch, jax and tensorflow (numpy runs them too). ``ivy_gym.rollout`` runs many
steps as one ``ivy.scan``; :mod:`ivy_gym.optimise` optimises actions and policies through
rollouts; Gymnasium facades are registered as ``ivy_gym/<Task>-v<N>`` on import.

Example:
    >>> import ivy_gym
    >>> env = ivy_gym.Pendulum()
    >>> state = env.reset((64,), f="torch")
    >>> traj = ivy_gym.rollout(env, state, torch.zeros(100, 64, 1))
"""

from ivy_gym import (
    base,
    cartpole,
    facades,
    mountain_car,
    optimise,
    pendulum,
    reacher,
    registration,
    rendering,
    rollouts,
    swimmer,
)
from ivy_gym.base import *  # noqa: F403
from ivy_gym.cartpole import *  # noqa: F403
from ivy_gym.facades import *  # noqa: F403
from ivy_gym.mountain_car import *  # noqa: F403
from ivy_gym.optimise import *  # noqa: F403
from ivy_gym.pendulum import *  # noqa: F403
from ivy_gym.reacher import *  # noqa: F403
from ivy_gym.registration import *  # noqa: F403
from ivy_gym.rendering import *  # noqa: F403
from ivy_gym.rollouts import *  # noqa: F403
from ivy_gym.swimmer import *  # noqa: F403

__all__ = [
    *base.__all__,
    *cartpole.__all__,
    *pendulum.__all__,
    *mountain_car.__all__,
    *reacher.__all__,
    *swimmer.__all__,
    *rollouts.__all__,
    *optimise.__all__,
    *rendering.__all__,
    *facades.__all__,
    *registration.__all__,
]

registration.register_envs()
