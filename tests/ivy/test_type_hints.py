"""Type hints on the public signatures: every parameter and every return of the core's functions
(``ivy/core/*.py``), of ``ivy.framework_handler``, ``ivy.nest`` and the stateful classes is
annotated, every annotation resolves (``typing.get_type_hints``), the framework-agnostic
dispatchers show the annotations written on their stubs, and the compositions bound in a backend
namespace keep theirs."""

from __future__ import annotations

import ast
import inspect
import os
import typing
from pathlib import Path

import pytest

import ivy
import ivy.stateful
from ivy import core, framework_handler, nest
from ivy.core._extensions import ExtensionNamespace
from ivy.stateful import checkpoint, initializers, module


def _module_functions(mod) -> dict[str, typing.Callable]:
    """The public functions defined in ``mod``: those of its ``__all__`` and any other public
    ``def`` (classes are walked by :func:`_stateful_methods`)."""
    names = set(getattr(mod, "__all__", ())) | {
        n for n, obj in vars(mod).items() if getattr(obj, "__module__", None) == mod.__name__
    }
    return {
        f"{mod.__name__}.{n}": getattr(mod, n)
        for n in sorted(names)
        if not n.startswith("_") and inspect.isfunction(getattr(mod, n))
    }


def _core_functions() -> dict[str, typing.Callable]:
    """Every name of every core group's ``__all__`` (stubs, compositions, by-hand dispatchers,
    aliases), as the group module holds it."""
    return {f"{g.__name__}.{n}": getattr(g, n) for g in core.GROUPS for n in g.__all__}


def _stateful_methods() -> dict[str, typing.Callable]:
    """``__init__``, ``__call__`` and the public methods and properties of the stateful
    classes."""
    out = {}
    for cls_name in ivy.stateful.__all__:
        cls = getattr(ivy.stateful, cls_name)
        if not isinstance(cls, type):
            continue
        for name, obj in vars(cls).items():
            if name.startswith("_") and name not in ("__init__", "__call__"):
                continue
            if isinstance(obj, property):
                obj = obj.fget
            if inspect.isfunction(obj):
                out[f"{cls_name}.{name}"] = obj
    return out


FUNCTIONS = {
    **_core_functions(),
    **_module_functions(framework_handler),
    **_module_functions(nest),
    **_module_functions(checkpoint),
    **_module_functions(initializers),
    **_module_functions(module),
    **_stateful_methods(),
}


def test_the_walk_finds_the_core():
    assert len(_core_functions()) == sum(len(g.__all__) for g in core.GROUPS) > 250
    assert "ivy.framework_handler.get_framework" in FUNCTIONS
    assert "ivy.nest.map_nest" in FUNCTIONS
    assert "Optimizer.step" in FUNCTIONS


@pytest.mark.parametrize("qualname", sorted(FUNCTIONS))
def test_every_parameter_and_the_return_are_annotated(qualname):
    sig = inspect.signature(FUNCTIONS[qualname])
    missing = [
        p.name for p in sig.parameters.values() if p.name != "self" and p.annotation is p.empty
    ]
    assert not missing, f"{qualname}: parameters without a type hint: {missing}"
    if not qualname.endswith(".__init__"):
        assert sig.return_annotation is not sig.empty, f"{qualname}: no return type hint"


@pytest.mark.parametrize("qualname", sorted(FUNCTIONS))
def test_every_annotation_resolves(qualname):
    fn = FUNCTIONS[qualname]
    hints = typing.get_type_hints(fn)  # a misspelt or unimported name raises NameError
    assert set(hints) == set(fn.__annotations__)


# ------------------------------------------------------------------------------------------------
# The dispatchers show the annotations written in ivy/core/<group>.py
# ------------------------------------------------------------------------------------------------


def _normal(annotation: str) -> str:
    return ast.dump(ast.parse(annotation, mode="eval"))


def _written_annotations() -> dict[str, dict[str, str]]:
    """``{name: {parameter or 'return': annotation}}`` of every top-level ``def`` of a public name
    in the core's group files, read from the source."""
    out = {}
    for group in core.GROUPS:
        tree = ast.parse(Path(group.__file__).read_text())
        for node in tree.body:
            if isinstance(node, ast.FunctionDef) and node.name in group.__all__:
                a = node.args
                params = [*a.posonlyargs, *a.args, *a.kwonlyargs, a.vararg, a.kwarg]
                written = {
                    p.arg: _normal(ast.unparse(p.annotation))
                    for p in params
                    if p is not None and p.annotation is not None
                }
                if node.returns is not None:
                    written["return"] = _normal(ast.unparse(node.returns))
                out[node.name] = written
    return out


WRITTEN = _written_annotations()


def _agnostic(name: str):
    """``ivy.<name>``; for ``fft``, whose name is also its extension's, the function in it."""
    obj = getattr(ivy, name)
    return getattr(obj, name) if isinstance(obj, ExtensionNamespace) else obj


@pytest.mark.parametrize("name", sorted(WRITTEN))
def test_the_agnostic_function_shows_the_annotations_of_its_definition(name):
    sig = inspect.signature(_agnostic(name))
    shown = {
        p.name: _normal(p.annotation)
        for p in sig.parameters.values()
        if p.annotation is not p.empty
    }
    if sig.return_annotation is not sig.empty:
        shown["return"] = _normal(sig.return_annotation)
    assert shown == WRITTEN[name]


def test_the_dispatchers_are_generated_functions():
    # so that the test above covers the annotations of generated dispatchers, not only of the
    # functions written out in full
    kinds = {getattr(_agnostic(n), "__ivy_kind__", None) for n in WRITTEN}
    assert {"dispatch", "composition"} <= kinds
    assert ivy.sin.__code__.co_filename.endswith(os.path.join("_dispatchers", "sin.py"))


# ------------------------------------------------------------------------------------------------
# Compositions bound in a backend namespace
# ------------------------------------------------------------------------------------------------

CORE_COMPOSITIONS = sorted(
    n
    for g in core.GROUPS
    for n in g.__all__
    if getattr(getattr(g, n), "__ivy_kind__", None) == "composition" and getattr(g, n).__name__ == n
)


def test_there_are_compositions():
    assert {"logspace", "safe_norm", "lstm_update", "isclose"} <= set(CORE_COMPOSITIONS)


@pytest.mark.parametrize("name", CORE_COMPOSITIONS)
def test_a_bound_composition_keeps_its_annotations(name):
    comp = _agnostic(name)
    bound = getattr(ivy.numpy, name)
    assert bound is not comp
    comp_sig, bound_sig = inspect.signature(comp), inspect.signature(bound)
    # every parameter, f included: a bound composition takes f (the same backend, or another
    # one whose composition it then runs), so code passing f runs under a global framework
    assert list(bound_sig.parameters.values()) == list(comp_sig.parameters.values())
    assert bound_sig.return_annotation == comp_sig.return_annotation
    assert bound_sig.return_annotation is not bound_sig.empty
    assert typing.get_type_hints(bound) == typing.get_type_hints(comp)
