"""Declarative input checks for ivy_vision (private).

A check states the shape an argument must have, and raises :class:`InputError` naming the
argument, the expected shape, the shape it got and the fix. It does not know which public
function it runs in: :func:`checked`, the decorator on every public function, adds that
function's name to the message (the outermost one, the function the user called).

Shape specs read as the docstrings do: ``("...", "H", "W", 1)`` is an image with any leading
batch dimensions and one channel; ``"..."`` stands for any number of leading dimensions (only
first), a name for any size, an int for that size, a tuple of ints for one of those sizes.

The helpers are generic (nothing here is about vision); they could move to the core.

Example:
    >>> check_shape((2, 4, 5, 1), ("...", "H", "W", 1), "depth")
    {'H': 4, 'W': 5}
"""

from __future__ import annotations

import functools

__all__ = ["InputError", "checked", "check_shape", "describe"]


class InputError(ValueError):
    """Bad input to a public function: ``str()`` is ``"<function>: <message>"``."""

    def __init__(self, message: str, function: str | None = None):
        super().__init__(message)
        self.message = message
        self.function = function

    def __str__(self) -> str:
        return f"{self.function}: {self.message}" if self.function else self.message


def checked(fn):
    """Name ``fn`` in the :class:`InputError` raised inside it (no cost unless one is raised).

    Example:
        >>> @checked
        ... def area(dims):
        ...     raise InputError("dims must be (height, width)")
        >>> area(3)
        Traceback (most recent call last):
        ...
        ivy_vision._checks.InputError: area: dims must be (height, width)
    """
    name = fn.__qualname__

    @functools.wraps(fn)
    def public(*args, **kwargs):
        try:
            return fn(*args, **kwargs)
        except InputError as error:
            raise InputError(error.message, name) from None

    return public


def describe(spec) -> str:
    """``("...", "H", "W", (3, 4))`` -> ``"[..., H, W, 3 or 4]"``."""

    def entry(e):
        if isinstance(e, tuple):
            return " or ".join(str(v) for v in e)
        return str(e)

    return "[" + ", ".join(entry(e) for e in spec) + "]"


def check_shape(shape: tuple, spec, what: str, hint: str = "") -> dict:
    """Raise an :class:`InputError` unless ``shape`` matches ``spec``; return the sizes of the
    named dimensions.

    Args:
        shape: the argument's shape.
        spec: ``"..."`` first for any leading dimensions, then per dimension a name (any size),
            an int or a tuple of ints.
        what: the argument's name, for the message.
        hint: how to fix it, appended to the message.

    Returns:
        ``{name: size}`` for the named dimensions.
    """
    spec = tuple(spec)
    leading = bool(spec) and spec[0] == "..."
    dims = spec[1:] if leading else spec
    shape = tuple(shape)
    fits = len(shape) >= len(dims) if leading else len(shape) == len(dims)
    named = {}
    if fits:
        tail = shape[len(shape) - len(dims) :]
        for size, want in zip(tail, dims):
            if isinstance(want, str):
                named[want] = size
            elif size not in (want if isinstance(want, tuple) else (want,)):
                fits = False
    if not fits:
        raise InputError(
            f"{what} must be {describe(spec)}; got shape {shape}." + (f" {hint}" if hint else "")
        )
    return named
