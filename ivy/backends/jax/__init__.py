"""ivy's jax backend: ``ivy.jax``. Dtypes are jax's own (``ivy.jax.float32 is jax.numpy.float32``);
the default float dtype is float32, as on every backend. 64-bit dtypes need
``jax.config.update('jax_enable_x64', True)``; the backend never changes jax's configuration.

Most functions come from the shared layer (``ivy/backends/array_api/``) bound to ``jax.numpy``;
the modules here hold only what differs on jax.
"""

import sys

import jax.numpy

from ivy.backends import _reals
from ivy.backends._assemble import assemble
from ivy.backends.jax import _helpers

assemble(
    sys.modules[__name__],
    backend="jax",
    package=__name__,
    native_dtypes=_helpers.NATIVE_DTYPES,
    xp=jax.numpy,
    bind=_helpers.SHARED,
    reals=_reals.WRAPPERS,
)
