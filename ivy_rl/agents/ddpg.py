"""DDPG: deep deterministic policy gradient (Lillicrap et al., 2016), the base of TD3 and D4PG.

A deterministic actor ``tanh(dense(torso(obs)))`` explores with noise added on the host
(:mod:`ivy_rl.explorations`); a critic ``Q(s, a)`` regresses on n-step targets
``R + γ^k Q'(s', π'(s'))`` from the target networks; the actor ascends ``Q(s, π(s))``; the
targets follow by soft updates. One compiled function per update (see
:mod:`ivy_rl.agents.off_policy`).

Example:
    >>> agent = DDPG(exploration="ornstein_uhlenbeck").initialize(
    ...     env.observation_space, env.action_space, seed=0, f="jax")
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ivy_rl.agents.off_policy import OffPolicyAgent
from ivy_rl.critics import CriticEnsemble, action_value_critic
from ivy_rl.explorations import make_exploration
from ivy_rl.models import (
    Actor,
    ActorCriticWithTargets,
    DeterministicHead,
    MLPTorso,
    ObservationEncoder,
    orthogonal_init,
)

__all__ = ["DDPG"]


class ExploresItself:
    """For DDPG's descendants whose stochastic policy explores by itself (SAC, MPO): acting
    adds no noise on the host, and there is no exploration state to keep. Listed before DDPG
    among the bases, so that it replaces DDPG's noise."""

    def _policy_actions(self, observations):
        return self._behaviour_actions(observations)

    def _reset_exploration(self, resets):
        pass

    def _exploration_state(self):
        return {}

    def _load_exploration_state(self, state):
        pass


