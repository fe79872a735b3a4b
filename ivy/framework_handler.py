"""Framework selection: the backend registry, type inference, and the global framework stack.

How a framework-agnostic call such as ``ivy.sin(x, f=None)`` picks its backend:

1. an explicit ``f`` (a name such as ``'torch'`` or a namespace such as ``ivy.torch``), else
2. the framework set globally with :func:`set_framework` (or a ``with`` block), else
3. the type of the array inputs, looked up in a dict keyed by ``type(x)``.

A type seen for the first time is resolved by the module its class (or a base class) was defined
in, so ``import ivy`` imports no framework and a framework that is not installed is never needed:
an object of a framework can only exist if that framework was already imported by the user.

While a framework is set globally, the backend's functions are bound into the ``ivy`` namespace
itself (``ivy.sin is ivy.torch.sin``), so calls through ``ivy`` cost nothing extra.
"""

from __future__ import annotations

import importlib
import importlib.util
import sys
import types
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from ivy.errors import (
    FrameworkNotInstalledError,
    MixedFrameworksError,
    NoFrameworkError,
    UnknownFrameworkError,
)
from ivy.typing import Framework

__all__ = [
    "Capabilities",
    "register_framework",
    "get_framework",
    "set_framework",
    "unset_framework",
    "current_framework",
    "available_frameworks",
    "installed_frameworks",
    "framework_of_type",
    "set_matmul_precision",
    "matmul_precision",
]


@dataclass(frozen=True)
class Capabilities:
    """What a backend can do beyond the Array API; what it cannot raises
    :class:`ivy.errors.UnsupportedError` (or, for ``compilation``, runs eagerly with a warning).

    Attributes:
        autodiff: automatic differentiation (``ivy.execute_with_gradients``, ``ivy.grad``...).
        compilation: a compiler behind ``ivy.compile_fn``.
        mutable_arrays: arrays written in place are seen by every view of their memory.
        devices: the kinds of device it places arrays on (``'cpu'``, ``'gpu'``).
        float64: 64-bit floats (and int64) work.
        compiled_loops: ``ivy.compile_fn`` keeps ``ivy.scan``, ``fori_loop`` and ``while_loop``
            loops: their body is traced once and the compiled program loops (jax's ``lax``
            loops, tensorflow's while loops), so compiling a long loop costs what a short one
            does. False where the compiler unrolls them, tracing the body once per step
            (``torch.compile``: compile time grows with the number of steps; a loop whose length
            depends on values cannot compile), or where there is no compiler. Code that compiles
            whole loops (a rollout, the epochs of an update) can choose from it where to put the
            compiled boundary.
        vectorised_jacobian: the native Jacobian (``ivy.execute_with_jacobian``'s
            ``method="native"``) vectorises over the output components as fast as one backward
            pass of a batch as many times bigger (jax's ``vmap``). False where it does not:
            tensorflow's pfor through a ``tf.while_loop`` (gigabytes), torch's batched backward
            pass (1.7x slower than replicated, on the double pendulum's swing-up); code that takes
            Jacobians of batched functions then uses ``method="replicate"``.
        eager_compiles_ops: the eager mode compiles every operation for each new combination of
            shapes and dtypes before running it (jax: tens of milliseconds each, so a first eager
            call of a program of a thousand operations takes a minute, and an eager loop of
            ``while_loop`` compiles its body at every call). Libraries whose kernels are large
            run them through a cached ``ivy.compile_fn`` there, also when the user calls them
            eagerly.

    Example:
        >>> ivy.framework_handler.capabilities("jax").compiled_loops
        True
    """

    autodiff: bool = False
    compilation: bool = False
    mutable_arrays: bool = False
    devices: tuple[str, ...] = ("cpu",)
    float64: bool = True
    compiled_loops: bool = False
    vectorised_jacobian: bool = False
    eager_compiles_ops: bool = False


@dataclass(frozen=True)
class _BackendSpec:
    module: str  # the ivy backend package
    package: str  # the framework's own import name
    extra: str | None  # the pyproject extra that installs it (None: a registered library)
    capabilities: Capabilities = Capabilities()
    namespace: Any = None  # a registered library's Array API namespace (or its import name)


