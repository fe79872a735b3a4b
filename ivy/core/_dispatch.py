"""Build the framework-agnostic functions of the core.

A core function is declared once as a stub: its signature (ending in ``f=None``) and docstring.
``@dispatch`` turns the stub into a dispatcher that resolves the backend namespace and calls the
backend function of the same name, forwarding every argument as it was given.

The dispatcher is generated from the stub's signature so that it is a plain Python function with
no ``*args`` packing: resolving the backend costs one dict lookup keyed by ``type(x)`` on the fast
path. ``benchmarks/dispatch_overhead.py`` measures what that costs against the native call.

Compositions (functions written once in terms of others) are marked with ``@composition``; they
resolve the namespace themselves (``xp = ivy.get_framework(x, f=f)``) and are also exposed in
every backend namespace with ``f`` bound to that backend.
"""

from __future__ import annotations

import ast
import builtins
import functools
import inspect
import types
from collections.abc import Callable
from typing import Any

from ivy import framework_handler as _fh

__all__ = ["dispatch", "composition", "alias", "DISPATCHED", "COMPOSITIONS"]

DISPATCHED: dict[str, Callable] = {}  # name -> framework-agnostic dispatcher
COMPOSITIONS: dict[str, Callable] = {}  # name -> composition (takes f=)

_TEMPLATE = """\
def {name}({params}):
    if f is None:
        ns = _current
        if ns is None:
{infer}
    else:
        try:
            ns = _by_f[f]
        except (KeyError, TypeError):
            ns = _resolve_f(f)
    return ns.{name}({call})
"""


def _infer_block(name: str, arrays: list[str], indent: str) -> str:
    """Source that sets ``ns`` from the types of the ``arrays`` parameters."""
    everything = ", ".join(arrays)
    slow = f"_infer({everything}, name='ivy.{name}')"
    if not arrays:
        return f"{indent}ns = _infer(name='ivy.{name}')"
    first, rest = arrays[0], arrays[1:]
    lines = [
        f"t = type({first})",
        "try:",
        "    ns = _by_type[t]",
        "except KeyError:",
        f"    ns = {slow}",
    ]
    if rest:
        mismatch = " or ".join(f"(type({p}) is not t and type({p}) not in _passive)" for p in rest)
        lines += ["else:", f"    if {mismatch}:", f"        ns = {slow}"]
    return "\n".join(indent + line for line in lines)


def _build(stub: Callable, arrays: list[str]) -> Callable:
    sig = inspect.signature(stub)
    params = list(sig.parameters.values())
    if not params or params[-1].name != "f" or params[-1].kind is not params[-1].KEYWORD_ONLY:
        raise TypeError(f"stub {stub.__name__} must end with a keyword-only parameter f=None")
    declared: list[str] = []
    call: list[str] = []
    slash_done = False
    star_done = False
    for p in params:
        if p.kind is p.VAR_POSITIONAL or p.kind is p.VAR_KEYWORD:
            raise TypeError(f"stub {stub.__name__}: *args/**kwargs are not supported")
        if p.kind is not p.POSITIONAL_ONLY and not slash_done:
            if any(q.kind is q.POSITIONAL_ONLY for q in params):
                declared.append("/")
            slash_done = True
        if p.kind is p.KEYWORD_ONLY and not star_done:
            declared.append("*")
            star_done = True
        declared.append(p.name if p.default is p.empty else f"{p.name}=None")
        if p.name == "f":
            continue
        call.append(p.name if p.kind is not p.KEYWORD_ONLY else f"{p.name}={p.name}")
    names = {p.name for p in params}
    unknown = set(arrays) - names
    if unknown:
        raise TypeError(f"stub {stub.__name__}: no parameters named {sorted(unknown)}")
    source = _TEMPLATE.format(
        name=stub.__name__,
        params=", ".join(declared),
        infer=_infer_block(stub.__name__, arrays, " " * 12),
        call=", ".join(call),
    )
    scope: dict[str, Any] = {}
    exec(compile(source, f"<ivy dispatch {stub.__name__}>", "exec"), _fh.dispatch_globals, scope)
    fn = scope[stub.__name__]
    fn.__defaults__ = stub.__defaults__
    fn.__kwdefaults__ = stub.__kwdefaults__
    functools.update_wrapper(fn, stub, updated=())
    del fn.__wrapped__  # the dispatcher is the real function; the stub has no body
    fn.__ivy_kind__ = "dispatch"
    _share_annotation_names(stub)
    return fn


