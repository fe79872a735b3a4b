"""The stateful layer: modules that hold their variables as a nest, layers, initializers,
optimizers and portable checkpoints.

A :class:`Module` is built for one framework; ``module(x)`` uses its own variables ``module.v``
and ``module(x, v=v)`` the nest given (pure: it differentiates and compiles). Optimizers update
nests functionally (``v, state = opt.step(v, grads, state)``) or a module in place
(``opt.minimize(module, loss_fn)``). ``module.save(path)`` writes an ``.npz`` file that a module
of the same architecture loads on any backend (``module.load(path)``).

Example:
    >>> import ivy, torch
    >>> ivy.seed(0)
    >>> model = ivy.MLP(3, (64, 64), 1, f="torch")
    >>> opt = ivy.Adam(1e-2)
    >>> x, y = torch.randn(32, 3), torch.randn(32, 1)
    >>> loss = opt.minimize(model, lambda v: ivy.mse(model(x, v=v), y))
    >>> model.save("mlp.npz")
    >>> ivy.MLP(3, (64, 64), 1, f="jax").load("mlp.npz")
    MLP(f=jax, dtype=float32, parameters=4481)
"""

from ivy.stateful import checkpoint, initializers  # noqa: F401 - submodules, as ivy.stateful.*
from ivy.stateful.checkpoint import load_weights, save_weights
from ivy.stateful.layers import LSTM, MLP, Conv, Conv1D, Conv2D, Conv3D, Linear, Sequential
from ivy.stateful.module import Module
from ivy.stateful.optimizers import SGD, Adam, AdamW, Optimizer

__all__ = [
    "Module",
    "Linear",
    "MLP",
    "Conv",
    "Conv1D",
    "Conv2D",
    "Conv3D",
    "LSTM",
    "Sequential",
    "Optimizer",
    "SGD",
    "Adam",
    "AdamW",
    "save_weights",
    "load_weights",
]
