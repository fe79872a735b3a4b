"""The Array API's array attributes that ``tf.Tensor`` lacks, added to it when ``ivy.tensorflow``
loads.

tf's tensors are the arrays of ``ivy.tensorflow``, and the standard asks of an array object
``__array_namespace__``, ``to_device``, ``T``, ``mT``, ``size``, ``__pos__`` and the shift
operators, none of which tf defines. numpy's and jax's arrays have them, and torch's have most.

Only what ``tf.Tensor`` lacks is added: nothing of tf's own is replaced (its operators, ``shape``,
``device``, ``__dlpack__``), so no tf program changes its answers. What changes is that tf tensors
now say which namespace they belong to: ``array_api_compat.array_namespace(tf_tensor)``, which
raised before (no library offers an Array API namespace for tensorflow), answers
``ivy.tensorflow``. ``IVY_TF_ARRAY_METHODS=0`` in the environment leaves ``tf.Tensor`` untouched.
"""

from __future__ import annotations

import os
import types

import numpy as np
import tensorflow as tf

from ivy.backends.tensorflow._helpers import tf_device
from ivy.core._dispatch import FUNCTIONS

# The versions of the standard whose array object this one satisfies.
_API_VERSIONS = ("2021.12", "2022.12", "2023.12")

# (Python scalars, numpy arrays and scalars, tensors): what the shift operators take as the other
# operand; for anything else they return NotImplemented, so that Python asks the other operand.
_OPERANDS = (bool, int, np.ndarray, np.generic, tf.Tensor)


def add_array_methods(ns: types.ModuleType, tensor_type: type = tf.Tensor) -> list[str]:
    """Add to ``tensor_type`` the Array API attributes it lacks, computed by the namespace ``ns``;
    returns the names added (none if ``IVY_TF_ARRAY_METHODS=0``)."""
    if os.environ.get("IVY_TF_ARRAY_METHODS", "1") == "0":
        return []
    methods = _methods(ns)
    added = [name for name in methods if not hasattr(tensor_type, name)]
    for name in added:
        setattr(tensor_type, name, methods[name])
    return added


def _methods(ns: types.ModuleType) -> dict:
    def __array_namespace__(self, /, *, api_version=None):
        if api_version is not None and api_version not in _API_VERSIONS:
            raise ValueError(
                f"ivy.tensorflow implements the Array API versions {', '.join(_API_VERSIONS)}; "
                f"got api_version={api_version!r}."
            )
        return ns

    def to_device(self, device, /, *, stream=None):
        if stream is not None:
            raise ValueError("tensorflow has no streams: call x.to_device(device) without one.")
        with tf.device(tf_device(device)):
            return tf.identity(self)

    def T(self):  # noqa: N802 - the standard's name
        if self.shape.rank is not None and self.shape.rank != 2:
            raise ValueError(
                f"x.T is defined for 2-D arrays; this one has {self.shape.rank} dimensions. Use "
                "ivy.matrix_transpose(x) (the last two axes) or ivy.permute_dims(x, axes)."
            )
        return tf.transpose(self)

    def mT(self):  # noqa: N802 - the standard's name
        if self.shape.rank is not None and self.shape.rank < 2:
            raise ValueError(
                f"x.mT needs an array of two or more dimensions; this one has {self.shape.rank}."
            )
        return FUNCTIONS["matrix_transpose"](self, f=ns)

    def size(self):
        return self.shape.num_elements()  # None where a dimension is unknown (in tf.function)

    def __pos__(self):
        return FUNCTIONS["positive"](self, f=ns)

    def binary(name: str, reflected: bool):
        fn = FUNCTIONS[name]  # ivy's dispatcher: its typed errors, numpy operands converted

        def method(self, other):
            if not isinstance(other, _OPERANDS):
                return NotImplemented
            return fn(other, self, f=ns) if reflected else fn(self, other, f=ns)

        return method

    return {
        "__array_namespace__": __array_namespace__,
        "to_device": to_device,
        "T": property(T, doc="The transpose of a 2-D array."),
        "mT": property(mT, doc="The transpose of the last two axes (a stack of matrices)."),
        "size": property(size, doc="The number of elements; None where a dimension is unknown."),
        "__pos__": __pos__,
        "__lshift__": binary("bitwise_left_shift", reflected=False),
        "__rlshift__": binary("bitwise_left_shift", reflected=True),
        "__rshift__": binary("bitwise_right_shift", reflected=False),
        "__rrshift__": binary("bitwise_right_shift", reflected=True),
    }
