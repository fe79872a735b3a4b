"""``Module``: a layer or network that holds its variables as a nest ``v``.

A module is built for one framework and creates its variables with that backend's functions. Its
parameters form a nest of dicts keyed by names (``{'layers': {'0': {'w': ..., 'b': ...}}}``).
``module(x)`` uses the module's own ``v``; ``module(x, v=v)`` uses the nest given and touches no
state, so it can run inside ``ivy.execute_with_gradients``, ``ivy.compile_fn`` or ``jax.jit``.
"""

from __future__ import annotations

import math
import os
import types
from collections.abc import Callable
from typing import Any

from ivy import framework_handler as _fh
from ivy.errors import MixedFrameworksError, NoFrameworkError
from ivy.typing import Array, Device, Dtype, Framework, Shape

__all__ = ["Module", "resolve_framework", "default_fans"]


def resolve_framework(f: Framework = None, dtype: Dtype | None = None) -> types.ModuleType:
    """The backend namespace a module is built for.

    Priority: an explicit ``f`` > the globally set framework > the framework that owns ``dtype``
    when it is a native dtype object (``torch.float64``, ``tf.float32``, ``jnp.float32``).

    Args:
        f: a framework name (``'torch'``) or namespace (``ivy.torch``), or None.
        dtype: a dtype name or a framework's own dtype object, or None.

    Returns:
        The backend namespace, e.g. ``ivy.torch``.

    Example:
        >>> resolve_framework(dtype=torch.float64).backend
        'torch'
    """
    if f is not None:
        return _fh.get_framework(f=f)
    current = _fh.current_framework()
    if current is not None:
        return current
    if dtype is not None and not isinstance(dtype, str):
        name = _fh.framework_of_type(type(dtype))
        if name is None and isinstance(dtype, type):  # np.float32 is itself a class
            name = _fh.framework_of_type(dtype)
        if name is not None:
            return _fh.load_backend(name)
    raise NoFrameworkError(
        "A Module needs a framework to create its variables. Pass f='torch' (or f=ivy.torch), "
        "a framework's own dtype (dtype=torch.float32), or set one globally with "
        "ivy.set_framework('torch') or `with ivy.set_framework('torch'):`."
    )


def default_fans(shape: Shape) -> tuple[int, int]:
    """``(fan_in, fan_out)`` of a weight of ``shape`` in ivy's layouts.

    2-D weights are ``[out, in]`` (as for ``ivy.linear``); weights of 3 or more dimensions are
    channel-last filters ``[*kernel, in, out]`` (as for ``ivy.conv2d``); a 1-D shape counts as
    ``[out]`` with ``fan_in == fan_out``.

    Example:
        >>> default_fans((3, 3, 16, 32))
        (144, 288)
    """
    shape = tuple(shape)
    if len(shape) == 0:
        return 1, 1
    if len(shape) == 1:
        return shape[0], shape[0]
    if len(shape) == 2:
        return shape[1], shape[0]
    receptive = math.prod(shape[:-2])
    return shape[-2] * receptive, shape[-1] * receptive


def _is_child_list(value: Any) -> bool:
    return isinstance(value, (list, tuple)) and any(isinstance(c, Module) for c in value)


