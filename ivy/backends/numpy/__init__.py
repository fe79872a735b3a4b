"""ivy's numpy backend: ``ivy.numpy``. Dtypes are numpy's own (``ivy.numpy.float32 is
numpy.float32``); the default float dtype is float32, as on every backend."""

from ivy.backends._assemble import assemble
from ivy.backends.numpy._helpers import NATIVE_DTYPES

assemble(__name__, globals(), NATIVE_DTYPES)
