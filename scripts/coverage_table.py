"""Generate ``docs/coverage.md``: which public function of ``ivy.core`` is exercised, on which
backend, by a passing test.

How it is measured (nothing is guessed from names):

1. The tests run under pytest with a recorder plugin. Before any test runs, the recorder replaces
   every public function of every backend namespace (``ivy.torch.svd``, the compositions bound
   there, and the functions behind the ``linalg``/``fft`` sub-namespaces) by a wrapper that notes
   ``(function, backend)`` when called. The framework-agnostic dispatchers look their backend
   function up in the namespace at call time, so ``ivy.svd(x)`` is seen as well as
   ``ivy.torch.svd(x)``. A framework-agnostic composition (``ivy.zero_pad(x)``) is wrapped too: it
   is counted on the backends whose functions it calls, itself or through the function it
   returns (``ivy.grad(loss)(xs)``).
2. The calls made while a test runs are kept only when the test passes (a call that raises, in
   a passing test, checked an error path and counts). A call that raises
   ``ivy.UnsupportedError`` is recorded as a tested refusal; a cell is ✓ as soon as one call
   succeeded. Tests that fail under the recorder are listed in the output.
3. Every public function of ``ivy.core`` (``ivy.core.__all__``, by group) gets one row and every
   backend one column. A cell with no passing call is a gap and must have a reason in
   :data:`KNOWN_GAPS`; ``--check`` fails when one has none.

The test files run in ``--jobs`` parallel pytest processes, each recording into a JSON file.

Usage:
    python scripts/coverage_table.py                    # tests/ivy -> docs/coverage.md
    python scripts/coverage_table.py --check            # also fail on unexplained gaps
    python scripts/coverage_table.py tests/ivy/test_fft.py --output /tmp/fft.md
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # this checkout's ivy, not another one installed
BACKENDS = ("numpy", "torch", "jax", "tensorflow")

# (function, backend) -> why no test exercises it there; backend "*" means every backend.
KNOWN_GAPS: dict[tuple[str, str], str] = {}


# ----------------------------------------------------------------------------------------------
# The recorder (runs inside each pytest process)
# ----------------------------------------------------------------------------------------------


class Recorder:
    """pytest plugin: wrap the backend namespaces' functions and keep the calls of passing
    tests."""

    # Tests that count what a compiler captures (graphs, breaks) see the wrappers, not ivy alone.
    wraps_backend_functions = True

    def __init__(self):
        # name -> backend -> [number of passing tests, the first of them]
        self.exercised: dict[str, dict[str, list]] = defaultdict(dict)
        self.unsupported: dict[str, dict[str, str]] = defaultdict(dict)
        self.calls: set[tuple[str, str]] | None = None  # the running test's (name, backend)
        self.refusals: dict[tuple[str, str], str] = {}
        self.active: list[str] = []  # agnostic compositions being run
        self.outcomes = {"passed": 0, "failed": 0, "skipped": 0}
        self.failures: list[str] = []  # tests that failed under the recorder

    # -- wrapping ------------------------------------------------------------------------------

    def _recording(self, fn, names: list[str], backend: str):
        import functools

        from ivy.errors import UnsupportedError

        recorder = self
        torch = sys.modules.get("torch")
        # torch.compile traces Python: recording there would make it guard on the recorder's
        # state and compile again (a test that counts compilations would fail here only)
        tracing = torch.compiler.is_compiling if torch is not None else (lambda: False)

        @functools.wraps(fn)
        def wrapper(*args, **kwargs):
            if tracing():
                return fn(*args, **kwargs)
            calls = recorder.calls
            seen = names + recorder.active  # this function, and the compositions running it
            try:
                out = fn(*args, **kwargs)
            except UnsupportedError as e:
                if calls is not None:
                    for name in seen:
                        recorder.refusals.setdefault((name, backend), str(e).splitlines()[0])
                raise
            except Exception:
                if calls is not None:  # an error path a test may check: exercised too
                    calls.update((name, backend) for name in seen)
                raise
            if calls is not None:
                calls.update((name, backend) for name in seen)
            return out

        return wrapper

    def _composition(self, fn, name=None):
        """``fn`` recording as itself the backend calls made while it runs, and while the
        function it returns runs (``grad(f)`` returns the function that calls the backend)."""
        import functools

        recorder = self
        name = name or fn.__name__

        @functools.wraps(fn)
        def wrapper(*args, **kwargs):
            recorder.active.append(name)
            try:
                out = fn(*args, **kwargs)
            finally:
                recorder.active.pop()
            given = (*args, *kwargs.values())
            if callable(out) and not hasattr(out, "shape") and all(out is not a for a in given):
                return recorder._composition(out, name)  # a new function (not one passed in)
            return out

        return wrapper

    def install(self, backends):
        import ivy
        from ivy.core._extensions import ExtensionNamespace
        from ivy.dtypes import DTYPE_NAMES

        for backend in backends:
            ns = getattr(ivy, backend)
            # the namespace, and the views of it that the dispatchers call (the natives in place
            # of shims, the shims for Python scalars): copies of its names, wrapped alike
            views = {id(v): v for v in (ns, ns.__ivy_fast__, ns.__ivy_scalars__)}
            for view in views.values():
                by_object: dict[int, list[str]] = defaultdict(list)
                for name in ns.__all__:
                    if name in DTYPE_NAMES:  # (jax without x64 has no 64-bit dtypes: no entry)
                        continue
                    value = view.__dict__.get(name)
                    if callable(value) and not isinstance(value, ExtensionNamespace):
                        by_object[id(value)].append(name)
                for names in by_object.values():
                    wrapper = self._recording(view.__dict__[names[0]], names, backend)
                    for name in names:
                        view.__dict__[name] = wrapper
            for value in list(vars(ns).values()):
                if isinstance(value, ExtensionNamespace):
                    own = value.__name__.rpartition(".")[2]
                    for name in value.__all__:  # forget what was resolved before the wrapping
                        value.__dict__.pop(name, None)
                    if value._call is not None:
                        value._call = self._recording(value._call, [own], backend)
        for info in ivy.list_functions(kind="composition"):
            name, comp = info.name, getattr(ivy.core, info.name)
            if getattr(ivy, name, None) is comp and getattr(ivy.core, name, None) is comp:
                wrapped = self._composition(comp)
                setattr(ivy, name, wrapped)
                setattr(ivy.core, name, wrapped)

    # -- pytest hooks --------------------------------------------------------------------------

    def pytest_collection_finish(self, session):
        self.install(session.config.ivy_backends)

    def pytest_runtest_setup(self, item):
        self.calls, self.refusals = set(), {}

    def pytest_runtest_logreport(self, report):
        if report.when == "call" or (report.when == "setup" and not report.passed):
            key = "passed" if report.passed else "skipped" if report.skipped else "failed"
            self.outcomes[key] += 1
            if key == "failed":
                self.failures.append(report.nodeid)
        if report.when != "call":
            return
        if report.passed:
            for name, backend in self.calls or ():
                entry = self.exercised[name].setdefault(backend, [0, report.nodeid])
                entry[0] += 1
            for (name, backend), message in self.refusals.items():
                self.unsupported[name][backend] = message
        self.calls = None

    def dump(self, path):
        data = {"exercised": self.exercised, "unsupported": self.unsupported}
        data["outcomes"], data["failures"] = self.outcomes, self.failures
        Path(path).write_text(json.dumps(data))


def run_shard(output: str, pytest_args: list[str]) -> int:
    import pytest

    recorder = Recorder()
    code = pytest.main(["-q", "-p", "no:cacheprovider", *pytest_args], plugins=[recorder])
    recorder.dump(output)
    return int(code)


# ----------------------------------------------------------------------------------------------
# The table
# ----------------------------------------------------------------------------------------------


def _merge(paths):
    exercised = defaultdict(dict)
    unsupported = defaultdict(dict)
    outcomes = defaultdict(int)
    outcomes["failures"] = []
    for path in paths:
        data = json.loads(Path(path).read_text())
        for name, per_backend in data["exercised"].items():
            for backend, (count, test) in per_backend.items():
                entry = exercised[name].setdefault(backend, [0, test])
                entry[0] += count
        for name, per_backend in data["unsupported"].items():
            unsupported[name].update(per_backend)
        for key, n in data["outcomes"].items():
            outcomes[key] += n
        outcomes["failures"] += data["failures"]
    return exercised, unsupported, outcomes


def _kind(name):
    import ivy

    info = ivy.function_info(name)
    if info.kind == "alias":
        return f"alias of `{info.target}`"
    return "composition" if info.kind == "composition" else "backend"


def render(exercised, unsupported, outcomes, backends, test_paths, seconds) -> tuple[str, list]:
    from ivy import core

    gaps, unexplained = [], []
    lines = [
        "# Test coverage of the core API by backend",
        "",
        "Generated by `scripts/coverage_table.py` from a run of "
        f"`pytest {' '.join(test_paths)}` ({outcomes['passed']} passed, {outcomes['failed']} "
        f"failed, {outcomes['skipped']} skipped, {seconds:.0f} s). Do not edit by hand.",
        "",
        "A cell is ✓ when a **passing** test called the function on that backend: every public",
        "function of each backend namespace is wrapped by a recorder while the tests run, so",
        "both `ivy.fn(x)` (which dispatches to the backend namespace) and `ivy.<backend>.fn(x)`",
        "count, and a framework-agnostic composition counts on the backends whose functions it",
        "calls. `refuses` means a passing test checked that the backend raises",
        "`ivy.UnsupportedError`. Any other gap is ✗ with its reason below.",
        "",
    ]
    header = "| function | kind | " + " | ".join(backends) + " |"
    rule = "|---|---|" + "---|" * len(backends)
    totals = dict.fromkeys(backends, 0)
    count = 0
    for group_name, group in zip(core.GROUP_NAMES, core.GROUPS):
        lines += [f"## {group_name}", "", header, rule]
        for name in group.__all__:
            count += 1
            cells = []
            for backend in backends:
                if backend in exercised.get(name, {}):
                    cells.append("✓")
                    totals[backend] += 1
                    continue
                message = unsupported.get(name, {}).get(backend)
                if message:
                    cells.append("refuses")
                    gaps.append((name, backend, f"raises UnsupportedError (tested): {message}"))
                    continue
                reason = KNOWN_GAPS.get((name, backend)) or KNOWN_GAPS.get((name, "*"))
                if reason is None:
                    reason = "no test exercises it (unexplained)"
                    unexplained.append((name, backend))
                gaps.append((name, backend, reason))
                cells.append("✗")
            lines.append(f"| `{name}` | {_kind(name)} | " + " | ".join(cells) + " |")
        lines.append("")
    lines += ["## Summary", "", "| backend | tested functions |", "|---|---|"]
    lines += [f"| {b} | {totals[b]} / {count} |" for b in backends]
    if outcomes["failures"]:
        lines += ["", "Tests that failed under the recorder (their calls are not counted):", ""]
        lines += [f"- `{nodeid}`" for nodeid in outcomes["failures"]]
    lines += ["", "## Gaps and their reasons", ""]
    if gaps:
        lines += ["| function | backend | reason |", "|---|---|---|"]
        lines += [f"| `{n}` | {b} | {r} |" for n, b, r in gaps]
    else:
        lines.append("None: every function is tested on every backend.")
    return "\n".join(lines) + "\n", unexplained


def _test_files(paths):
    files = []
    for p in paths:
        path = ROOT / p
        if path.is_dir():
            files += sorted(str(f.relative_to(ROOT)) for f in path.rglob("test_*.py"))
        else:
            files.append(p)
    return files


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("paths", nargs="*", default=["tests/ivy"], help="test files or folders")
    parser.add_argument("--output", default="docs/coverage.md")
    parser.add_argument("--jobs", type=int, default=2, help="parallel pytest processes")
    parser.add_argument("--backends", default=None, help="comma-separated, default: installed")
    parser.add_argument("--check", action="store_true", help="fail on gaps with no reason")
    parser.add_argument("--shard", help=argparse.SUPPRESS)  # internal: record one pytest run
    args, rest = parser.parse_known_args(argv)
    if args.shard:
        chosen = ["--backends", args.backends] if args.backends else []
        return run_shard(args.shard, args.paths + chosen + rest)

    import importlib.util

    backends = [b.strip() for b in args.backends.split(",")] if args.backends else list(BACKENDS)
    backends = [b for b in backends if importlib.util.find_spec(b) is not None]
    files = _test_files(args.paths)
    start = time.time()
    with tempfile.TemporaryDirectory() as tmp:
        pending = list(enumerate(files))
        running, outputs = [], []
        while pending or running:
            while pending and len(running) < args.jobs:
                i, test_file = pending.pop(0)
                out = os.path.join(tmp, f"shard{i}.json")
                cmd = [sys.executable, __file__, "--shard", out, test_file]
                cmd += ["--backends", ",".join(backends), *rest]
                log = open(os.path.join(tmp, f"shard{i}.log"), "w")  # noqa: SIM115
                running.append(
                    (subprocess.Popen(cmd, cwd=ROOT, stdout=log, stderr=log), out, log, test_file)
                )
            time.sleep(0.2)
            for entry in list(running):
                proc, out, log, test_file = entry
                if proc.poll() is None:
                    continue
                running.remove(entry)
                log.close()
                if os.path.exists(out):
                    outputs.append(out)
                    print(f"{test_file}: exit {proc.returncode}", file=sys.stderr)
                else:
                    print(
                        f"{test_file}: recorded nothing (exit {proc.returncode})", file=sys.stderr
                    )
        exercised, unsupported, outcomes = _merge(outputs)
    text, unexplained = render(
        exercised, unsupported, outcomes, backends, args.paths, time.time() - start
    )
    output = ROOT / args.output
    output.parent.mkdir(parents=True, exist_ok=True)
    output.write_text(text)
    print(f"wrote {output}: {len(unexplained)} unexplained gaps", file=sys.stderr)
    for name, backend in unexplained:
        print(f"  unexplained gap: {name} on {backend}", file=sys.stderr)
    return 1 if args.check and unexplained else 0


if __name__ == "__main__":
    sys.exit(main())
