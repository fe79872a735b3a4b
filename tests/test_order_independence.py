"""The suite does not depend on the order of its tests: no test draws from a random generator
that a module shares between its tests (what a test got depended on the tests that ran before it
in the same worker: ``test_rasterize_triangles_against_loops[jax]`` failed once in a full run and
passed alone). Tests draw from the ``rng`` fixture (``tests/conftest.py``), a generator of their
own; module constants may be drawn at import from a generator deleted right after.

The other half of the check is running the suite shuffled (``--shuffle SEED``, see
``tests/conftest.py``)."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent
CHECKED = ("ivy", "ivy_mechanics", "ivy_vision", "ivy_rl", "scripts")
_GENERATORS = ("default_rng", "RandomState", "Generator", "Random")
_GLOBAL_STATE = ("seed", "rand", "randn", "normal", "uniform", "random", "randint", "choice",
                 "permutation", "shuffle", "standard_normal")  # fmt: skip


def _call_name(node: ast.AST) -> str | None:
    if isinstance(node, ast.Call):
        func = node.func
        if isinstance(func, ast.Attribute):
            return func.attr
        if isinstance(func, ast.Name):
            return func.id
    return None


def shared_generators(path: Path) -> list[str]:
    """Module-level names bound to a random generator and never deleted, and draws from numpy's
    global generator (``np.random.normal(...)``) anywhere, in one test file."""
    tree = ast.parse(path.read_text(), str(path))
    bound, deleted = {}, set()
    for node in tree.body:
        if isinstance(node, ast.Assign) and _call_name(node.value) in _GENERATORS:
            for target in node.targets:
                if isinstance(target, ast.Name):
                    bound[target.id] = node.lineno
        if isinstance(node, ast.Delete):
            deleted |= {t.id for t in node.targets if isinstance(t, ast.Name)}
    found = [f"{path}:{line}: {name}" for name, line in bound.items() if name not in deleted]
    for node in ast.walk(tree):
        func = getattr(node, "func", None)
        if (
            isinstance(node, ast.Call)
            and isinstance(func, ast.Attribute)
            and func.attr in _GLOBAL_STATE
            and isinstance(func.value, ast.Attribute)
            and func.value.attr == "random"
            and isinstance(func.value.value, ast.Name)
            and func.value.value.id in ("np", "numpy")
        ):
            found.append(f"{path}:{node.lineno}: np.random.{func.attr} (numpy's global state)")
    return found


@pytest.mark.parametrize("directory", CHECKED)
def test_no_test_draws_from_a_generator_shared_by_its_module(directory):
    found = [
        f for path in sorted((ROOT / directory).rglob("*.py")) for f in shared_generators(path)
    ]
    assert not found, "draw from the rng fixture instead:\n" + "\n".join(found)


def test_the_check_finds_what_it_looks_for(tmp_path):
    shared = tmp_path / "test_shared.py"
    shared.write_text("import numpy as np\nrng = np.random.default_rng(0)\n")
    assert shared_generators(shared) == [f"{shared}:2: rng"]
    constants = tmp_path / "test_constants.py"
    constants.write_text(
        "import numpy as np\n_d = np.random.default_rng(0)\nX = _d.normal()\ndel _d\n"
    )
    assert shared_generators(constants) == []
    global_state = tmp_path / "test_global.py"
    global_state.write_text("import numpy as np\ndef test():\n    np.random.normal()\n")
    assert "global state" in shared_generators(global_state)[0]


def test_the_rng_fixture_is_the_tests_own(rng, request):
    """The same draws for a test whatever ran before it (seeded by its name)."""
    import zlib

    import numpy as np

    name = f"{request.node.module.__name__}::{request.node.originalname}"
    expected = np.random.default_rng(zlib.crc32(name.encode())).random(3)
    np.testing.assert_array_equal(rng.random(3), expected)