# The module that assembles a registered library's namespace (its ``assemble_registered(name,
# spec)``), imported by name when the library is first used, as the built-in backends' packages
# are: framework selection sits below the backends and imports none of them itself.
_REGISTERED_ASSEMBLY = "ivy.backends.array_api._register"


_BACKENDS: dict[str, _BackendSpec] = {
    "numpy": _BackendSpec(
        "ivy.backends.numpy", "numpy", "numpy", Capabilities(mutable_arrays=True)
    ),
    "torch": _BackendSpec(
        "ivy.backends.torch",
        "torch",
        "torch",
        Capabilities(autodiff=True, compilation=True, mutable_arrays=True, devices=("cpu", "gpu")),
    ),
    "jax": _BackendSpec(
        "ivy.backends.jax",
        "jax",
        "jax",
        Capabilities(
            autodiff=True,
            compilation=True,
            devices=("cpu", "gpu", "tpu"),
            compiled_loops=True,
            vectorised_jacobian=True,
            eager_compiles_ops=True,
        ),
    ),
    "tensorflow": _BackendSpec(
        "ivy.backends.tensorflow",
        "tensorflow",
        "tensorflow",
        Capabilities(autodiff=True, compilation=True, devices=("cpu", "gpu"), compiled_loops=True),
    ),
}
_ALIASES = {"np": "numpy", "pytorch": "torch", "tf": "tensorflow"}

# Root module of a class -> backend name. Framework objects are recognised by where their class
# (or one of its bases) was defined, which never requires importing anything.
_MODULE_ROOTS = {
    "numpy": "numpy",
    "torch": "torch",
    "jax": "jax",
    "jaxlib": "jax",
    "tensorflow": "tensorflow",
}

# Types that never decide a framework on their own: Python scalars, None, strings, slices...
_PASSIVE: frozenset[type] = frozenset(
    {int, float, bool, complex, str, bytes, type(None), slice, type(Ellipsis)}
)
# Containers that are searched for arrays.
_CONTAINERS = (list, tuple, dict)

# The state that generated dispatch functions read. They are compiled with this dict as their
# globals, so updating an entry here updates every one of them at once.
#   _current  : the namespace set globally, or None
#   _by_type  : type(x) -> namespace, for array types only
#   _by_f     : value of ``f`` (name or namespace) -> namespace
#
# Inference (``get_framework``, ``_infer``) looks types up by ``id(type)``, an int, in
# ``_by_type_id`` and the tables of neutral and weak types: a compiler that traces Python and
# guards on what it read (torch.compile's dynamo) then guards on that one key being present,
# where a dict keyed by types is guarded on its length and key order, so that every type met
# later anywhere (a Parameter, a class of the user's) would recompile every compiled function
# that inferred its framework. A type's id is never reused: the tables keep each type alive.
# The generated dispatchers keep ``_by_type[type(x)]``: ``id()`` would add about 25 ns to every
# inferred call (numpy's 10-element add: 1.6x -> 1.8x native); under torch.compile they
# recompile when a new array type is registered, which happens once per type.
# The namespaces there are the backends' fast views (``ns.__ivy_fast__``): the backend namespace
# with the framework's own function in place of each shim that only adds what the framework
# refuses (torch's unsigned types...). What the native refuses, the dispatcher's ``_recover``
# hands to the full namespace's shim; so a dispatched call costs what the native call costs.
dispatch_globals: dict[str, Any] = {
    "_current": None,
    "_by_type": {},
    "_by_f": {},
    "_passive": _PASSIVE,
}
_fast_by_type: dict[type, Any] = dispatch_globals["_by_type"]
_fast_by_f: dict[Any, Any] = dispatch_globals["_by_f"]
# The same maps to the backend namespaces themselves (get_framework, inference).
_by_type: dict[type, types.ModuleType] = {}
_by_type_id: dict[int, types.ModuleType] = {}  # id(type) -> namespace, as _by_type
_by_f: dict[Any, types.ModuleType] = {}


def _fast(ns: types.ModuleType) -> Any:
    return getattr(ns, "__ivy_fast__", ns)


# id(type) -> type; numpy scalars: numpy only if no other framework is present
_weak_types: dict[int, type] = {}
_neutral_types: dict[int, type] = {id(t): t for t in _PASSIVE}  # id(type) -> type