def _share_annotation_names(stub: Callable) -> None:
    """Make the names used in ``stub``'s annotations (``Array``, ``Sequence``...) resolvable in
    the dispatchers' globals, ``_fh.dispatch_globals``, so that ``typing.get_type_hints`` works on
    the dispatcher as on the stub. Nothing at call time reads them."""
    for annotation in stub.__annotations__.values():
        if not isinstance(annotation, str):
            continue
        for node in ast.walk(ast.parse(annotation, mode="eval")):
            if not isinstance(node, ast.Name) or node.id not in stub.__globals__:
                continue  # builtins (int, tuple...) resolve by themselves
            value = stub.__globals__[node.id]
            if hasattr(builtins, node.id) or node.id.startswith("_"):
                raise TypeError(
                    f"stub {stub.__name__}: the annotation name {node.id!r} would shadow a builtin "
                    f"or the dispatchers' own names; use another name"
                )
            if _fh.dispatch_globals.setdefault(node.id, value) is not value:
                raise TypeError(
                    f"stub {stub.__name__}: the annotation name {node.id!r} means another object "
                    f"in another stub's module; import it from the same place"
                )


def dispatch(*arrays: str | Callable) -> Callable:
    """Turn a stub into a framework-agnostic dispatcher.

    ``@dispatch`` infers the framework from the first parameter; ``@dispatch("x1", "x2")`` from
    the named parameters (lists, tuples and dicts among them are searched for arrays), and
    ``@dispatch()`` from none (the framework then comes from ``f`` or the global setting).
    """
    if len(arrays) == 1 and callable(arrays[0]):
        stub = arrays[0]
        first = next(iter(inspect.signature(stub).parameters))
        return _register(_build(stub, [] if first == "f" else [first]))

    def decorate(stub: Callable) -> Callable:
        return _register(_build(stub, list(arrays)))

    return decorate


def _register(fn: Callable) -> Callable:
    DISPATCHED[fn.__name__] = fn
    return fn


def composition(fn: Callable) -> Callable:
    """Mark ``fn`` (which takes ``f=None``) as a composition exposed in every backend namespace."""
    fn.__ivy_kind__ = "composition"
    COMPOSITIONS[fn.__name__] = fn
    return fn


def alias(name: str, target: Callable) -> Callable:
    """Register ``name`` as another spelling of the core function ``target``.

    The alias is the very same object in the agnostic namespace and in each backend namespace.
    """
    registry = COMPOSITIONS if target.__name__ in COMPOSITIONS else DISPATCHED
    registry[name] = target
    _ALIASES[name] = target.__name__
    return target


_ALIASES: dict[str, str] = {}


def _bind_compositions(ns: types.ModuleType) -> None:
    """Check that ``ns`` implements every dispatched function, then expose every composition in
    it with ``f`` bound to it."""
    missing = sorted(n for n in DISPATCHED if n not in _ALIASES and not hasattr(ns, n))
    if missing:
        raise ImportError(f"ivy backend {ns.__name__} does not implement {missing}")
    added = []
    for name, comp in COMPOSITIONS.items():
        if name in _ALIASES:
            continue
        bound = _bound(comp, ns)
        setattr(ns, name, bound)
        added.append(name)
    for name, target in _ALIASES.items():
        setattr(ns, name, getattr(ns, target))
        added.append(name)
    ns.__all__ = sorted(set(ns.__all__) | set(added))


def _bound(comp: Callable, ns: types.ModuleType) -> Callable:
    def bound(*args: Any, **kwargs: Any) -> Any:
        return comp(*args, f=ns, **kwargs)

    # The same code with the composition's globals, where typing.get_type_hints finds the names
    # its annotations use.
    bound = types.FunctionType(bound.__code__, comp.__globals__, None, None, bound.__closure__)
    functools.update_wrapper(bound, comp)
    bound.__annotations__ = {k: v for k, v in comp.__annotations__.items() if k != "f"}
    sig = inspect.signature(comp)
    bound.__signature__ = sig.replace(
        parameters=[p for p in sig.parameters.values() if p.name != "f"]
    )
    del bound.__wrapped__
    return bound


_fh.on_backend_load(_bind_compositions)
