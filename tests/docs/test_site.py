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


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    out = tmp_path_factory.mktemp("site")
    command = [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-q", "-c", "docs/site"]
    build = subprocess.run(
        [*command, "-d", str(out / ".doctrees"), ".", str(out)],
        cwd=ROOT,
        capture_output=True,
        text=True,
    )
    assert build.returncode == 0, f"the site's build warned or failed:\n{build.stderr[-6000:]}"
    return out


def test_the_site_builds_without_warnings(site):
    for page in ("index.html", "docs/site/index.html", "docs/site/getting_started.html"):
        assert (site / page).is_file(), page
    notebooks = sorted(p.stem for p in (ROOT / "notebooks").glob("*.ipynb"))
    for name in notebooks:
        html = (site / "notebooks" / f"{name}.html").read_text()
        assert "output" in html, f"{name}: rendered without its stored outputs"
    assert (site / "_images").is_dir() and any((site / "_images").glob("profile_overhead*.png"))


def test_every_public_name_has_a_reference_entry(site):
    documented = inventory(site / "objects.inv")
    missing = sorted(public_names() - documented)
    assert not missing, f"public names without a reference entry: {missing}"