_loaded: dict[str, types.ModuleType] = {}
_stack: list[types.ModuleType] = []
_on_load: list[Callable[[types.ModuleType], None]] = []


def run_as_is_in_autograph(fn: Callable) -> Callable:
    """Mark ``fn`` so that tensorflow's AutoGraph calls it as it is inside a ``tf.function``.

    ivy's functions hold no Python control flow on tensor values (they also run under
    ``jax.jit``), so there is nothing for AutoGraph to convert, as in tensorflow's own library,
    which AutoGraph never converts. Left to itself, AutoGraph would convert them and everything
    they call, ivy's framework selection and ``importlib`` included, which costs trace time and
    is fragile. The mark is the attribute that ``tf.autograph.experimental.do_not_convert`` sets
    on its wrappers; nothing is imported for it (``tests/ivy/test_dispatch.py`` checks that a
    ``tf.function`` of ivy functions prints nothing).
    """
    fn.autograph_info__ = {}
    return fn


# ----------------------------------------------------------------------------------------------
# The registry
# ----------------------------------------------------------------------------------------------


def register_framework(
    name: str,
    namespace: types.ModuleType | str,
    *,
    autodiff: bool = False,
    compilation: bool = False,
    mutable_arrays: bool = False,
    devices: tuple[str, ...] = ("cpu",),
    float64: bool = True,
    compiled_loops: bool = False,
) -> None:
    """Make an Array API namespace (2023.12) a backend of ivy, under ``name``.

    Its functions come from ivy's shared layer bound to ``namespace`` (``ivy/backends/array_api/``):
    the standard's functions as the library has them, ivy's rules on top (float32 defaults,
    integer inputs of functions of real numbers in float32), and the functions the standard lacks
    (``gather_nd``, convolutions, random numbers, ``einsum``...) through numpy on the host (DLPack).
    What the flags deny raises :class:`ivy.errors.UnsupportedError` naming the backend. Nothing is
    imported until the backend is first used; arrays of the library are then recognised by the
    module their class comes from.

    Args:
        name: the backend's name (``f=name``, ``ivy.<name>``).
        namespace: the namespace (``array_api_strict``) or its import name.
        autodiff: the library differentiates (it would need its own gradients module to use it).
        compilation: the library compiles (likewise).
        mutable_arrays: in-place writes are seen through every view.
        devices: the kinds of device its arrays may live on.
        float64: 64-bit floats work.
        compiled_loops: its compiler keeps loops (see :class:`Capabilities`).

    Example:
        >>> ivy.register_framework("array_api_strict", "array_api_strict")
        >>> import array_api_strict as xp
        >>> ivy.sin(xp.asarray([0.0]))               # inferred from the array's type
        Array([0.], dtype=array_api_strict.float64)
    """
    if name in _BACKENDS and _BACKENDS[name].namespace is None:
        raise ValueError(f"{name!r} is one of ivy's own backends; choose another name")
    package = namespace if isinstance(namespace, str) else namespace.__name__
    if name in _loaded:
        raise ValueError(f"the backend {name!r} is already loaded; register it before first use")
    _BACKENDS[name] = _BackendSpec(
        f"ivy.backends.{name}",
        package,
        None,
        Capabilities(
            autodiff, compilation, mutable_arrays, tuple(devices), float64, compiled_loops
        ),
        namespace,
    )
    _MODULE_ROOTS[package.partition(".")[0]] = name


def capabilities(name: str) -> Capabilities:
    """The :class:`Capabilities` of backend ``name`` (installed or not; none is imported)."""
    return _BACKENDS[_canonical_name(name)].capabilities


def native_package(name: str) -> str:
    """The import name of backend ``name``'s own framework (``'tensorflow'`` for ``'tf'``).

    Nothing is imported; an unknown name raises :class:`UnknownFrameworkError`.

    Example:
        >>> native_package("tf")
        'tensorflow'
    """
    return _BACKENDS[_canonical_name(name)].package


def available_frameworks() -> tuple[str, ...]:
    """Names of every framework ivy supports, installed or not."""
    return tuple(_BACKENDS)


