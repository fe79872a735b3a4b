"""ivy's tensorflow backend: ``ivy.tensorflow``. Dtypes are tf's own (``ivy.tensorflow.float32 is
tf.float32``); the default float dtype is float32 and the default int dtype int64 (not tf's
int32)."""

import sys as _sys

from ivy.backends import _assemble
from ivy.backends.tensorflow import _array_object, _helpers

_assemble.assemble(
    _sys.modules[__name__],
    backend="tensorflow",
    package=__name__,
    native_dtypes=_helpers.NATIVE_DTYPES,
    reals=_helpers.REALS,
    devices=_helpers.devices,
    array_types=_helpers.ARRAY_TYPES,
    # (tf converts Python scalars itself, but caches them by value: -0.0 could come back as 0.0,
    # and ints out of a dtype's range would wrap; the shims convert them, see ``_helpers.fast``)
    scalars_need_shims=True,
)

# tf.Tensor as the standard's array object: the attributes it lacks (``_array_object.py``).
_array_object.add_array_methods(_sys.modules[__name__])
