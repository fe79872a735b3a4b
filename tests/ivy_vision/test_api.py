"""The public API: listed once in ``__all__`` and covered by the tests, keyword-only ``f=None``
everywhere, docstrings with Args/Returns/Example that run, compositions that resolve the
framework once, and an import that loads no framework."""

from __future__ import annotations

import inspect
import pathlib
import re
import subprocess
import sys

import pytest

import ivy_vision as vis
from tests._doctests import docstring_examples, run_example
from tests.ivy_vision._cases import CASES

PACKAGE = pathlib.Path(vis.__file__).parent
TESTS = pathlib.Path(__file__).parent
MODULES = ["ivy_vision"] + [m.__name__ for m in vis.MODULES]


def _public_callables():
    """Every public function, and every public method and classmethod of the public classes."""
    out = {}
    for name in vis.__all__:
        obj = getattr(vis, name)
        if inspect.isclass(obj):
            for attr, member in vars(obj).items():
                if attr.startswith("_"):
                    continue
                fn = member.__func__ if isinstance(member, (classmethod, staticmethod)) else member
                if inspect.isfunction(fn):
                    out[f"{name}.{attr}"] = fn
        else:
            out[name] = obj
    return out


def test_all_is_complete_unique_and_tested():
    assert len(vis.__all__) == len(set(vis.__all__))
    for module in vis.MODULES:
        for name in module.__all__:
            assert getattr(vis, name) is getattr(module, name)
    sources = "\n".join(p.read_text() for p in TESTS.glob("test_*.py"))
    tested = set(re.findall(r"\bvis\.(\w+)", sources)) | set(CASES)
    untested = set(vis.__all__) - tested
    assert not untested, f"public names without a test: {sorted(untested)}"


@pytest.mark.parametrize("name", sorted(_public_callables()))
def test_signature_and_docstring(name):
    fn = _public_callables()[name]
    params = inspect.signature(fn).parameters
    f = params.get("f")
    assert f is not None and f.default is None, f"{name} must take f=None"
    assert f.kind is inspect.Parameter.KEYWORD_ONLY, f"{name}: f must be keyword-only"
    assert list(params)[-1] == "f", f"{name}: f must come last"
    doc = inspect.getdoc(fn)
    for section in ("Args:", "Returns:", "Example:"):
        assert section in doc, f"{name} docstring lacks {section}"


@pytest.mark.parametrize("example", docstring_examples(MODULES))
def test_docstring_examples(example, request, tmp_path, monkeypatch):
    globs = {n: getattr(vis, n) for n in vis.__all__}
    run_example(example, globs, request.config, tmp_path, monkeypatch)


def test_every_module_has_examples():
    with_examples = {example.values[0].globs["__name__"] for example in docstring_examples(MODULES)}
    assert set(MODULES) == with_examples, set(MODULES) - with_examples


def test_compositions_resolve_the_framework_once():
    """Inside the package ``ivy`` is only used to resolve the framework; every primitive is
    called on the namespace ``xp``; no framework is imported and no backend is named."""
    for path in PACKAGE.rglob("*.py"):
        source = path.read_text()
        uses = set(re.findall(r"\bivy\.(\w+)\(", source))
        assert uses <= {"get_framework"}, f"{path.name} calls ivy.{uses - {'get_framework'}}"
        assert not re.search(r"^\s*(import|from)\s+(torch|jax|tensorflow)\b", source, re.M), path
        assert not re.search(r"['\"](torch|jax|tensorflow)['\"]", source), path.name
        assert not re.search(r"\bfrom ivy_mechanics\.\w*_", source), path.name  # no private


def test_import_loads_no_framework():
    code = (
        "import sys, ivy_vision; "
        "print([m for m in ('torch', 'jax', 'tensorflow') if m in sys.modules])"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=PACKAGE.parent, check=True
    )
    assert out.stdout.strip() == "[]"