class Module:
    """Base class of layers and networks whose variables form a nest ``v``.

    A subclass calls ``super().__init__(dtype=dtype, device=device, f=f)`` first, then creates
    its variables with :meth:`add_variable` and its sub-modules as attributes (a module, or a
    list of modules and plain callables; pass them ``**self.build_args``), and implements
    ``_forward(self, v, *args, **kwargs)`` reading its variables from ``v`` and calling each
    sub-module ``m`` as ``self.m(x, v=v['m'])``.

    Args:
        dtype: dtype of the variables (a name or the framework's dtype object); float32 if None.
        device: device of the variables (``'cpu'``, ``'gpu:0'``); the backend's default if None.
        f: the framework (name or namespace). Default: the global framework, else the
            framework of a native ``dtype``.

    Example:
        >>> class Affine(ivy.Module):
        ...     def __init__(self, n, *, dtype=None, device=None, f=None):
        ...         super().__init__(dtype=dtype, device=device, f=f)
        ...         self.add_variable("scale", ivy.stateful.initializers.ones, (n,))
        ...         self.add_variable("shift", ivy.stateful.initializers.zeros, (n,))
        ...     def _forward(self, v, x):
        ...         return x * v["scale"] + v["shift"]
        >>> m = Affine(3, f="numpy")
        >>> m(np.ones(3, np.float32))
        array([1., 1., 1.], dtype=float32)
    """

    def __init__(
        self, *, dtype: Dtype | None = None, device: Device | None = None, f: Framework = None
    ) -> None:
        d = self.__dict__
        d["_f"] = resolve_framework(f, dtype)
        d["_dtype"] = "float32" if dtype is None else dtype
        d["_device"] = device
        d.setdefault("_variables", {})
        d.setdefault("_children", {})

    # ------------------------------------------------------------------------------------------
    # Construction
    # ------------------------------------------------------------------------------------------

    @property
    def f(self) -> types.ModuleType:
        """The backend namespace the module computes with (``ivy.torch`` ...)."""
        return self._f

    @property
    def dtype(self) -> Dtype:
        """The dtype its variables were created with."""
        return self._dtype

    @property
    def device(self) -> Device | None:
        """The device its variables were created on (None: the backend's default)."""
        return self._device

    @property
    def build_args(self) -> dict[str, Any]:
        """``dict(dtype=..., device=..., f=...)``, to build sub-modules like this module."""
        return {"dtype": self._dtype, "device": self._device, "f": self._f}

    def add_variable(
        self,
        name: str,
        initializer: Callable[..., Array],
        shape: Shape,
        *,
        fan_in: int | None = None,
        fan_out: int | None = None,
    ) -> Array:
        """Create a variable with ``initializer`` and store it in ``v`` under ``name``.

        The initializer is called as ``initializer(shape, fan_in=, fan_out=, dtype=, device=,
        f=)``; fans default to :func:`default_fans` of ``shape``.

        Args:
            name: key of the variable in ``v``.
            initializer: e.g. ``ivy.stateful.initializers.glorot_uniform``.
            shape: shape of the variable.
            fan_in: number of inputs of a unit, to override the default.
            fan_out: number of outputs of a unit, to override the default.

        Returns:
            The new array.
        """
        if not isinstance(name, str) or "/" in name:
            raise ValueError(f"variable names must be strings without '/', got {name!r}")
        if name in self._children:
            raise ValueError(f"{type(self).__name__} already has a sub-module named {name!r}")
        shape = tuple(int(s) for s in shape)
        default_in, default_out = default_fans(shape)
        value = initializer(
            shape,
            fan_in=default_in if fan_in is None else fan_in,
            fan_out=default_out if fan_out is None else fan_out,
            dtype=self._dtype,
            device=self._device,
            f=self._f,
        )
        self._variables[name] = value
        return value

    def __setattr__(self, name: str, value: Any) -> None:
        children = self.__dict__.setdefault("_children", {})
        if isinstance(value, Module) or _is_child_list(value):
            if name in self.__dict__.get("_variables", ()):
                raise ValueError(f"{type(self).__name__} already has a variable named {name!r}")
            for child in value if isinstance(value, (list, tuple)) else (value,):
                if isinstance(child, Module) and child.f is not self.__dict__.get("_f", child.f):
                    raise MixedFrameworksError(
                        f"sub-module {name!r} was built for {child.f.backend} but "
                        f"{type(self).__name__} for {self._f.backend}; build them with the "
                        f"same f= (pass **self.build_args)."
                    )
            children[name] = value
        else:
            children.pop(name, None)
        object.__setattr__(self, name, value)

    def __delattr__(self, name: str) -> None:
        self.__dict__.get("_children", {}).pop(name, None)
        object.__delattr__(self, name)

    # ------------------------------------------------------------------------------------------
    # The variables
    # ------------------------------------------------------------------------------------------

    @property
    def v(self) -> dict[str, Any]:
        """The variables as a nest of dicts: own variables, then one entry per sub-module.

        A fresh dict is returned on each access (the arrays are shared); assign a whole nest of
        the same structure to replace the variables: ``module.v = new_v``.
        """
        out = dict(self._variables)
        for name, child in self._children.items():
            if isinstance(child, Module):
                out[name] = child.v
            else:
                out[name] = {str(i): c.v for i, c in enumerate(child) if isinstance(c, Module)}
        return out

    @v.setter
    def v(self, new_v: dict[str, Any]) -> None:
        self._assign(new_v, type(self).__name__)

    def _assign(self, new_v: dict[str, Any], where: str) -> None:
        if not isinstance(new_v, dict):
            raise TypeError(f"{where}: v must be a dict, got {type(new_v).__name__}")
        expected = set(self._variables) | set(self._children)
        if set(new_v) != expected:
            raise KeyError(
                f"{where}: v has keys {sorted(new_v)} but the module expects {sorted(expected)}"
            )
        for name in self._variables:
            self._variables[name] = new_v[name]
        for name, child in self._children.items():
            if isinstance(child, Module):
                child._assign(new_v[name], f"{where}.{name}")
                continue
            sub = new_v[name]
            keys = {str(i) for i, c in enumerate(child) if isinstance(c, Module)}
            if not isinstance(sub, dict) or set(sub) != keys:
                got = sorted(sub) if isinstance(sub, dict) else type(sub).__name__
                raise KeyError(f"{where}.{name}: v has keys {got} but expects {sorted(keys)}")
            for i, c in enumerate(child):
                if isinstance(c, Module):
                    c._assign(sub[str(i)], f"{where}.{name}[{i}]")

    @property
    def num_parameters(self) -> int:
        """Total number of scalar parameters in ``v``."""
        return sum(math.prod(tuple(x.shape)) for _, x in _leaves_with_paths(self.v))

    # ------------------------------------------------------------------------------------------
    # Calling
    # ------------------------------------------------------------------------------------------

    def __call__(self, *args: Any, v: dict[str, Any] | None = None, **kwargs: Any) -> Any:
        """Run the module on ``args`` with its own variables, or with the nest ``v`` given.

        With ``v`` the call is pure (it reads no state), so it can be differentiated with
        respect to ``v`` and compiled.
        """
        return self._forward(self.v if v is None else v, *args, **kwargs)

    def _forward(self, v: dict[str, Any], *args: Any, **kwargs: Any) -> Any:
        raise NotImplementedError(f"{type(self).__name__} must implement _forward(self, v, ...)")

    # ------------------------------------------------------------------------------------------
    # Saving and loading
    # ------------------------------------------------------------------------------------------

    def save(self, path: str | os.PathLike) -> None:
        """Write the variables to a portable ``.npz`` checkpoint that any backend can load.

        Example:
            >>> model = ivy.MLP(4, (8,), 1, f="torch")
            >>> model.save("mlp.npz")
        """
        from ivy.stateful.checkpoint import save_weights

        save_weights(path, self.v)

    def load(self, path: str | os.PathLike) -> Module:
        """Replace the variables by those of a checkpoint written on any backend.

        Keys and shapes must match; values are converted to this module's framework and to the
        dtype and device of the variables they replace.

        Returns:
            The module itself.

        Example:
            >>> ivy.MLP(4, (8,), 1, f="torch").save("mlp.npz")
            >>> model = ivy.MLP(4, (8,), 1, f="jax").load("mlp.npz")  # written with torch
        """
        from ivy.stateful.checkpoint import load_weights

        self.v = load_weights(path, like=self.v)
        return self

    def __repr__(self) -> str:
        return (
            f"{type(self).__name__}(f={self._f.backend}, dtype={self._dtype}, "
            f"parameters={self.num_parameters})"
        )


def _leaves_with_paths(nest: Any, prefix: tuple[str, ...] = ()):
    """Yield ``(path, leaf)`` for every array in a nest of dicts, lists and tuples."""
    if isinstance(nest, dict):
        for key in nest:
            yield from _leaves_with_paths(nest[key], prefix + (str(key),))
    elif isinstance(nest, (list, tuple)):
        for i, item in enumerate(nest):
            yield from _leaves_with_paths(item, prefix + (str(i),))
    elif nest is not None:
        yield prefix, nest