def installed_frameworks() -> tuple[str, ...]:
    """Names of the supported frameworks that are installed here (none is imported)."""
    return tuple(n for n, s in _BACKENDS.items() if importlib.util.find_spec(s.package) is not None)


def _canonical_name(name: str) -> str:
    key = name.lower()
    key = _ALIASES.get(key, key)
    if key not in _BACKENDS:
        raise UnknownFrameworkError(
            f"Unknown framework {name!r}. Choose one of {', '.join(_BACKENDS)} "
            f"(as f='torch', f=ivy.torch, or ivy.set_framework('torch'))."
        )
    return key


def load_backend(name: str) -> types.ModuleType:
    """Import (once) and return the ivy namespace of backend ``name``."""
    name = _canonical_name(name)
    ns = _loaded.get(name)
    if ns is not None:
        return ns
    spec = _BACKENDS[name]
    # (A framework whose arrays exist is imported: no look-up. This code may run inside a user's
    # tf.function, where AutoGraph would try, and fail, to convert importlib's functions.)
    if spec.package not in sys.modules and importlib.util.find_spec(spec.package) is None:
        if spec.extra is None:
            how = f"Install it with pip install {spec.package}"
        else:
            hint = "" if name == "numpy" else f" or pip install 'ivy[{spec.extra}]'"
            how = f"Install it with pip install '.[{spec.extra}]' from the ivy repository{hint}"
        raise FrameworkNotInstalledError(
            f"ivy's {name} backend needs the package '{spec.package}', which is not installed. "
            f"{how}, or choose another of the installed frameworks: "
            f"{', '.join(installed_frameworks())}."
        )
    if spec.namespace is not None:  # a registered library: assembled from the shared layer
        importlib.import_module(_REGISTERED_ASSEMBLY).assemble_registered(name, spec)
        return _loaded[name]
    __import__(spec.module)  # its package assembles and registers it (a builtin: see above)
    return _loaded[name]


def register_loaded(
    name: str, ns: types.ModuleType, capabilities: Any = None, array_types: Any = ()
) -> None:
    """Record ``ns``, an assembled backend namespace, as backend ``name`` (called once, by
    ``ivy.backends._assemble.assemble``), and run the load hooks on it.

    The framework's ``array_types`` enter the dispatchers' table now, and with them numpy's
    (ivy imports numpy anyway): the table then grows only when another framework loads or a
    subclass is met, and a user's torch.compile of ivy code, which guards on the table's size,
    does not recompile the first time a numpy array or a Parameter passes through ivy."""
    ns.backend = name
    ns.use = _Use(ns)
    ns.capabilities = capabilities if capabilities is not None else _BACKENDS[name].capabilities
    for hook in _on_load:
        hook(ns)
    _loaded[name] = ns
    keys = [name, ns] + [alias for alias, target in _ALIASES.items() if target == name]
    for key in keys:
        _by_f[key] = ns
        _fast_by_f[key] = _fast(ns)
    for t in array_types:
        _register_type(t, ns)
    _switch_precision(ns)  # ivy's precision from the start (see set_matmul_precision)
    if "numpy" not in _loaded and "numpy" in _BACKENDS:
        load_backend("numpy")


def on_backend_load(hook: Callable[[types.ModuleType], None]) -> None:
    """Run ``hook(namespace)`` for every backend, now for the loaded ones and later for the rest."""
    _on_load.append(hook)
    for ns in list(_loaded.values()):
        hook(ns)


def _resolve_f(f: Any) -> types.ModuleType:
    """Namespace for an explicit ``f`` argument: a name or a backend namespace."""
    if isinstance(f, str):
        return load_backend(f)
    if isinstance(f, types.ModuleType) and getattr(f, "backend", None) in _loaded:
        return f
    raise UnknownFrameworkError(
        f"f={f!r} is not a framework. Pass a name ({', '.join(_BACKENDS)}) "
        f"or a namespace such as ivy.torch."
    )


dispatch_globals["_resolve_f"] = _resolve_f


# ----------------------------------------------------------------------------------------------
# Type inference
# ----------------------------------------------------------------------------------------------


def framework_of_type(t: type) -> str | None:
    """Backend name that owns objects of type ``t``, or None for a type of no framework."""
    for klass in t.__mro__:
        root = klass.__module__.partition(".")[0]
        name = _MODULE_ROOTS.get(root)
        if name is not None:
            return name
    return None


