"""ivy: write numerical code once, run it on numpy, torch, jax and tensorflow.

``import ivy`` imports no framework. The per-backend namespaces ``ivy.numpy``, ``ivy.torch``,
``ivy.jax`` and ``ivy.tensorflow`` are imported on first access.

Example:
    >>> import numpy as np, ivy
    >>> ivy.clip(np.array([-1., 2.]), 0, 1)           # framework inferred: numpy
    array([0., 1.])
    >>> ivy.clip(np.array([-1., 2.]), 0, 1, f='torch') # framework chosen: torch
    tensor([0., 1.], dtype=torch.float64)
"""

from ivy import (
    core,
    dtypes,
    errors,
    framework_handler,
    nest,  # noqa: F401 - ivy.nest: map, flatten, unflatten nests
    registry,
    stateful,  # noqa: F401 - ivy.stateful: modules, layers, optimizers, checkpoints
    typing,  # noqa: F401 - ivy.typing: Array, Framework, Dtype, Shape ... for signatures
)
from ivy.backends._assemble import ARRAY_API_CONSTANTS, ARRAY_API_VERSION
from ivy.core import *  # noqa: F403 - the public API is listed in ivy.core.__all__
from ivy.core._extensions import agnostic_extensions
from ivy.dtypes import *  # noqa: F403
from ivy.errors import *  # noqa: F403
from ivy.framework_handler import (
    Capabilities,
    available_frameworks,
    current_framework,
    framework_of_type,
    get_framework,
    installed_frameworks,
    matmul_precision,
    register_framework,
    set_framework,
    set_matmul_precision,
    unset_framework,
)
from ivy.registry import FunctionInfo, function_info, list_functions
from ivy.stateful import *  # noqa: F403 - Module, Linear, MLP, ..., Adam, save_weights ...
from ivy.threads import set_threads

__version__ = "0.1.0"

# The Array API extensions as namespaces, ivy.linalg and ivy.fft (their functions are flat too).
_EXTENSIONS = agnostic_extensions()
globals().update(_EXTENSIONS)

globals().update(ARRAY_API_CONSTANTS)
__array_api_version__ = ARRAY_API_VERSION

__all__ = sorted(
    set(core.__all__)
    | set(dtypes.__all__)
    | set(errors.__all__)
    | set(framework_handler.__all__)
    | set(registry.__all__)
    | {"set_threads"}
    | set(_EXTENSIONS)
    | {"e", "pi", "inf", "nan", "newaxis"}
)


def __getattr__(name: str):
    """Load the backend namespaces ``ivy.numpy``, ``ivy.torch``, ... on first access."""
    if name in framework_handler.available_frameworks():
        ns = framework_handler.load_backend(name)
        globals()[name] = ns
        return ns
    raise AttributeError(f"module 'ivy' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(framework_handler.available_frameworks()))
