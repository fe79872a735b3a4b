"""Conversion of arrays from one framework to another, written once as a composition over the
target backend's ``from_dlpack``."""

from __future__ import annotations

from types import ModuleType

from ivy import framework_handler as _fh
from ivy.core._dispatch import composition
from ivy.typing import Array, ArrayLike, Framework

__all__ = ["to_framework"]


@composition
def to_framework(x: ArrayLike, framework: str | ModuleType, /, *, f: Framework = None) -> Array:
    """``x`` as an array of ``framework``, sharing its memory where the frameworks allow.

    The array goes through DLPack (the target backend's ``from_dlpack``): numpy, torch and jax
    arrays on the CPU convert into each other without a copy wherever the importer accepts the
    buffer (torch -> numpy, numpy -> torch, jax -> numpy and jax -> torch always; jax and tf copy
    buffers that are not aligned as they require). A torch tensor that requires gradients is
    detached: gradients do not flow between frameworks. Where DLPack cannot carry the array at
    all, the data are copied through numpy, with the same values and dtype. Memory shared with a
    jax or tf array must not be written afterwards: those frameworks assume it immutable.

    Args:
        x: an array of any backend.
        framework: the target: a name (``'jax'``) or a namespace (``ivy.jax``).
        f: unused: the framework of ``x`` is always read from its type (neither ``f`` nor the
            globally set framework changes what ``x`` is). Python scalars and lists are
            converted with the target's ``asarray``.

    Returns:
        The array in the target framework (``x`` itself when it is already of that framework).

    Example: ``ivy.to_framework(np.arange(3.), 'torch')`` -> ``tensor([0., 1., 2.],
    dtype=torch.float64)``, sharing the numpy array's memory.
    """
    owner = _fh.framework_of_type(type(x))
    target = _fh.get_framework(f=framework)
    if owner == target.backend:
        return x
    if owner is None:
        return target.asarray(x)
    try:
        return target.from_dlpack(x)
    except Exception:  # DLPack cannot carry this array: a copy gives the same values and dtype
        return target.asarray(_fh.get_framework(f=owner).to_numpy(x))
