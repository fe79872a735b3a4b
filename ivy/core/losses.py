"""Loss functions: compositions written once for every backend.

Every loss takes ``(pred, target)`` of the same (or broadcastable) shapes and a ``reduction``:
``'mean'`` (the default: the mean over every element, or over every sample for the categorical
loss), ``'sum'``, or ``'none'`` (the unreduced losses). Targets are arrays of floats: the
categorical loss takes one-hot or probability targets, never integer class indices (convert them
with ``ivy.one_hot(labels, depth, dtype=...)``). Cross-entropies from logits are computed in the
stable forms (``softplus``/``log_softmax``); from probabilities, the predictions are clipped to
``[eps, 1 - eps]`` (``[eps, 1]`` for the categorical loss) before the log.
"""

from __future__ import annotations

from typing import Literal

from ivy import framework_handler as _fh
from ivy.core._dispatch import composition
from ivy.typing import Array, Framework

__all__ = ["mse", "huber", "binary_cross_entropy", "categorical_cross_entropy"]

_REDUCTIONS = ("mean", "sum", "none")


def _check_reduction(reduction, fn):
    if reduction not in _REDUCTIONS:
        raise ValueError(f"{fn}: unknown reduction {reduction!r}; use 'mean', 'sum' or 'none'.")


def _reduce(xp, loss, reduction):
    if reduction == "mean":
        return xp.mean(loss)
    if reduction == "sum":
        return xp.sum(loss)
    return loss


@composition
def mse(
    pred: Array,
    target: Array,
    /,
    *,
    reduction: Literal["mean", "sum", "none"] = "mean",
    f: Framework = None,
) -> Array:
    """Mean squared error ``(pred - target) ** 2``, reduced.

    Args:
        pred: predictions.
        target: targets, broadcastable to ``pred``.
        reduction: ``'mean'``, ``'sum'`` or ``'none'``.

    Returns:
        A scalar array, or the elementwise losses for ``reduction='none'``.

    Example:
        >>> ivy.mse(np.array([1., 2.]), np.array([0., 0.]))
        np.float64(2.5)
    """
    _check_reduction(reduction, "mse")
    xp = _fh.get_framework(pred, f=f)
    return _reduce(xp, xp.square(xp.subtract(pred, target)), reduction)


@composition
def huber(
    pred: Array,
    target: Array,
    /,
    *,
    delta: float = 1.0,
    reduction: Literal["mean", "sum", "none"] = "mean",
    f: Framework = None,
) -> Array:
    """Huber loss: ``d**2 / 2`` where ``|d| <= delta``, else ``delta * (|d| - delta / 2)``, with
    ``d = pred - target`` (torch's ``HuberLoss``, tf's ``Huber``).

    Args:
        pred: predictions.
        target: targets, broadcastable to ``pred``.
        delta: where the loss turns from quadratic to linear (> 0).
        reduction: ``'mean'``, ``'sum'`` or ``'none'``.

    Returns:
        A scalar array, or the elementwise losses for ``reduction='none'``.

    Example:
        >>> ivy.huber(np.array([0.5, 3.]), np.array([0., 0.]), reduction="none")
        array([0.125, 2.5  ])
    """
    _check_reduction(reduction, "huber")
    if not delta > 0:
        raise ValueError(f"huber: delta must be positive, got {delta!r}.")
    xp = _fh.get_framework(pred, f=f)
    d = xp.subtract(pred, target)
    a = xp.abs(d)
    quadratic = xp.multiply(xp.square(d), 0.5)
    linear = xp.multiply(xp.subtract(a, 0.5 * delta), delta)
    return _reduce(xp, xp.where(xp.less_equal(a, delta), quadratic, linear), reduction)


@composition
def binary_cross_entropy(
    pred: Array,
    target: Array,
    /,
    *,
    from_logits: bool = False,
    reduction: Literal["mean", "sum", "none"] = "mean",
    eps: float = 1e-7,
    f: Framework = None,
) -> Array:
    """Binary cross-entropy ``-(t log p + (1 - t) log(1 - p))``, elementwise, reduced.

    Args:
        pred: probabilities ``p`` in ``[0, 1]``, or logits with ``from_logits=True``.
        target: targets ``t`` in ``[0, 1]`` (hard 0/1 labels or soft labels), broadcastable.
        from_logits: ``pred`` are logits ``z``; the loss is then computed stably as
            ``max(z, 0) - z t + log1p(exp(-|z|))``.
        reduction: ``'mean'``, ``'sum'`` or ``'none'``.
        eps: probabilities are clipped to ``[eps, 1 - eps]`` (ignored with ``from_logits``).

    Returns:
        A scalar array, or the elementwise losses for ``reduction='none'``.

    Example:
        >>> ivy.binary_cross_entropy(np.array([0.9, 0.2]), np.array([1., 0.]))
        np.float64(0.16425203348601802)
    """
    _check_reduction(reduction, "binary_cross_entropy")
    xp = _fh.get_framework(pred, f=f)
    if from_logits:
        positive = xp.greater(pred, 0)
        loss = xp.add(
            xp.subtract(xp.where(positive, pred, 0), xp.multiply(pred, target)),
            xp.log1p(xp.exp(xp.where(positive, xp.negative(pred), pred))),
        )
    else:
        p = xp.clip(pred, eps, 1 - eps)
        loss = xp.negative(
            xp.add(
                xp.multiply(target, xp.log(p)),
                xp.multiply(xp.subtract(1, target), xp.log1p(xp.negative(p))),
            )
        )
    return _reduce(xp, loss, reduction)


@composition
def categorical_cross_entropy(
    pred: Array,
    target: Array,
    /,
    *,
    axis: int = -1,
    from_logits: bool = False,
    reduction: Literal["mean", "sum", "none"] = "mean",
    eps: float = 1e-7,
    f: Framework = None,
) -> Array:
    """Categorical cross-entropy ``-sum(t * log p, axis)`` with one-hot or probability targets.

    Args:
        pred: class probabilities along ``axis`` (summing to one), or logits with
            ``from_logits=True`` (then ``log p = log_softmax(pred)``, computed stably).
        target: one-hot or probability targets of the same shape (floats, not class indices:
            use ``ivy.one_hot(labels, n_classes, dtype='float32')``).
        axis: the class axis.
        from_logits: ``pred`` are logits.
        reduction: ``'mean'`` (over the samples), ``'sum'`` or ``'none'`` (one loss per
            sample: ``pred``'s shape without ``axis``).
        eps: probabilities are clipped to ``[eps, 1]`` before the log (ignored with
            ``from_logits``).

    Returns:
        A scalar array, or the per-sample losses for ``reduction='none'``.

    Example:
        >>> ivy.categorical_cross_entropy(np.array([[0.7, 0.2, 0.1]]), np.array([[1., 0., 0.]]))
        np.float64(0.35667494393873245)
    """
    _check_reduction(reduction, "categorical_cross_entropy")
    xp = _fh.get_framework(pred, f=f)
    log_p = xp.log_softmax(pred, axis) if from_logits else xp.log(xp.clip(pred, eps, 1))
    loss = xp.negative(xp.sum(xp.multiply(target, log_p), axis=axis))
    return _reduce(xp, loss, reduction)
