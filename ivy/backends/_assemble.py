"""The one assembly of a backend namespace: after ``import ivy.backends.<name>`` it is complete.

What a namespace exports derives from the core (:data:`ivy.core._dispatch.REGISTRY`); a backend
repeats no list of the core's names. For each core group that has functions every backend must
implement, the namespace takes them from, in order of precedence:

1. the backend's own module of the group's name (``ivy/backends/torch/linalg.py``), which holds
   only what differs on that backend;
2. the shared layer (``ivy/backends/array_api/<group>.py``), functions written once against an
   Array API namespace ``xp`` and bound to the backend's (numpy, jax, any registered library);
3. the native namespace itself, for the functions that the shared layer declares native
   (``NATIVE`` in the shared module: ``add`` is ``xp.add``).

Then the rules declared on the core's stubs are applied (``@dispatch(reals=True)``: integer and
boolean inputs of functions of real numbers compute in float32, by the backend's ``reals``
wrappers), compositions are bound with ``f`` set to the namespace, aliases are the very same
objects as their targets, dtypes are the native dtype objects, the Array API extensions become
sub-namespaces (``ivy.torch.linalg``), and the namespace is registered with the framework
handler (``ivy.get_framework(f='torch')``).
"""

from __future__ import annotations

import functools
import importlib
import importlib.util
import inspect
import sys
import types
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from ivy import framework_handler as _fh
from ivy.backends._inspection import info_function
from ivy.backends._reals import scalar_operands
from ivy.core import GROUP_NAMES, GROUPS
from ivy.core._dispatch import REGISTRY
from ivy.core._extensions import ExtensionNamespace, extension_groups
from ivy.dtypes import DTYPE_NAMES
from ivy.errors import UnavailableDtypeError

ARRAY_API_VERSION = "2023.12"
ARRAY_API_CONSTANTS = {
    "e": 2.718281828459045,
    "pi": 3.141592653589793,
    "inf": float("inf"),
    "nan": float("nan"),
    "newaxis": None,
}
SHARED_PACKAGE = "ivy.backends.array_api"


def backend_names(group: str | None = None) -> list[str]:
    """The names every backend implements (of one core group, or all), from the core."""
    return sorted(
        n
        for n, info in REGISTRY.items()
        if info.implemented_by_backends and (group is None or info.group == group)
    )


