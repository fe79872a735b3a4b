"""Conventions that hold across the repository: the core and every applied library.

- ``f`` (the framework choice) is keyword-only with default None on every public function and
  method of ``ivy`` and of every applied package (``ivy_mechanics``, ``ivy_gym``, ...): positional
  ``f`` would make ``fn(x, 'zyx')`` and ``fn(x, 'torch')`` ambiguous.
- Applied packages import nothing private from another package (``ivy.core._dispatch``,
  ``ivy_mechanics._kernels``, ...): shared numerics live in the core's public API.
- ``import <package>`` imports no framework (tensorflow alone takes seconds).
- Applied packages never compare a framework's name (``xp.backend == "numpy"``, ``backend in
  ("jax", "tensorflow")``): they ask the backend's capabilities (``xp.capabilities.autodiff``,
  ``.compilation``, ``.compiled_loops``, ``.float64``) or the core's functions
  (``ivy.compiled_scan``, ``ivy.enable_float64``, ``ivy.dtype_name``).
- Applied packages call ``ivy.<name>(..., f=...)`` only where ``ivy.<name>`` takes ``f`` while a
  framework is set globally too (the core's compositions, ``get_framework``): a backend's
  primitive bound into ``ivy`` (``ivy.scan``, ``ivy.seed``) has no ``f``, so such calls break
  the library for users who set a framework; resolve ``xp`` once and call ``xp.scan(...)``.
- Applied packages read no other object's private attributes (``env._boxes``, ``core._step``,
  ``model._forward``): only those of ``self``, ``cls``, ``super()``, and of objects of the
  module's own classes (a class of the module, a variable annotated with one, made by one, or a
  copy of ``self``).

Applied packages are found on disk (every top-level ``ivy_*`` package), so a new library is
checked the day it lands.
"""

from __future__ import annotations

import ast
import importlib
import inspect
import pathlib
import subprocess
import sys
import types

import pytest

import ivy

ROOT = pathlib.Path(__file__).resolve().parents[1]
APPLIED = sorted(
    p.name for p in ROOT.iterdir() if p.name.startswith("ivy_") and (p / "__init__.py").exists()
)
PACKAGES = ["ivy", *APPLIED]
FRAMEWORKS = ("torch", "jax", "tensorflow")


def _public_callables(module: types.ModuleType, prefix: str):
    """``(qualified name, callable)`` for every public function, class constructor and public
    method reachable from ``module.__all__`` (recursing into public submodules and namespaces)."""
    seen: set[int] = set()
    out = []

    def walk(mod, path):
        for name in getattr(mod, "__all__", ()):
            obj = getattr(mod, name)
            if id(obj) in seen:
                continue
            seen.add(id(obj))
            qual = f"{path}.{name}"
            if isinstance(obj, types.ModuleType):
                walk(obj, qual)
            elif inspect.isclass(obj):
                for attr, value in vars(obj).items():
                    if attr.startswith("_") and attr not in ("__init__", "__call__"):
                        continue
                    value = (
                        value.__func__ if isinstance(value, (classmethod, staticmethod)) else value
                    )
                    if inspect.isfunction(value):
                        out.append((f"{qual}.{attr}", value))
            elif callable(obj):
                out.append((qual, obj))

    walk(module, prefix)
    return out


def _framework_parameter_problem(fn) -> str | None:
    try:
        sig = inspect.signature(fn)
    except (TypeError, ValueError):  # builtins without a signature take no f
        return None
    p = sig.parameters.get("f")
    if p is None:
        return None
    if p.kind is not p.KEYWORD_ONLY:
        return f"f is {p.kind.description}"
    if p.default is not None:
        return f"f defaults to {p.default!r}, not None"
    return None


@pytest.mark.parametrize("package", PACKAGES)
def test_f_is_keyword_only(package):
    module = importlib.import_module(package)
    callables = _public_callables(module, package)
    if package == "ivy":
        callables += _public_callables(ivy.nest, "ivy.nest")
    assert callables, f"{package} exports no public callables"
    problems = [
        f"{name}{inspect.signature(fn)}: {problem}"
        for name, fn in callables
        if (problem := _framework_parameter_problem(fn))
    ]
    assert not problems, "\n".join(problems)


def test_every_core_function_takes_f():
    """Every dispatched function and composition of the core can be told its framework."""
    missing = [
        name
        for name in ivy.core.__all__
        if callable(fn := getattr(ivy.core, name))
        and getattr(fn, "__ivy_kind__", None) in ("dispatch", "composition")
        and "f" not in inspect.signature(fn).parameters
    ]
    assert not missing, missing


def test_every_mechanics_function_takes_f():
    import ivy_mechanics

    missing = [
        name
        for name, fn in _public_callables(ivy_mechanics, "ivy_mechanics")
        if "f" not in inspect.signature(fn).parameters
    ]
    assert not missing, missing


