"""ivy_mechanics: rotations, poses and coordinates, written once for every ivy backend.

Every function is framework-agnostic: it takes ``f=None`` (a framework name or namespace;
inferred from the inputs when None), resolves the backend once, accepts arbitrary leading batch
dimensions, keeps the float dtype of its input, and works under ``jax.jit`` and ``tf.function``.

Conventions: active right-handed rotations; quaternions scalar-last ``[x, y, z, w]``; Euler
sequences spelled as scipy does (``'XYZ'`` intrinsic, ``'xyz'`` extrinsic). Conversions are
exact at the identity, at rotations by pi and at gimbal lock, with finite gradients there.

Modules: :mod:`ivy_mechanics.orientation` (rotations), :mod:`ivy_mechanics.pose`,
:mod:`ivy_mechanics.position` (coordinates) and :mod:`ivy_mechanics.lie` (SO(3) and SE(3)).

Example:
    >>> import numpy as np, ivy_mechanics as mech
    >>> mech.rot_vec_to_quaternion(np.zeros(3))
    array([0., 0., 0., 1.])
"""

from ivy_mechanics import lie, orientation, pose, position
from ivy_mechanics.lie import *  # noqa: F403
from ivy_mechanics.orientation import *  # noqa: F403
from ivy_mechanics.pose import *  # noqa: F403
from ivy_mechanics.position import *  # noqa: F403

__all__ = [
    *orientation.__all__,
    *pose.__all__,
    *position.__all__,
    *lie.__all__,
]
