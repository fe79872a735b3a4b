"""Utilities: conversion to numpy and lists, shape, dtype, device."""

from __future__ import annotations

from ivy.core._dispatch import dispatch

__all__ = ["to_numpy", "to_list", "shape", "dtype", "dev"]


@dispatch
def to_numpy(x, /, *, f=None):
    """``x`` as a numpy array (detached, on the CPU)."""


@dispatch
def to_list(x, /, *, f=None):
    """``x`` as nested Python lists (a scalar for a 0-d array)."""


@dispatch
def shape(x, /, *, f=None):
    """Shape of ``x`` as a tuple of ints."""


@dispatch
def dtype(x, /, *, as_str=False, f=None):
    """Dtype of ``x``: the framework's object, or its name with ``as_str=True``."""


@dispatch
def dev(x, /, *, f=None):
    """Device of ``x`` as a string: ``'cpu'`` or ``'gpu:0'``."""
