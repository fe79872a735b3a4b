"""MPO: maximum a posteriori policy optimisation (Abdolmaleki et al., 2018).

A Gaussian actor and a critic ``Q(s, a)`` with targets. The critic regresses on expected-SARSA
n-step targets ``R + γ^k mean_j Q'(s', a'_j)`` with ``a'_j`` sampled from the target policy
(:class:`~ivy_rl.off_policy_updaters.ExpectedSARSA`). The actor
(:class:`~ivy_rl.off_policy_updaters.MaximumAPosterioriPolicyOptimization`): for each state,
``num_samples`` actions of the target policy are weighted by ``softmax(Q'(s, a_j) / η)`` (the
E-step, with the temperature η found by its dual under a KL bound ``epsilon``); the policy then
fits those weighted actions by maximum likelihood (the M-step) with its mean and its scale
fitted separately, each under a per-dimension KL bound to the target policy (``epsilon_mean``,
``epsilon_std``) enforced by Lagrange multipliers learned alongside. Every sample's noise is
drawn by the agent's numpy generator and passed in.

Example:
    >>> import gymnasium as gym, numpy as np
    >>> env = gym.make("Pendulum-v1")
    >>> agent = MPO(num_samples=20, epsilon=0.1).initialize(
    ...     env.observation_space, env.action_space, seed=0, f="jax")
    >>> agent.step(np.zeros((2, 3), np.float32)).shape
    (2, 1)
"""

from __future__ import annotations

from functools import partial

from ivy_rl.agents.ddpg import DDPG, MODEL, UPDATER
from ivy_rl.explorations import NoNoise
from ivy_rl.off_policy_models import ActorQModel
from ivy_rl.off_policy_updaters import ExpectedSARSA, MaximumAPosterioriPolicyOptimization

__all__ = ["MPO"]

_MPO_ACTOR = {
    "actor_lr": "lr",
    "num_samples": "num_samples",
    "epsilon": "epsilon",
    "epsilon_mean": "epsilon_mean",
    "epsilon_std": "epsilon_std",
    "initial_log_temperature": "initial_log_temperature",
    "initial_log_alpha_mean": "initial_log_alpha_mean",
    "initial_log_alpha_std": "initial_log_alpha_std",
    "min_log_dual": "min_log_dual",
    "dual_lr": "dual_lr",
    **UPDATER,
}


class MPO(DDPG):
    """Maximum a posteriori policy optimisation with decoupled KL constraints.

    Args:
        As for :class:`~ivy_rl.agents.DDPG`; MPO explores by sampling its policy, the dual
        variables and their KL bounds are its actor updater's.

    Settings: the flat settings (``MPO(batch_size=...)``, the command line's
    ``--agent-kwargs``) are those its parts declare, each once, with its type, default and
    meaning (the ``settings`` of each part's class, :mod:`ivy_rl.settings`), and the agent's
    defaults where they differ: ``MPO.settings()`` lists them, and ``python -m
    ivy_rl.agents.defaults MPO Pendulum-v1`` prints them beside the task family's defaults
    (:func:`~ivy_rl.agents.defaults.settings_table`).

    Example:
        >>> MPO(hidden_sizes=(256, 256), num_samples=20).config["num_samples"]
        20
    """

    scheduled = ("actor_lr", "critic_lr", "dual_lr")
    parts = {
        "model": (partial(ActorQModel, policy="gaussian"), MODEL),
        "replay": DDPG.parts["replay"],
        "exploration": (NoNoise, {"start_steps": "start_steps"}),
        "actor_updater": (MaximumAPosterioriPolicyOptimization, _MPO_ACTOR),
        "critic_updater": (
            ExpectedSARSA,
            {"critic_lr": "lr", "num_samples": "num_samples", **UPDATER},
        ),
    }
