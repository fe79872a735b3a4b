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

from functools import partial
from typing import Any

from ivy_rl.agents.ddpg import DDPG, MODEL, UPDATER
from ivy_rl.off_policy_models import ActorQModel
from ivy_rl.off_policy_updaters import (
    DistributionalDeterministicPolicyGradient,
    DistributionalDeterministicQLearning,
)

__all__ = ["D4PG"]


class D4PG(DDPG):
    """DDPG with a categorical distributional critic.

    Args:
        As for :class:`~ivy_rl.agents.DDPG` (the support of the critic, ``v_min`` below
        ``v_max`` and ``atoms``, is its model's).

    Settings: the flat settings (``D4PG(batch_size=...)``, the command line's
    ``--agent-kwargs``) are those its parts declare, each once, with its type, default and
    meaning (the ``settings`` of each part's class, :mod:`ivy_rl.settings`), and the agent's
    defaults where they differ: ``D4PG.settings()`` lists them, and ``python -m
    ivy_rl.agents.defaults D4PG Pendulum-v1`` prints them beside the task family's defaults
    (:func:`~ivy_rl.agents.defaults.settings_table`).

    Example:
        >>> agent = D4PG(v_min=-1000.0, v_max=0.0, atoms=51)    # Pendulum's returns are <= 0
        >>> agent.config["v_min"], agent.config["atoms"]
        (-1000.0, 51)
    """

    _defaults: dict[str, Any] = dict(return_steps=5)
    parts = {
        **DDPG.parts,
        "model": (
            partial(ActorQModel, policy="deterministic", critic_head="categorical"),
            {**MODEL, "v_min": "v_min", "v_max": "v_max", "atoms": "atoms"},
        ),
        "actor_updater": (
            DistributionalDeterministicPolicyGradient,
            {"actor_lr": "lr", **UPDATER},
        ),
        "critic_updater": (DistributionalDeterministicQLearning, {"critic_lr": "lr", **UPDATER}),
    }

    def _check_config(self, config):
        if not config["v_min"] < config["v_max"]:
            raise ValueError(
                f"D4PG: v_min ({config['v_min']}) must be below v_max ({config['v_max']})"
            )
        if config["atoms"] < 2:
            raise ValueError(f"D4PG: atoms must be >= 2, got {config['atoms']}")