def assemble(
    namespace: types.ModuleType | Mapping[str, Any],
    *,
    backend: str,
    native_dtypes: Mapping[str, Any],
    package: str | None = None,
    xp: Any = None,
    bind: Mapping[str, Any] | None = None,
    reals: Mapping[str, Callable] | None = None,
    capabilities: Any = None,
    fallback: Callable[[str], Callable] | None = None,
    dtypes_now: Mapping[str, Callable[[], bool]] | None = None,
    devices: Callable[[], list[str]] | None = None,
    array_api_capabilities: Mapping[str, Any] | None = None,
    scalars_need_shims: bool = False,
    natives_in_namespace: bool = False,
    array_types: Sequence[type] = (),
    precision: Callable[[str], Callable[[], None]] | None = None,
) -> types.ModuleType:
    """Fill ``namespace`` with the backend's public names and register it as backend ``backend``.

    Args:
        namespace: the backend package's module (or its ``globals()``).
        backend: the name it is known by (``'torch'``, ``'array_api_strict'``...).
        native_dtypes: dtype name -> the native dtype object, for every ivy dtype the backend
            has (a missing one is left out of the namespace: reading it raises AttributeError,
            so that ``hasattr(ns, 'float16')`` tells whether the backend has it).
        package: the package holding the backend's own group modules (None: none).
        xp: the Array API namespace that the shared layer is bound to (None: not used).
        bind: what the shared layer's functions find besides ``xp``: the backend's helpers
            (``native_dtype``, ``check_device``, ``as_inexact``...).
        reals: ``{'unary': w, 'binary': w, 'options': w}``, each ``w(native, name)`` wrapping a
            function of real numbers so that integer and boolean inputs compute in float32
            (see ``ivy/backends/_reals.py``); None: the backend's functions do it themselves.
        capabilities: the backend's :class:`ivy.framework_handler.Capabilities`.
        fallback: ``fallback(name)`` gives the function for a name that neither the backend nor
            the shared layer provides (a registered library's host bridge); None: none.
        dtypes_now: dtype name -> a callable telling whether the backend can hold that dtype
            at the time of the call (jax's 64-bit types, while ``jax_enable_x64`` is off: the
            namespace then has no such attribute); None: every native dtype, always.
        devices: a callable giving ivy's names of the devices the backend sees, for
            ``__array_namespace_info__().devices()``; None: the default device only.
        array_api_capabilities: the Array API capability flags, for
            ``__array_namespace_info__().capabilities()``; None: boolean indexing and
            data-dependent shapes.
        scalars_need_shims: the framework's natives promote Python scalars otherwise than ivy
            (numpy and jax: an int8 array plus 2.5 is float64 there, float32 in ivy), so
            dispatched calls with Python scalars go to the namespace's shims, not its fast view.
        natives_in_namespace: the namespace exports the framework's natives themselves where
            a shim only adds Python-scalar promotion (numpy: ``ivy.numpy.add is numpy.add``, so
            ``ivy.numpy`` and ``set_framework('numpy')`` cost nothing); the shims stay in a view
            that ivy's dispatchers use for calls with Python scalars.
        array_types: the framework's array types, registered for inference at once (see
            ``framework_handler.register_loaded``); others (subclasses) as they are met.
        precision: ``precision(name) -> restore``: sets the framework's switches for the
            precision of float32 matrix products and convolutions to ivy's ``'highest'`` or
            ``'high'`` and returns what restores them (see ``ivy.set_matmul_precision``);
            None: nothing to switch.

    Returns:
        The namespace module, complete.
    """
    module = (
        namespace if isinstance(namespace, types.ModuleType) else sys.modules[namespace["__name__"]]
    )
    ns = module.__dict__
    ns["backend"] = backend
    bind = {"backend_name": backend, "backend_ns": module, **(bind or {})}
    shared_bound: dict[str, dict[str, Any]] = {}
    exported: set[str] = set()
    missing: list[str] = []
    for group_name in GROUP_NAMES:
        names = backend_names(group_name)
        if not names:
            continue
        own = _own_module(package, group_name)
        shared = (
            shared_bound.setdefault(group_name, _shared(group_name, xp, bind))
            if xp is not None
            else {}
        )
        for name in names:
            fn = getattr(own, name, None) if own is not None else None
            if fn is None:
                fn = shared.get(name)
            if fn is None and fallback is not None:
                fn = fallback(name)
            if fn is None:
                missing.append(name)
                continue
            info = REGISTRY[name]
            if info.reals and reals is not None and not getattr(fn, "__ivy_reals__", False):
                fn = reals[info.reals](fn, name)
            ns[name] = fn
            exported.add(name)
    if missing:
        raise ImportError(f"ivy backend {backend!r} does not implement {sorted(missing)}")
    known = {n: t for n, t in native_dtypes.items() if t is not None}
    sometimes = dict(dtypes_now or {})
    ns.update({n: t for n, t in known.items() if n not in sometimes})
    exported.update(DTYPE_NAMES)  # a dtype the backend lacks (now) is no attribute: see below
    ns["__getattr__"] = _dtype_getattr(module, backend, known, sometimes)
    ns["__array_namespace_info__"] = info_function(
        module,
        devices,
        dict(array_api_capabilities or _ARRAY_API_CAPABILITIES),
    )
    ns.update(ARRAY_API_CONSTANTS)
    exported.update(ARRAY_API_CONSTANTS)
    ns["__array_api_version__"] = ARRAY_API_VERSION
    for name, info in REGISTRY.items():
        if info.kind == "composition":
            ns[name] = _bound(_core_function(name), module)
            exported.add(name)
    for name, info in REGISTRY.items():
        if info.kind == "alias":
            ns[name] = ns[info.target]
            exported.add(name)
    for ext, group in extension_groups(GROUPS):
        call = ns[ext] if ext in group.__all__ else None  # fft: a callable namespace
        ns[ext] = ExtensionNamespace(f"ivy.{backend}.{ext}", group.__all__, ns.__getitem__, call)
        exported.add(ext)
    ns["__all__"] = sorted(exported)
    _drop_unexported(module, exported)
    scalars = module
    if natives_in_namespace:
        scalars = _view(module, {}, "<scalars>")
        for name in exported:
            if getattr(ns.get(name), "__ivy_scalar_shim__", False):
                ns[name] = ns[name].__ivy_native__
    fast = _fast_view(module, exported)
    module.__ivy_precision__ = precision
    module.__ivy_fast__ = fast
    module.__ivy_scalars__ = scalars
    if fast is not module:
        fast.__ivy_scalars__ = scalars if scalars_need_shims else fast
    if scalars is not module:
        scalars.__ivy_scalars__ = scalars
        scalars.__ivy_fast__ = fast
    _fh.register_loaded(backend, module, capabilities, array_types)
    return module