def _classify(t: type) -> types.ModuleType | None:
    """Resolve and cache a type never seen before."""
    name = framework_of_type(t)
    if name is None:
        _neutral_types[id(t)] = t
        return None
    ns = load_backend(name)
    if name == "numpy" and issubclass(t, _numpy_generic()):
        _weak_types[id(t)] = t
    else:
        _register_type(t, ns)
    return ns


def _register_type(t: type, ns: types.ModuleType) -> None:
    _by_type[t] = ns
    _by_type_id[id(t)] = ns
    _fast_by_type[t] = _fast(ns)


def _numpy_generic() -> type:
    return sys.modules["numpy"].generic


def _infer(*objs: Any, name: str = "this function") -> types.ModuleType:
    """Infer the namespace from the arrays found in ``objs`` (searching lists, tuples, dicts).

    Raises MixedFrameworksError when arrays of two frameworks are found and NoFrameworkError when
    none is found.
    """
    found: types.ModuleType | None = None
    weak: types.ModuleType | None = None
    pending = list(objs)
    while pending:
        obj = pending.pop()
        t = type(obj)
        key = id(t)  # (see dispatch_globals)
        ns = _by_type_id.get(key)
        if ns is None:
            if key in _neutral_types:
                if isinstance(obj, _CONTAINERS):
                    pending.extend(obj.values() if isinstance(obj, dict) else obj)
                continue
            if key in _weak_types:
                weak = _loaded["numpy"]
                continue
            if isinstance(obj, _CONTAINERS):
                pending.extend(obj.values() if isinstance(obj, dict) else obj)
                continue
            ns = _classify(t)
            if ns is None:
                continue
            if key in _weak_types:
                weak = ns
                continue
        if found is None:
            found = ns
        elif ns is not found:
            raise MixedFrameworksError(
                f"{name} got arrays of two frameworks, {found.backend} and {ns.backend}. "
                f"Convert them to one framework first (e.g. with ivy.to_numpy or the framework's "
                f"own conversion), or pass f= to choose the framework explicitly."
            )
    if found is not None:
        return found
    if weak is not None:
        return weak
    what = "has no array input" if not objs else "got no array among its inputs"
    raise NoFrameworkError(
        f"{name} {what} to infer a framework from ({', '.join(_BACKENDS)}). "
        f"Choose one with f='torch' (or f=ivy.torch), "
        f"globally with ivy.set_framework('torch'), or in a block with "
        f"`with ivy.set_framework('torch'):`."
    )


dispatch_globals["_infer"] = _infer


def _mixed(ns: Any, objs: tuple, name: str) -> Any:
    """The namespace for a call whose array arguments are not all of one type: that of the
    first when the others are Python scalars, else inferred from all of them; its
    ``__ivy_scalars__`` (the backend's functions that promote Python scalars by ivy's rules)
    where a Python scalar is among them, on either side."""
    first = type(objs[0])
    for obj in objs[1:]:
        t = type(obj)
        if t is not first and t not in _PASSIVE:
            ns = _infer(*objs, name=name)
            break
    else:
        return ns.__ivy_scalars__
    return ns.__ivy_scalars__ if any(type(obj) in _PASSIVE for obj in objs) else ns


dispatch_globals["_mixed"] = _mixed


def to_namespace(ns: types.ModuleType, value: Any) -> Any:
    """``value`` with the arrays of other frameworks in it (also inside lists and tuples)
    converted to arrays of the backend ``ns``; Python scalars, ``ns``'s own arrays and other
    objects as they are. What every function does with its array arguments when ``f`` is given
    (``ivy.sin(np_array, f='torch')`` computes on torch)."""
    ns = getattr(ns, "__ivy_full__", ns)
    t = type(value)
    if t in _PASSIVE:
        return value
    owner = _by_type.get(t)
    if owner is ns:
        return value
    if owner is None:
        if t is list or t is tuple:
            items = [to_namespace(ns, v) for v in value]
            if all(a is b for a, b in zip(items, value)):
                return value
            return items if t is list else tuple(items)
        if id(t) in _neutral_types:
            return value
        name = framework_of_type(t)
        if name is None:
            _neutral_types[id(t)] = t
            return value
        if name == ns.backend:  # a type of the framework not seen yet (a tracer, a variable)
            return value
    return ns.asarray(value)


