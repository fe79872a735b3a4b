"""TRPO: trust region policy optimisation, a natural gradient step per segment.

Example:
    >>> agent = TRPO(max_kl=0.01).initialize(env.observation_space, env.action_space, f="jax")
"""

from __future__ import annotations

from typing import Any

from ivy_rl import updaters
from ivy_rl.agents.a2c import A2C, _Logs

__all__ = ["TRPO"]


class TRPO(A2C):
    """Trust region policy optimisation (Schulman et al., 2015): once per segment, the actor
    takes the natural gradient step of the importance-sampled surrogate within a KL trust
    region (conjugate gradient on Fisher-vector products, backtracking line search); the
    critic then regresses the λ-returns for ``critic_iterations`` passes.

    Args:
        max_kl: the trust region's radius δ (mean KL between the old and new policies).
        cg_steps: conjugate-gradient iterations.
        damping: added to the Fisher-vector products (``F + damping I``).
        backtrack_steps: candidate steps of the line search.
        backtrack_coefficient: shrink factor between candidates.
        Others: as for :class:`~ivy_rl.agents.A2C`.

    Example:
        >>> TRPO(max_kl=0.01, cg_steps=10, backtrack_steps=10)
    """

    _defaults: dict[str, Any] = dict(
        max_kl=0.01,
        cg_steps=10,
        damping=0.1,
        backtrack_steps=10,
        backtrack_coefficient=0.8,
    )

    def _build_learning(self) -> None:
        self._train_actor_critic = self._compile(self._trust_region_iteration)
        self._train_critic = self._compile(self._critic_iteration)

    def _trust_region_iteration(self, v, states, stats, batch, indices):
        xp = self.xp
        c = self.config
        part = self._select(batch, indices)
        obs = part["observations"]
        old = self.model.actor(obs, stats["obs"], v=v["actor"])
        old = old.like({k[len("dist_") :]: a for k, a in part.items() if k.startswith("dist_")})

        def surrogate(actor_v):
            dist = self.model.actor(obs, stats["obs"], v=actor_v)
            ratios = xp.exp(dist.log_prob_raw(part["actions"]) - part["log_probs"])
            loss = -xp.mean(ratios * part["advantages"])
            if c["entropy_coeff"]:
                loss = loss - c["entropy_coeff"] * xp.mean(dist.entropy())
            return loss

        def kl(actor_v):
            return xp.mean(old.kl(self.model.actor(obs, stats["obs"], v=actor_v)))

        actor_v, actor_infos = updaters.trust_region_step(
            xp,
            v["actor"],
            surrogate,
            kl,
            max_kl=c["max_kl"],
            cg_steps=c["cg_steps"],
            damping=c["damping"],
            backtrack_steps=c["backtrack_steps"],
            backtrack_coefficient=c["backtrack_coefficient"],
        )
        new_v, new_states, infos = self._critic_iteration(
            {"actor": actor_v, "critic": v["critic"]}, states, stats, batch, indices
        )
        infos.update({f"actor/{k}": x for k, x in actor_infos.items()})
        return new_v, new_states, infos

    def _learn(self) -> dict[str, float]:
        self._evaluate()
        keys = ["observations", "actions", "advantages", "returns", "log_probs"]
        keys += [k for k in self.replay.buffers if k.startswith("dist_")]
        batch = self._device_batch(*keys)
        logs = _Logs()
        v, states = self.v, self.optimizer_states
        v, states, infos = self._train_actor_critic(
            v, states, self.stats, batch, self._all_indices()
        )
        logs.add({k: x for k, x in infos.items() if k.startswith("actor/")})
        for indices in self.replay.batch_indices(self.rng):
            idx = (
                self._all_indices() if indices is None else self.xp.asarray(indices.astype("int32"))
            )
            v, states, infos = self._train_critic(v, states, self.stats, batch, idx)
            logs.add(infos)
        self.v, self.optimizer_states = v, states
        self._after_learning()
        return logs.means(self.xp)