# Public attributes of every namespace besides ``__all__`` (set by the framework handler): the
# backend's name, its :class:`Capabilities` and ``with ivy.<name>.use:``.
NAMESPACE_ATTRIBUTES = ("backend", "capabilities", "use")


def _drop_unexported(module: types.ModuleType, exported: set[str]) -> None:
    """Remove what the package's imports left in its namespace (its group modules, which the
    import system sets as attributes): every namespace has exactly the same public names."""
    ns = module.__dict__
    for name in [n for n in ns if not n.startswith("_")]:
        if name not in exported and name not in NAMESPACE_ATTRIBUTES:
            del ns[name]


def _fast_view(module: types.ModuleType, exported: set[str]) -> Any:
    """What the framework-agnostic dispatchers call: ``module`` itself, or, where some of its
    functions are shims that only add what the framework's native refuses (they carry the
    native as ``__ivy_native__``), a view of it with those natives in their place. The
    dispatchers hand what a native refuses to the shim (``framework_handler._recover``)."""
    natives = {
        name: native
        for name in exported
        if (native := getattr(module.__dict__.get(name), "__ivy_native__", None)) is not None
    }
    if not natives:
        return module
    return _view(module, natives, "<fast>")


def _view(module: types.ModuleType, replaced: dict[str, Any], tag: str) -> types.ModuleType:
    """A copy of ``module``'s public names with ``replaced`` in their place."""
    view = types.ModuleType(f"{module.__name__}.{tag}")
    view.__dict__.update({k: v for k, v in module.__dict__.items() if not k.startswith("__")})
    view.__dict__.update(replaced)
    view.__ivy_full__ = module
    return view


_ARRAY_API_CAPABILITIES = {
    "boolean indexing": True,
    "data-dependent shapes": True,
    "max dimensions": None,
}


def _dtype_getattr(
    module: types.ModuleType,
    backend: str,
    known: Mapping[str, Any],
    sometimes: Mapping[str, Callable[[], bool]],
) -> Callable[[str], Any]:
    """The namespace's module ``__getattr__`` (PEP 562), called only for names its dict lacks:
    the dtypes that come and go (``sometimes``), and a clear error for those it never has."""

    def __getattr__(name: str) -> Any:
        available = sometimes.get(name)
        if available is not None:
            if available():
                return known[name]
            raise UnavailableDtypeError(
                f"ivy.{backend}.{name}: {backend} cannot hold {name} arrays now. For jax, enable "
                f"64-bit types first: jax.config.update('jax_enable_x64', True)."
            )
        if name in DTYPE_NAMES:
            raise UnavailableDtypeError(f"ivy.{backend} has no dtype {name}: {backend} lacks it.")
        raise AttributeError(f"module {module.__name__!r} has no attribute {name!r}")

    return __getattr__


def _own_module(package: str | None, group: str) -> types.ModuleType | None:
    if package is None or importlib.util.find_spec(f"{package}.{group}") is None:
        return None
    return importlib.import_module(f"{package}.{group}")


