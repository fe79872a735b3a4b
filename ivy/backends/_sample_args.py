"""Argument checks shared by every backend's ``top_k`` and ``random_categorical`` (pure Python,
no framework)."""

from __future__ import annotations

import operator

from ivy.errors import AxisError, DtypeError, InvalidValueError


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


def floating_draw(function: str, backend: str, dtype, floating: bool) -> None:
    """Refuse an integer or boolean ``dtype`` for ``random_uniform`` or ``random_normal``: their
    draws are real numbers, and rounding them to integers gave a plausible but wrong sample
    (mostly zeros from ``U[0, 1)``) on numpy, torch and tensorflow where jax refused."""
    if not floating:
        raise DtypeError(
            f"draws real numbers; dtype {dtype!r} is not a floating dtype. Give a floating "
            f"dtype (float32 by default), or draw integers with ivy.randint.",
            function=function,
            argument="dtype",
            backend=backend,
        )


def _number(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def check_draw_bounds(function: str, a, b, backend: str) -> None:
    """Refuse bounds given as Python numbers that describe no distribution, as numpy does:
    ``random_uniform`` with ``low > high`` (torch and tensorflow drew from ``[high, low)``, jax
    returned ``low``), ``random_normal`` with ``std < 0`` (the others drew with ``|std|``) and
    ``randint`` with ``low >= high`` (jax returned ``low``). Bounds given as arrays are not
    read (that would cost a transfer from the device; inside compiled code they have no
    values)."""
    if not (_number(a) and _number(b)):
        return
    bad = {
        "random_uniform": (a > b, f"low ({a}) must not exceed high ({b})"),
        "random_normal": (b < 0, f"std ({b}) must not be negative"),
        "randint": (a >= b, f"low ({a}) must be less than high ({b})"),
    }[function]
    if bad[0]:
        raise InvalidValueError(
            bad[1] + ".",
            function=function,
            argument="high" if function != "random_normal" else "std",
            backend=backend,
        )
