"""Python ints beyond the range of the integer array beside them, answered alike on every backend.

``ivy.add(int8_array, 300)``: numpy 2 raises ``OverflowError`` (the Python int takes the array's
dtype, NEP 50, and does not fit); torch, jax and tensorflow convert the int to int8 and wrap it
around, adding 44. ivy answers as numpy does, on every backend:

- the comparisons answer exactly without computing: every element of an int8 array is less than
  300 and greater than -129;
- the functions of real numbers (``divide``, ``atan2``, ``copysign``, ``hypot``, ``logaddexp``,
  ``nextafter``) take the int as a float, since they compute integer arrays in float32 anyway;
- every other binary function raises ``OverflowError`` naming the function, the value and the
  dtype.

A backend calls :func:`operands` where one operand of a binary function is a Python int
(``type(v) is int``: not a bool) and the other an array; ints from 0 to 127, which fit every
integer dtype, cost one comparison.
"""

from __future__ import annotations

import operator
from collections.abc import Callable
from typing import Any

import numpy as np

COMPARISONS: dict[str, Callable[[Any, Any], bool]] = {
    "equal": operator.eq,
    "not_equal": operator.ne,
    "less": operator.lt,
    "less_equal": operator.le,
    "greater": operator.gt,
    "greater_equal": operator.ge,
}
REALS = frozenset({"divide", "atan2", "copysign", "hypot", "logaddexp", "nextafter"})
_RANGES = {
    name: (int(np.iinfo(name).min), int(np.iinfo(name).max))
    for name in ("int8", "int16", "int32", "int64", "uint8", "uint16", "uint32", "uint64")
}


def resolve(name: str, x1: Any, x2: Any, dtype: str) -> tuple[Any, Any] | bool:
    """The operands of the binary function ``name`` where ``x1`` or ``x2`` is a Python int and
    the other an array of dtype ``dtype`` (its name).

    Returns:
        ``(x1, x2)``: as given where the int fits ``dtype`` (or ``dtype`` is not an integer
        one), with the int as a float for a function of real numbers; or a bool, a comparison's
        answer for every element of the array.

    Raises:
        OverflowError: for every other function, where the int does not fit ``dtype``.
    """
    value = x1 if type(x1) is int else x2
    bounds = _RANGES.get(dtype)
    if bounds is None or bounds[0] <= value <= bounds[1] or type(x1) is type(x2):
        return x1, x2
    if name in REALS:
        return (float(x1), x2) if x1 is value else (x1, float(x2))
    compare = COMPARISONS.get(name)
    if compare is not None:
        element = bounds[0]  # every element is on the same side of ``value`` as this one
        return compare(value, element) if x1 is value else compare(element, value)
    raise OverflowError(
        f"ivy.{name}: Python integer {value} is out of bounds for {dtype} ({bounds[0]} to "
        f"{bounds[1]}), the dtype of the array it meets. Make it an array of a wider dtype "
        f"(ivy.asarray({value}, dtype=...)) or cast the array first."
    )


def operands(native: Callable, name: str, x1: Any, x2: Any) -> tuple[Any, Any]:
    """The operands of the backend's binary function ``name`` (whose framework function is
    ``native``) where ``x1`` or ``x2`` is a Python int: ``(x1, x2)`` as :func:`resolve` gives
    them, or ``(answer, None)``, the comparison's answer as an array of the framework."""
    value = x1 if type(x1) is int else x2
    if 0 <= value <= 127:
        return x1, x2
    array = x2 if value is x1 else x1
    dtype = getattr(array, "dtype", None)
    if dtype is None:
        return x1, x2
    out = resolve(name, x1, x2, dtype_name(dtype))
    if type(out) is bool:
        return answer_of(native, name, array, out), None
    return out


def dtype_name(dtype: Any) -> str:
    """'int8' for numpy's, jax's, tensorflow's (``.name``), torch's and array_api_strict's
    (``str``: 'torch.int8') int8 dtype."""
    return getattr(dtype, "name", None) or str(dtype).rpartition(".")[2]


def answer_of(compare: Callable[[Any, Any], Any], name: str, array: Any, answer: bool) -> Any:
    """``answer`` for every element of ``array``, made by the backend's comparison ``compare``
    itself (so in the array's framework, shape and device): ``x op x`` holds everywhere or
    nowhere, integers having no NaN, as ``0 op 0`` does."""
    same = compare(array, array)
    return same if answer is COMPARISONS[name](0, 0) else ~same
