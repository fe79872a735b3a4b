"""tensorflow backend: convolutions, channel-last (tf's own layout), with ``tf.nn.conv1d``,
``conv2d``, ``conv3d``, their transposes and ``depthwise_conv2d``.

tf's CPU kernels reject some dilation settings (float64 dilated convolutions and their gradients,
strides together with dilations in ``tf.nn.convolution``), so a dilated kernel is expanded with
zeros between its taps and run undilated: the same result, on every dtype. Explicit padding is
added with ``tf.pad``; transposed convolutions are computed in full ('VALID') and then cropped.
"""

from __future__ import annotations

import tensorflow as tf

from ivy.backends import _nn_args as A

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


def static_shape(x):
    return tuple(x.shape)


def flatten_batch(x, nd):
    """``x`` with its leading axes folded into one, and a function that unfolds a result."""
    rank = len(x.shape)
    if rank == nd + 2:
        return x, lambda y: y
    shape = tf.shape(x)
    lead = shape[: rank - nd - 1]
    x = tf.reshape(x, tf.concat([[-1], shape[rank - nd - 1 :]], 0))
    return x, lambda y: tf.reshape(y, tf.concat([lead, tf.shape(y)[1:]], 0))


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


def _convert(x, filters):
    x = tf.convert_to_tensor(x)
    filters = tf.convert_to_tensor(filters)
    if filters.dtype != x.dtype:
        raise TypeError(
            f"x is {x.dtype.name} but filters are {filters.dtype.name}; cast one of them "
            f"(ivy.astype) so that both have the same dtype."
        )
    return x, filters


def _apply_padding(x, padding, windows, strides, fn):
    """``x`` padded as tf cannot, and the padding string to give tf ('SAME' or 'VALID')."""
    nd = len(windows)
    parsed = A.parse_padding(padding, nd, fn)
    sizes = tuple(x.shape[1:-1])
    if None not in sizes:  # static sizes (always, eagerly): check the output is not empty
        A.output_sizes(
            sizes, windows, strides, A.explicit_pads(parsed, sizes, windows, strides), fn
        )
    if isinstance(parsed, str):
        return x, parsed
    return pad_spatial(x, parsed), "VALID"


def _conv(x, filters, strides, padding, dilations, nd, fn):
    x, filters = _convert(x, filters)
    A.check_conv(static_shape(x), static_shape(filters), nd, fn)
    kernel = tuple(filters.shape[:nd])
    s = A.as_tuple(strides, nd, "strides", fn)
    d = A.as_tuple(dilations, nd, "dilations", fn)
    x, unflatten = flatten_batch(x, nd)
    windows = A.effective_windows(kernel, d)
    x, tf_padding = _apply_padding(x, padding, windows, s, fn)
    y = _CONV[nd](x, dilate_kernel(filters, d), s, tf_padding)
    return unflatten(y)


def crop_or_pad(y, lows, out_sizes):
    """``y[:, lo : lo + n, ..., :]`` per spatial axis, extended with zeros past its end."""
    index, extend = [slice(None)], [(0, 0)]
    for lo, n, size in zip(lows, out_sizes, y.shape[1:-1]):
        m = max(min(n, size - lo), 0)
        index.append(slice(lo, lo + m))
        extend.append((0, n - m))
    y = y[tuple(index)]
    if any(e != (0, 0) for e in extend):
        y = tf.pad(y, extend + [(0, 0)])
    return y


def _conv_transpose(x, filters, strides, padding, output_shape, dilations, nd, fn):
    x, filters = _convert(x, filters)
    A.check_conv(static_shape(x), static_shape(filters), nd, fn, transpose=True)
    kernel = tuple(filters.shape[:nd])
    s = A.as_tuple(strides, nd, "strides", fn)
    d = A.as_tuple(dilations, nd, "dilations", fn)
    x, unflatten = flatten_batch(x, nd)
    sizes = tuple(x.shape[1:-1])
    out_sizes, lows, full_sizes = A.transpose_geometry(
        sizes, A.effective_windows(kernel, d), s, padding, output_shape, fn, filters.shape[-2]
    )
    batch = x.shape[0] if x.shape[0] is not None else tf.shape(x)[0]
    full = _CONV_TRANSPOSE[nd](
        x, dilate_kernel(filters, d), [batch, *full_sizes, filters.shape[-2]], s
    )
    return unflatten(crop_or_pad(full, lows, out_sizes))


def conv1d(x, filters, strides, padding, /, *, dilations=1):
    return _conv(x, filters, strides, padding, dilations, 1, "conv1d")


def conv2d(x, filters, strides, padding, /, *, dilations=1):
    return _conv(x, filters, strides, padding, dilations, 2, "conv2d")


def conv3d(x, filters, strides, padding, /, *, dilations=1):
    return _conv(x, filters, strides, padding, dilations, 3, "conv3d")


def conv1d_transpose(x, filters, strides, padding, /, *, output_shape=None, dilations=1):
    return _conv_transpose(
        x, filters, strides, padding, output_shape, dilations, 1, "conv1d_transpose"
    )


def conv2d_transpose(x, filters, strides, padding, /, *, output_shape=None, dilations=1):
    return _conv_transpose(
        x, filters, strides, padding, output_shape, dilations, 2, "conv2d_transpose"
    )


def conv3d_transpose(x, filters, strides, padding, /, *, output_shape=None, dilations=1):
    return _conv_transpose(
        x, filters, strides, padding, output_shape, dilations, 3, "conv3d_transpose"
    )


def depthwise_conv2d(x, filters, strides, padding, /, *, dilations=1):
    fn = "depthwise_conv2d"
    x, filters = _convert(x, filters)
    A.check_depthwise(static_shape(x), static_shape(filters), fn)
    kernel = tuple(filters.shape[:2])
    s = A.as_tuple(strides, 2, "strides", fn)
    d = A.as_tuple(dilations, 2, "dilations", fn)
    x, unflatten = flatten_batch(x, 2)
    windows = A.effective_windows(kernel, d)
    step = s
    if s[0] != s[1]:  # tf's kernel takes equal strides only: stride 1, then subsample
        sizes = tuple(x.shape[1:-1])
        padding = A.explicit_pads(A.parse_padding(padding, 2, fn), sizes, windows, s)
        step = (1, 1)
    x, tf_padding = _apply_padding(x, padding, windows, step, fn)
    y = tf.nn.depthwise_conv2d(
        x, dilate_kernel(filters, d)[..., None], strides=(1, *step, 1), padding=tf_padding
    )
    if step != s:
        y = y[:, :: s[0], :: s[1]]
    return unflatten(y)
