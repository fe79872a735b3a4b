"""A segment replay for on-policy agents: the last ``size`` steps of every worker, their
λ-returns and advantages, and mini-batches drawn from them.

Buffers are numpy arrays ``[size, workers, ...]`` on the host; returns and advantages use
:func:`ivy_rl.returns.lambda_returns` with partial-episode bootstrapping (bootstrapped at time
limits, not at terminations).

Example:
    >>> seg = Segment(size=4, discount=0.99, trace_decay=0.95)
    >>> seg.store(observations=obs, actions=a, rewards=r, resets=d, terminations=t)
    >>> seg.ready()
    False
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import numpy as np

import ivy
from ivy_rl.returns import lambda_returns

__all__ = ["Segment"]


class Segment:
    """The replay of on-policy agents.

    Args:
        size: steps per worker in a segment (the update happens when it is full).
        discount: γ of the returns.
        trace_decay: λ of the returns.
        batch_size: transitions per mini-batch (None: the whole segment).
        batch_iterations: passes over the segment (epochs) per update.

    Example:
        >>> seg = Segment(size=2048, batch_size=64, batch_iterations=10)
    """

    def __init__(
        self,
        size: int = 2048,
        *,
        discount: float = 0.99,
        trace_decay: float = 0.95,
        batch_size: int | None = None,
        batch_iterations: int = 10,
    ) -> None:
        if size < 1:
            raise ValueError(f"Segment: size must be >= 1, got {size}")
        if batch_size is not None and batch_size < 1:
            raise ValueError(f"Segment: batch_size must be >= 1 or None, got {batch_size}")
        self.size = int(size)
        self.discount = float(discount)
        self.trace_decay = float(trace_decay)
        self.batch_size = batch_size
        self.batch_iterations = int(batch_iterations)
        self.buffers: dict[str, np.ndarray] | None = None
        self.index = 0

    def ready(self) -> bool:
        """Whether the segment is full."""
        return self.index == self.size

    def store(self, **arrays: Any) -> None:
        """Store one step of every worker: arrays ``[workers, ...]`` by name."""
        if self.index >= self.size:
            raise RuntimeError("Segment is full: call get_full() or clear() before storing more")
        if self.buffers is None:
            self.buffers = {
                k: np.zeros((self.size,) + np.shape(v), np.asarray(v).dtype)
                for k, v in arrays.items()
            }
        for key, value in arrays.items():
            self.buffers[key][self.index] = value
        self.index += 1

    @property
    def workers(self) -> int:
        return 0 if self.buffers is None else next(iter(self.buffers.values())).shape[1]

    def compute_returns(self, values: np.ndarray, next_values: np.ndarray) -> None:
        """Store ``values``, ``returns`` (λ-returns) and ``advantages`` (returns - values)
        from the critic's ``values`` and ``next_values`` of shape ``[size, workers]``."""
        b = self.buffers
        values = np.asarray(values).reshape(b["rewards"].shape)
        next_values = np.asarray(next_values).reshape(b["rewards"].shape)
        returns = lambda_returns(
            b["rewards"].astype(values.dtype),
            next_values,
            b["resets"],
            b["terminations"],
            discount=self.discount,
            trace_decay=self.trace_decay,
            f=ivy.numpy,
        )
        b["values"], b["next_values"], b["returns"] = values, next_values, returns
        b["advantages"] = returns - values

    def get_full(self, *keys: str, normalize_advantages: bool = True) -> dict[str, np.ndarray]:
        """The named buffers flattened to ``[size * workers, ...]``; ``advantages``
        standardised unless ``normalize_advantages`` is False."""
        out = {}
        for key in keys:
            value = self.buffers[key]
            if key == "advantages" and normalize_advantages:
                std = value.std()
                value = (value - value.mean()) / (std if std > 0 else 1.0)
            out[key] = value.reshape((-1,) + value.shape[2:])
        return out

    def batch_indices(self, rng: np.random.Generator) -> Iterator[np.ndarray | None]:
        """Index arrays of the mini-batches of all passes (None: the whole segment)."""
        total = self.size * self.workers
        for _ in range(self.batch_iterations):
            if self.batch_size is None or self.batch_size >= total:
                yield None
                continue
            order = rng.permutation(total)
            for start in range(0, total - self.batch_size + 1, self.batch_size):
                yield order[start : start + self.batch_size]

    def clear(self) -> None:
        """Start a new segment."""
        self.index = 0

    def state_dict(self) -> dict[str, np.ndarray]:
        """The buffers and the write position."""
        state = {"index": np.asarray(self.index, np.int64)}
        for key, value in (self.buffers or {}).items():
            state[f"buffers/{key}"] = value
        return state

    def load_state_dict(self, state: dict[str, Any]) -> None:
        self.index = int(state["index"])
        buffers = {k.split("/", 1)[1]: np.array(v) for k, v in state.items() if "/" in k}
        self.buffers = buffers or None
