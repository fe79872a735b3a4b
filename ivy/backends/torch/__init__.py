"""ivy's torch backend: ``ivy.torch``. Dtypes are torch's own (``ivy.torch.float32 is
torch.float32``); the default float dtype is float32, as on every backend."""

import sys as _sys

import torch as _torch

from ivy.backends import _assemble
from ivy.backends.torch import _helpers

_assemble.assemble(
    _sys.modules[__name__],
    backend="torch",
    package=__name__,
    native_dtypes=_helpers.NATIVE_DTYPES,
    reals=_helpers.REALS,
    devices=_helpers.devices,
    array_types=(_torch.Tensor, _torch.nn.Parameter),
)
