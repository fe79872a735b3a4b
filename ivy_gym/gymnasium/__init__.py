"""Gymnasium facades over ivy_gym's cores, and their registration as ``ivy_gym/<Task>-v<N>``.

Importing this package imports gymnasium and registers the ids (``import ivy_gym`` alone does
neither, unless gymnasium is already imported: then it registers them too, so that
``gymnasium.make("ivy_gym:ivy_gym/Pendulum-v1")`` works with nothing imported by hand).

Example:
    >>> import gymnasium, ivy_gym.gymnasium
    >>> env = gymnasium.make("ivy_gym/Pendulum-v1", framework="torch", device="cpu")
    >>> envs = gymnasium.make_vec("ivy_gym/CartPole-v1", num_envs=1024,
    ...                           vectorization_mode="vector_entry_point", framework="jax")
"""

from ivy_gym.gymnasium import facades, registration
from ivy_gym.gymnasium.facades import *  # noqa: F403
from ivy_gym.gymnasium.registration import *  # noqa: F403

__all__ = [*facades.__all__, *registration.__all__]

registration.register_envs()
