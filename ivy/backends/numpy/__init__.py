"""ivy's numpy backend: ``ivy.numpy``. Dtypes are numpy's own (``ivy.numpy.float32 is
numpy.float32``); the default float dtype is float32, as on every backend.

Most functions come from the shared layer (``ivy/backends/array_api/``) bound to numpy; the
modules here hold only what differs on numpy.
"""

import sys as _sys

import numpy as _numpy

from ivy.backends import _assemble, _reals
from ivy.backends.numpy import _helpers

_assemble.assemble(
    _sys.modules[__name__],
    backend="numpy",
    package=__name__,
    native_dtypes=_helpers.NATIVE_DTYPES,
    xp=_numpy,
    bind=_helpers.SHARED,
    reals=_reals.WRAPPERS,
    scalars_need_shims=True,
    natives_in_namespace=True,
    array_types=(_numpy.ndarray,),
)
