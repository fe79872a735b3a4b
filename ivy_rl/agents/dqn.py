"""Value-based agents for discrete actions: DQN (Mnih et al., 2015) with double Q-learning
(van Hasselt et al., 2016) and a dueling head (Wang et al., 2016), and its branching variant for
MultiDiscrete actions (Tavakoli et al., 2018): one head per action dimension over a shared torso.

Both explore ε-greedily on the host (:class:`ivy_rl.explorations.EpsilonGreedy`) and learn from
n-step transitions of the replay (bootstrapped after time limits, not after terminations) with
a Huber loss; the target network follows by soft updates (``target_tau=1``: copies). A Discrete
space is one branch, so both agents share one update
(:class:`~ivy_rl.off_policy_updaters.QLearning`): the target value is
``R + γ^k mean_d Q'_d(s', argmax_a Q_d(s', a))`` (double) or ``... max_a Q'_d(s', a)``.

The agent is its parts: ``DQN(model=QModel(...), replay=Transitions(...),
exploration=EpsilonGreedy(...), updater=QLearning(...))``.

Example:
    >>> import gymnasium as gym, numpy as np
    >>> env = gym.make("CartPole-v1")
    >>> agent = DQN(dueling=True, double=True).initialize(
    ...     env.observation_space, env.action_space, seed=0, f="jax")
    >>> agent.test_step(np.zeros((2, 4), np.float32))   # greedy actions of 2 workers
    array([0, 0])
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ivy_rl.agents.ddpg import REPLAY, UPDATER
from ivy_rl.agents.off_policy import OffPolicyAgent
from ivy_rl.explorations import EpsilonGreedy
from ivy_rl.off_policy_models import QModel
from ivy_rl.off_policy_updaters import QLearning
from ivy_rl.replays import Transitions

__all__ = ["DQN", "BranchingDQN"]


class DQN(OffPolicyAgent):
    """Deep Q-learning for Discrete actions.

    Parts: ``model`` (:class:`~ivy_rl.off_policy_models.QModel`), ``replay``
    (:class:`~ivy_rl.replays.Transitions`), ``exploration``
    (:class:`~ivy_rl.explorations.EpsilonGreedy`), ``updater``
    (:class:`~ivy_rl.off_policy_updaters.QLearning`).

    Args:
        model, replay, exploration, updater: the parts (default: built from the flat settings,
            see Parts; ``hidden_sizes`` is the Q-network's torso).
        settings: the flat settings of the parts not given, and ``fusion``
            (:mod:`ivy_rl.agents.fusion`).

    Settings: the flat settings (``DQN(batch_size=...)``, the command line's
    ``--agent-kwargs``) are those its parts declare, each once, with its type, default and
    meaning (the ``settings`` of each part's class, :mod:`ivy_rl.settings`), and the agent's
    defaults where they differ: ``DQN.settings()`` lists them, and ``python -m
    ivy_rl.agents.defaults DQN CartPole-v1`` prints them beside the task family's defaults
    (:func:`~ivy_rl.agents.defaults.settings_table`).

    Example:
        >>> DQN(hidden_sizes=(64, 64), epsilon_decay_steps=10_000).config["hidden_sizes"]
        (64, 64)
    """

    supported_action_spaces = ("Discrete",)
    _defaults: dict[str, Any] = dict(start_steps=0, batch_size=128)
    parts = {
        "model": (
            QModel,
            {
                "hidden_sizes": "hidden_sizes",
                "activation": "activation",
                "dueling": "dueling",
                "normalize_observations": "normalize_observations",
                "target_tau": "target_tau",
            },
        ),
        "replay": (Transitions, REPLAY),
        "exploration": (
            EpsilonGreedy,
            {
                "epsilon_start": "start",
                "epsilon_end": "end",
                "epsilon_decay_steps": "decay_steps",
                "start_steps": "start_steps",
            },
        ),
        "updater": (QLearning, {"critic_lr": "lr", "double": "double", **UPDATER}),
    }
    _updater_logs = {"updater": "critic"}

    def _num_actions(self):
        sizes = self.model.branch_sizes
        return sizes[0] if self.action_kind == "Discrete" else sizes

    def _learn(self):
        logs = super()._learn()
        logs["actor/epsilon"] = self.exploration.epsilon(self.steps)
        return logs


class BranchingDQN(DQN):
    """DQN for MultiDiscrete actions: a shared torso and one Q-head per action dimension
    (action branching); each dimension is chosen greedily by its own head and the target averages
    the branches' bootstrap values.

    Args:
        As for :class:`DQN` (``dueling``: the branches share one state value).

    Example:
        >>> import gymnasium, numpy as np
        >>> obs_space = gymnasium.spaces.Box(-1, 1, (4,))
        >>> agent = BranchingDQN().initialize(obs_space, gymnasium.spaces.MultiDiscrete([3, 5]),
        ...                                   f="jax")
        >>> agent.step(np.zeros((2, 4), np.float32)).shape     # one choice per dimension
        (2, 2)
    """

    supported_action_spaces = ("MultiDiscrete",)

    def _random_actions(self, count):
        sizes = np.asarray(self.model.branch_sizes)
        return np.floor(self.rng.random((count, len(sizes))) * sizes).astype(np.int64)

    def _env_actions(self, unit_actions):
        start = np.asarray(self.action_space.start).reshape(-1)
        actions = np.asarray(unit_actions, np.int64) + start
        return actions.astype(self.action_space.dtype)
