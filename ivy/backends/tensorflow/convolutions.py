"""tensorflow backend: the one convolution, channel-last (tf's own layout), with ``tf.nn.conv1d``,
``conv2d``, ``conv3d``, their transposes and ``depthwise_conv2d``.

tf's CPU kernels reject some dilation settings (float64 dilated convolutions and their gradients,
strides together with dilations in ``tf.nn.convolution``), so a dilated kernel is expanded with
zeros between its taps and run undilated: the same result, on every dtype. Padding that is
neither tf's 'SAME' nor 'VALID' for the input's sizes is added with ``tf.pad``; transposed
convolutions are computed in full ('VALID') and then cropped. tf's CPU has no grouped
convolution: depthwise 2-D ones (one group per channel) run as ``tf.nn.depthwise_conv2d``, others
as one convolution per group.
"""

from __future__ import annotations

import tensorflow as tf

from ivy._args import nn as A
from ivy.errors import UnsupportedError

# The rank-specific functions: ``tf.nn.convolution`` builds 3-D ops whose gradient fails
# (their ``data_format`` attribute is unset).
_CONV = {
    1: lambda x, w, s, padding: tf.nn.conv1d(x, w, s[0], padding),
    2: lambda x, w, s, padding: tf.nn.conv2d(x, w, s, padding),
    3: lambda x, w, s, padding: tf.nn.conv3d(x, w, (1, *s, 1), padding),
}
_CONV_TRANSPOSE = {
    1: lambda x, w, shape, s: tf.nn.conv1d_transpose(x, w, shape, s[0], "VALID"),
    2: lambda x, w, shape, s: tf.nn.conv2d_transpose(x, w, shape, s, "VALID"),
    3: lambda x, w, shape, s: tf.nn.conv3d_transpose(x, w, shape, (1, *s, 1), "VALID"),
}


def dilate_kernel(filters, dilations):
    """``filters`` with ``d - 1`` zeros between the taps of each spatial axis."""
    for axis, d in enumerate(dilations):
        if d == 1:
            continue
        shape = list(filters.shape)
        k = shape[axis]
        spaced = tf.expand_dims(filters, axis + 1)
        zeros = tf.zeros(shape[: axis + 1] + [d - 1] + shape[axis + 1 :], filters.dtype)
        spaced = tf.concat([spaced, zeros], axis + 1)
        spaced = tf.reshape(spaced, shape[:axis] + [k * d] + shape[axis + 1 :])
        filters = spaced[(slice(None),) * axis + (slice(0, d * (k - 1) + 1),)]
    return filters


def pad_spatial(x, pads, value=0):
    return tf.pad(x, [(0, 0), *pads, (0, 0)], constant_values=value)


def native_padding(x, padding, windows, strides, value=0):
    """``x``, padded where tf cannot, and tf's padding string ('SAME' or 'VALID') for the rest:
    explicit pads that equal tf's 'SAME' (or no padding) go to tf's kernels as they are."""
    if isinstance(padding, str):  # sizes unknown until run time (see conv_general)
        return x, padding
    if all(lo == 0 and hi == 0 for lo, hi in padding):
        return x, "VALID"
    if padding == A.same_pads(tuple(x.shape[1:-1]), windows, strides):
        return x, "SAME"
    return pad_spatial(x, padding, value), "VALID"


def _convert(x, filters):
    x = tf.convert_to_tensor(x)
    filters = tf.convert_to_tensor(filters)
    if filters.dtype != x.dtype:
        raise TypeError(
            f"x is {x.dtype.name} but filters are {filters.dtype.name}; cast one of them "
            f"(ivy.astype) so that both have the same dtype."
        )
    return x, filters


def _crop(y, crops):
    return y[(slice(None), *(slice(lo, n - hi) for (lo, hi), n in zip(crops, y.shape[1:-1])))]


def conv_general(x, filters, strides, padding, dilations, /, *, groups=1, transpose=False):
    x, filters = _convert(x, filters)
    if x.shape[0] == 0:  # tf's convolutions give back their input for an empty batch
        one = tf.zeros((1, *x.shape[1:]), x.dtype)
        out = conv_general(
            one, filters, strides, padding, dilations, groups=groups, transpose=transpose
        )
        return out[:0]
    nd = len(strides)
    kernel = dilate_kernel(filters, dilations)
    windows = tuple(kernel.shape[:nd])
    if transpose:
        full_sizes = [(n - 1) * s + w for n, s, w in zip(x.shape[1:-1], strides, windows)]
        batch = x.shape[0] if x.shape[0] is not None else tf.shape(x)[0]
        full = _CONV_TRANSPOSE[nd](x, kernel, [batch, *full_sizes, filters.shape[-2]], strides)
        return _crop(full, padding)
    if groups == 1:
        x, tf_padding = native_padding(x, padding, windows, strides)
        return _CONV[nd](x, kernel, strides, tf_padding)
    if nd != 2 or filters.shape[-2] != 1 or filters.shape[-1] != groups:
        # tf's CPU has no grouped convolution: one convolution per group
        xs, ws = tf.split(x, groups, axis=-1), tf.split(filters, groups, axis=-1)
        return tf.concat(
            [conv_general(a, w, strides, padding, dilations) for a, w in zip(xs, ws)], axis=-1
        )
    step = strides
    if strides[0] != strides[1]:  # tf's kernel takes equal strides only: stride 1, then subsample
        step = (1, 1)
        if padding == "SAME":  # unknown sizes: tf's 'SAME' of stride 1 is not that of strides
            raise UnsupportedError(
                "depthwise_conv2d on tensorflow: 'SAME' padding with unequal strides needs the "
                "spatial sizes before run time; give the tf.function an input_signature with "
                "known sizes, or equal strides."
            )
    x, tf_padding = native_padding(x, padding, windows, step)
    y = tf.nn.depthwise_conv2d(
        x, tf.reshape(kernel, (*windows, groups, 1)), strides=(1, *step, 1), padding=tf_padding
    )
    return y if step == strides else y[:, :: strides[0], :: strides[1]]
