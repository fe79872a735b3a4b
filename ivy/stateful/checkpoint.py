"""Portable checkpoints: a nest of arrays saved as an ``.npz`` file of numpy arrays.

Each array is stored under its path in the nest joined by ``'/'`` (``'layers/0/w'``), as read by
``ivy.to_numpy``, so a checkpoint written on one backend loads on any other.

Example:
    >>> torch_model = ivy.MLP(4, (8,), 1, f="torch")
    >>> jax_model = ivy.MLP(4, (8,), 1, f="jax")
    >>> save_weights("mlp.npz", torch_model.v)
    >>> jax_model.v = load_weights("mlp.npz", like=jax_model.v)
"""

from __future__ import annotations

import os
from typing import Any

from ivy import framework_handler as _fh
from ivy.errors import NoFrameworkError
from ivy.typing import Device, Framework, Nest

__all__ = ["save_weights", "load_weights", "nest_to_flat_dict", "flat_dict_to_nest"]

SEPARATOR = "/"


def nest_to_flat_dict(nest: Nest) -> dict[str, Any]:
    """``{'a/b': leaf}`` for every leaf of a nest of dicts (and lists or tuples, by index).

    Example:
        >>> w = np.zeros(2)
        >>> nest_to_flat_dict({"layers": {"0": {"w": w}}})
        {'layers/0/w': array([0., 0.])}
    """
    flat: dict[str, Any] = {}

    def walk(node: Any, prefix: str) -> None:
        if isinstance(node, dict):
            items = node.items()
        elif isinstance(node, (list, tuple)):
            items = enumerate(node)
        else:
            if not prefix:
                raise TypeError("a checkpoint needs a nest (dict) of arrays, not a single array")
            flat[prefix] = node
            return
        for key, value in items:
            key = str(key)
            if not key or SEPARATOR in key:
                raise ValueError(f"nest keys must be non-empty and contain no '/', got {key!r}")
            walk(value, f"{prefix}{SEPARATOR}{key}" if prefix else key)

    walk(nest, "")
    return flat


def flat_dict_to_nest(flat: dict[str, Any]) -> dict[str, Any]:
    """The nest of dicts of a ``{'a/b': leaf}`` dict (inverse of :func:`nest_to_flat_dict`).

    Example:
        >>> w = np.zeros(2)
        >>> flat_dict_to_nest({"layers/0/w": w})
        {'layers': {'0': {'w': array([0., 0.])}}}
    """
    nest: dict[str, Any] = {}
    for path, leaf in flat.items():
        *parents, last = path.split(SEPARATOR)
        node = nest
        for key in parents:
            node = node.setdefault(key, {})
        node[last] = leaf
    return nest


def save_weights(path: str | os.PathLike, v: Nest) -> None:
    """Save a nest of arrays of any backend to the ``.npz`` file ``path`` (exactly that name).

    Args:
        path: file to write.
        v: nest of dicts of arrays (e.g. ``module.v`` or an optimizer state).

    Example:
        >>> model = ivy.MLP(4, (8,), 1, f="torch")
        >>> save_weights("mlp.npz", model.v)
    """
    import numpy as np  # imported on use: ``import ivy`` imports no framework

    flat = nest_to_flat_dict(v)
    arrays = {}
    for key, leaf in flat.items():
        xp = _fh.get_framework(leaf)
        arrays[key] = np.asarray(xp.to_numpy(leaf))
    with open(path, "wb") as fh:
        np.savez(fh, **arrays)


def load_weights(
    path: str | os.PathLike,
    *,
    like: Nest | None = None,
    device: Device | None = None,
    f: Framework = None,
) -> dict[str, Any]:
    """Load a checkpoint written by :func:`save_weights` on any backend.

    Args:
        path: the ``.npz`` file.
        like: a nest to load into (e.g. ``module.v``): the keys and shapes must match, and each
            array takes the framework, dtype and device of the array it replaces.
        device: device of the arrays when ``like`` is None.
        f: framework of the arrays when ``like`` is None (default: the global framework).

    Returns:
        A nest of dicts of arrays of the chosen framework.

    Example:
        >>> model = ivy.MLP(4, (8,), 1, f="jax")
        >>> save_weights("mlp.npz", ivy.MLP(4, (8,), 1, f="torch").v)
        >>> model.v = load_weights("mlp.npz", like=model.v)
        >>> v = load_weights("mlp.npz", f="jax")
    """
    import numpy as np  # imported on use: ``import ivy`` imports no framework

    with np.load(path, allow_pickle=False) as data:
        stored = {key: data[key] for key in data.files}
    if like is None:
        xp = _fh.get_framework(f=f) if f is not None else _fh.current_framework()
        if xp is None:
            raise NoFrameworkError(
                "load_weights needs a framework for the arrays: pass like=module.v, f='torch' "
                "(or f=ivy.torch), or set one with ivy.set_framework('torch')."
            )
        return flat_dict_to_nest(
            {key: xp.asarray(value, device=device) for key, value in stored.items()}
        )
    target = nest_to_flat_dict(like)
    missing, extra = sorted(set(target) - set(stored)), sorted(set(stored) - set(target))
    if missing or extra:
        raise KeyError(
            f"checkpoint {os.fspath(path)!r} does not match the nest: missing {missing}, "
            f"unexpected {extra}"
        )
    loaded = {}
    for key, old in target.items():
        value = stored[key]
        xp = _fh.get_framework(old)
        if tuple(value.shape) != tuple(xp.shape(old)):
            raise ValueError(
                f"checkpoint {os.fspath(path)!r}: {key} has shape {tuple(value.shape)}, "
                f"expected {tuple(xp.shape(old))}"
            )
        loaded[key] = xp.asarray(value, dtype=xp.dtype(old), device=xp.dev(old))
    return _rebuild(like, loaded, "")


def _rebuild(like: Any, loaded: dict[str, Any], prefix: str) -> Any:
    """A nest with the containers of ``like`` and the leaves of ``loaded`` (keyed by path)."""
    join = (lambda k: f"{prefix}{SEPARATOR}{k}") if prefix else str
    if isinstance(like, dict):
        return {k: _rebuild(val, loaded, join(k)) for k, val in like.items()}
    if isinstance(like, (list, tuple)):
        items = [_rebuild(val, loaded, join(i)) for i, val in enumerate(like)]
        return type(like)(items) if type(like) in (list, tuple) else type(like)(*items)
    return loaded[prefix]
