"""Baseline agents that do not learn: uniform random actions and a constant action.

Example:
    >>> import gymnasium as gym, numpy as np
    >>> env = gym.make("Pendulum-v1")
    >>> agent = Uniform().initialize(env.observation_space, env.action_space, seed=0)
    >>> agent.step(np.zeros((4, 3)))                    # four random actions
    array([[ 0.54784673],
           [-0.92085314],
           [-1.836106  ],
           [-1.9338895 ]], dtype=float32)
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ivy_rl.agents.agent import Agent

__all__ = ["Uniform", "Constant"]


class Uniform(Agent):
    """Actions drawn uniformly from the action space (Box: ``[low, high]``, or ``[-1, 1]``
    rescaled when bounded; Discrete: every action equally likely), in training and in tests.

    Example:
        >>> import gymnasium as gym, numpy as np
        >>> obs_space = gym.spaces.Box(-1, 1, (2,))
        >>> agent = Uniform().initialize(obs_space, gym.spaces.Discrete(3), seed=1)
        >>> agent.step(np.zeros((4, 2)))
        array([1, 1, 2, 2])
    """

    def _draw(self, count: int) -> np.ndarray:
        if self.action_kind == "Discrete":
            return self.rng.integers(0, int(self.action_space.n), size=count)
        if self._action_bounds is None:
            raise ValueError(
                "Uniform needs a bounded Box action space; this one has infinite bounds"
            )
        return self.rng.uniform(-1.0, 1.0, size=(count,) + self.action_space.shape)

    def step(self, observations: Any) -> np.ndarray:
        self._check_initialized()
        return self._env_actions(self._draw(len(observations)))

    def test_step(self, observations: Any) -> np.ndarray:
        return self.step(observations)


class Constant(Agent):
    """The same action at every step.

    Args:
        value: the action in the environment's action space; default: the middle of a Box
            (zeros when unbounded) or action 0 (the space's ``start``) of a Discrete space.

    Example:
        >>> import gymnasium as gym, numpy as np
        >>> obs_space, box_space = gym.spaces.Box(-1, 1, (2,)), gym.spaces.Box(-2, 2, (1,))
        >>> Constant(value=[0.5]).initialize(obs_space, box_space).step(np.zeros((2, 2)))
        array([[0.5],
               [0.5]], dtype=float32)
    """

    def __init__(self, *, value: Any = None) -> None:
        super().__init__(value=value)

    def _build(self) -> None:
        value = self.config["value"]
        space = self.action_space
        if value is None:
            if self.action_kind == "Discrete":
                action = np.asarray(int(space.start), np.int64)
            elif self._action_bounds is None:
                action = np.zeros(space.shape, space.dtype)
            else:
                low, high = self._action_bounds
                action = ((low + high) / 2).astype(space.dtype)
        else:
            action = np.asarray(
                value, dtype=np.int64 if self.action_kind == "Discrete" else space.dtype
            )
            if not space.contains(action):
                raise ValueError(f"Constant: value {value!r} is not in the action space {space}")
        self._action = action

    def step(self, observations: Any) -> np.ndarray:
        self._check_initialized()
        return np.repeat(self._action[None], len(observations), axis=0)

    def test_step(self, observations: Any) -> np.ndarray:
        return self.step(observations)
