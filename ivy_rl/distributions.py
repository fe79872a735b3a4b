"""Action distributions of policies, written once on a backend namespace ``xp``.

Sampling takes its noise as an argument (standard normal noise for Gaussians, Gumbel noise for
categoricals): the agents draw that noise from their own numpy generator, so a seed gives the
same actions on every backend, compiled code draws nothing, and a checkpoint holds the whole
random state as the generator's state.

Example:
    >>> import numpy as np, ivy
    >>> d = Normal(ivy.numpy, np.zeros(2), np.ones(2))
    >>> float(d.log_prob(np.zeros(2)))
    -1.8378770664093453
"""

from __future__ import annotations

import math
from typing import Any

from ivy.typing import Array

__all__ = ["Normal", "SquashedNormal", "Categorical", "Deterministic"]

_HALF_LOG_2PI = 0.5 * math.log(2.0 * math.pi)


class Normal:
    """Independent normal distributions over the last axis (a diagonal Gaussian).

    Args:
        xp: the backend namespace (``ivy.torch`` ...).
        loc: ``[..., n]`` means.
        scale: ``[..., n]`` standard deviations (broadcast against ``loc``).

    Example:
        >>> import torch, ivy
        >>> d = Normal(ivy.torch, torch.zeros(2), torch.ones(2))
        >>> a = d.sample(torch.tensor([1.0, -1.0]))      # the noise: standard normal draws
        >>> a, d.log_prob(a)
        (tensor([ 1., -1.]), tensor(-2.8379))
    """

    noise = "normal"

    def __init__(self, xp: Any, loc: Array, scale: Array) -> None:
        self.xp, self.loc = xp, loc
        self.scale = xp.broadcast_to(scale, tuple(loc.shape)) if scale.shape != loc.shape else scale

    def sample(self, noise: Array) -> Array:
        """``loc + scale * noise`` for standard normal ``noise`` of the shape of ``loc``."""
        return self.loc + self.scale * noise

    def mode(self) -> Array:
        """The most likely action: ``loc``."""
        return self.loc

    def sample_raw(self, noise: Array) -> Array:
        """The form of a sample that agents store (here the sample itself)."""
        return self.sample(noise)

    def log_prob_raw(self, raw: Array) -> Array:
        """Log-probability of a stored sample (here :meth:`log_prob`)."""
        return self.log_prob(raw)

    def raw_to_action(self, raw: Array) -> Array:
        """The action of a stored sample (here the sample itself)."""
        return raw

    def log_prob(self, actions: Array) -> Array:
        """Log-density of ``actions``, summed over the last axis: ``[...]``."""
        xp = self.xp
        z = (actions - self.loc) / self.scale
        per_dim = -0.5 * xp.square(z) - xp.log(self.scale) - _HALF_LOG_2PI
        return xp.sum(per_dim, axis=-1)

    def entropy(self) -> Array:
        """Entropy summed over the last axis: ``[...]``."""
        xp = self.xp
        return xp.sum(0.5 + _HALF_LOG_2PI + xp.log(self.scale), axis=-1)

    def kl(self, other: Normal) -> Array:
        """``KL(self || other)`` summed over the last axis: ``[...]``."""
        xp = self.xp
        var_ratio = xp.square(self.scale / other.scale)
        mean_term = xp.square((self.loc - other.loc) / other.scale)
        return xp.sum(0.5 * (var_ratio + mean_term - 1.0 - xp.log(var_ratio)), axis=-1)

    def params(self) -> dict[str, Array]:
        """The arrays that define the distribution, to store and rebuild it (:meth:`like`)."""
        return {"loc": self.loc, "scale": self.scale}

    def like(self, params: dict[str, Array]) -> Normal:
        """A distribution of the same kind from :meth:`params`' arrays."""
        return type(self)(self.xp, params["loc"], params["scale"])


