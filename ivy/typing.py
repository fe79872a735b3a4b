"""Type aliases for public signatures, shared by the core and the applied libraries.

These are annotations for readers, editors and type checkers; nothing checks them at run time
(an array of any framework passes wherever ``Array`` is written). Importing this module imports
no framework.

Example:
    >>> from ivy.typing import Array, Framework
    >>> def scale(x: Array, factor: float, *, f: Framework = None) -> Array: ...
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from types import ModuleType
from typing import Any, TypeAlias, Union

__all__ = ["Array", "Framework", "Dtype", "Shape", "Device", "Nest", "Scalar", "ArrayLike"]

#: An array of any supported framework: a numpy ``ndarray``, a torch ``Tensor``, a jax ``Array``
#: (or a tracer under ``jax.jit``/``jax.grad``), a tensorflow ``Tensor`` or ``Variable``.
Array: TypeAlias = Any

#: A Python scalar, accepted beside arrays where the Array API allows it.
Scalar: TypeAlias = Union[bool, int, float, complex]

#: An array, or a value ``asarray`` turns into one (a scalar, a nested list of scalars).
ArrayLike: TypeAlias = Union[Array, Scalar, Sequence[Any]]

#: A framework choice: a name (``'torch'``, ``'tf'``), a backend namespace (``ivy.torch``), or
#: None to use the global framework or infer it from the inputs.
Framework: TypeAlias = Union[str, ModuleType, None]

#: A dtype: its name (``'float32'``) anywhere, or a native dtype object (``torch.float32``).
Dtype: TypeAlias = Union[str, Any]

#: A shape or batch shape: a tuple (or sequence) of non-negative ints.
Shape: TypeAlias = Union[tuple[int, ...], Sequence[int]]

#: A device: ``'cpu'``, ``'gpu:0'``, or a native device object.
Device: TypeAlias = Union[str, Any]

#: A nest: arrays in nested dicts, lists and tuples (variables, gradients, optimiser states).
Nest: TypeAlias = Union[Array, Mapping[str, Any], Sequence[Any]]
