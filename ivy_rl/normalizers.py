"""Normalisers of observations and returns: running mean and standard deviation, kept in
float64 numpy on the host and updated from the data the agent sees.

An agent records values as they arrive (:meth:`MeanStd.record`) and folds them into the
statistics at each update (:meth:`MeanStd.update`), so the statistics stay fixed while a batch
is used. :meth:`MeanStd.stats` gives ``{'mean', 'std'}`` in the model's dtype for the models'
calls, and :meth:`MeanStd.state_dict` everything a checkpoint needs.

Example:
    >>> import numpy as np
    >>> norm = MeanStd((2,))
    >>> norm.record(np.array([[0.0, 1.0], [2.0, 3.0]])); norm.update()
    >>> norm.mean, norm.std
    (array([1., 2.]), array([1., 1.]))
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

__all__ = ["MeanStd", "ReturnNormalizer"]


class MeanStd:
    """Running mean and standard deviation over all values recorded so far.

    Args:
        shape: shape of one value (``()`` for scalars).
        epsilon: lower bound of the standard deviation.

    Example:
        A constant feature's standard deviation is ``epsilon``, never 0:

        >>> import numpy as np
        >>> norm = MeanStd((2,))
        >>> norm.record(np.array([[1.0, 0.0], [3.0, 0.0]])); norm.update()
        >>> norm.stats("float32")
        {'mean': array([2., 0.], dtype=float32), 'std': array([1.  , 0.01], dtype=float32)}
    """

    def __init__(self, shape: Sequence[int] = (), *, epsilon: float = 1e-2) -> None:
        self.shape = tuple(int(s) for s in shape)
        self.epsilon = float(epsilon)
        self.count = 0
        self.mean = np.zeros(self.shape)
        self.mean_sq = np.ones(self.shape)
        self.std = np.ones(self.shape)
        self._reset_pending()

    def _reset_pending(self) -> None:
        self.new_count = 0
        self.new_sum = np.zeros(self.shape)
        self.new_sum_sq = np.zeros(self.shape)

    def record(self, values: Any) -> None:
        """Add ``values`` of shape ``[..., *shape]`` to the pending sums."""
        values = np.asarray(values, dtype=np.float64)
        if values.shape[values.ndim - len(self.shape) :] != self.shape:
            raise ValueError(f"values of shape {values.shape} do not end with {self.shape}")
        flat = values.reshape((-1,) + self.shape)
        self.new_count += flat.shape[0]
        self.new_sum += flat.sum(axis=0)
        self.new_sum_sq += np.square(flat).sum(axis=0)

    def update(self) -> None:
        """Fold the pending values into the mean and standard deviation."""
        if self.new_count == 0:
            return
        self.count, self.mean, self.mean_sq = _fold_moments(
            self.count, self.mean, self.mean_sq, self.new_count, self.new_sum, self.new_sum_sq
        )
        self.std = _standard_deviation(np, self.mean, self.mean_sq, self.epsilon)
        self._reset_pending()

    def moments(self, dtype: Any = "float32") -> dict[str, np.ndarray]:
        """``{'count', 'mean', 'mean_sq'}`` as numpy arrays of ``dtype``: the state that a
        compiled function folds new values into (see :meth:`set_moments`)."""
        return {
            "count": np.asarray(self.count, dtype),
            "mean": self.mean.astype(dtype),
            "mean_sq": self.mean_sq.astype(dtype),
        }

    def set_moments(self, count: Any, mean: Any, mean_sq: Any) -> None:
        """Take the count and moments computed elsewhere (e.g. :meth:`moments` folded inside a
        compiled update); the standard deviation follows."""
        self.count = int(np.rint(np.asarray(count, np.float64)))
        self.mean = np.asarray(mean, np.float64).reshape(self.shape)
        self.mean_sq = np.asarray(mean_sq, np.float64).reshape(self.shape)
        self.std = _standard_deviation(np, self.mean, self.mean_sq, self.epsilon)

    def stats(self, dtype: Any = "float32") -> dict[str, np.ndarray]:
        """``{'mean', 'std'}`` as numpy arrays of ``dtype``."""
        return {"mean": self.mean.astype(dtype), "std": self.std.astype(dtype)}

    def normalize(self, values: Any) -> np.ndarray:
        """``(values - mean) / std`` in numpy."""
        return (np.asarray(values) - self.mean) / self.std

    def state_dict(self) -> dict[str, np.ndarray]:
        """The statistics and the pending sums, as numpy arrays."""
        return {
            "count": np.asarray(self.count, np.int64),
            "mean": self.mean,
            "mean_sq": self.mean_sq,
            "std": self.std,
            "new_count": np.asarray(self.new_count, np.int64),
            "new_sum": self.new_sum,
            "new_sum_sq": self.new_sum_sq,
        }

    def load_state_dict(self, state: dict[str, Any]) -> None:
        """Restore :meth:`state_dict`'s arrays."""
        self.count = int(state["count"])
        self.new_count = int(state["new_count"])
        for key in ("mean", "mean_sq", "std", "new_sum", "new_sum_sq"):
            value = np.asarray(state[key], np.float64)
            if value.shape != self.shape:
                raise ValueError(f"{key} has shape {value.shape}, expected {self.shape}")
            setattr(self, key, value)


def _fold_moments(count, mean, mean_sq, new_count, new_sum, new_sum_sq):
    """``(count, mean, mean_sq)`` after adding ``new_count`` values of sum ``new_sum`` and sum of
    squares ``new_sum_sq``; plain arithmetic, so numpy values and arrays of any backend (inside
    compiled functions too) work alike."""
    total = count + new_count
    w_old, w_new = count / total, new_count / total
    mean = w_old * mean + w_new * (new_sum / new_count)
    mean_sq = w_old * mean_sq + w_new * (new_sum_sq / new_count)
    return total, mean, mean_sq


def _standard_deviation(xp, mean, mean_sq, epsilon):
    """``max(sqrt(max(mean_sq - mean², 0)), epsilon)`` on the backend namespace ``xp``."""
    variance = xp.maximum(mean_sq - mean * mean, 0.0)
    return xp.maximum(xp.sqrt(variance), epsilon)


class ReturnNormalizer(MeanStd):
    """Mean and standard deviation of the critic's targets (the λ-returns): the critic's head
    predicts ``(return - mean) / std`` and the critic returns ``head * std + mean``.

    Example:
        >>> import numpy as np
        >>> norm = ReturnNormalizer()
        >>> norm.record(np.array([10.0, 20.0, 30.0])); norm.update()     # λ-returns of a batch
        >>> norm.normalize(np.array([10.0, 20.0, 30.0])).round(3)
        array([-1.225,  0.   ,  1.225])
    """

    def __init__(self, *, epsilon: float = 1e-2) -> None:
        super().__init__((), epsilon=epsilon)