def test_the_check_catches_positional_f():
    """The walker sees a positional ``f`` (so the tests above can fail)."""

    def positional(x, f=None): ...

    def keyword(x, *, f=None): ...

    def wrong_default(x, *, f="torch"): ...

    assert _framework_parameter_problem(positional).startswith("f is positional")
    assert _framework_parameter_problem(keyword) is None
    assert "defaults to" in _framework_parameter_problem(wrong_default)


def _private(name: str) -> bool:
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__"))


def _private_imports(package: str) -> list[str]:
    """Imports of another package's private module or name, anywhere in ``package``'s files."""
    found = []
    for path in sorted((ROOT / package).rglob("*.py")):
        tree = ast.parse(path.read_text(), str(path))
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
                modules = [node.module]
                names = [a.name for a in node.names]
            elif isinstance(node, ast.Import):
                modules, names = [a.name for a in node.names], []
            else:
                continue
            for module in modules:
                parts = module.split(".")
                if parts[0] == package:
                    continue  # a package's own private modules are its business
                if any(_private(p) for p in parts) or any(_private(n) for n in names):
                    where = f"{path.relative_to(ROOT)}:{node.lineno}"
                    found.append(f"{where}: from {module} import {', '.join(names) or '*'}")
    return found


@pytest.mark.parametrize("package", APPLIED)
def test_applied_packages_import_nothing_private(package):
    assert not _private_imports(package), "\n".join(_private_imports(package))


@pytest.mark.parametrize("package", PACKAGES)
def test_import_loads_no_framework(package):
    code = f"import sys, {package}; print(sorted(m for m in {FRAMEWORKS!r} if m in sys.modules))"
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True
    ).stdout.strip()
    assert out == "[]", f"import {package} imported {out}"


def test_import_works_without_optree_and_nests_say_what_to_install():
    """optree is a dependency of ivy, but ``import ivy`` (and array functions) must not need it;
    the nest functions that do name the package to install."""
    code = (
        "import sys\n"
        "class Block:\n"
        "    def find_spec(self, name, path=None, target=None):\n"
        "        if name.split('.')[0] == 'optree':\n"
        "            raise ModuleNotFoundError(name)\n"
        "sys.meta_path.insert(0, Block())\n"
        "import numpy as np, ivy\n"
        "print(ivy.add(np.ones(2), 1.0).tolist())\n"
        "try:\n"
        "    ivy.nest.map_nest(abs, [1])\n"
        "except ModuleNotFoundError as e:\n"
        "    print(e)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True
    ).stdout
    assert out.startswith("[2.0, 2.0]\n")
    assert "pip install optree" in out


# ----------------------------------------------------------------------------------------------
# No framework names in applied code; no private attributes of other objects
# ----------------------------------------------------------------------------------------------

FRAMEWORK_NAMES = frozenset(
    {"numpy", "np", "torch", "pytorch", "jax", "tensorflow", "tf", "array_api_strict"}
)


def _names_a_framework(node: ast.AST) -> bool:
    """A string constant that is a framework's name, or a tuple, list or set holding one."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value in FRAMEWORK_NAMES
    if isinstance(node, (ast.Tuple, ast.List, ast.Set)):
        return any(_names_a_framework(e) for e in node.elts)
    return False


def framework_name_comparisons(tree: ast.AST) -> list[tuple[int, str]]:
    """``(line, code)`` of each comparison with a framework's name (``==``, ``!=``, ``in``,
    ``is``...) and each ``match`` case on one."""
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Compare):
            if any(_names_a_framework(o) for o in (node.left, *node.comparators)):
                found.append((node.lineno, ast.unparse(node)))
        elif isinstance(node, ast.match_case):
            values = [p.value for p in ast.walk(node.pattern) if isinstance(p, ast.MatchValue)]
            if any(_names_a_framework(v) for v in values):
                found.append((node.pattern.lineno, f"case {ast.unparse(node.pattern)}"))
    return found


def _annotation_names(annotation: ast.AST | None) -> set[str]:
    if annotation is None:
        return set()
    if isinstance(annotation, ast.Constant) and isinstance(annotation.value, str):
        try:
            annotation = ast.parse(annotation.value, mode="eval").body
        except SyntaxError:
            return set()
    return {n.id for n in ast.walk(annotation) if isinstance(n, ast.Name)}


def _own_receivers(tree: ast.AST) -> set[str]:
    """Names whose private attributes the module may read: ``self``, ``cls``, its classes, and
    variables of its classes (annotated with one, made by one, or made from ``self``)."""
    classes = {n.name for n in ast.walk(tree) if isinstance(n, ast.ClassDef)}
    names = {"self", "cls"} | classes
    for node in ast.walk(tree):
        if isinstance(node, ast.arg) and _annotation_names(node.annotation) & classes:
            names.add(node.arg)
        elif isinstance(node, ast.AnnAssign) and _annotation_names(node.annotation) & classes:
            if isinstance(node.target, ast.Name):
                names.add(node.target.id)
        elif isinstance(node, ast.Assign) and isinstance(node.value, ast.Call):
            call = node.value
            made_by_own_class = isinstance(call.func, ast.Name) and call.func.id in classes
            from_self = bool(call.args) and ast.unparse(call.args[0]) in ("self", "cls")
            if made_by_own_class or from_self:  # (``copy.copy(self)``, ``replace(self, ...)``)
                names |= {t.id for t in node.targets if isinstance(t, ast.Name)}
    return names


def private_attribute_reads(tree: ast.AST) -> list[tuple[int, str]]:
    """``(line, code)`` of each read of a private attribute (``obj._name``, not a dunder) of an
    object that is not the module's own (see :func:`_own_receivers`)."""
    own = _own_receivers(tree)
    found = []
    for node in ast.walk(tree):
        if not (isinstance(node, ast.Attribute) and _private(node.attr)):
            continue
        receiver = node.value
        if isinstance(receiver, ast.Name) and receiver.id in own:
            continue
        if isinstance(receiver, ast.Call) and ast.unparse(receiver) in ("super()", "type(self)"):
            continue
        found.append((node.lineno, ast.unparse(node)))
    return found


