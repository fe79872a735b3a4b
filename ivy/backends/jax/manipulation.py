"""jax backend: shape manipulation (jax.numpy's own functions where they match)."""

from __future__ import annotations

import itertools

import jax
import jax.numpy as jnp
import numpy as np

from ivy._args.axes import new_axis_positions

reshape = jnp.reshape
# (jnp.permute_dims refuses negative axes, which the standard's tests pass)
permute_dims = jnp.transpose
transpose = jnp.transpose
concat = jnp.concat
stack = jnp.stack
unstack = jnp.unstack
squeeze = jnp.squeeze
flip = jnp.flip
tile = jnp.tile
repeat = jnp.repeat
roll = jnp.roll
swapaxes = jnp.swapaxes
broadcast_to = jnp.broadcast_to


def split(x, /, num_or_size_splits=None, *, axis=0):
    size = x.shape[axis]
    if num_or_size_splits is None:
        num_or_size_splits = size
    if isinstance(num_or_size_splits, (int, np.integer)):
        if size % num_or_size_splits:
            raise ValueError(
                f"split: axis {axis} of size {size} does not divide into "
                f"{num_or_size_splits} equal pieces; pass a list of piece sizes instead."
            )
        return jnp.split(x, num_or_size_splits, axis=axis)
    sizes = [int(s) for s in num_or_size_splits]
    if sum(sizes) != size:
        raise ValueError(
            f"split: piece sizes {sizes} add up to {sum(sizes)}, not to the size "
            f"{size} of axis {axis}."
        )
    return jnp.split(x, list(itertools.accumulate(sizes[:-1])), axis=axis)


def expand_dims(x, /, axis=0):
    try:
        return jnp.expand_dims(x, axis)
    except ValueError:  # jax's is a ValueError: ivy's AxisError is an IndexError too
        new_axis_positions(axis, jnp.ndim(x), "expand_dims", "jax")
        raise


if jax.__version_info__ < (0, 11):
    broadcast_arrays = jnp.broadcast_arrays  # a list, as the Array API (2023.12) says
else:  # jax 0.11 returns a tuple

    def broadcast_arrays(*arrays):
        return list(jnp.broadcast_arrays(*arrays))


moveaxis = jnp.moveaxis
