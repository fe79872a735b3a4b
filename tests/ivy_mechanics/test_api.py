"""The public API: listed once in ``__all__``, every function covered by the test table, the
design's signature and docstring conventions, runnable docstring examples, and compositions
that resolve the framework once (no ``ivy.<fn>`` dispatch inside, no clamps)."""

from __future__ import annotations

import inspect
import pathlib
import pkgutil
import re

import pytest

import ivy_mechanics as mech
from tests._doctests import docstring_examples, run_example
from tests.ivy_mechanics._cases import CASES, NOT_FUNCTIONS, RANDOM_CASES

PACKAGE = pathlib.Path(mech.__file__).parent
MODULES = sorted(
    m.name for m in pkgutil.walk_packages(mech.__path__, "ivy_mechanics.") if not m.ispkg
) + ["ivy_mechanics", "ivy_mechanics.orientation"]


def test_all_is_complete_and_covered_by_the_tests():
    assert len(mech.__all__) == len(set(mech.__all__))
    assert set(mech.__all__) == set(CASES) | set(RANDOM_CASES) | NOT_FUNCTIONS
    for name in mech.__all__:
        assert hasattr(mech, name), name


@pytest.mark.parametrize("name", sorted(set(mech.__all__) - NOT_FUNCTIONS))
def test_signature_and_docstring(name):
    fn = getattr(mech, name)
    params = list(inspect.signature(fn).parameters.values())
    assert params[-1].name == "f" and params[-1].default is None, f"{name} must end with f=None"
    doc = inspect.getdoc(fn)
    for section in ("Args:", "Returns:", "Example:"):
        assert section in doc, f"{name} docstring lacks {section}"


@pytest.mark.parametrize("example", docstring_examples(MODULES))
def test_docstring_examples(example, request, tmp_path, monkeypatch):
    globs = {n: getattr(mech, n) for n in mech.__all__}
    run_example(example, globs, request.config, tmp_path, monkeypatch)


def test_compositions_resolve_the_framework_once():
    """Inside the package ``ivy`` is only used to resolve the framework: every primitive is
    called on the namespace ``xp``. And no value is clamped or clipped."""
    for path in PACKAGE.rglob("*.py"):
        source = path.read_text()
        uses = set(re.findall(r"\bivy\.(\w+)\(", source))
        assert uses <= {"get_framework"}, f"{path.name} calls ivy.{uses - {'get_framework'}}"
        assert not re.search(r"\b(clip|clamp|minimum|maximum)\(", source), path.name
