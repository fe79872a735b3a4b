"""Agents: the :class:`Agent` interface, baselines (``Uniform``, ``Constant``) and the
on-policy agents ``A2C``, ``PPO`` and ``TRPO`` (Box and Discrete actions).

Example:
    >>> agent = ivy_rl.agents.make("PPO", batch_size=64)
    >>> agent.initialize(env.observation_space, env.action_space, seed=0, f="torch")
"""

from __future__ import annotations

from typing import Any

from ivy_rl.agents.a2c import A2C
from ivy_rl.agents.agent import Agent
from ivy_rl.agents.apg import APG
from ivy_rl.agents.baselines import Constant, Uniform
from ivy_rl.agents.fusion import FUSION_LEVELS, compiled_scan_unrolls
from ivy_rl.agents.ppo import PPO
from ivy_rl.agents.shac import SHAC
from ivy_rl.agents.trpo import TRPO

__all__ = [
    "Agent",
    "Uniform",
    "Constant",
    "A2C",
    "PPO",
    "TRPO",
    "APG",
    "SHAC",
    "AGENTS",
    "make",
    "compiled_scan_unrolls",
    "FUSION_LEVELS",
]

AGENTS: dict[str, type[Agent]] = {
    "A2C": A2C,
    "PPO": PPO,
    "TRPO": TRPO,
    "APG": APG,
    "SHAC": SHAC,
    "Uniform": Uniform,
    "Constant": Constant,
}


def make(name: str, **settings: Any) -> Agent:
    """An agent by name (``'PPO'``, ``'A2C'``, ``'TRPO'``, ``'Uniform'``, ``'Constant'``;
    case-insensitive) with its settings.

    Example:
        >>> make("ppo", epochs=20)
        PPO({...})
    """
    by_lower = {key.lower(): cls for key, cls in AGENTS.items()}
    cls = by_lower.get(str(name).lower())
    if cls is None:
        raise ValueError(f"unknown agent {name!r}; available agents: {', '.join(AGENTS)}")
    return cls(**settings)
