"""torch backend: sorting (torch's own: NaN is the largest value, last ascending and first
descending; a stable descending sort keeps equal elements in their order)."""

from __future__ import annotations

import torch

__all__ = ["argsort", "sort"]


def argsort(x, /, *, axis=-1, descending=False, stable=True):
    return torch.argsort(x, dim=axis, descending=descending, stable=stable)


def sort(x, /, *, axis=-1, descending=False, stable=True):
    return torch.sort(x, dim=axis, descending=descending, stable=stable).values
