"""ivy's tensorflow backend: ``ivy.tensorflow``. Dtypes are tf's own (``ivy.tensorflow.float32 is
tf.float32``); the default float dtype is float32 and the default int dtype int64 (not tf's
int32)."""

import sys

from ivy.backends._assemble import assemble
from ivy.backends.tensorflow import _helpers
from ivy.backends.tensorflow._array_object import add_array_methods
from ivy.backends.tensorflow._helpers import NATIVE_DTYPES, REALS, devices

assemble(
    sys.modules[__name__],
    backend="tensorflow",
    package=__name__,
    native_dtypes=NATIVE_DTYPES,
    reals=REALS,
    devices=devices,
    array_types=_helpers.ARRAY_TYPES,
    # (tf converts Python scalars itself, but caches them by value: -0.0 could come back as 0.0,
    # and ints out of a dtype's range would wrap; the shims convert them, see ``_helpers.fast``)
    scalars_need_shims=True,
)

# tf.Tensor as the standard's array object: the attributes it lacks (``_array_object.py``).
add_array_methods(sys.modules[__name__])