dispatch_globals["_to_namespace"] = to_namespace


def _recover(ns: Any, name: str, err: Exception, args: tuple, kwargs: dict) -> Any:
    """What a dispatcher does when the backend function raised ``err``: the backend's own
    function handles what the framework's native refused (when the fast view called the
    native), and an error still left is raised as the typed ivy error that names the function,
    the argument and the backend (``ivy/core/_diagnose.py``)."""
    full = getattr(ns, "__ivy_full__", ns)
    fn = getattr(full, name)
    if fn is not getattr(ns, name):
        try:
            return fn(*args, **kwargs)
        except Exception as again:  # noqa: BLE001 - explained below
            err = again
    better = _explain[0](full, name, err, args, kwargs)
    if better is err:
        raise err
    raise better from err


dispatch_globals["_recover"] = _recover

# What turns a backend's error into ivy's typed error (``ivy/core/_diagnose.py``, installed by the
# core with :func:`explain_errors_with`); until then errors pass as they are.
_explain: list[Callable[..., Exception]] = [lambda ns, name, err, args, kwargs: err]


def explain_errors_with(explain: Callable[..., Exception]) -> None:
    """Install ``explain(ns, name, err, args, kwargs) -> Exception``, which the dispatchers call
    when a backend function raised ``err``: the core's diagnosis (this module sits below the
    core and imports nothing of it)."""
    _explain[0] = explain


# ----------------------------------------------------------------------------------------------
# Public selection API
# ----------------------------------------------------------------------------------------------


@run_as_is_in_autograph
def get_framework(*args: Any, f: Framework = None) -> types.ModuleType:
    """Return the backend namespace to use for ``args``.

    Priority: explicit ``f`` > the globally set framework > inference from the inputs (which
    searches lists, tuples and dicts).

    Args:
        *args: values whose arrays decide the framework.
        f: a framework name (``'torch'``) or namespace (``ivy.torch``), or None.

    Returns:
        The backend namespace, e.g. ``ivy.torch``.

    Example:
        >>> xp = ivy.get_framework(np.ones(3))
        >>> xp.backend
        'numpy'
    """
    if f is not None:
        try:
            return _by_f[f]
        except (KeyError, TypeError):
            return _resolve_f(f)
    if _stack:
        return _stack[-1]
    return _infer(*args, name="get_framework")


def current_framework() -> types.ModuleType | None:
    """The globally set backend namespace, or None when no framework is set."""
    return _stack[-1] if _stack else None


class _Scope:
    """Returned by set_framework; as a context manager it restores the state it replaced."""

    __slots__ = ("_depth", "_ns")

    def __init__(self, depth: int, ns: types.ModuleType):
        self._depth = depth
        self._ns = ns

    def __enter__(self) -> types.ModuleType:
        return self._ns

    def __exit__(self, *exc_info: object) -> None:
        _restore_depth(self._depth)

    def __repr__(self) -> str:
        return f"<ivy framework scope {self._ns.backend}>"


class _Use:
    """``with ivy.torch.use:`` sets the framework for a block; reusable and nestable."""

    __slots__ = ("_ns", "_depths")

    def __init__(self, ns: types.ModuleType):
        self._ns = ns
        self._depths: list[int] = []

    def __enter__(self) -> types.ModuleType:
        self._depths.append(len(_stack))
        _push(self._ns)
        return self._ns

    def __exit__(self, *exc_info: object) -> None:
        _restore_depth(self._depths.pop())

    def __repr__(self) -> str:
        return f"<ivy.{self._ns.backend}.use>"


def set_framework(framework: str | types.ModuleType) -> _Scope:
    """Set the framework globally: ``ivy.<fn>`` becomes the backend function itself.

    Usable as a statement (undo with :func:`unset_framework`) or as a context manager, which
    restores the previous state on exit, also when the block raises. Settings nest as a stack.

    Args:
        framework: a name (``'torch'``) or a namespace (``ivy.torch``).

    Example:
        >>> with ivy.set_framework('numpy'):
        ...     ivy.sin is ivy.numpy.sin
        True
    """
    ns = _resolve_f(framework)
    depth = len(_stack)
    _push(ns)
    return _Scope(depth, ns)


