"""Type aliases for the public signatures of ivy_mechanics."""

from __future__ import annotations

from types import ModuleType
from typing import Any, Union

#: An array of any supported framework (numpy ndarray, torch Tensor, jax Array, tf Tensor).
Array = Any
#: A framework choice: a name such as ``'torch'``, a namespace such as ``ivy.torch``, or None
#: (inferred from the inputs).
Framework = Union[str, ModuleType, None]
