"""Errors raised by ivy. Each message says what the user can do about it.

Bad input (shapes that do not broadcast, axes or indices out of range, a dtype a function does
not take) raises an :class:`InvalidArgumentError` subclass on every backend, whose message names
the function, the argument and the backend. Each is also a subclass of the builtin error that
such input raises in Python and numpy (``IndexError``, ``ValueError``, ``TypeError``), so
existing ``except`` clauses keep working:

    >>> try:
    ...     ivy.take(ivy.zeros(2, f="torch"), ivy.asarray([5], f="torch"))
    ... except IndexError as err:
    ...     print(err)
    ivy.take (torch backend), argument 'indices': index 5 is out of bounds for size 2 ...
"""

from __future__ import annotations

__all__ = [
    "IvyError",
    "UnknownFrameworkError",
    "FrameworkNotInstalledError",
    "MixedFrameworksError",
    "NoFrameworkError",
    "UnsupportedError",
    "UnavailableDtypeError",
    "InvalidArgumentError",
    "ShapeError",
    "AxisError",
    "IndexOutOfBoundsError",
    "DtypeError",
    "InvalidValueError",
    "LinAlgError",
    "UnavailableDeviceError",
    "unavailable_device",
]


class IvyError(Exception):
    """Base class of every error that ivy raises on purpose."""


class UnknownFrameworkError(IvyError, ValueError):
    """A framework name that ivy does not know."""


class FrameworkNotInstalledError(IvyError, ImportError):
    """A known framework whose package is not installed."""


class MixedFrameworksError(IvyError, TypeError):
    """Arrays of two different frameworks passed to one call."""


class NoFrameworkError(IvyError, TypeError):
    """No framework could be chosen: no array input, no ``f=`` and no global framework."""


class UnsupportedError(IvyError, NotImplementedError):
    """A function that a backend truly cannot provide (e.g. gradients on numpy)."""


class UnavailableDtypeError(IvyError, AttributeError):
    """A dtype attribute of a backend namespace that the backend does not have, or cannot hold
    now (``ivy.jax.float64`` while jax's 64-bit types are off). An AttributeError, so that
    ``hasattr(ivy.jax, 'float64')`` tells whether float64 arrays can be made now."""


class InvalidArgumentError(IvyError):
    """Bad input to an ivy function. The message names the function, the argument and the
    backend, which are also attributes (``function``, ``argument``, ``backend``; None where not
    known)."""

    def __init__(
        self,
        message: str,
        *,
        function: str | None = None,
        argument: str | None = None,
        backend: str | None = None,
    ) -> None:
        self.function, self.argument, self.backend = function, argument, backend
        where = f"ivy.{function}" if function else "ivy"
        if backend:
            where += f" ({backend} backend)"
        if argument:
            where += f", argument {argument!r}"
        super().__init__(f"{where}: {message}")


class ShapeError(InvalidArgumentError, ValueError):
    """Shapes that do not broadcast together, or do not fit the function (a ValueError)."""


class AxisError(InvalidArgumentError, ValueError, IndexError):
    """An axis out of range for the array's number of dimensions, or repeated (a ValueError and
    an IndexError, as numpy's ``AxisError``)."""

    @staticmethod
    def out_of_range(axis: int, ndim: int) -> str:
        """The message for ``axis`` outside an array of ``ndim`` dimensions."""
        dims = f"{ndim} dimension{'' if ndim == 1 else 's'}"
        if not ndim:
            return f"axis {axis} is out of range: a 0-d array has no axis (give at least 1-d)."
        return f"axis {axis} is out of range for an array of {dims} (valid: {-ndim} to {ndim - 1})."


class IndexOutOfBoundsError(InvalidArgumentError, IndexError):
    """An index out of range for the axis it indexes (an IndexError). Raised in eager calls on
    every backend; compiled code cannot check values (see ``docs/conformance.md``)."""


class DtypeError(InvalidArgumentError, TypeError):
    """A dtype that the function does not take (a TypeError): the same on every backend, unlike
    :class:`UnsupportedError`, which is what one backend cannot do."""


class InvalidValueError(InvalidArgumentError, ValueError):
    """Values that the function cannot take (a ValueError), where a framework says so in its own
    error class (tensorflow's ``InvalidArgumentError``, torch's ``RuntimeError``)."""


class LinAlgError(InvalidValueError):
    """A matrix the function cannot take: singular (``inv``, ``solve``), not positive definite
    (``cholesky``). Raised in eager calls on every backend (numpy's ``LinAlgError`` is also a
    ValueError); compiled jax code returns inf or NaN instead."""


class UnavailableDeviceError(InvalidArgumentError, ValueError):
    """A device that the backend does not have on this machine, or a name that is no device
    (a ValueError). Raised in the same words on every backend by :func:`unavailable_device`."""


def unavailable_device(device, xp, *, function: str | None = None) -> UnavailableDeviceError:
    """The error for ``device``, which the backend namespace ``xp`` does not have here: it names
    the device asked for and the devices the backend has, in ivy's names, in the same words on
    every backend. Backends raise it; so can any library that takes ``device=``.

    Args:
        device: the device asked for (an ivy name such as ``'gpu:0'``, or anything else given).
        xp: the backend namespace (``ivy.torch`` ...).
        function: the public function that was called, for the message.

    Returns:
        The error, to raise.

    Example:
        >>> raise ivy.unavailable_device("gpu:0", ivy.numpy, function="asarray")
        Traceback (most recent call last):
        ...
        ivy.errors.UnavailableDeviceError: ivy.asarray (numpy backend), argument 'device': numpy has
        no device 'gpu:0' on this machine; its devices here: 'cpu'. Give one of them (ivy names
        devices 'cpu' and 'gpu:N').
    """
    backend = xp.backend
    try:
        found = [xp.dev(xp.zeros((), device=d)) for d in xp.__array_namespace_info__().devices()]
    except Exception:  # (listing the devices must not hide the error being reported)
        found = ["cpu"]
    names = ", ".join(repr(n) for n in dict.fromkeys(found))
    return UnavailableDeviceError(
        f"{backend} has no device {device!r} on this machine; its devices here: {names}. Give "
        f"one of them (ivy names devices 'cpu' and 'gpu:N').",
        function=function,
        argument="device",
        backend=backend,
    )