class DDPG(OffPolicyAgent):
    """Deep deterministic policy gradient, with n-step returns and partial-episode
    bootstrapping.

    Args:
        exploration: ``'normal'``, ``'ornstein_uhlenbeck'`` or ``'none'``.
        exploration_scale: the noise's scale (actions in ``[-1, 1]``).
        Others: as for :class:`~ivy_rl.agents.off_policy.OffPolicyAgent`.

    Example:
        >>> DDPG(hidden_sizes=(64, 64), exploration_scale=0.2)
    """

    supported_action_spaces = ("Box",)
    _defaults: dict[str, Any] = dict(exploration="normal", exploration_scale=0.1)
    _critics = 1  # critics in the ensemble (TD3 and SAC: twin critics)
    _critic_head = "value"

    # ------------------------------------------------------------------------------------------
    # Building
    # ------------------------------------------------------------------------------------------

    def _policy_head(self, in_size: int, action_size: int, init: Any) -> Any:
        return DeterministicHead(in_size, action_size, weight_init=init, **self._build_args())

    def _build_args(self) -> dict[str, Any]:
        return {"dtype": self.dtype, "device": self.device, "f": self.xp}

    def _actor_critic(self) -> ActorCriticWithTargets:
        """The actor and the critic(s), initialised from the agent's generator, with targets."""
        c, rng = self.config, self.rng
        action_size = int(np.prod(self.action_space.shape))
        torso = MLPTorso(
            self.observation_size,
            c["hidden_sizes"],
            c["activation"],
            weight_init=orthogonal_init(rng, math.sqrt(2.0)),
            **self._build_args(),
        )
        head = self._policy_head(torso.out_size, action_size, orthogonal_init(rng, 0.01))
        actor = Actor(ObservationEncoder(self.observation_size, f=self.xp), torso, head)
        critics = [
            action_value_critic(
                self.observation_size,
                action_size,
                c["critic_hidden_sizes"] or c["hidden_sizes"],
                rng=rng,
                activation=c["activation"],
                head=self._critic_head,
                **self._critic_head_args(),
                **self._build_args(),
            )
            for _ in range(self._critics)
        ]
        critic = critics[0] if self._critics == 1 else CriticEnsemble(critics)
        return ActorCriticWithTargets(actor, critic)

    def _critic_head_args(self) -> dict[str, Any]:
        return {}

    def _build_parts(self):
        model = self._actor_critic()
        self.model = model
        c = self.config
        self.optimizers = {"actor": self._adam(c["actor_lr"]), "critic": self._adam(c["critic_lr"])}
        return dict(model.v), dict(model.target_v)

    def _build_exploration(self) -> None:
        c = self.config
        self.exploration = make_exploration(c["exploration"], c["exploration_scale"])

    # ------------------------------------------------------------------------------------------
    # Acting
    # ------------------------------------------------------------------------------------------

    def _act_fn(self, v, obs_stats, observations, noise):
        return self.model.actor(observations, obs_stats, v=v["actor"]).mode()

    def _mode_fn(self, v, obs_stats, observations):
        return self.model.actor(observations, obs_stats, v=v["actor"]).mode()

    def _policy_actions(self, observations):
        return self.exploration(super()._policy_actions(observations), self.rng)

    def _reset_exploration(self, resets):
        self.exploration.reset(resets)

    def _exploration_state(self):
        return self.exploration.state_dict()

    def _load_exploration_state(self, state):
        self.exploration.load_state_dict(state)

    # ------------------------------------------------------------------------------------------
    # Learning
    # ------------------------------------------------------------------------------------------

    def _q(self, critic_v, observations, actions, obs_stats):
        """The critic's values ``[batch]``."""
        return self.model.critic(observations, actions, obs_stats, v=critic_v)

    def _target_values(self, v, targets, batch, obs_stats, x):
        """``Q'(s', π'(s'))`` of the target networks ``[batch]``."""
        following = batch["next_observations"]
        actions = self.model.actor(following, obs_stats, v=targets["actor"]).mode()
        return self._q(targets["critic"], following, actions, obs_stats)

    def _critic_loss(self, critic_v, batch, targets, obs_stats):
        values = self._q(critic_v, batch["observations"], batch["actions"], obs_stats)
        return self.xp.mean(self.xp.square(values - targets))

    def _actor_loss(self, actor_v, critic_v, batch, obs_stats, x):
        observations = batch["observations"]
        actions = self.model.actor(observations, obs_stats, v=actor_v).mode()
        return -self.xp.mean(self._q(critic_v, observations, actions, obs_stats))

    def _critic_targets(self, v, targets, batch, obs_stats, x):
        """What the critic regresses on: ``R + γ^k Q'(s', π'(s'))`` (constants)."""
        next_values = self._target_values(v, targets, batch, obs_stats, x)
        return self.xp.stop_gradient(batch["returns"] + batch["discounts"] * next_values)

    def _critic_step(self, v, targets, states, indices, arrays, obs_stats, x):
        """A critic step on the batch of ``indices``: ``(v, states, loss, batch)``."""
        batch = self._batch(arrays, indices)
        goal = self._critic_targets(v, targets, batch, obs_stats, x)
        critic_v, critic_state, infos = self._minimize(
            "critic",
            lambda w: self._critic_loss(w, batch, goal, obs_stats),
            v["critic"],
            states["critic"],
        )
        return {**v, "critic": critic_v}, {**states, "critic": critic_state}, infos["loss"], batch

    def _actor_step(self, v, states, batch, obs_stats, x):
        actor_v, actor_state, infos = self._minimize(
            "actor",
            lambda w: self._actor_loss(w, v["critic"], batch, obs_stats, x),
            v["actor"],
            states["actor"],
        )
        return {**v, "actor": actor_v}, {**states, "actor": actor_state}, infos

    def _learn_step(self, carry, x, arrays, obs_stats):
        v, targets, states = carry["v"], carry["targets"], carry["states"]
        v, states, critic_loss, batch = self._critic_step(
            v, targets, states, x["indices"], arrays, obs_stats, x
        )
        v, states, actor_infos = self._actor_step(v, states, batch, obs_stats, x)
        targets = self._soft_update(targets, v, tuple(targets))
        logs = {"critic/loss": critic_loss, **{f"actor/{k}": a for k, a in actor_infos.items()}}
        return {"v": v, "targets": targets, "states": states}, logs
