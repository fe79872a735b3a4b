"""Critics of off-policy agents: action values ``Q(s, a)``, twin critics, a categorical
distributional value head (D4PG), Q-networks over discrete actions (dueling, and one branch per
action dimension for MultiDiscrete spaces), and target networks moved by soft updates.

Like :mod:`ivy_rl.models`, each part is an ``ivy.Module`` called purely with its variables
``v`` and the observation statistics, so the whole update compiles.

Example:
    >>> import numpy as np, jax.numpy as jnp
    >>> critic = action_value_critic(3, 1, (64, 64), rng=np.random.default_rng(0), f="jax")
    >>> obs, actions = jnp.zeros((5, 3)), jnp.zeros((5, 1))
    >>> critic(obs, actions, None, v=critic.v).shape          # [batch]
    (5,)
    >>> target_v = ivy_rl.models.polyak_update(critic.v, critic.v, 0.005)   # a target network
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

import ivy
from ivy.typing import Array, Framework, Nest
from ivy_rl.models import (
    MLPTorso,
    ObservationEncoder,
    ValueHead,
    orthogonal_init,
    polyak_update,
)

__all__ = [
    "ActionValueCritic",
    "CriticEnsemble",
    "CategoricalValueHead",
    "CategoricalValues",
    "QNetwork",
    "DiscreteQHead",
    "BranchingQHead",
    "project_categorical",
    "soft_update",
    "action_value_critic",
]


class ActionValueCritic(ivy.Module):
    """``head(torso([encoder(obs, stats), actions]))``: an action-value function.

    Called as ``critic(obs, actions, obs_stats, v=...)``; the output is the head's (``[batch]``
    for a :class:`~ivy_rl.models.ValueHead`, a :class:`CategoricalValues` for a
    :class:`CategoricalValueHead`).

    Example:
        >>> import torch
        >>> critic = ActionValueCritic(ObservationEncoder(3), MLPTorso(4, (64,), f="torch"),
        ...                            ValueHead(64, f="torch"))    # torso: 3 + 1 inputs
        >>> critic(torch.zeros(5, 3), torch.zeros(5, 1), None).shape
        torch.Size([5])
    """

    def __init__(self, encoder: Callable, torso: ivy.Module, head: ivy.Module) -> None:
        super().__init__(dtype=torso.dtype, device=torso.device, f=torso.f)
        self.encoder, self.torso, self.head = encoder, torso, head

    def _forward(self, v, obs, actions, obs_stats=None):
        x = self._f.concat([self.encoder(obs, obs_stats), actions], axis=-1)
        return self.head(self.torso(x, v=v["torso"]), v=v["head"])


class CriticEnsemble(ivy.Module):
    """Several critics of the same inputs (twin critics: two), outputs stacked on a new
    leading axis: ``[critics, batch]``.

    Example:
        >>> import numpy as np, jax.numpy as jnp
        >>> rng = np.random.default_rng(0)
        >>> twin = CriticEnsemble([action_value_critic(3, 1, (64,), rng=rng, f="jax")
        ...                        for _ in range(2)])
        >>> twin(jnp.zeros((5, 3)), jnp.zeros((5, 1)), None).shape   # [critics, batch]
        (2, 5)
    """

    def __init__(self, critics: Sequence[ivy.Module]) -> None:
        first = critics[0]
        super().__init__(dtype=first.dtype, device=first.device, f=first.f)
        self.critics = list(critics)

    def _forward(self, v, *args):
        outs = [c(*args, v=v["critics"][str(i)]) for i, c in enumerate(self.critics)]
        return self._f.stack(outs, axis=0)


class CategoricalValues:
    """A categorical distribution of values over a fixed support (the atoms).

    Attributes:
        logits: ``[..., atoms]`` log-probabilities (normalised).
        support: ``[atoms]`` the values of the atoms.
    """

    def __init__(self, xp: Any, logits: Array, support: Array) -> None:
        self.xp, self.support = xp, support
        self.logits = xp.log_softmax(logits, axis=-1)

    def probs(self) -> Array:
        return self.xp.exp(self.logits)

    def mean(self) -> Array:
        """The expected value ``[...]``."""
        return self.xp.sum(self.probs() * self.support, axis=-1)


class CategoricalValueHead(ivy.Module):
    """A distributional value head (C51 / D4PG): logits over ``atoms`` values evenly spaced in
    ``[v_min, v_max]``; returns :class:`CategoricalValues`.

    Example:
        >>> import torch
        >>> head = CategoricalValueHead(64, -150.0, 150.0, 51, f="torch")
        >>> values = head(torch.zeros(2, 64))           # uniform over the atoms here
        >>> values.probs().shape, values.mean()
        (torch.Size([2, 51]), tensor([0., 0.]))
    """

    def __init__(
        self,
        in_size: int,
        v_min: float = -150.0,
        v_max: float = 150.0,
        atoms: int = 51,
        *,
        weight_init: Callable | None = None,
        dtype=None,
        device=None,
        f=None,
    ) -> None:
        super().__init__(dtype=dtype, device=device, f=f)
        if not v_min < v_max or atoms < 2:
            raise ValueError(
                f"CategoricalValueHead needs v_min < v_max and atoms >= 2, got v_min={v_min}, "
                f"v_max={v_max}, atoms={atoms}"
            )
        init = weight_init or orthogonal_init(np.random.default_rng(0), 1.0)
        self.layer = ivy.Linear(in_size, int(atoms), weight_init=init, **self.build_args)
        self.v_min, self.v_max, self.atoms = float(v_min), float(v_max), int(atoms)

    def support(self) -> Array:
        values = np.linspace(self.v_min, self.v_max, self.atoms)
        return self._f.asarray(values, dtype=self.dtype, device=self.device)

    def _forward(self, v, x):
        return CategoricalValues(self._f, self.layer(x, v=v["layer"]), self.support())


def project_categorical(
    xp: Any, probs: Array, returns: Array, discounts: Array, support: Array
) -> Array:
    """The categorical projection of D4PG/C51: the distribution of ``returns + discounts * Z``
    (``Z`` with ``probs`` on ``support``) put back on ``support``, each shifted atom split
    between its two nearest atoms (values beyond the ends go to the ends). Branch-free.

    Args:
        xp: backend namespace.
        probs: ``[batch, atoms]`` probabilities of the next values.
        returns: ``[batch]`` (n-step) rewards.
        discounts: ``[batch]`` discounts (0 after a termination).
        support: ``[atoms]`` evenly spaced values.

    Returns:
        ``[batch, atoms]`` target probabilities.

    Example:
        A return of 0.5 plus 0.9 times a value of 0 falls half-way between the atoms 0 and 1:

        >>> import jax.numpy as jnp, ivy
        >>> support = jnp.array([-1.0, 0.0, 1.0])
        >>> probs = jnp.array([[0.0, 1.0, 0.0]])                 # the next value is 0
        >>> project_categorical(ivy.jax, probs, jnp.array([0.5]), jnp.array([0.9]), support)
        Array([[0. , 0.5, 0.5]], dtype=float32)
    """
    atoms = int(support.shape[0])
    v_min, v_max = support[0], support[atoms - 1]
    spacing = (v_max - v_min) / (atoms - 1)
    shifted = xp.clip(returns[:, None] + discounts[:, None] * support[None, :], v_min, v_max)
    # weight of shifted atom j on atom i: max(0, 1 - |shifted_j - z_i| / spacing)
    distance = xp.abs(shifted[:, None, :] - support[None, :, None]) / spacing
    weights = xp.clip(1.0 - distance, 0.0, 1.0)
    return xp.sum(weights * probs[:, None, :], axis=-1)


class DiscreteQHead(ivy.Module):
    """Action values of ``num_actions`` discrete actions ``[..., num_actions]``; with
    ``dueling``: ``V(s) + A(s, a) - mean_a A(s, a)`` (Wang et al., 2016).

    Example:
        >>> import jax.numpy as jnp
        >>> DiscreteQHead(64, 2, dueling=True, f="jax")(jnp.ones((5, 64))).shape
        (5, 2)
    """

    def __init__(
        self,
        in_size: int,
        num_actions: int,
        *,
        dueling: bool = False,
        weight_init: Callable | None = None,
        dtype=None,
        device=None,
        f=None,
    ) -> None:
        super().__init__(dtype=dtype, device=device, f=f)
        init = weight_init or orthogonal_init(np.random.default_rng(0), 1.0)
        self.advantages = ivy.Linear(in_size, int(num_actions), weight_init=init, **self.build_args)
        self.dueling = bool(dueling)
        if self.dueling:
            self.value = ValueHead(in_size, weight_init=init, **self.build_args)
        self.num_actions = int(num_actions)

    def _forward(self, v, x):
        advantages = self.advantages(x, v=v["advantages"])
        if not self.dueling:
            return advantages
        value = self.value(x, v=v["value"])
        return value[..., None] + advantages - self._f.mean(advantages, axis=-1, keepdims=True)


class BranchingQHead(ivy.Module):
    """One :class:`DiscreteQHead` per action dimension over shared features (action branching,
    Tavakoli et al., 2018): a list of ``[..., n_d]`` action values; with ``dueling`` the
    branches share one state value.

    Example:
        >>> import torch
        >>> head = BranchingQHead(64, [3, 5], dueling=True, f="torch")
        >>> [q.shape[-1] for q in head(torch.ones(2, 64))]
        [3, 5]
    """

    def __init__(
        self,
        in_size: int,
        sizes: Sequence[int],
        *,
        dueling: bool = False,
        weight_init: Callable | None = None,
        dtype=None,
        device=None,
        f=None,
    ) -> None:
        super().__init__(dtype=dtype, device=device, f=f)
        init = weight_init or orthogonal_init(np.random.default_rng(0), 1.0)
        self.sizes = tuple(int(n) for n in sizes)
        self.branches = [
            ivy.Linear(in_size, n, weight_init=init, **self.build_args) for n in self.sizes
        ]
        self.dueling = bool(dueling)
        if self.dueling:
            self.value = ValueHead(in_size, weight_init=init, **self.build_args)

    def _forward(self, v, x):
        xp = self._f
        outs = [b(x, v=v["branches"][str(i)]) for i, b in enumerate(self.branches)]
        if not self.dueling:
            return outs
        value = self.value(x, v=v["value"])[..., None]
        return [value + a - xp.mean(a, axis=-1, keepdims=True) for a in outs]


class QNetwork(ivy.Module):
    """``head(torso(encoder(obs, stats)))`` for value-based agents: action values of every
    discrete action. Called as ``q(obs, obs_stats, v=...)``.

    Example:
        >>> import torch
        >>> q = QNetwork(ObservationEncoder(4), MLPTorso(4, (64, 64), f="torch"),
        ...              DiscreteQHead(64, 2, f="torch"))
        >>> q(torch.zeros(5, 4), None).shape            # [batch, actions]
        torch.Size([5, 2])
    """

    def __init__(self, encoder: Callable, torso: ivy.Module, head: ivy.Module) -> None:
        super().__init__(dtype=torso.dtype, device=torso.device, f=torso.f)
        self.encoder, self.torso, self.head = encoder, torso, head

    def _forward(self, v, obs, obs_stats=None):
        x = self.encoder(obs, obs_stats)
        return self.head(self.torso(x, v=v["torso"]), v=v["head"])


def soft_update(target_v: Nest, v: Nest, tau: float, *, f: Framework = None) -> Nest:
    """Deprecated: :func:`ivy_rl.models.polyak_update` (the same function, the one name kept).

    Example:
        >>> ivy_rl.models.polyak_update({"a": np.zeros(2)}, {"a": np.ones(2)}, 0.5, f="numpy")
        {'a': array([0.5, 0.5])}
    """
    warnings.warn(
        "ivy_rl.critics.soft_update is deprecated: use ivy_rl.models.polyak_update (the same "
        "function)",
        DeprecationWarning,
        stacklevel=2,
    )
    return polyak_update(target_v, v, tau, f=f)


def action_value_critic(
    observation_size: int,
    action_size: int,
    sizes: Sequence[int] = (256, 256),
    *,
    rng: np.random.Generator,
    activation: str = "relu",
    head: str = "value",
    v_min: float = -150.0,
    v_max: float = 150.0,
    atoms: int = 51,
    observation_clip: float | None = 10.0,
    dtype: Any = None,
    device: Any = None,
    f: Framework = None,
) -> ActionValueCritic:
    """An action-value critic initialised from ``rng`` (orthogonal weights, gain ``sqrt(2)`` in
    the torso and 1 in the head).

    Args:
        observation_size: features of a flattened observation.
        action_size: features of an action.
        sizes: hidden sizes of the torso.
        rng: numpy generator of the initial weights.
        activation: of the torso.
        head: ``'value'`` (a scalar) or ``'categorical'`` (a distribution over ``atoms``
            values in ``[v_min, v_max]``).
        observation_clip: bound of normalised observations.
        dtype, device, f: as for ``ivy.Module``.

    Returns:
        The critic.

    Example:
        >>> critic = action_value_critic(3, 1, (64, 64), rng=np.random.default_rng(0), f="jax")
    """
    build = {"dtype": dtype, "device": device, "f": f}
    torso = MLPTorso(
        observation_size + action_size,
        sizes,
        activation,
        weight_init=orthogonal_init(rng, math.sqrt(2.0)),
        **build,
    )
    init = orthogonal_init(rng, 1.0)
    if head == "value":
        out = ValueHead(torso.out_size, weight_init=init, **build)
    elif head == "categorical":
        out = CategoricalValueHead(torso.out_size, v_min, v_max, atoms, weight_init=init, **build)
    else:
        raise ValueError(
            f"action_value_critic: head must be 'value' or 'categorical', got {head!r}"
        )
    encoder = ObservationEncoder(observation_size, clip=observation_clip, f=f)
    return ActionValueCritic(encoder, torso, out)
