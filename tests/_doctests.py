"""Docstring examples as tests, one test per docstring, on the backends each example names.

Written once for every package::

    EXAMPLES = docstring_examples("ivy_gym")                 # collected when the module loads

    @pytest.mark.parametrize("example", EXAMPLES)
    def test_docstring_examples(example, request, tmp_path, monkeypatch):
        run_example(example, {"ivy_gym": ivy_gym}, request.config, tmp_path, monkeypatch)

An example names a backend by the words of its code: ``torch``; ``jax`` or ``jnp``; ``tf.`` or
``tensorflow`` (``f="torch"``, ``ivy.jax`` and ``torch.ones`` all name theirs). A docstring whose
examples name a backend that is not installed, or not selected for the run (``--backends``,
``IVY_BACKENDS``), is skipped; the others run as written, with numpy and the named frameworks'
modules in their globals (``np``, ``torch``, ``jax``, ``jnp``, ``tf``), ``ivy`` and ``math``,
and what the caller adds. Examples run in a temporary directory (some save files), and those that
name jax run with its 64-bit types off, as users get it by default.

Examples that change the process for good (registering a backend) are listed in ``ISOLATED``
and run in a fresh process, as a user runs them. Examples too slow for the suite's time budget are listed by name (``slow=``) and run only with
``IVY_SLOW_EXAMPLES=1``. Only the modules whose source holds an example (``>>>``) are imported to
collect them, so that a backend package is never imported for nothing. Known failures are listed by
the docstring's name (``xfail={"pkg.module.fn": "why"}``); one that passes shows as XPASS in the
summary, to be removed from the list.
"""

from __future__ import annotations

import contextlib
import copy
import doctest
import importlib
import math
import os
import pathlib
import re

import numpy as np
import pytest

#: a backend, the words that name it in an example, and the globals it gives the examples
FRAMEWORKS = {
    "torch": (re.compile(r"\btorch\b"), {"torch": "torch"}),
    "jax": (re.compile(r"\b(jax|jnp)\b"), {"jax": "jax", "jnp": "jax.numpy"}),
    "tensorflow": (re.compile(r"\b(tf\.|tensorflow\b)"), {"tf": "tensorflow"}),
}

OPTIONFLAGS = doctest.NORMALIZE_WHITESPACE | doctest.ELLIPSIS

#: docstrings whose examples change the process for good, run in a fresh one as a user runs them
ISOLATED = {
    "ivy.framework_handler.register_framework": "registers a backend, which the suite has loaded",
}

_IN_A_FRESH_PROCESS = """
import doctest, importlib, sys
import numpy as np
import ivy
module = importlib.import_module(sys.argv[1])
tests = [t for t in doctest.DocTestFinder().find(module) if t.name == sys.argv[2]]
runner = doctest.DocTestRunner(optionflags=int(sys.argv[3]))
for test in tests:
    test.globs.update(np=np, ivy=ivy)
    runner.run(test)
sys.exit(1 if runner.failures or not tests else 0)
"""


def example_modules(package: str) -> list[str]:
    """The modules of ``package`` (itself included) whose source holds a docstring example, by
    reading the files: no module is imported here."""
    root = pathlib.Path(importlib.util.find_spec(package).origin).parent
    names = []
    for path in sorted(root.rglob("*.py")):
        if ">>>" not in path.read_text(encoding="utf-8"):
            continue
        parts = path.relative_to(root.parent).with_suffix("").parts
        names.append(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
    return names


def collect(modules) -> list[doctest.DocTest]:
    """Every docstring with examples in ``modules`` (names), in order, each once."""
    finder = doctest.DocTestFinder(exclude_empty=True)
    found: dict[str, doctest.DocTest] = {}
    for name in modules:
        for test in finder.find(importlib.import_module(name)):
            if test.examples:
                found.setdefault(test.name, test)
    return list(found.values())


def docstring_examples(
    package_or_modules, xfail: dict[str, str] | None = None, slow: dict[str, str] | None = None
) -> list:
    """``pytest.param`` per docstring with examples, for ``@pytest.mark.parametrize``: of a
    package (by name; every module holding an example) or of the given list of modules.

    ``slow``: docstrings (by name, with what makes them slow) whose examples take longer than the
    suite's budget allows (full-size optimisations); they run only with ``IVY_SLOW_EXAMPLES=1``.
    """
    if isinstance(package_or_modules, str):
        modules = example_modules(package_or_modules)
    else:
        modules = list(package_or_modules)
    xfail, slow = xfail or {}, slow or {}
    run_slow = os.environ.get("IVY_SLOW_EXAMPLES", "0") not in ("", "0")
    params = []
    for test in collect(modules):
        marks = []
        if test.name in xfail:
            marks.append(pytest.mark.xfail(reason=xfail[test.name], strict=False))
        if test.name in slow and not run_slow:
            reason = f"slow: {slow[test.name]} (IVY_SLOW_EXAMPLES=1 runs it)"
            marks.append(pytest.mark.skip(reason=reason))
        params.append(pytest.param(test, id=test.name, marks=marks))
    return params


def named_frameworks(test: doctest.DocTest) -> set[str]:
    """The backends the examples of ``test`` name (numpy is always there)."""
    source = "\n".join(example.source for example in test.examples)
    return {name for name, (words, _) in FRAMEWORKS.items() if words.search(source)}


def _as_users_run(test):
    """jax as users get it by default, 64-bit types off (what the examples' outputs show), even
    where the test run turns them on; unless the examples turn them on or ask for float64."""
    source = "\n".join(example.source for example in test.examples)
    if "jax" not in named_frameworks(test) or re.search(r"enable_float64|x64|float64", source):
        return contextlib.nullcontext()
    import jax

    return jax.enable_x64(False)


def run_example(test, globs: dict, config, tmp_path, monkeypatch) -> doctest.TestResults:
    """Run one docstring's examples; skip if they name a backend this run does not have."""
    selected = set(getattr(config, "ivy_backends", ()))
    missing = named_frameworks(test) - selected
    if missing:
        pytest.skip(f"{test.name}'s examples use {sorted(missing)}, not installed or not selected")
    extra = {"np": np, "math": math, "ivy": importlib.import_module("ivy")}
    for name in named_frameworks(test):
        for alias, module in FRAMEWORKS[name][1].items():
            extra[alias] = importlib.import_module(module)
    if test.name in ISOLATED:
        import subprocess
        import sys

        args = [test.globs["__name__"], test.name, str(OPTIONFLAGS)]
        run = subprocess.run(
            [sys.executable, "-c", _IN_A_FRESH_PROCESS, *args],
            capture_output=True,
            text=True,
            timeout=300,
        )
        assert run.returncode == 0, run.stdout + run.stderr
        return None
    test = copy.copy(test)
    test.globs = {**test.globs, **extra, **globs}
    monkeypatch.chdir(tmp_path)
    report: list[str] = []
    runner = doctest.DocTestRunner(verbose=False, optionflags=OPTIONFLAGS)
    with _as_users_run(test):
        result = runner.run(test, out=report.append, clear_globs=True)
    assert result.failed == 0, "".join(report)
    return result
