"""tensorflow backend: random numbers from one module-level ``tf.random.Generator``.

The generator's state is a tf.Variable, so draws inside a tf.function differ from call to call,
and :func:`seed` resets that same state, which compiled functions see too.
"""

from __future__ import annotations

import tensorflow as tf

from ivy.backends._sample_args import categorical_args, check_draw_bounds, floating_draw
from ivy.backends.tensorflow._helpers import native_dtype, placed, tensor, tensor_of

_generator: list[tf.random.Generator] = []  # created on first use


def _rng() -> tf.random.Generator:
    if not _generator:
        with tf.init_scope():  # out of any tf.function being traced
            _generator.append(tf.random.Generator.from_non_deterministic_state())
    return _generator[0]


def seed(seed_value=0):
    if _generator:
        _generator[0].reset_from_seed(seed_value)
    else:
        with tf.init_scope():
            _generator.append(tf.random.Generator.from_seed(seed_value))


def _shape(shape, a, b):
    """``shape`` as a list, or the broadcast shape of the bounds ``a`` and ``b``."""
    if shape is None:
        return tf.broadcast_dynamic_shape(tf.shape(a), tf.shape(b))
    return [shape] if isinstance(shape, int) else shape


def random_uniform(low=0.0, high=1.0, shape=None, *, dtype=None, device=None):
    dt = native_dtype(dtype) or tf.float32
    floating_draw("random_uniform", "tensorflow", dtype, dt.is_floating or dt.is_complex)
    check_draw_bounds("random_uniform", low, high, "tensorflow")
    work = dt if dt.is_floating else tf.float64
    with placed(device):
        low, high = tensor_of(low, work), tensor_of(high, work)
        out = low + (high - low) * _rng().uniform(_shape(shape, low, high), dtype=work)
        return out if work is dt else tf.cast(out, dt)


def random_normal(mean=0.0, std=1.0, shape=None, *, dtype=None, device=None):
    dt = native_dtype(dtype) or tf.float32
    floating_draw("random_normal", "tensorflow", dtype, dt.is_floating or dt.is_complex)
    check_draw_bounds("random_normal", mean, std, "tensorflow")
    work = dt if dt.is_floating else tf.float64
    with placed(device):
        mean, std = tensor_of(mean, work), tensor_of(std, work)
        out = mean + std * _rng().normal(_shape(shape, mean, std), dtype=work)
        return out if work is dt else tf.cast(out, dt)


def randint(low, high, shape=None, *, dtype=None, device=None):
    dt = native_dtype(dtype) or tf.int64
    scalars = isinstance(low, int) and isinstance(high, int)
    check_draw_bounds("randint", low, high, "tensorflow")
    with placed(device):
        low, high = tensor_of(low, tf.int64), tensor_of(high, tf.int64)
        if not scalars:
            tf.debugging.assert_less(low, high, message="randint: low must be less than high")
        # Full-range 64-bit integers reduced modulo the span: bias below span / 2**64.
        bits = _rng().uniform_full_int(_shape(shape, low, high), dtype=tf.int64)
        out = low + tf.math.floormod(bits, high - low)
        return out if dt is tf.int64 else tf.cast(out, dt)


def shuffle(x, /):
    x = tensor(x)
    keys = _rng().uniform_full_int(tf.shape(x)[:1], dtype=tf.int64)
    return tf.gather(x, tf.argsort(keys))


def random_categorical(logits, /, *, num_samples=1, dtype=None):
    """``tf.random.stateless_categorical`` seeded from the generator, which advances it."""
    logits = tensor(logits)
    n = categorical_args(logits.shape.as_list(), num_samples)
    if logits.dtype not in (tf.float32, tf.float64):
        logits = tf.cast(logits, tf.float32)
    dt = native_dtype(dtype) or tf.int64
    seed = _rng().make_seeds(1)[:, 0]
    out = tf.random.stateless_categorical(tf.reshape(logits, [-1, n]), num_samples, seed)
    shape = tf.concat([tf.shape(logits)[:-1], [num_samples]], axis=0)
    return tf.cast(tf.reshape(out, shape), dt)
