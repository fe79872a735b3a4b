"""Errors raised by ivy. Each message says what the user can do about it."""

__all__ = [
    "IvyError",
    "UnknownFrameworkError",
    "FrameworkNotInstalledError",
    "MixedFrameworksError",
    "NoFrameworkError",
    "UnsupportedError",
    "UnavailableDtypeError",
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
