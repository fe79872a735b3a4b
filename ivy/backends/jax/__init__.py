"""ivy's jax backend: ``ivy.jax``. Dtypes are jax's own (``ivy.jax.float32 is jax.numpy.float32``);
the default float dtype is float32, as on every backend. 64-bit dtypes need
``jax.config.update('jax_enable_x64', True)``; the backend never changes jax's configuration.

While 64-bit types are off, ``ivy.jax`` has no ``int64``, ``uint64``, ``float64`` or
``complex128`` attribute (``hasattr(ivy.jax, 'float64')`` is False, reading it raises
:class:`ivy.errors.UnavailableDtypeError`, an AttributeError), and
``ivy.jax.__array_namespace_info__()`` lists only the dtypes jax can hold; switching x64 on, even
after import, makes them appear (the namespace asks jax's configuration at each look-up).

Most functions come from the shared layer (``ivy/backends/array_api/``) bound to ``jax.numpy``;
the modules here hold only what differs on jax.
"""

import sys as _sys

import jax.numpy as _jnp

from ivy.backends import _assemble, _reals
from ivy.backends.jax import _helpers

_assemble.assemble(
    _sys.modules[__name__],
    backend="jax",
    package=__name__,
    native_dtypes=_helpers.NATIVE_DTYPES,
    xp=_jnp,
    bind=_helpers.SHARED,
    reals=_reals.WRAPPERS,
    scalars_need_shims=True,
    dtypes_now=_helpers.X64_DTYPES,
    devices=_helpers.devices,
    array_api_capabilities=_helpers.ARRAY_API_CAPABILITIES,
    array_types=(type(_jnp.zeros(())),),
)
