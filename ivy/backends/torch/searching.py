"""torch backend: searching (torch's own functions: ``axis``/``keepdims`` are accepted spellings
of ``dim``/``keepdim``, and ``axis=None`` flattens)."""

from __future__ import annotations

import torch

__all__ = ["argmax", "argmin", "where"]

argmax = torch.argmax
argmin = torch.argmin
where = torch.where
