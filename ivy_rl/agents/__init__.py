"""Agents: the :class:`Agent` interface, baselines (``Uniform``, ``Constant``) and the
on-policy agents ``A2C``, ``PPO`` and ``TRPO`` (Box and Discrete actions).

Example:
    >>> import gymnasium as gym, numpy as np
    >>> env = gym.make("Pendulum-v1")
    >>> agent = ivy_rl.agents.make("PPO", environment="Pendulum-v1", batch_size=64)
    >>> agent = agent.initialize(env.observation_space, env.action_space, seed=0, f="jax")
    >>> agent.step(np.zeros((4, 3), np.float32)).shape     # an action for each of 4 workers
    (4, 1)
"""

from __future__ import annotations

from typing import Any

from ivy_rl.agents.a2c import A2C
from ivy_rl.agents.agent import Agent
from ivy_rl.agents.apg import APG
from ivy_rl.agents.baselines import Constant, Uniform
from ivy_rl.agents.d4pg import D4PG
from ivy_rl.agents.ddpg import DDPG
from ivy_rl.agents.defaults import (
    DEFAULTS,
    SETTINGS,
    check_setting,
    defaults_for,
    settings_table,
    task_family,
)
from ivy_rl.agents.dqn import DQN, BranchingDQN
from ivy_rl.agents.fusion import FUSION_LEVELS, compiled_scan_unrolls
from ivy_rl.agents.mpo import MPO
from ivy_rl.agents.ppo import PPO
from ivy_rl.agents.sac import SAC
from ivy_rl.agents.shac import SHAC
from ivy_rl.agents.td3 import TD3
from ivy_rl.agents.trpo import TRPO
from ivy_rl.settings import Setting

__all__ = [
    "Agent",
    "Uniform",
    "Constant",
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
    "AGENTS",
    "make",
    "DEFAULTS",
    "task_family",
    "settings_table",
    "check_setting",
    "compiled_scan_unrolls",
    "FUSION_LEVELS",
]

AGENTS: dict[str, type[Agent]] = {
    "A2C": A2C,
    "PPO": PPO,
    "TRPO": TRPO,
    "APG": APG,
    "SHAC": SHAC,
    "DDPG": DDPG,
    "TD3": TD3,
    "SAC": SAC,
    "MPO": MPO,
    "D4PG": D4PG,
    "DQN": DQN,
    "BranchingDQN": BranchingDQN,
    "Uniform": Uniform,
    "Constant": Constant,
}


def _resolve(name: str) -> str:
    """The key of :data:`AGENTS` for ``name`` (case-insensitive); a ValueError otherwise."""
    by_lower = {key.lower(): key for key in AGENTS}
    key = by_lower.get(str(name).lower())
    if key is None:
        raise ValueError(f"unknown agent {name!r}; available agents: {', '.join(AGENTS)}")
    return key


def make(name: str, *, environment: Any = None, **settings: Any) -> Agent:
    """An agent by name (``'PPO'``, ``'SAC'``, ``'DQN'``, ...; case-insensitive) with the
    defaults of the environment's task family (:data:`~ivy_rl.agents.defaults.DEFAULTS`),
    overridden by ``settings``.

    ``make(name)`` is ``AGENTS[name]()``; with an environment, the family's row may change
    some defaults (``python -m ivy_rl.agents.defaults SAC Pendulum-v1`` lists them). Every
    setting is checked once (type and range, declared by the agent's parts) before anything is
    built, and the error names it; ``agent.config`` holds every value used.

    Args:
        name: the agent's name.
        environment: a Gymnasium id (or environment) whose family's defaults apply; None: the
            agent's own defaults.
        settings: settings that override the defaults (JSON values, as ``--agent-kwargs``),
            or parts (``model=``, ``replay=``, ...).

    Returns:
        The agent, not initialized.

    Example:
        >>> make("PPO", environment="CartPole-v1").config["segment_size"]
        32
    """
    key = _resolve(name)
    return AGENTS[key](**{**defaults_for(key, environment), **settings})


make.resolve = _resolve

# every agent's flat settings, derived from their parts, for check_setting
for _cls in AGENTS.values():
    if _cls.parts is not None or _cls.own_settings:
        for _name, (_spec, _, _) in _cls.settings().items():
            SETTINGS.setdefault(_name, _spec)
SETTINGS.setdefault("value", Setting("any", meaning="Constant's action"))
