"""ivy_rl's tests compare agents across torch, jax and tensorflow by name (the same update on
each, a checkpoint written on one and continued on another). A test that is not parametrised
over the ``backend`` fixtures needs all three; where one is not installed or not selected
(``IVY_BACKENDS``), it is skipped with the reason, never failed."""

from __future__ import annotations

import pytest

FRAMEWORKS = ("torch", "jax", "tensorflow")
PARAMETRISED = {"backend", "diff_backend", "graph_backend", "mutable_backend"}


def quick(backend: str) -> list[str]:
    """The command line's flag for the quickest tiny run on ``backend``: eager, except on jax,
    whose eager operations each compile once (a tiny run's one ``jax.jit`` is quicker)."""
    return [] if backend == "jax" else ["--eager"]


def pytest_collection_modifyitems(config, items):
    missing = [f for f in FRAMEWORKS if f not in config.ivy_backends]
    if not missing:
        return
    skip = pytest.mark.skip(
        reason=f"compares torch, jax and tensorflow; {', '.join(missing)} not installed or selected"
    )
    for item in items:
        if item.path.parent.name == "ivy_rl" and not PARAMETRISED & set(item.fixturenames):
            item.add_marker(skip)