def _offences(package: str, check) -> list[str]:
    out = []
    for path in sorted((ROOT / package).rglob("*.py")):
        tree = ast.parse(path.read_text(), str(path))
        out += [f"{path.relative_to(ROOT)}:{line}: {code}" for line, code in check(tree)]
    return out


@pytest.mark.parametrize("package", APPLIED)
def test_applied_packages_compare_no_framework_names(package):
    found = _offences(package, framework_name_comparisons)
    assert not found, (
        "ask the backend's capabilities (xp.capabilities.autodiff, .compilation, "
        ".compiled_loops, .vectorised_jacobian, .float64) or the core (ivy.compiled_scan, ivy.enable_float64, "
        "ivy.dtype_name) instead of a framework's name:\n" + "\n".join(found)
    )


@pytest.mark.parametrize("package", APPLIED)
def test_applied_packages_read_no_private_attributes_of_others(package):
    found = _offences(package, private_attribute_reads)
    assert not found, "make the contract public (or read it through self):\n" + "\n".join(found)


def ivy_calls_with_f(tree: ast.AST) -> list[tuple[int, str]]:
    """``ivy.<name>(..., f=...)`` calls: (line, name)."""
    return [
        (node.lineno, node.func.attr)
        for node in ast.walk(tree)
        if isinstance(node, ast.Call)
        and isinstance(node.func, ast.Attribute)
        and isinstance(node.func.value, ast.Name)
        and node.func.value.id == "ivy"
        and any(k.arg == "f" for k in node.keywords)
    ]


@pytest.mark.parametrize("package", APPLIED)
def test_applied_packages_pass_f_only_where_a_set_framework_takes_it(package):
    calls = _offences(package, ivy_calls_with_f)
    with ivy.set_framework("numpy"):
        found = [
            c
            for c in calls
            if "f" not in inspect.signature(getattr(ivy, c.rsplit(" ", 1)[1])).parameters
        ]
    assert not found, (
        "these calls fail while a framework is set globally (the backend's function has no f): "
        "resolve xp = ivy.get_framework(..., f=f) once and call xp.<name>(...):\n"
        + "\n".join(found)
    )


def test_the_convention_checks_find_what_they_look_for():
    """Both checks flag what they must and leave legitimate code alone."""
    flagged = ast.parse(
        "if xp.backend == 'numpy': pass\n"
        "compile = xp.backend != 'torch'\n"
        "fast = backend in ('jax', 'tensorflow')\n"
        "same = 'tf' is name\n"
        "match framework:\n"
        "    case 'torch':\n"
        "        pass\n"
    )
    assert [line for line, _ in framework_name_comparisons(flagged)] == [1, 2, 3, 4, 6]
    calls = ast.parse("ivy.scan(g, c, xs, f=xp)\nxp.scan(g, c, xs)\nivy.compile_fn(g, f=xp)\n")
    assert ivy_calls_with_f(calls) == [(1, "scan"), (3, "compile_fn")]
    fine = ast.parse(
        "if dtype == 'float32' and mode in ('train', 'eval'): pass\n"
        "ok = xp.capabilities.compiled_loops\n"
    )
    assert framework_name_comparisons(fine) == []
    reads = ast.parse(
        "import copy\n"
        "class Env:\n"
        "    def __init__(self):\n"
        "        self._boxes = 1\n"
        "    def __eq__(self, other: 'Env'):\n"
        "        return self._boxes == other._boxes\n"
        "    def narrowed(self):\n"
        "        new = copy.copy(self)\n"
        "        new._boxes = super()._boxes + Env._count + type(self)._count\n"
        "        return new\n"
        "def bad(env, core):\n"
        "    low = env._boxes\n"
        "    return core._step(self.model._forward, env.__class__)\n"
    )
    assert private_attribute_reads(reads) == [
        (12, "env._boxes"),
        (13, "core._step"),
        (13, "self.model._forward"),
    ]