def unset_framework() -> None:
    """Undo the most recent :func:`set_framework`; a no-op when no framework is set."""
    if _stack:
        _restore_depth(len(_stack) - 1)


# ----------------------------------------------------------------------------------------------
# Precision of float32 matrix products and convolutions
# ----------------------------------------------------------------------------------------------

MATMUL_PRECISIONS = ("highest", "high")
_matmul_precision = ["highest"]
_restorers: list[Callable[[], None] | None] = []  # one per entry of _stack


def set_matmul_precision(precision: str) -> None:
    """Choose the precision of ivy's float32 matrix products and convolutions, on every backend.

    ``'highest'`` (the default): full float32, so that every backend gives the same answer, on
    GPUs too. ``'high'``: the framework may use TF32 tensor cores (torch, tensorflow) or bf16
    passes (jax), faster on recent GPUs and about 3 significant digits less exact.

    ivy sets the frameworks' own switches (jax's ``jax_default_matmul_precision``; torch's
    ``fp32_precision`` of ``torch.backends.cuda.matmul`` and cuDNN; tensorflow's TF32
    execution) when it loads a backend and when ``set_framework`` (or a ``with`` block) binds
    one; unsetting it restores the values found before. Changing the precision applies it to
    every loaded backend at once.

    Args:
        precision: ``'highest'`` or ``'high'``.

    Example:
        >>> ivy.set_matmul_precision("high")     # opt into TF32 / bf16 passes
        >>> ivy.set_matmul_precision("highest")  # back to full float32
    """
    if precision not in MATMUL_PRECISIONS:
        raise ValueError(
            f"set_matmul_precision: precision must be one of {MATMUL_PRECISIONS}, got "
            f"{precision!r} ('highest': full float32; 'high': TF32 or bf16 passes)."
        )
    _matmul_precision[0] = precision
    for ns in _loaded.values():
        _switch_precision(ns)


def matmul_precision() -> str:
    """The precision of ivy's float32 matrix products and convolutions (see
    :func:`set_matmul_precision`)."""
    return _matmul_precision[0]


def _switch_precision(ns: types.ModuleType) -> Callable[[], None] | None:
    """Set ``ns``'s framework switches to ivy's precision; what restores them, or None."""
    switch = getattr(ns, "__ivy_precision__", None)
    return None if switch is None else switch(_matmul_precision[0])


# ----------------------------------------------------------------------------------------------
# Binding into the ivy namespace
# ----------------------------------------------------------------------------------------------

_MISSING = object()
_saved: dict[str, Any] = {}  # ivy's own (framework-agnostic) attributes replaced by a binding


def _push(ns: types.ModuleType) -> None:
    _stack.append(ns)
    _restorers.append(_switch_precision(ns))
    _bind(ns)


def _restore_depth(depth: int) -> None:
    if len(_stack) <= depth:
        return
    del _stack[depth:]
    while len(_restorers) > depth:
        restore = _restorers.pop()
        if restore is not None:
            restore()
    if _stack:
        _bind(_stack[-1])
    else:
        _unbind()


def _bind(ns: types.ModuleType) -> None:
    ivy_dict = sys.modules["ivy"].__dict__
    own = ns.__dict__
    for name in ns.__all__:
        if name not in _saved:
            _saved[name] = ivy_dict.get(name, _MISSING)
        # (a dtype the backend cannot hold now, such as jax's float64 without x64, is no
        # attribute of the namespace: ivy keeps its name, which then raises where it is used)
        value = own.get(name, _saved[name])
        if value is _MISSING:
            ivy_dict.pop(name, None)
        else:
            ivy_dict[name] = value
    # (the namespace itself, not its fast view: no inference sees the Python scalars then)
    dispatch_globals["_current"] = ns


def _unbind() -> None:
    ivy_dict = sys.modules["ivy"].__dict__
    for name, value in _saved.items():
        if value is _MISSING:
            ivy_dict.pop(name, None)
        else:
            ivy_dict[name] = value
    _saved.clear()
    dispatch_globals["_current"] = None
