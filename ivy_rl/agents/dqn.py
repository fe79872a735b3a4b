"""Value-based agents for discrete actions: DQN (Mnih et al., 2015) with double Q-learning
(van Hasselt et al., 2016) and a dueling head (Wang et al., 2016), and its branching variant for
MultiDiscrete actions (Tavakoli et al., 2018): one head per action dimension over a shared torso.

Both explore ε-greedily on the host (:class:`ivy_rl.explorations.EpsilonGreedy`) and learn from
n-step transitions of the replay (bootstrapped after time limits, not after terminations) with
a Huber loss; the target network follows by soft updates (``target_tau=1``: copies). A Discrete
space is one branch, so both agents share one update: the target value is
``R + γ^k mean_d Q'_d(s', argmax_a Q_d(s', a))`` (double) or ``... max_a Q'_d(s', a)``.

Example:
    >>> agent = DQN(dueling=True, double=True).initialize(
    ...     env.observation_space, env.action_space, seed=0, f="jax")
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ivy_rl.agents.off_policy import OffPolicyAgent
from ivy_rl.critics import BranchingQHead, DiscreteQHead, QNetwork
from ivy_rl.explorations import EpsilonGreedy
from ivy_rl.models import MLPTorso, ObservationEncoder, orthogonal_init

__all__ = ["DQN", "BranchingDQN"]


class DQN(OffPolicyAgent):
    """Deep Q-learning for Discrete actions.

    Args:
        dueling: a dueling head (state value plus centred advantages).
        double: double Q-learning targets (the online network chooses, the target evaluates).
        epsilon_start, epsilon_end, epsilon_decay_steps: the ε-greedy schedule (environment
            steps).
        critic_lr: Adam learning rate of the Q-network.
        Others: as for :class:`~ivy_rl.agents.off_policy.OffPolicyAgent` (``hidden_sizes`` is
        the Q-network's torso).

    Example:
        >>> DQN(hidden_sizes=(64, 64), epsilon_decay_steps=10_000)
    """

    supported_action_spaces = ("Discrete",)
    _unused = ("actor_lr", "critic_hidden_sizes")
    _defaults: dict[str, Any] = dict(
        hidden_sizes=(64, 64),
        dueling=True,
        double=True,
        epsilon_start=1.0,
        epsilon_end=0.05,
        epsilon_decay_steps=10_000,
        start_steps=0,
        batch_size=128,
        target_tau=0.01,
    )

    def _branch_sizes(self) -> tuple[int, ...]:
        return (int(self.action_space.n),)

    def _head(self, in_size: int, init: Any) -> Any:
        return DiscreteQHead(
            in_size,
            self._branch_sizes()[0],
            dueling=self.config["dueling"],
            weight_init=init,
            dtype=self.dtype,
            device=self.device,
            f=self.xp,
        )

    def _build_parts(self):
        c, rng = self.config, self.rng
        build = {"dtype": self.dtype, "device": self.device, "f": self.xp}
        torso = MLPTorso(
            self.observation_size,
            c["hidden_sizes"],
            c["activation"],
            weight_init=orthogonal_init(rng, math.sqrt(2.0)),
            **build,
        )
        head = self._head(torso.out_size, orthogonal_init(rng, 1.0))
        encoder = ObservationEncoder(self.observation_size, f=self.xp)
        self.q_network = QNetwork(encoder, torso, head)
        v = {"q": self.q_network.v}
        self.optimizers = {"q": self._adam(c["critic_lr"])}
        return v, {"q": self.q_network.v}

    def _build_exploration(self):
        c = self.config
        self.exploration = EpsilonGreedy(
            c["epsilon_start"], c["epsilon_end"], c["epsilon_decay_steps"]
        )

    # ------------------------------------------------------------------------------------------
    # The branches: a Discrete space is one
    # ------------------------------------------------------------------------------------------

    def _branches(self, q_v, observations, obs_stats):
        """Action values per branch: a list of ``[..., n_d]``."""
        return [self.q_network(observations, obs_stats, v=q_v)]

    def _branch_actions(self, actions):
        return [actions]

    def _greedy(self, branches):
        return self.xp.argmax(branches[0], axis=-1)

    # ------------------------------------------------------------------------------------------
    # Acting
    # ------------------------------------------------------------------------------------------

    def _act_fn(self, v, obs_stats, observations, noise):
        return self._greedy(self._branches(v["q"], observations, obs_stats))

    def _mode_fn(self, v, obs_stats, observations):
        return self._greedy(self._branches(v["q"], observations, obs_stats))

    def _policy_actions(self, observations):
        greedy = super()._policy_actions(observations)
        sizes = self._branch_sizes()
        num_actions = sizes[0] if self.action_kind == "Discrete" else sizes
        return self.exploration(greedy, self.rng, num_actions=num_actions, steps=self.steps)

    # ------------------------------------------------------------------------------------------
    # Learning
    # ------------------------------------------------------------------------------------------

    def _next_values(self, v, targets, following, obs_stats):
        """``mean_d`` of the branches' bootstrap values ``[batch]``."""
        xp = self.xp
        target_branches = self._branches(targets["q"], following, obs_stats)
        if self.config["double"]:
            online = self._branches(v["q"], following, obs_stats)
            values = [
                xp.sum(
                    xp.one_hot(xp.argmax(o, axis=-1), int(t.shape[-1]), dtype=t.dtype) * t,
                    axis=-1,
                )
                for o, t in zip(online, target_branches)
            ]
        else:
            values = [xp.max(t, axis=-1) for t in target_branches]
        return xp.mean(xp.stack(values), axis=0)

    def _q_loss(self, q_v, batch, goal, obs_stats):
        xp = self.xp
        branches = self._branches(q_v, batch["observations"], obs_stats)
        losses = []
        for values, actions in zip(branches, self._branch_actions(batch["actions"])):
            chosen = xp.one_hot(actions, int(values.shape[-1]), dtype=values.dtype)
            error = xp.sum(chosen * values, axis=-1) - goal
            size = xp.abs(error)
            losses.append(xp.mean(xp.where(size < 1.0, 0.5 * xp.square(error), size - 0.5)))
        return xp.mean(xp.stack(losses))

    def _learn_step(self, carry, x, arrays, obs_stats):
        xp = self.xp
        v, targets, states = carry["v"], carry["targets"], carry["states"]
        batch = self._batch(arrays, x["indices"])
        next_values = self._next_values(v, targets, batch["next_observations"], obs_stats)
        goal = xp.stop_gradient(batch["returns"] + batch["discounts"] * next_values)
        q_v, q_state, infos = self._minimize(
            "q", lambda w: self._q_loss(w, batch, goal, obs_stats), v["q"], states["q"]
        )
        v, states = {**v, "q": q_v}, {**states, "q": q_state}
        targets = self._soft_update(targets, v, ("q",))
        return {"v": v, "targets": targets, "states": states}, {"critic/loss": infos["loss"]}

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
        >>> BranchingDQN().initialize(obs_space, gymnasium.spaces.MultiDiscrete([3, 3]), f="jax")
    """

    supported_action_spaces = ("MultiDiscrete",)

    def _branch_sizes(self):
        return tuple(int(n) for n in np.asarray(self.action_space.nvec).reshape(-1))

    def _head(self, in_size, init):
        return BranchingQHead(
            in_size,
            self._branch_sizes(),
            dueling=self.config["dueling"],
            weight_init=init,
            dtype=self.dtype,
            device=self.device,
            f=self.xp,
        )

    def _branches(self, q_v, observations, obs_stats):
        return self.q_network(observations, obs_stats, v=q_v)

    def _branch_actions(self, actions):
        return [actions[..., d] for d in range(len(self._branch_sizes()))]

    def _greedy(self, branches):
        xp = self.xp
        return xp.stack([xp.argmax(b, axis=-1) for b in branches], axis=-1)

    def _random_actions(self, count):
        sizes = np.asarray(self._branch_sizes())
        return np.floor(self.rng.random((count, len(sizes))) * sizes).astype(np.int64)

    def _env_actions(self, unit_actions):
        start = np.asarray(self.action_space.start).reshape(-1)
        actions = np.asarray(unit_actions, np.int64) + start
        return actions.astype(self.action_space.dtype)
