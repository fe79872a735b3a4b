"""The documentation site builds with the documented command, without a warning (a broken
reference, a page in no table of contents, a docstring that does not parse), and every public
name of the six packages has an entry in its API reference."""

from __future__ import annotations

import importlib
import inspect
import pathlib
import subprocess
import sys
import zlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
PACKAGES = ("ivy", "ivy_mechanics", "ivy_vision", "ivy_robot", "ivy_gym", "ivy_rl")

pytest.importorskip("sphinx", reason="the site needs the docs extra: pip install -e '.[docs]'")
pytest.importorskip("furo", reason="the site needs the docs extra: pip install -e '.[docs]'")
pytest.importorskip("myst_nb", reason="the site needs the docs extra: pip install -e '.[docs]'")


def public_names() -> set[str]:
    """Every public name, as the reference documents it: each package's ``__all__``; a module
    listed there (``ivy_rl.agents``) with its own ``__all__``, under the package where the
    package exports the name itself; and the public submodules the packages document as their
    own namespaces (``ivy.nest``, ``ivy.typing``, ``ivy_robot.physics``; ``ivy.stateful``'s
    names are exported by ``ivy``)."""
    names = set()
    for package in PACKAGES:
        module = importlib.import_module(package)
        for name in module.__all__:
            obj = getattr(module, name)
            names.add(f"{package}.{name}")
            if inspect.ismodule(obj):
                for sub in set(obj.__all__) - {name}:  # ivy.fft.fft: ivy.fft itself
                    flat = getattr(module, sub, None) is getattr(obj, sub)
                    names.add(f"{package}.{sub}" if flat else f"{package}.{name}.{sub}")
    for namespace, owner in (
        ("ivy.stateful", "ivy"),
        ("ivy.nest", "ivy.nest"),
        ("ivy.typing", "ivy.typing"),
        ("ivy_robot.physics", "ivy_robot.physics"),
    ):
        names |= {f"{owner}.{n}" for n in importlib.import_module(namespace).__all__}
    return names


def inventory(path: pathlib.Path) -> set[str]:
    """The Python objects of a Sphinx inventory (``objects.inv``, format 2)."""
    data = path.read_bytes()
    for _ in range(4):  # the header: four lines of text, then zlib
        data = data[data.index(b"\n") + 1 :]
    names = set()
    for line in zlib.decompress(data).decode().splitlines():
        name, role = line.split(" ", 2)[:2]
        if role.startswith("py:"):
            names.add(name)
    return names


def build_site(out: pathlib.Path) -> subprocess.CompletedProcess:
    """The README's command, into ``out``."""
    command = [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-c", "docs/site"]
    return subprocess.run(
        [*command, "-d", str(out / ".doctrees"), ".", str(out)],
        cwd=ROOT,
        capture_output=True,
        text=True,
    )


def test_the_site_builds_and_documents_every_public_name(tmp_path):
    """One test (one build, whichever worker runs it): no warning, the pages, the notebooks
    with their stored outputs, the figures, and a reference entry for every public name."""
    build = build_site(tmp_path)
    assert build.returncode == 0, f"the site's build warned or failed:\n{build.stderr[-6000:]}"
    for page in ("index.html", "docs/site/index.html", "docs/site/getting_started.html"):
        assert (tmp_path / page).is_file(), page
    for notebook in sorted((ROOT / "notebooks").glob("*.ipynb")):
        html = (tmp_path / "notebooks" / f"{notebook.stem}.html").read_text()
        assert "cell_output" in html, f"{notebook.name}: rendered without its stored outputs"
    assert any((tmp_path / "_images").glob("profile_overhead*.png")), "the overhead figure"
    missing = sorted(public_names() - inventory(tmp_path / "objects.inv"))
    assert not missing, f"public names without a reference entry: {missing}"
