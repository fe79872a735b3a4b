"""ivy's torch backend: ``ivy.torch``. Dtypes are torch's own (``ivy.torch.float32 is
torch.float32``); the default float dtype is float32, as on every backend."""

import sys

import torch

from ivy.backends._assemble import assemble
from ivy.backends.torch._helpers import NATIVE_DTYPES, REALS, devices

assemble(
    sys.modules[__name__],
    backend="torch",
    package=__name__,
    native_dtypes=NATIVE_DTYPES,
    reals=REALS,
    devices=devices,
    array_types=(torch.Tensor, torch.nn.Parameter),
)
