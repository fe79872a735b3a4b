"""Utilities: conversion to numpy and lists, shape, dtype, device."""

from __future__ import annotations

from typing import Any

from ivy.core._dispatch import dispatch
from ivy.typing import Array, Dtype, Framework, Scalar

__all__ = ["to_numpy", "to_list", "shape", "dtype", "dev"]


@dispatch
def to_numpy(x: Array, /, *, f: Framework = None) -> Array:
    """``x`` as a numpy array (detached, on the CPU)."""


@dispatch
def to_list(x: Array, /, *, f: Framework = None) -> list[Any] | Scalar:
    """``x`` as nested Python lists (a scalar for a 0-d array)."""


@dispatch
def shape(x: Array, /, *, f: Framework = None) -> tuple[int, ...]:
    """Shape of ``x`` as a tuple of ints."""


@dispatch
def dtype(x: Array, /, *, as_str: bool = False, f: Framework = None) -> Dtype:
    """Dtype of ``x``: the framework's object, or its name with ``as_str=True``."""


@dispatch
def dev(x: Array, /, *, f: Framework = None) -> str:
    """Device of ``x`` as a string: ``'cpu'`` or ``'gpu:0'``."""
