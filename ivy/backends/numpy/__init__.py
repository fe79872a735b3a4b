"""ivy's numpy backend: ``ivy.numpy``. Dtypes are numpy's own (``ivy.numpy.float32 is
numpy.float32``); the default float dtype is float32, as on every backend."""

from ivy.backends.numpy import (
    creation,
    data_type,
    elementwise,
    general,
    indexing,
    linalg,
    manipulation,
    random,
    searching,
    statistical,
)
from ivy.backends.numpy._helpers import NATIVE_DTYPES
from ivy.backends.numpy.creation import *  # noqa: F403
from ivy.backends.numpy.data_type import *  # noqa: F403
from ivy.backends.numpy.elementwise import *  # noqa: F403
from ivy.backends.numpy.general import *  # noqa: F403
from ivy.backends.numpy.indexing import *  # noqa: F403
from ivy.backends.numpy.linalg import *  # noqa: F403
from ivy.backends.numpy.manipulation import *  # noqa: F403
from ivy.backends.numpy.random import *  # noqa: F403
from ivy.backends.numpy.searching import *  # noqa: F403
from ivy.backends.numpy.statistical import *  # noqa: F403

globals().update(NATIVE_DTYPES)

__all__ = sorted(
    {
        name
        for group in (
            creation, data_type, elementwise, general, indexing, linalg, manipulation, random,
            searching, statistical,
        )
        for name in group.__all__
    }
    | set(NATIVE_DTYPES)
)
