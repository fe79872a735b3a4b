"""TRPO: trust region policy optimisation, a natural gradient step per segment.

The whole update is one compiled function by default (see :mod:`ivy_rl.agents.a2c`): the
returns, the trust-region step of the actor (conjugate gradient and line search, unrolled), then
an ``ivy.scan`` over the critic's mini-batches.

Example:
    >>> import gymnasium as gym, numpy as np
    >>> env = gym.make("Pendulum-v1")
    >>> agent = TRPO(max_kl=0.01).initialize(env.observation_space, env.action_space, f="jax")
    >>> agent.step(np.zeros((2, 3), np.float32)).shape
    (2, 1)
"""

from __future__ import annotations

from ivy_rl.agents.a2c import A2C
from ivy_rl.updaters import TrustRegionPolicyGradient

__all__ = ["TRPO"]


class TRPO(A2C):
    """Trust region policy optimisation (Schulman et al., 2015): once per segment, the actor
    takes the natural gradient step of the importance-sampled surrogate within a KL trust
    region (conjugate gradient on Fisher-vector products, backtracking line search); the
    critic then regresses the λ-returns for ``critic_iterations`` passes.

    The old policy of the KL is rebuilt from the distribution parameters stored when acting
    (not recomputed from the actor's variables), so it is a constant of the step on every
    backend.

    Its actor updater is a :class:`~ivy_rl.updaters.TrustRegionPolicyGradient` (no optimiser,
    so no ``actor_lr``).

    Args:
        As for :class:`~ivy_rl.agents.A2C`.

    Settings: the flat settings (``TRPO(batch_size=...)``, the command line's
    ``--agent-kwargs``) are those its parts declare, each once, with its type, default and
    meaning (the ``settings`` of each part's class, :mod:`ivy_rl.settings`), and the agent's
    defaults where they differ: ``TRPO.settings()`` lists them, and ``python -m
    ivy_rl.agents.defaults TRPO CartPole-v1`` prints them beside the task family's defaults
    (:func:`~ivy_rl.agents.defaults.settings_table`).

    Example:
        >>> agent = TRPO(max_kl=0.01, cg_steps=10, backtrack_steps=10)
        >>> agent.config["max_kl"], agent.config["cg_steps"], "actor_lr" in agent.config
        (0.01, 10, False)
    """

    _TRUST_REGION = ("max_kl", "cg_steps", "damping", "backtrack_steps", "backtrack_coefficient")
    parts = {
        **A2C.parts,
        "actor_updater": (
            TrustRegionPolicyGradient,
            {**{k: k for k in _TRUST_REGION}, "entropy_coeff": "entropy_coeff"},
        ),
    }

    def _optimize(self, v, states, stats, batch, orders):
        actor_v, actor_logs = self._run_once(
            "trust_region_step", self._trust_region_step, v["actor"], stats, batch
        )
        (critic_v, critic_state), critic_logs = self._run_critic(v, states, stats, batch, orders)
        logs = {f"actor/{k}": x for k, x in actor_logs.items()}
        logs.update(critic_logs)
        new_v = {"actor": actor_v, "critic": critic_v}
        return new_v, {"critic": critic_state}, logs

    def _trust_region_step(self, actor_v, stats, batch):
        def actor(w):
            return self.model.actor(batch["observations"], stats["obs"], v=w)

        return self.actor_updater.step(actor, actor_v, batch["distribution"], batch)
