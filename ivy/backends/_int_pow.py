"""Integers to negative integer powers, the same on every backend (written once, against any
array library's operators and a ``where``).

The result is not an integer, and the Array API leaves it to the implementation: numpy and
tensorflow raise, torch answers 0 (``2 ** -1``) and jax wraps around (``2 ** -1`` is
``-2**63``). ivy takes numpy's answer where the values are known: an error that says to cast
the base to a floating dtype. Inside a compiled program, where they are not, the result is the
integer part of the real power: ``1`` for a base of 1, ``±1`` for -1 (the exponent's parity),
``0`` for any other base, 0 included.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


def integer_pow(
    native: Callable[[Any, Any], Any],
    x1: Any,
    x2: Any,
    *,
    integral: Callable[[Any], bool],
    values_known: Callable[[Any], bool],
    any_negative: Callable[[Any], bool],
    where: Callable[[Any, Any, Any], Any],
    backend: str,
) -> Any:
    """``native(x1, x2)`` (``x1 ** x2``) with the rule above where both are integers."""
    if not (integral(x1) and integral(x2)):
        return native(x1, x2)
    if values_known(x2):
        if any_negative(x2):
            if type(x1) is int or type(x2) is int:  # beyond the array's dtype: OverflowError
                try:  # first, as every binary function says (``_int_scalars``)
                    native(x1, x2)
                except OverflowError:
                    raise
                except Exception:  # noqa: BLE001 - the native's own refusal of the power
                    pass
            from ivy.errors import InvalidValueError

            raise InvalidValueError(
                "integers to negative integer powers are not allowed (the result is not an "
                "integer). Cast the base to a floating dtype first: "
                "ivy.pow(ivy.astype(x1, 'float32'), x2).",
                function="pow",
                argument="x2",
                backend=backend,
            )
        return native(x1, x2)
    out = native(x1, abs(x2))
    return where((x2 < 0) & (abs(x1) != 1), out - out, out)