def _shared(group: str, xp: Any, bind: Mapping[str, Any] | None) -> dict[str, Any]:
    """The shared layer's functions of ``group``, bound to ``xp`` and the backend's helpers."""
    if importlib.util.find_spec(f"{SHARED_PACKAGE}.{group}") is None:
        return {}
    module = importlib.import_module(f"{SHARED_PACKAGE}.{group}")
    return bind_shared(module, xp, bind or {})


def bind_shared(module: types.ModuleType, xp: Any, bind: Mapping[str, Any]) -> dict[str, Any]:
    """The public functions of the shared module ``module``, bound to ``xp``.

    Each function is the same code with new globals: the module's own, with ``xp`` and the names
    in ``bind`` replaced. Calls between the module's functions stay within the bound copies, so
    a backend pays nothing for the sharing; ``inspect.getsource`` and tracebacks show the shared
    file. The names in the module's ``NATIVE`` are taken from ``xp`` as they are; a function
    that needs more of ``xp`` than the standard (the module's ``NEEDS``) is left out where ``xp``
    lacks it.
    """
    scope = dict(module.__dict__)
    scope["xp"] = xp
    scope.update(bind)
    out: dict[str, Any] = {}
    needs = getattr(module, "NEEDS", {})
    for name, value in module.__dict__.items():
        if isinstance(value, types.FunctionType) and value.__module__ == module.__name__:
            if all(hasattr(xp, attr) for attr in needs.get(name, ())):
                scope[name] = out[name] = _rebind(value, scope)
    for table, wrap in (
        (getattr(module, "NATIVE", {}), None),
        (getattr(module, "SCALAR_OPERANDS", {}), scalar_operands),
    ):
        for name, path in table.items():
            native = xp
            for part in path.split("."):
                native = getattr(native, part, None)
            if native is not None and name not in out:
                out[name] = native if wrap is None else wrap(native, name)
    return {n: f for n, f in out.items() if not n.startswith("_")}


def _rebind(fn: types.FunctionType, scope: dict[str, Any]) -> types.FunctionType:
    new = types.FunctionType(fn.__code__, scope, fn.__name__, fn.__defaults__, fn.__closure__)
    new.__kwdefaults__ = fn.__kwdefaults__
    new.__doc__ = fn.__doc__
    new.__qualname__ = fn.__qualname__
    new.__module__ = fn.__module__
    new.__dict__.update(fn.__dict__)
    return new


def _core_function(name: str) -> Callable:
    """The composition ``name`` as written (without the agnostic function's conversions)."""
    fn = getattr(GROUPS[GROUP_NAMES.index(REGISTRY[name].group)], name)
    return getattr(fn, "__ivy_body__", fn)


def _bound(comp: Callable, ns: types.ModuleType) -> Callable:
    """The composition ``comp`` with ``f`` bound to the namespace ``ns``.

    An explicit ``f`` is accepted, so that code written with ``ivy.compile_fn(fn, f=xp)`` also
    runs while a framework is set globally (when ``ivy.compile_fn`` is this backend's): ``f``
    naming this backend costs one comparison, and ``f`` naming another one runs that backend's
    composition, as ``f`` chooses the framework everywhere else.
    """

    name = comp.__name__

    def elsewhere(f: Any) -> Any:
        other = _fh.get_framework(f=f)
        return None if other is ns else getattr(other, name)

    def bound(*args: Any, f: Any = None, **kwargs: Any) -> Any:
        if f is not None and f is not ns:
            other = elsewhere(f)
            if other is not None:
                return other(*args, **kwargs)
        return comp(*args, f=ns, **kwargs)

    # The same code with the composition's globals, where typing.get_type_hints finds the names
    # its annotations use.
    bound = types.FunctionType(bound.__code__, comp.__globals__, None, (), bound.__closure__)
    bound.__kwdefaults__ = {"f": None}
    functools.update_wrapper(bound, comp)
    bound.__signature__ = inspect.signature(comp)  # f included: it is accepted
    del bound.__wrapped__
    return _fh.run_as_is_in_autograph(bound)
