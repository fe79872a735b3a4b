"""Argument checks shared by every backend's ``top_k`` and ``random_categorical`` (pure Python,
no framework)."""

from __future__ import annotations

import operator

from ivy.errors import AxisError


def top_k_axis(shape, k, axis) -> int:
    """``axis`` of an array of ``shape`` as a non-negative int, after checking that ``k`` elements
    can be taken along it (a size that is unknown, None inside ``tf.function``, is not checked)."""
    ndim = len(shape)
    if not -ndim <= axis < ndim:  # a 0-d array included: it has no axis
        raise AxisError(AxisError.out_of_range(axis, ndim), function="top_k", argument="axis")
    axis %= ndim
    k = operator.index(k)
    size = shape[axis]
    if k < 0 or (size is not None and k > size):
        raise ValueError(
            f"top_k: k must be between 0 and the size of axis {axis} ({size}); got k={k}."
        )
    return axis


def categorical_args(shape, num_samples) -> int:
    """The number of classes (the last axis of ``shape``), after checking the arguments of
    ``random_categorical``."""
    if len(shape) == 0 or shape[-1] == 0:
        raise ValueError(
            f"random_categorical: logits must have a last axis of at least one class; got shape "
            f"{tuple(shape)}."
        )
    if operator.index(num_samples) < 0:
        raise ValueError(f"random_categorical: num_samples must be >= 0; got {num_samples}.")
    return shape[-1]
