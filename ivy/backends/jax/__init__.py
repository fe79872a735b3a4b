"""ivy's jax backend: ``ivy.jax``. Dtypes are jax's own (``ivy.jax.float32 is jax.numpy.float32``);
the default float dtype is float32, as on every backend. 64-bit dtypes need
``jax.config.update('jax_enable_x64', True)``; the backend never changes jax's configuration."""

from ivy.backends._assemble import assemble
from ivy.backends.jax._helpers import NATIVE_DTYPES

assemble(__name__, globals(), NATIVE_DTYPES)
