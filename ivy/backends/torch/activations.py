"""torch backend: the activations with a kernel of their own (the rest are compositions)."""

from __future__ import annotations

import torch
import torch.nn.functional as F

from ivy.backends.torch._helpers import as_inexact


def relu(x, /):
    """``max(x, 0)``, with ``relu(-0) = +0`` as on every backend (``torch.relu`` keeps ``-0``;
    ``ivy/backends/_signed_zeros.py``): torch's ``threshold``, one kernel as well."""
    return torch.threshold(x, 0, 0)


sigmoid = torch.sigmoid


def gelu(x, /, approximate=False):
    return F.gelu(as_inexact(x), approximate="tanh" if approximate else "none")


def softmax(x, /, axis=-1):
    return torch.softmax(as_inexact(x), axis)


def log_softmax(x, /, axis=-1):
    return torch.log_softmax(as_inexact(x), axis)
