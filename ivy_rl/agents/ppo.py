"""PPO: proximal policy optimisation with the clipped surrogate and a KL early stop.

Example:
    >>> agent = PPO(segment_size=32, batch_size=256, epochs=20).initialize(
    ...     env.observation_space, env.action_space, seed=0, f="jax")
"""

from __future__ import annotations

from typing import Any

from ivy_rl import updaters
from ivy_rl.agents.a2c import A2C, _Logs

__all__ = ["PPO"]


class PPO(A2C):
    """Proximal policy optimisation (Schulman et al., 2017): ``epochs`` passes of
    mini-batches over each segment, training the actor on the clipped surrogate and the critic
    on the λ-returns; the actor stops for the rest of the update once the KL estimate of a
    mini-batch exceeds ``kl_threshold`` (the critic goes on).

    Args:
        ratio_clip: ε of the clipped ratio ``[1 - ε, 1 + ε]``.
        kl_threshold: KL between the old and the current policy beyond which the actor stops
            (None: never).
        epochs: passes over the segment per update.
        batch_size: transitions per mini-batch (None: the whole segment).
        Others: as for :class:`~ivy_rl.agents.A2C`.

    Example:
        >>> PPO(ratio_clip=0.2, kl_threshold=0.015, epochs=10, batch_size=64)
    """

    _unused = ("critic_iterations",)
    _defaults: dict[str, Any] = dict(
        segment_size=2048,
        batch_size=64,
        epochs=10,
        ratio_clip=0.2,
        kl_threshold=0.015,
        gradient_clip=0.5,
    )

    def _passes(self) -> int:
        return self.config["epochs"]

    def _actor_loss(self, actor_v, stats, batch):
        dist = self.model.actor(batch["observations"], stats["obs"], v=actor_v)
        return updaters.clipped_ratio_loss(
            self.xp,
            dist,
            batch["actions"],
            batch["log_probs"],
            batch["advantages"],
            self.config["ratio_clip"],
            self.config["entropy_coeff"],
        )

    def _learn(self) -> dict[str, float]:
        xp = self.xp
        self._evaluate()
        batch = self._device_batch("observations", "actions", "advantages", "returns", "log_probs")
        threshold = self.config["kl_threshold"]
        logs = _Logs()
        v, states = self.v, self.optimizer_states
        train_actor = True
        for indices in self.replay.batch_indices(self.rng):
            idx = self._all_indices() if indices is None else xp.asarray(indices.astype("int32"))
            if train_actor:
                v, states, infos = self._train_actor_critic(v, states, self.stats, batch, idx)
                if threshold is not None:
                    train_actor = float(xp.to_numpy(infos["actor/kl"])) <= threshold
            else:
                v, states, infos = self._train_critic(v, states, self.stats, batch, idx)
            logs.add(infos)
        self.v, self.optimizer_states = v, states
        self._after_learning()
        return logs.means(xp)
