"""The core's layers import in one direction (read from the source, nothing is imported).

From the bottom: the base (errors, typing, dtype names, nests, the argument rules in
``ivy/_args`` that the core and the backends both apply), framework selection
(``framework_handler``), the core (``ivy/core``: stubs, dispatch, compositions), the backends
(``ivy/backends``: assembled from the core's registry), the stateful API, and the ``ivy``
package itself. A module imports only from its own layer or those below; selection loads the
backends by name (the package names it registers), and the core installs its error diagnosis
into selection (``framework_handler.explain_errors_with``). No module imports itself back
through others: the graph has no cycle. Every import counts, also one inside a function.
"""

from __future__ import annotations

import ast
import pathlib

import ivy

ROOT = pathlib.Path(ivy.__file__).parent

# (layer, the modules in it: a name and everything below it), bottom first.
LAYERS = (
    ("base", ("ivy.errors", "ivy.typing", "ivy.dtypes", "ivy.nest", "ivy._args")),
    ("selection", ("ivy.framework_handler",)),
    ("core", ("ivy.core", "ivy.registry")),
    ("backends", ("ivy.backends",)),
    ("stateful", ("ivy.stateful",)),
    ("package", ("ivy",)),
)


def _modules() -> dict[str, pathlib.Path]:
    out = {}
    for path in ROOT.rglob("*.py"):
        parts = list(path.relative_to(ROOT.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        out[".".join(parts)] = path
    return out


MODULES = _modules()


def _existing(name: str) -> str:
    """The module that ``name`` (a module, or a name inside one) lives in."""
    while name not in MODULES:
        name = name.rpartition(".")[0]
    return name


def _imports(module: str) -> set[tuple[str, int]]:
    """``(imported ivy module, line)`` for every import statement of ``module``."""
    path = MODULES[module]
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package
                for _ in range(node.level - 1):
                    anchor = anchor.rpartition(".")[0]
                base = f"{anchor}.{base}" if base else anchor
            names = [
                f"{base}.{a.name}" if f"{base}.{a.name}" in MODULES else base for a in node.names
            ]
        else:
            continue
        found |= {(_existing(n), node.lineno) for n in names if n.split(".")[0] == "ivy"}
    return found


GRAPH = {m: _imports(m) for m in MODULES}


def layer_of(module: str) -> int:
    best = None
    for level, (_, prefixes) in enumerate(LAYERS):
        for prefix in prefixes:
            if module == prefix or module.startswith(prefix + "."):
                if best is None or len(prefix) > best[1]:
                    best = (level, len(prefix))
    assert best is not None, f"{module} is in no layer: add it to LAYERS"
    return best[0]


def upward_imports(graph: dict[str, set[tuple[str, int]]]) -> list[str]:
    return [
        f"{m}:{line} imports {target} ({LAYERS[layer_of(m)][0]} -> {LAYERS[layer_of(target)][0]})"
        for m, targets in sorted(graph.items())
        for target, line in sorted(targets)
        if layer_of(target) > layer_of(m)
    ]


def find_cycle(graph: dict[str, set[tuple[str, int]]]) -> list[str] | None:
    state: dict[str, int] = {}  # 1: on the current path, 2: done
    path: list[str] = []

    def visit(module: str) -> list[str] | None:
        state[module] = 1
        path.append(module)
        for target, _ in sorted(graph.get(module, ())):
            if target == module:
                continue
            if state.get(target) == 1:
                return path[path.index(target) :] + [target]
            if target not in state:
                cycle = visit(target)
                if cycle:
                    return cycle
        path.pop()
        state[module] = 2
        return None

    for module in sorted(graph):
        if module not in state:
            cycle = visit(module)
            if cycle:
                return cycle
    return None


def test_every_module_imports_only_its_layer_and_those_below():
    upward = upward_imports(GRAPH)
    assert not upward, "imports that go up a layer:\n" + "\n".join(upward)


def test_the_import_graph_has_no_cycle():
    cycle = find_cycle(GRAPH)
    assert cycle is None, "an import cycle: " + " -> ".join(cycle)


def test_the_checks_find_what_they_look_for():
    """Imports inside functions are read, and an upward import or a cycle is reported (checks
    that read nothing would pass)."""
    assert any(t == "ivy.core._dtype_rules" for t, _ in GRAPH["ivy.core._diagnose"])
    bad = {
        "ivy.core.creation": {("ivy.backends.torch.creation", 3)},
        "ivy.backends.torch.creation": {("ivy.core.creation", 5)},
    }
    assert upward_imports(bad) == [
        "ivy.core.creation:3 imports ivy.backends.torch.creation (core -> backends)"
    ]
    assert find_cycle(bad) == [
        "ivy.backends.torch.creation",
        "ivy.core.creation",
        "ivy.backends.torch.creation",
    ]
