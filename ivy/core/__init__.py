"""Framework-agnostic definitions of ivy's functions, one module per group.

Every public module here is a group, listed below by name (so that editors and static tools see
``ivy.clip``); each backend package may have a module of the same name holding what differs on
that backend (``ivy/backends/_assemble.py``). To add a group: add its module here, in the imports,
``GROUPS`` and the ``__all__`` sums (``tests/ivy/test_registry.py`` checks that every module of this
package is listed).
"""

from ivy import framework_handler as _fh
from ivy.core import (
    _diagnose,
    activations,
    compilation,
    control_flow,
    convolutions,
    creation,
    cumulative,
    data_type,
    elementwise,
    fft,
    gradients,
    image,
    indexing,
    interpolation,
    layers,
    linalg,
    linalg_extras,
    losses,
    manipulation,
    numerics,
    padding,
    pooling,
    random,
    searching,
    sets,
    sorting,
    statistical,
    utility,
)

GROUPS = (
    activations,
    compilation,
    control_flow,
    convolutions,
    creation,
    cumulative,
    data_type,
    elementwise,
    fft,
    gradients,
    image,
    indexing,
    interpolation,
    layers,
    linalg,
    linalg_extras,
    losses,
    manipulation,
    numerics,
    padding,
    pooling,
    random,
    searching,
    sets,
    sorting,
    statistical,
    utility,
)
GROUP_NAMES = tuple(g.__name__.rpartition(".")[2] for g in GROUPS)

_fh.explain_errors_with(_diagnose.explain)  # the dispatchers' typed errors

__all__: list[str] = []
__all__ += activations.__all__
__all__ += compilation.__all__
__all__ += control_flow.__all__
__all__ += convolutions.__all__
__all__ += creation.__all__
__all__ += cumulative.__all__
__all__ += data_type.__all__
__all__ += elementwise.__all__
__all__ += fft.__all__
__all__ += gradients.__all__
__all__ += image.__all__
__all__ += indexing.__all__
__all__ += interpolation.__all__
__all__ += layers.__all__
__all__ += linalg.__all__
__all__ += linalg_extras.__all__
__all__ += losses.__all__
__all__ += manipulation.__all__
__all__ += numerics.__all__
__all__ += padding.__all__
__all__ += pooling.__all__
__all__ += random.__all__
__all__ += searching.__all__
__all__ += sets.__all__
__all__ += sorting.__all__
__all__ += statistical.__all__
__all__ += utility.__all__

# After GROUPS: ``from ivy.core.fft import *`` rebinds the name ``fft`` to the function.
from ivy.core.activations import *  # noqa: E402, F403
from ivy.core.compilation import *  # noqa: E402, F403
from ivy.core.control_flow import *  # noqa: E402, F403
from ivy.core.convolutions import *  # noqa: E402, F403
from ivy.core.creation import *  # noqa: E402, F403
from ivy.core.cumulative import *  # noqa: E402, F403
from ivy.core.data_type import *  # noqa: E402, F403
from ivy.core.elementwise import *  # noqa: E402, F403
from ivy.core.fft import *  # noqa: E402, F403
from ivy.core.gradients import *  # noqa: E402, F403
from ivy.core.image import *  # noqa: E402, F403
from ivy.core.indexing import *  # noqa: E402, F403
from ivy.core.interpolation import *  # noqa: E402, F403
from ivy.core.layers import *  # noqa: E402, F403
from ivy.core.linalg import *  # noqa: E402, F403
from ivy.core.linalg_extras import *  # noqa: E402, F403
from ivy.core.losses import *  # noqa: E402, F403
from ivy.core.manipulation import *  # noqa: E402, F403
from ivy.core.numerics import *  # noqa: E402, F403
from ivy.core.padding import *  # noqa: E402, F403
from ivy.core.pooling import *  # noqa: E402, F403
from ivy.core.random import *  # noqa: E402, F403
from ivy.core.searching import *  # noqa: E402, F403
from ivy.core.sets import *  # noqa: E402, F403
from ivy.core.sorting import *  # noqa: E402, F403
from ivy.core.statistical import *  # noqa: E402, F403
from ivy.core.utility import *  # noqa: E402, F403
