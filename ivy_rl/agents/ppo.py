"""PPO: proximal policy optimisation with the clipped surrogate and a KL early stop.

The whole update is one compiled function by default (see :mod:`ivy_rl.agents.a2c`): the
returns, then an ``ivy.scan`` over the mini-batches of every epoch, each step training the actor
and the critic. The KL early stop is a mask carried through the scan: once a mini-batch's KL
estimate exceeds ``kl_threshold``, the remaining actor steps leave the actor and its optimiser
state unchanged (the critic goes on).

Example:
    >>> import gymnasium as gym, numpy as np
    >>> env = gym.make("Pendulum-v1")
    >>> agent = PPO(segment_size=32, batch_size=256, epochs=20).initialize(
    ...     env.observation_space, env.action_space, seed=0, f="jax")
    >>> agent.step(np.zeros((8, 3), np.float32)).shape      # 8 workers: 256 steps a segment
    (8, 1)
"""

from __future__ import annotations

from typing import Any

from ivy_rl.agents.a2c import A2C
from ivy_rl.replays import Segment
from ivy_rl.updaters import ClippedRatio

__all__ = ["PPO"]

_ACTOR_LOGS = ("loss", "kl", "clip_fraction", "entropy")


class PPO(A2C):
    """Proximal policy optimisation (Schulman et al., 2017): ``epochs`` passes of
    mini-batches over each segment, training the actor on the clipped surrogate and the critic
    on the λ-returns; the actor stops for the rest of the update once the KL estimate of a
    mini-batch exceeds ``kl_threshold`` (the critic goes on).

    Its actor updater is a :class:`~ivy_rl.updaters.ClippedRatio`.

    Args:
        As for :class:`~ivy_rl.agents.A2C` (``epochs`` is the replay's passes over the segment).

    Settings: the flat settings (``PPO(batch_size=...)``, the command line's
    ``--agent-kwargs``) are those its parts declare, each once, with its type, default and
    meaning (the ``settings`` of each part's class, :mod:`ivy_rl.settings`), and the agent's
    defaults where they differ: ``PPO.settings()`` lists them, and ``python -m
    ivy_rl.agents.defaults PPO CartPole-v1`` prints them beside the task family's defaults
    (:func:`~ivy_rl.agents.defaults.settings_table`).

    Example:
        >>> agent = PPO(ratio_clip=0.2, kl_threshold=0.015, epochs=10, batch_size=64)
        >>> agent.config["kl_threshold"], agent.config["epochs"]
        (0.015, 10)
    """

    scheduled = ("actor_lr", "critic_lr", "ratio_clip")
    _defaults: dict[str, Any] = dict(
        segment_size=2048, batch_size=64, actor_gradient_clip=0.5, critic_gradient_clip=0.5
    )
    parts = {
        **A2C.parts,
        "replay": (Segment, {**A2C.REPLAY_SETTINGS, "epochs": "batch_iterations"}),
        "actor_updater": (
            ClippedRatio,
            {
                "actor_lr": "lr",
                "ratio_clip": "ratio_clip",
                "kl_threshold": "kl_threshold",
                "entropy_coeff": "entropy_coeff",
                "actor_gradient_clip": "gradient_clip",
            },
        ),
    }

    def _optimize(self, v, states, stats, batch, orders):
        xp = self.xp
        carry = (v, states, self._asarray(True))
        (v, states, _), ys = self._run_loop("ppo_step", self._ppo_step, carry, orders, stats, batch)
        # the actor's scalars are averaged over the steps it took
        taken = ys["actor/taken"]
        count = xp.sum(taken)
        logs = {
            f"actor/{k}": xp.sum(ys[f"actor/{k}"] * taken) / xp.maximum(count, 1.0)
            for k in _ACTOR_LOGS
        }
        logs["actor/iterations"] = count
        logs["critic/loss"] = xp.mean(ys["critic/loss"])
        return v, states, logs

    def _ppo_step(self, carry, indices, stats, batch):
        """One mini-batch: an actor step (masked once the KL stop has fired) and a critic step."""
        v, states, active = carry
        keys = ("observations", "actions", "log_probs", "advantages", "returns")
        part = self._select(batch, indices, keys)
        actor_v, actor_state, actor_infos = self.actor_updater.minimize(
            lambda w: self._actor_loss(w, stats, part),
            v["actor"],
            states["actor"],
            stats["scheduled"].get("actor_lr"),
        )
        threshold = self.actor_updater.kl_threshold
        if threshold is not None:
            actor_v = self._masked(active, actor_v, v["actor"])
            actor_state = self._masked(active, actor_state, states["actor"])
        critic_v, critic_state, critic_infos = self.critic_updater.minimize(
            lambda w: self._critic_loss(w, stats, part),
            v["critic"],
            states["critic"],
            stats["scheduled"].get("critic_lr"),
        )
        ys = {f"actor/{k}": actor_infos[k] for k in _ACTOR_LOGS}
        ys["actor/taken"] = self.xp.astype(active, actor_infos["loss"].dtype)
        ys["critic/loss"] = critic_infos["loss"]
        if threshold is not None:  # the KL before this step's update decides the next steps
            active = self.xp.logical_and(active, actor_infos["kl"] <= threshold)
        new_v = {"actor": actor_v, "critic": critic_v}
        new_states = {"actor": actor_state, "critic": critic_state}
        return (new_v, new_states, active), ys

    def _actor_loss(self, actor_v, stats, batch):
        dist = self.model.actor(batch["observations"], stats["obs"], v=actor_v)
        return self.actor_updater.loss(dist, batch, stats["scheduled"].get("ratio_clip"))

    def _iteration_counts(self, batches: int) -> dict[str, float]:
        return {"critic/iterations": float(batches)}  # the actor's count is computed
