"""The model parts of the off-policy agents: what networks to build once the spaces are known,
how they act, and which of them have targets.

:class:`ActorQModel` (DDPG, TD3, SAC, MPO, D4PG): an actor (deterministic, squashed Gaussian or
Gaussian) and one or more action-value critics ``Q(s, a)`` (scalar or categorical), with target
copies. :class:`QModel` (DQN): a Q-network over discrete actions (one head, or one per
dimension of a MultiDiscrete space), with a target copy. Weights are drawn from the agent's
numpy generator in a fixed order (the actor's torso, its head, then each critic), so a seed
gives the same networks on every backend.

Example:
    >>> from ivy_rl.off_policy_models import ActorQModel
    >>> model = ActorQModel((64, 64), policy="squashed_gaussian", critics=2, targets=("critic",))
    >>> agent = ivy_rl.agents.SAC(model=model)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

import ivy
from ivy.typing import Framework
from ivy_rl import settings as _s
from ivy_rl.critics import (
    BranchingQHead,
    CriticEnsemble,
    DiscreteQHead,
    QNetwork,
    action_value_critic,
)
from ivy_rl.models import (
    Actor,
    ActorCriticWithTargets,
    DeterministicHead,
    GaussianHead,
    MLPTorso,
    ObservationEncoder,
    SquashedGaussianHead,
    orthogonal_init,
)

__all__ = ["ActorQModel", "QModel", "POLICIES"]

#: the policy heads of :class:`ActorQModel`
POLICIES = ("deterministic", "squashed_gaussian", "gaussian")


class ActorQModel:
    """An actor and action-value critics with targets: the model part of DDPG, TD3, SAC, MPO
    and D4PG.

    Args:
        hidden_sizes: hidden sizes of the actor's torso.
        critic_hidden_sizes: of the critics' torsos (None: ``hidden_sizes``).
        activation: activation of the torsos.
        policy: ``'deterministic'`` (``tanh`` of a dense layer; DDPG, TD3, D4PG),
            ``'squashed_gaussian'`` (SAC) or ``'gaussian'`` (``tanh`` mean, state-dependent
            scale in ``[1e-4, 1]``, samples clipped to ``[-1, 1]``; MPO). The Gaussian policies
            act by sampling (noise drawn by the agent's generator).
        critics: critics in the ensemble (2: twin critics, whose values stack on axis 0).
        critic_head: ``'value'`` (a scalar) or ``'categorical'`` (a distribution over
            ``atoms`` values in ``[v_min, v_max]``; D4PG).
        v_min, v_max, atoms: the categorical critic's support.
        normalize_observations: normalise observations by their running mean and std.
        targets: the parts with target networks (``'actor'``, ``'critic'``).
        target_tau: step of the targets' soft updates (1: copy).

    Example:
        >>> model = ivy_rl.off_policy_models.ActorQModel(policy="deterministic", critics=2)
        >>> agent = ivy_rl.agents.TD3(model=model)
    """

    settings = {
        "hidden_sizes": _s.SIZES,
        "critic_hidden_sizes": _s.CRITIC_SIZES,
        "activation": _s.ACTIVATION,
        "normalize_observations": _s.Setting(
            "bool", meaning="normalise observations by their running mean and std"
        ),
        "target_tau": _s.Setting(
            "float", 0.0, 1.0, open_low=True, meaning="soft update of targets"
        ),
        "v_min": _s.Setting("float", meaning="lowest value of the categorical critic's support"),
        "v_max": _s.Setting("float", meaning="highest value of the categorical critic's support"),
        "atoms": _s.Setting("int", 2, meaning="atoms of the categorical critic's support"),
    }

    def __init__(
        self,
        hidden_sizes: Sequence[int] = (256, 256),
        critic_hidden_sizes: Sequence[int] | None = None,
        activation: str = "relu",
        policy: str = "deterministic",
        critics: int = 1,
        critic_head: str = "value",
        v_min: float = -150.0,
        v_max: float = 150.0,
        atoms: int = 51,
        normalize_observations: bool = True,
        targets: Sequence[str] = ("actor", "critic"),
        target_tau: float = 0.005,
    ) -> None:
        if policy not in POLICIES:
            raise ValueError(
                f"ActorQModel: policy must be one of {', '.join(map(repr, POLICIES))}, "
                f"got {policy!r}"
            )
        if critic_head not in ("value", "categorical"):
            raise ValueError(
                f"ActorQModel: critic_head must be 'value' or 'categorical', got {critic_head!r}"
            )
        if critic_head == "categorical":
            if not v_min < v_max:
                raise ValueError(f"ActorQModel: v_min ({v_min}) must be below v_max ({v_max})")
            if atoms < 2:
                raise ValueError(f"ActorQModel: atoms must be >= 2, got {atoms}")
        if int(critics) != critics or critics < 1:
            raise ValueError(f"ActorQModel: critics must be an integer >= 1, got {critics!r}")
        if not set(targets) <= {"actor", "critic"}:
            raise ValueError(f"ActorQModel: targets are among 'actor', 'critic', got {targets}")
        _check_tau(target_tau, "ActorQModel")
        self.hidden_sizes = tuple(hidden_sizes)
        self.critic_hidden_sizes = (
            None if critic_hidden_sizes is None else tuple(critic_hidden_sizes)
        )
        self.activation, self.policy, self.critics = activation, policy, int(critics)
        self.critic_head = critic_head
        self.v_min, self.v_max, self.atoms = v_min, v_max, atoms
        self.normalize_observations = normalize_observations
        self.targets, self.target_tau = tuple(targets), target_tau

    @property
    def samples(self) -> bool:
        """Whether the policy acts by sampling (the agent passes standard normal noise)."""
        return self.policy != "deterministic"

    def initialize(
        self,
        observation_space: Any,
        action_space: Any,
        *,
        rng: np.random.Generator,
        dtype: Any = None,
        device: Any = None,
        f: Framework = None,
    ) -> ActorQModel:
        """Build the networks for the spaces, their weights drawn from ``rng``; then
        ``actor``, ``critic``, ``v`` (``{'actor', 'critic'}``) and ``target_v`` (the parts of
        ``targets``)."""
        self.xp = f = ivy.get_framework(f=f)
        build = {"dtype": dtype, "device": device, "f": f}
        observation_size = int(np.prod(observation_space.shape))
        self.action_size = action_size = int(np.prod(action_space.shape))
        torso = MLPTorso(
            observation_size,
            self.hidden_sizes,
            self.activation,
            weight_init=orthogonal_init(rng, math.sqrt(2.0)),
            **build,
        )
        init = orthogonal_init(rng, 0.01)
        if self.policy == "deterministic":
            head = DeterministicHead(torso.out_size, action_size, weight_init=init, **build)
        elif self.policy == "squashed_gaussian":
            head = SquashedGaussianHead(torso.out_size, action_size, weight_init=init, **build)
        else:
            head = GaussianHead(
                torso.out_size,
                action_size,
                loc_activation="tanh",
                state_dependent_scale=True,
                scale_min=1e-4,
                scale_max=1.0,
                weight_init=init,
                **build,
            )
        actor = Actor(ObservationEncoder(observation_size, f=f), torso, head)
        critics = [
            action_value_critic(
                observation_size,
                action_size,
                self.critic_hidden_sizes or self.hidden_sizes,
                rng=rng,
                activation=self.activation,
                head=self.critic_head,
                v_min=self.v_min,
                v_max=self.v_max,
                atoms=self.atoms,
                **build,
            )
            for _ in range(self.critics)
        ]
        critic = critics[0] if self.critics == 1 else CriticEnsemble(critics)
        self.module = ActorCriticWithTargets(actor, critic)
        self.actor, self.critic = actor, critic
        self.v = dict(self.module.v)
        self.target_v = {p: self.module.target_v[p] for p in self.targets}
        return self

    def q(self, critic_v: Any, observations: Any, actions: Any, obs_stats: Any) -> Any:
        """The critics' values ``[batch]`` (``[critics, batch]`` for an ensemble; categorical
        values for a categorical head)."""
        return self.critic(observations, actions, obs_stats, v=critic_v)

    def act(self, v: Any, obs_stats: Any, observations: Any, noise: Any) -> Any:
        """Actions of the behaviour policy in ``[-1, 1]`` (``noise``: standard normal
        ``[batch, actions]`` where the policy samples, else None)."""
        dist = self.actor(observations, obs_stats, v=v["actor"])
        if self.policy == "deterministic":
            return dist.mode()
        if self.policy == "squashed_gaussian":
            return dist.sample(noise)
        return self.xp.clip(dist.sample(noise), -1.0, 1.0)

    def mode(self, v: Any, obs_stats: Any, observations: Any) -> Any:
        """Actions of the test policy."""
        return self.actor(observations, obs_stats, v=v["actor"]).mode()


class QModel:
    """A Q-network over discrete actions with a target copy: the model part of DQN (a
    Discrete space: one head) and BranchingDQN (a MultiDiscrete space: one head per
    dimension over the shared torso).

    Args:
        hidden_sizes: hidden sizes of the torso.
        activation: activation of the torso.
        dueling: a dueling head (state value plus centred advantages).
        normalize_observations: normalise observations by their running mean and std.
        target_tau: step of the target network's soft updates (1: copy).

    Example:
        >>> model = ivy_rl.off_policy_models.QModel((64, 64), dueling=False)
        >>> ivy_rl.agents.DQN(model=model).config["dueling"]
        False
    """

    settings = {
        "hidden_sizes": _s.SIZES,
        "activation": _s.ACTIVATION,
        "dueling": _s.Setting("bool", meaning="a dueling head"),
        "normalize_observations": ActorQModel.settings["normalize_observations"],
        "target_tau": ActorQModel.settings["target_tau"],
    }

    samples = False
    targets = ("q",)

    def __init__(
        self,
        hidden_sizes: Sequence[int] = (64, 64),
        activation: str = "relu",
        dueling: bool = True,
        normalize_observations: bool = True,
        target_tau: float = 0.01,
    ) -> None:
        _check_tau(target_tau, "QModel")
        self.hidden_sizes, self.activation = tuple(hidden_sizes), activation
        self.dueling, self.normalize_observations = dueling, normalize_observations
        self.target_tau = target_tau

    def initialize(
        self,
        observation_space: Any,
        action_space: Any,
        *,
        rng: np.random.Generator,
        dtype: Any = None,
        device: Any = None,
        f: Framework = None,
    ) -> QModel:
        """Build the Q-network for the spaces (weights from ``rng``); then ``v`` and
        ``target_v`` (``{'q'}``) and ``branch_sizes``."""
        self.xp = f = ivy.get_framework(f=f)
        build = {"dtype": dtype, "device": device, "f": f}
        observation_size = int(np.prod(observation_space.shape))
        self.branching = type(action_space).__name__ == "MultiDiscrete"
        if self.branching:
            self.branch_sizes = tuple(int(n) for n in np.asarray(action_space.nvec).reshape(-1))
        else:
            self.branch_sizes = (int(action_space.n),)
        torso = MLPTorso(
            observation_size,
            self.hidden_sizes,
            self.activation,
            weight_init=orthogonal_init(rng, math.sqrt(2.0)),
            **build,
        )
        init = orthogonal_init(rng, 1.0)
        if self.branching:
            head = BranchingQHead(
                torso.out_size, self.branch_sizes, dueling=self.dueling, weight_init=init, **build
            )
        else:
            head = DiscreteQHead(
                torso.out_size,
                self.branch_sizes[0],
                dueling=self.dueling,
                weight_init=init,
                **build,
            )
        self.q_network = QNetwork(ObservationEncoder(observation_size, f=f), torso, head)
        self.v = {"q": self.q_network.v}
        self.target_v = {"q": self.q_network.v}
        return self

    def branches(self, q_v: Any, observations: Any, obs_stats: Any) -> list:
        """Action values per branch: a list of ``[..., n_d]``."""
        out = self.q_network(observations, obs_stats, v=q_v)
        return list(out) if self.branching else [out]

    def branch_actions(self, actions: Any) -> list:
        """The actions of each branch (indices)."""
        if not self.branching:
            return [actions]
        return [actions[..., d] for d in range(len(self.branch_sizes))]

    def greedy(self, branches: list) -> Any:
        xp = self.xp
        if not self.branching:
            return xp.argmax(branches[0], axis=-1)
        return xp.stack([xp.argmax(b, axis=-1) for b in branches], axis=-1)

    def act(self, v: Any, obs_stats: Any, observations: Any, noise: Any) -> Any:
        """Greedy actions (indices; ``[batch, dims]`` when branching)."""
        return self.greedy(self.branches(v["q"], observations, obs_stats))

    def mode(self, v: Any, obs_stats: Any, observations: Any) -> Any:
        return self.greedy(self.branches(v["q"], observations, obs_stats))


def _check_tau(tau: float, who: str) -> None:
    if not 0.0 < tau <= 1.0:
        raise ValueError(f"{who}: target_tau must be in (0, 1], got {tau!r}")
