"""D4PG: distributed distributional deterministic policy gradients (Barth-Maron et al., 2018),
on one machine: DDPG with a categorical distributional critic and n-step returns.

The critic gives a distribution over ``atoms`` values in ``[v_min, v_max]``; its target is the
target critic's distribution at ``(s', π'(s'))`` shifted by the n-step return, scaled by the
discount and projected back onto the atoms (:func:`ivy_rl.critics.project_categorical`), and it
learns by cross-entropy; the actor ascends the critic's expected value.

Example:
    >>> agent = D4PG(v_min=-150.0, v_max=150.0, atoms=51, return_steps=5)
"""

from __future__ import annotations

from typing import Any

from ivy_rl.agents.ddpg import DDPG
from ivy_rl.critics import project_categorical

__all__ = ["D4PG"]


class D4PG(DDPG):
    """DDPG with a categorical distributional critic.

    Args:
        v_min, v_max: the range of the critic's support.
        atoms: the number of atoms of the support.
        Others: as for :class:`~ivy_rl.agents.DDPG`.

    Example:
        >>> D4PG(v_min=-1000.0, v_max=0.0, atoms=51)
    """

    _defaults: dict[str, Any] = dict(v_min=-150.0, v_max=150.0, atoms=51, return_steps=5)
    _critic_head = "categorical"

    def _check_config(self, config):
        if not config["v_min"] < config["v_max"]:
            raise ValueError(
                f"D4PG: v_min ({config['v_min']}) must be below v_max ({config['v_max']})"
            )
        if config["atoms"] < 2:
            raise ValueError(f"D4PG: atoms must be >= 2, got {config['atoms']}")

    def _critic_head_args(self):
        c = self.config
        return {"v_min": c["v_min"], "v_max": c["v_max"], "atoms": c["atoms"]}

    def _critic_targets(self, v, targets, batch, obs_stats, x):
        following = batch["next_observations"]
        actions = self.model.actor(following, obs_stats, v=targets["actor"]).mode()
        values = self._q(targets["critic"], following, actions, obs_stats)
        projected = project_categorical(
            self.xp, values.probs(), batch["returns"], batch["discounts"], values.support
        )
        return self.xp.stop_gradient(projected)

    def _critic_loss(self, critic_v, batch, targets, obs_stats):
        values = self._q(critic_v, batch["observations"], batch["actions"], obs_stats)
        return -self.xp.mean(self.xp.sum(targets * values.logits, axis=-1))

    def _actor_loss(self, actor_v, critic_v, batch, obs_stats, x):
        observations = batch["observations"]
        actions = self.model.actor(observations, obs_stats, v=actor_v).mode()
        return -self.xp.mean(self._q(critic_v, observations, actions, obs_stats).mean())
