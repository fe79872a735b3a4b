"""Declarative input checks for ivy_vision (private): the core's, :mod:`ivy.checks`.

A check states the shape an argument must have, and raises :class:`InputError` naming the
argument, the expected shape, the shape it got and the fix. :func:`checked`, the decorator on
every public function, adds that function's name to the message (the outermost one, the function
the user called) and brings the array arguments to one floating dtype (integers compute in
float32, float32 with float64 promotes), the same on every backend; the arguments that are ids
or masks are named in its ``exact=``.

Example:
    >>> check_shape((2, 4, 5, 1), ("...", "H", "W", 1), "depth")
    {'H': 4, 'W': 5}
"""

from __future__ import annotations

from ivy.checks import InputError, check_shape, checked, describe

__all__ = ["InputError", "checked", "check_shape", "describe"]
