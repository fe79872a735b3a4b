"""ivy_rl: reinforcement-learning agents written once with ivy, trained with the same numbers
on torch, jax and tensorflow.

The design follows Tonic's modular agents (models built from an encoder, a torso and a head;
replays; normalisers; updaters) and the time-limit handling of Pardo et al. (2018): an episode
cut by a time limit is a reset, not a termination, and the value of its last state is
bootstrapped (partial-episode bootstrapping); optionally the remaining time is an input
(:class:`~ivy_rl.environments.TimeFeature`).

Modules: :mod:`ivy_rl.returns` (λ-returns, GAE, n-step returns), :mod:`ivy_rl.distributions`,
:mod:`ivy_rl.models`, :mod:`ivy_rl.normalizers`, :mod:`ivy_rl.replays`, :mod:`ivy_rl.updaters`,
:mod:`ivy_rl.off_policy_models`, :mod:`ivy_rl.off_policy_updaters`,
:mod:`ivy_rl.differentiable_parts`, :mod:`ivy_rl.settings`, :mod:`ivy_rl.agents`,
:mod:`ivy_rl.environments`, :mod:`ivy_rl.trainer`, :mod:`ivy_rl.checkpoints`,
:mod:`ivy_rl.console`, :mod:`ivy_rl.logger`, :mod:`ivy_rl.evaluation`, :mod:`ivy_rl.threads`;
commands ``python -m ivy_rl.train``, ``python -m ivy_rl.plot`` and ``python -m ivy_rl.play``.

``import ivy_rl`` imports no deep-learning framework.

Agents are composed of parts (a model, a replay, an actor updater and a critic updater), and
:func:`ivy_rl.agents.make` builds them with the defaults of a task family.

Example:
    A short run (CartPole-v1 takes about ``steps=100_000`` to learn; here 2,000 show the calls):

    >>> import ivy_rl
    >>> agent = ivy_rl.agents.make("PPO", environment="CartPole-v1")
    >>> trainer = ivy_rl.Trainer(steps=2_000, epoch_steps=1_000, test_episodes=1,
    ...                          show_progress=False)
    >>> rows = trainer.run(agent, "CartPole-v1", workers=8, seed=0, f="jax", out="runs/ppo")
    finished: 2,000 steps in ...
    >>> len(rows), rows[-1]["train/steps"]                # one row per epoch, as in log.csv
    (2, 2000)
"""

import importlib.util as _importlib_util

if _importlib_util.find_spec("gymnasium") is None:  # (before any module of ivy_rl imports it)
    raise ModuleNotFoundError(
        "ivy_rl trains on Gymnasium environments, and gymnasium is not installed: install "
        "ivy's [rl] extra (pip install 'ivy[rl]'), or gymnasium itself (pip install gymnasium).",
        name="gymnasium",
    )

from ivy_rl import (  # noqa: E402
    agents,
    buffers,
    checkpoints,
    console,
    critics,
    differentiable_parts,
    distributions,
    environments,
    evaluation,
    explorations,
    models,
    normalizers,
    off_policy_models,
    off_policy_updaters,
    replays,
    returns,
    settings,
    threads,
    updaters,
)
from ivy_rl.agents import (
    A2C,
    AGENTS,
    APG,
    D4PG,
    DDPG,
    DQN,
    MPO,
    PPO,
    SAC,
    SHAC,
    TD3,
    TRPO,
    Agent,
    BranchingDQN,
    Constant,
    Uniform,
    make,
)
from ivy_rl.evaluation import evaluate
from ivy_rl.returns import generalized_advantages, lambda_returns, n_step_returns

__all__ = [
    "agents",
    "buffers",
    "critics",
    "distributions",
    "environments",
    "explorations",
    "models",
    "normalizers",
    "replays",
    "returns",
    "updaters",
    "off_policy_models",
    "off_policy_updaters",
    "differentiable_parts",
    "settings",
    "checkpoints",
    "console",
    "evaluation",
    "threads",
    "Agent",
    "A2C",
    "PPO",
    "TRPO",
    "APG",
    "SHAC",
    "DDPG",
    "TD3",
    "SAC",
    "MPO",
    "D4PG",
    "DQN",
    "BranchingDQN",
    "Uniform",
    "Constant",
    "AGENTS",
    "make",
    "Trainer",
    "TrainingInterrupted",
    "evaluate",
    "lambda_returns",
    "generalized_advantages",
    "n_step_returns",
]


def __getattr__(name: str):
    # the trainer (environments, workers) is imported on first use
    if name in ("Trainer", "TrainingInterrupted"):
        from ivy_rl import trainer

        return getattr(trainer, name)
    raise AttributeError(f"module 'ivy_rl' has no attribute {name!r}")
