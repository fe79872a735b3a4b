"""Layers: Linear, MLP, Conv1D/2D/3D, LSTM and Sequential.

Each layer is a :class:`~ivy.stateful.module.Module`: its variables are a nest ``v``, and
``layer(x, v=v)`` is a pure function of ``x`` and ``v``. Layouts follow ivy's functional API:
``ivy.linear`` weights are ``[out, in]``, convolutions are channel-last with filters
``[*kernel, in, out]``, ``ivy.lstm_update`` kernels are ``[in, 4 * hidden]`` (gates i, f, g, o).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

from ivy import framework_handler as _fh
from ivy.stateful.initializers import glorot_uniform, orthogonal, zeros
from ivy.stateful.module import Module
from ivy.typing import Device, Dtype, Framework

__all__ = ["Linear", "MLP", "Conv", "Conv1D", "Conv2D", "Conv3D", "LSTM", "Sequential"]


def _activation(spec: str | Callable | None, xp) -> Callable | None:
    """An activation given by name (``'relu'``: the backend's own function) or a callable."""
    if spec is None or callable(spec):
        return spec
    fn = getattr(xp, spec, None)
    if fn is None:
        raise ValueError(f"unknown activation {spec!r}: ivy.{xp.backend} has no function {spec!r}")
    return fn


class Linear(Module):
    """A dense layer ``y = x @ w.T + b`` with ``w`` of shape ``[out, in]``.

    Args:
        in_features: size of the last axis of the input.
        out_features: size of the last axis of the output.
        bias: whether to add a bias ``b`` of shape ``[out]``.
        weight_init: initializer of ``w`` (default Glorot uniform).
        bias_init: initializer of ``b`` (default zeros).
        dtype, device, f: see :class:`~ivy.stateful.module.Module`.

    Returns (when called on ``x`` of shape ``[..., in]``):
        An array of shape ``[..., out]``.

    Example:
        >>> layer = ivy.Linear(3, 2, f="torch")
        >>> layer(torch.ones(5, 3)).shape
        torch.Size([5, 2])
        >>> sorted(layer.v)
        ['b', 'w']
    """

    def __init__(
        self,
        in_features: int,
        out_features: int,
        *,
        bias: bool = True,
        weight_init: Callable = glorot_uniform,
        bias_init: Callable = zeros,
        dtype: Dtype | None = None,
        device: Device | None = None,
        f: Framework = None,
    ) -> None:
        super().__init__(dtype=dtype, device=device, f=f)
        self.in_features = in_features
        self.out_features = out_features
        self.use_bias = bias
        self.add_variable("w", weight_init, (out_features, in_features))
        if bias:
            self.add_variable("b", bias_init, (out_features,), fan_in=in_features)

    def _forward(self, v, x):
        return self._f.linear(x, v["w"], v["b"] if self.use_bias else None)


class MLP(Module):
    """A multi-layer perceptron: Linear layers with an activation between them.

    Args:
        in_features: size of the input's last axis.
        hidden_features: sizes of the hidden layers, e.g. ``(256, 256)``.
        out_features: size of the output's last axis.
        activation: between layers: a name of an ivy function (``'relu'``, ``'tanh'``...) or a
            callable.
        output_activation: applied to the output (None: linear output).
        bias, weight_init, bias_init: as for :class:`Linear`.
        dtype, device, f: see :class:`~ivy.stateful.module.Module`.

    The variables are ``{'layers': {'0': {'w', 'b'}, '1': ..., ...}}``.

    Example:
        >>> mlp = ivy.MLP(4, (32, 32), 1, f="jax")
        >>> y = mlp(jnp.ones((8, 4)))              # own variables
        >>> y = mlp(jnp.ones((8, 4)), v=mlp.v)     # the nest given: pure
    """

    def __init__(
        self,
        in_features: int,
        hidden_features: Sequence[int],
        out_features: int,
        *,
        activation: str | Callable = "relu",
        output_activation: str | Callable | None = None,
        bias: bool = True,
        weight_init: Callable = glorot_uniform,
        bias_init: Callable = zeros,
        dtype: Dtype | None = None,
        device: Device | None = None,
        f: Framework = None,
    ) -> None:
        super().__init__(dtype=dtype, device=device, f=f)
        sizes = [in_features, *hidden_features, out_features]
        self.layers = [
            Linear(
                n_in,
                n_out,
                bias=bias,
                weight_init=weight_init,
                bias_init=bias_init,
                **self.build_args,
            )
            for n_in, n_out in zip(sizes[:-1], sizes[1:])
        ]
        self.activation = _activation(activation, self._f)
        self.output_activation = _activation(output_activation, self._f)
        self._steps = [(str(i), layer) for i, layer in enumerate(self.layers)]

    def _forward(self, v, x):
        layers_v = v["layers"]
        key, layer = self._steps[0]
        x = layer._forward(layers_v[key], x)
        for key, layer in self._steps[1:]:
            x = layer._forward(layers_v[key], self.activation(x))
        return x if self.output_activation is None else self.output_activation(x)


class Conv(Module):
    """An N-D convolution, channel-last: input ``[batch..., *spatial, in_channels]``.

    Args:
        dims: number of spatial dimensions (1, 2 or 3).
        in_channels, out_channels: channels of the input and of the output.
        kernel_size: an int or one int per spatial dimension.
        strides, padding, dilations: as for ``ivy.conv2d`` (padding ``'SAME'`` or ``'VALID'``).
        bias: whether to add a bias of shape ``[out_channels]``.
        weight_init, bias_init: initializers of the filters ``[*kernel, in, out]`` and bias.
        dtype, device, f: see :class:`~ivy.stateful.module.Module`.

    Example:
        >>> conv = ivy.Conv2D(3, 8, 3, f="tensorflow")
        >>> conv(tf.ones((2, 16, 16, 3))).shape
        TensorShape([2, 16, 16, 8])
    """

    def __init__(
        self,
        dims: int,
        in_channels: int,
        out_channels: int,
        kernel_size: int | Sequence[int],
        *,
        strides: int | Sequence[int] = 1,
        padding: str = "SAME",
        dilations: int | Sequence[int] = 1,
        bias: bool = True,
        weight_init: Callable = glorot_uniform,
        bias_init: Callable = zeros,
        dtype: Dtype | None = None,
        device: Device | None = None,
        f: Framework = None,
    ) -> None:
        if dims not in (1, 2, 3):
            raise ValueError(f"Conv supports 1, 2 or 3 spatial dimensions, got dims={dims}")
        super().__init__(dtype=dtype, device=device, f=f)
        kernel = (kernel_size,) * dims if isinstance(kernel_size, int) else tuple(kernel_size)
        if len(kernel) != dims:
            raise ValueError(f"kernel_size {kernel_size!r} does not have {dims} dimension(s)")
        self.dims = dims
        self.in_channels = in_channels
        self.out_channels = out_channels
        self.kernel_size = kernel
        self.strides = strides
        self.padding = padding
        self.dilations = dilations
        self.use_bias = bias
        self._conv_name = f"conv{dims}d"
        self.add_variable("w", weight_init, (*kernel, in_channels, out_channels))
        if bias:
            fan_in = in_channels * math.prod(kernel)
            self.add_variable("b", bias_init, (out_channels,), fan_in=fan_in)

    def _forward(self, v, x):
        conv = getattr(self._f, self._conv_name)
        y = conv(x, v["w"], self.strides, self.padding, dilations=self.dilations)
        return self._f.add(y, v["b"]) if self.use_bias else y


class Conv1D(Conv):
    """1-D convolution on ``[batch, width, channels]``; arguments as :class:`Conv` less ``dims``.

    Example: ``ivy.Conv1D(4, 8, 5, f='jax')(jnp.ones((2, 32, 4))).shape == (2, 32, 8)``.
    """

    def __init__(
        self, in_channels: int, out_channels: int, kernel_size: int | Sequence[int], **kwargs: Any
    ) -> None:
        super().__init__(1, in_channels, out_channels, kernel_size, **kwargs)


class Conv2D(Conv):
    """2-D convolution on ``[batch, height, width, channels]``; arguments as :class:`Conv`.

    Example: ``ivy.Conv2D(3, 8, 3, f='torch')(torch.ones(2, 16, 16, 3)).shape == (2, 16, 16, 8)``.
    """

    def __init__(
        self, in_channels: int, out_channels: int, kernel_size: int | Sequence[int], **kwargs: Any
    ) -> None:
        super().__init__(2, in_channels, out_channels, kernel_size, **kwargs)


class Conv3D(Conv):
    """3-D convolution on ``[batch, depth, height, width, channels]``; arguments as :class:`Conv`.

    Example: ``ivy.Conv3D(1, 4, 3, f='numpy')(np.ones((1, 8, 8, 8, 1), 'float32'))``.
    """

    def __init__(
        self, in_channels: int, out_channels: int, kernel_size: int | Sequence[int], **kwargs: Any
    ) -> None:
        super().__init__(3, in_channels, out_channels, kernel_size, **kwargs)


class _LSTMLayer(Module):
    """One LSTM layer over a whole sequence, with ``ivy.lstm_update``."""

    def __init__(
        self, in_features, hidden_features, *, bias, kernel_init, recurrent_init, bias_init, **kw
    ) -> None:
        super().__init__(**kw)
        self.hidden_features = hidden_features
        self.use_bias = bias
        gates = 4 * hidden_features
        self.add_variable(
            "kernel", kernel_init, (in_features, gates), fan_in=in_features, fan_out=gates
        )
        self.add_variable(
            "recurrent_kernel",
            recurrent_init,
            (hidden_features, gates),
            fan_in=hidden_features,
            fan_out=gates,
        )
        if bias:
            self.add_variable("bias", bias_init, (gates,), fan_in=in_features, fan_out=gates)

    def _forward(self, v, x, h, c):
        bias = v["bias"] if self.use_bias else None
        return self._f.lstm_update(x, h, c, v["kernel"], v["recurrent_kernel"], bias)


class LSTM(Module):
    """A stack of LSTM layers run over a sequence ``x`` of shape ``[batch..., time, in]``.

    Args:
        in_features: size of the input's last axis.
        hidden_features: size of each layer's hidden state.
        num_layers: number of stacked layers; each layer reads the previous one's outputs.
        bias: whether each layer has a bias ``[4 * hidden]`` (gates i, f, g, o).
        kernel_init: initializer of the input kernels ``[in, 4 * hidden]`` (Glorot uniform).
        recurrent_init: initializer of the recurrent kernels ``[hidden, 4 * hidden]``
            (orthogonal).
        bias_init: initializer of the biases (zeros).
        dtype, device, f: see :class:`~ivy.stateful.module.Module`.

    Called as ``lstm(x, initial_state=None, v=None)``, where ``initial_state`` is a list of
    ``(h, c)`` per layer (zeros if None).

    Returns:
        ``(hs, states)``: the last layer's hidden states ``[batch..., time, hidden]`` and the
        final ``(h, c)`` of each layer, each ``[batch..., hidden]``.

    Example:
        >>> lstm = ivy.LSTM(3, 16, num_layers=2, f="jax")
        >>> hs, [(h0, c0), (h1, c1)] = lstm(jnp.ones((4, 10, 3)))
        >>> hs.shape
        (4, 10, 16)
    """

    def __init__(
        self,
        in_features: int,
        hidden_features: int,
        *,
        num_layers: int = 1,
        bias: bool = True,
        kernel_init: Callable = glorot_uniform,
        recurrent_init: Callable = orthogonal,
        bias_init: Callable = zeros,
        dtype: Dtype | None = None,
        device: Device | None = None,
        f: Framework = None,
    ) -> None:
        super().__init__(dtype=dtype, device=device, f=f)
        self.in_features = in_features
        self.hidden_features = hidden_features
        self.num_layers = num_layers
        self.layers = [
            _LSTMLayer(
                in_features if i == 0 else hidden_features,
                hidden_features,
                bias=bias,
                kernel_init=kernel_init,
                recurrent_init=recurrent_init,
                bias_init=bias_init,
                **self.build_args,
            )
            for i in range(num_layers)
        ]

    def _forward(self, v, x, initial_state=None):
        xp = self._f
        if initial_state is None:
            batch = tuple(x.shape[:-2])
            zero = xp.zeros(batch + (self.hidden_features,), dtype=x.dtype, device=self._device)
            initial_state = [(zero, zero)] * self.num_layers
        layers_v = v["layers"]
        states = []
        for i, layer in enumerate(self.layers):
            h, c = initial_state[i]
            x, state = layer._forward(layers_v[str(i)], x, h, c)
            states.append(tuple(state))
        return x, states


class Sequential(Module):
    """Modules and functions applied one after the other.

    Args:
        *layers: modules (their variables go to ``v['layers'][str(position)]``) and callables
            of one array (activations such as ``ivy.relu``, or names such as ``'relu'``).
        dtype, device: recorded for reference; the layers own their variables.
        f: the framework; default: that of the first module among ``layers``.

    Example:
        >>> net = ivy.Sequential(ivy.Linear(4, 8, f="torch"), "relu", ivy.Linear(8, 1, f="torch"))
        >>> sorted(net.v["layers"])
        ['0', '2']
    """

    def __init__(
        self,
        *layers: Module | Callable | str,
        dtype: Dtype | None = None,
        device: Device | None = None,
        f: Framework = None,
    ) -> None:
        modules = [m for m in layers if isinstance(m, Module)]
        if f is None and _fh.current_framework() is None and modules:
            f = modules[0].f
        if dtype is None and modules:
            dtype = modules[0].dtype
        super().__init__(dtype=dtype, device=device, f=f)
        self.layers = [m if isinstance(m, Module) else _activation(m, self._f) for m in layers]
        self._steps = [
            (str(i), m) if isinstance(m, Module) else (None, m) for i, m in enumerate(self.layers)
        ]

    def _forward(self, v, x):
        layers_v = v.get("layers")
        for key, layer in self._steps:
            x = layer(x) if key is None else layer._forward(layers_v[key], x)
        return x