class SquashedNormal(Normal):
    """``tanh`` of a diagonal Gaussian: actions in ``(-1, 1)``.

    Samples, log-probabilities and :meth:`mode` act on the squashed actions; the agents store
    the pre-squash samples (``raw``) because ``atanh`` of a squashed sample loses precision
    near ±1: :meth:`log_prob_raw` takes them.

    Example:
        >>> import jax.numpy as jnp, ivy
        >>> d = SquashedNormal(ivy.jax, jnp.zeros(1), jnp.ones(1))
        >>> raw = d.sample_raw(jnp.array([0.5]))           # what the agents store
        >>> d.squash(raw), d.log_prob_raw(raw)
        (Array([0.46211717], dtype=float32), Array(-0.8037095, dtype=float32))
    """

    def sample_raw(self, noise: Array) -> Array:
        """The pre-squash sample ``loc + scale * noise``."""
        return Normal.sample(self, noise)

    def squash(self, raw: Array) -> Array:
        """``tanh(raw)``."""
        return self.xp.tanh(raw)

    def raw_to_action(self, raw: Array) -> Array:
        return self.squash(raw)

    def sample(self, noise: Array) -> Array:
        return self.squash(self.sample_raw(noise))

    def mode(self) -> Array:
        return self.xp.tanh(self.loc)

    def log_prob_raw(self, raw: Array) -> Array:
        """Log-density of ``tanh(raw)`` from the pre-squash sample ``raw``."""
        xp = self.xp
        # log(1 - tanh(x)^2) = 2 (log 2 - x - softplus(-2x)), stable for large |x|
        correction = 2.0 * (math.log(2.0) - raw - xp.softplus(-2.0 * raw))
        return Normal.log_prob(self, raw) - xp.sum(correction, axis=-1)

    def log_prob(self, actions: Array) -> Array:
        xp = self.xp
        clipped = xp.clip(actions, -1.0 + 1e-6, 1.0 - 1e-6)
        return self.log_prob_raw(xp.atanh(clipped))

    def entropy(self) -> Array:
        """Entropy of the Gaussian before squashing (the squashed one has no closed form)."""
        return Normal.entropy(self)


class Categorical:
    """Categorical distributions over the last axis of ``logits``.

    Args:
        xp: the backend namespace.
        logits: ``[..., num_actions]`` unnormalised log-probabilities.

    Example:
        >>> import jax.numpy as jnp, ivy
        >>> d = Categorical(ivy.jax, jnp.log(jnp.array([[0.2, 0.8]])))
        >>> d.mode(), d.sample(jnp.array([[3.0, 0.0]]))        # the noise: Gumbel draws
        (Array([1], dtype=int32), Array([0], dtype=int32))
    """

    noise = "gumbel"

    def __init__(self, xp: Any, logits: Array) -> None:
        self.xp = xp
        self.logits = logits - xp.logsumexp(logits, axis=-1, keepdims=True)

    def sample(self, noise: Array) -> Array:
        """Gumbel-max sampling: ``argmax(logits + noise)`` for Gumbel ``noise``; int64 ``[...]``."""
        return self.xp.argmax(self.logits + noise, axis=-1)

    def mode(self) -> Array:
        return self.xp.argmax(self.logits, axis=-1)

    def log_prob(self, actions: Array) -> Array:
        """``log p(actions)`` for integer actions ``[...]`` (any integer or float dtype)."""
        xp = self.xp
        n = self.logits.shape[-1]
        one_hot = xp.one_hot(xp.astype(actions, "int32"), n, dtype=self.logits.dtype)
        return xp.sum(one_hot * self.logits, axis=-1)

    def sample_raw(self, noise: Array) -> Array:
        return self.sample(noise)

    def log_prob_raw(self, raw: Array) -> Array:
        return self.log_prob(raw)

    def raw_to_action(self, raw: Array) -> Array:
        return raw

    def probs(self) -> Array:
        return self.xp.exp(self.logits)

    def entropy(self) -> Array:
        return -self.xp.sum(self.probs() * self.logits, axis=-1)

    def kl(self, other: Categorical) -> Array:
        return self.xp.sum(self.probs() * (self.logits - other.logits), axis=-1)

    def params(self) -> dict[str, Array]:
        return {"logits": self.logits}

    def like(self, params: dict[str, Array]) -> Categorical:
        return Categorical(self.xp, params["logits"])


class Deterministic:
    """A point mass at ``actions`` (deterministic policies); ``sample`` adds exploration noise
    scaled by ``noise_scale`` and clips to ``[-1, 1]``.

    Example:
        >>> import torch, ivy
        >>> d = Deterministic(ivy.torch, torch.tensor([0.5, 0.95]), noise_scale=0.1)
        >>> d.sample(torch.tensor([1.0, 1.0]))             # noise: standard normal draws
        tensor([0.6000, 1.0000])
    """

    noise = "normal"

    def __init__(self, xp: Any, actions: Array, noise_scale: float = 0.1) -> None:
        self.xp, self.actions, self.noise_scale = xp, actions, noise_scale

    def sample(self, noise: Array) -> Array:
        return self.xp.clip(self.actions + self.noise_scale * noise, -1.0, 1.0)

    def mode(self) -> Array:
        return self.actions

    def sample_raw(self, noise: Array) -> Array:
        return self.sample(noise)

    def raw_to_action(self, raw: Array) -> Array:
        return raw

    def params(self) -> dict[str, Array]:
        return {"actions": self.actions}

    def like(self, params: dict[str, Array]) -> Deterministic:
        return Deterministic(self.xp, params["actions"], self.noise_scale)
