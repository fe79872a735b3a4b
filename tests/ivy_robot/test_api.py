"""The public API: listed once in ``__all__``; ``f`` keyword-only with default None on every
public function and method that has it, and present on every public function; docstrings with
Args/Returns/Example, and examples that run; no framework imported by ``import ivy_robot``; the
kernels call primitives on the resolved namespace, never ``ivy.<fn>``; no other package's
private module imported."""

from __future__ import annotations

import functools
import importlib
import importlib.util
import inspect
import pathlib
import pkgutil
import re
import subprocess
import sys

import numpy as np
import pytest

import ivy_robot
from ivy_robot import physics
from tests._doctests import docstring_examples, run_example

PACKAGE = pathlib.Path(ivy_robot.__file__).parent
MODULES = ["ivy_robot"] + sorted(
    m.name for m in pkgutil.walk_packages(ivy_robot.__path__, "ivy_robot.") if not m.ispkg
)
#: ivy_robot.physics: MuJoCo's pipeline as kernels of the backend namespace (xp first), its own
#: public API (``ivy_robot.physics.__all__``)
PHYSICS = [m for m in MODULES if m.startswith("ivy_robot.physics.")]
PHYSICS_FUNCTIONS = [
    getattr(physics, n) for n in physics.__all__ if inspect.isfunction(getattr(physics, n))
]
#: physics functions that build or describe a model (no arrays, no xp)
PHYSICS_BUILDERS = {"read_model", "read_contact_table", "gather", "row_kinds"}
CLASSES = [
    getattr(ivy_robot, n) for n in ivy_robot.__all__ if inspect.isclass(getattr(ivy_robot, n))
]
FUNCTIONS = [
    getattr(ivy_robot, n) for n in ivy_robot.__all__ if inspect.isfunction(getattr(ivy_robot, n))
]
METHODS = [
    (cls, name, member)
    for cls in CLASSES
    for name, member in vars(cls).items()
    if inspect.isfunction(member) and not name.startswith("_")
]
#: public functions and methods that take no array (they describe or build models)
NO_ARRAYS = {
    "load_mjcf", "mujoco_quaternion_to_rot_mat", "panda_mjcf", "from_mjcf", "body_id", "site_id",
    "collision_spheres", "num_link_samples", "step_fn",
}  # fmt: skip


def test_all_is_complete():
    assert len(ivy_robot.__all__) == len(set(ivy_robot.__all__))
    for name in ivy_robot.__all__:
        assert hasattr(ivy_robot, name), name
    public = {
        name
        for module in MODULES[1:]
        if module not in PHYSICS
        for name in getattr(importlib.import_module(module), "__all__", [])
    }
    assert public == set(ivy_robot.__all__)
    assert len(physics.__all__) == len(set(physics.__all__))
    in_modules = {
        name
        for module in PHYSICS
        for name in getattr(importlib.import_module(module), "__all__", [])
    }
    assert in_modules | {"Gather", "gather"} == set(physics.__all__)


@pytest.mark.parametrize("fn", PHYSICS_FUNCTIONS, ids=lambda f: f.__qualname__)
def test_physics_kernels_take_the_namespace_first(fn):
    params = list(inspect.signature(fn).parameters)
    if fn.__name__ not in PHYSICS_BUILDERS:
        assert params[0] == "xp", f"{fn.__qualname__}: a kernel takes the namespace xp first"
    doc = inspect.getdoc(fn)
    assert doc and "Example:" in doc, f"{fn.__qualname__} has no example"


@pytest.mark.parametrize("fn", FUNCTIONS + [m for _, _, m in METHODS], ids=lambda f: f.__qualname__)
def test_signature_and_docstring(fn):
    params = inspect.signature(fn).parameters
    if fn.__name__ not in NO_ARRAYS:
        assert "f" in params, f"{fn.__qualname__} takes arrays but no f="
    if "f" in params:
        assert params["f"].kind is inspect.Parameter.KEYWORD_ONLY, f"{fn.__qualname__}: f"
        assert params["f"].default is None
    doc = inspect.getdoc(fn)
    assert doc, f"{fn.__qualname__} has no docstring"
    sections = ("Args:", "Returns:", "Example:") if len(params) > 1 else ("Example:",)
    for section in sections:
        assert section in doc, f"{fn.__qualname__} docstring lacks {section}"


@pytest.mark.parametrize("example", docstring_examples(MODULES))
def test_docstring_examples(example, request, tmp_path, monkeypatch):
    module = example.globs["__name__"]
    run_example(example, _globals(module), request.config, tmp_path, monkeypatch)


def test_every_public_module_has_examples():
    with_examples = {example.values[0].globs["__name__"] for example in docstring_examples(MODULES)}
    public = {m for m in MODULES[1:] if not m.split(".")[-1].startswith("_")}
    assert public <= with_examples, f"modules without a runnable example: {public - with_examples}"


@functools.cache
def _shared_globals(module: str) -> dict:
    """What the examples of one module share (as when the module's examples ran together): the
    Panda's tree, a drone planner, MuJoCo's Hopper for the physics modules."""
    import ivy_mechanics as mech

    globs = {
        "mech": mech,
        **{n: getattr(ivy_robot, n) for n in ivy_robot.__all__},
        "tree": ivy_robot.KinematicTree.from_mjcf(ivy_robot.panda_mjcf()),
        # the drone of DronePlanner's example, for the examples of the planners' methods
        "planner": ivy_robot.DronePlanner(
            ivy_robot.RigidMobile([[0.0, 0.0, 0.0]]),
            ivy_robot.SceneSDF(["ball"], ["sphere"], [[0.3, 0, 0]], [np.eye(4)]),
            body_radius=0.1,
        ),
        "start": np.array([-1.0, 0.05, 0, 0, 0, 0]),
        "goal": np.array([1.0, 0, 0, 0, 0, 0]),
    }
    if module in PHYSICS or module == "ivy_robot.physics":
        globs.update(_physics_globals())
    return globs


def _globals(module: str) -> dict:
    return dict(_shared_globals(module))


def _physics_globals() -> dict:
    """The Hopper (and the Swimmer) of Gymnasium for the physics modules' examples: ``model``,
    ``data`` (its forward dynamics at rest), ``xp``, the paths, MuJoCo and the public names."""
    import os

    import gymnasium
    import mujoco

    import ivy

    assets = os.path.join(os.path.dirname(gymnasium.__file__), "envs", "mujoco", "assets")
    hopper_xml = os.path.join(assets, "hopper.xml")
    model = physics.read_model(mujoco.MjModel.from_xml_path(hopper_xml))
    xp = ivy.numpy
    data = physics.forward(xp, model, physics.make_data(xp, model, model.qpos0, np.zeros(6)))
    return {
        **{n: getattr(physics, n) for n in physics.__all__},
        "mujoco": mujoco,
        "hopper_xml": hopper_xml,
        "swimmer_xml": os.path.join(assets, "swimmer.xml"),
        "model": model,
        "data": data,
        "xp": xp,
    }


def test_import_loads_no_framework():
    code = (
        "import sys, ivy_robot; "
        "print(sorted(m for m in ('torch', 'jax', 'tensorflow', 'mujoco') if m in sys.modules))"
    )
    root = str(PACKAGE.parent)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=root)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "[]"


def test_kernels_use_the_namespace():
    """Primitives are called on the resolved namespace ``xp``; ``ivy.`` appears only to resolve
    it and for the functional gradient, compilation, optimizer and conversion entry points."""
    allowed = {"get_framework", "execute_with_gradients", "compile_fn", "Adam", "to_numpy"}
    for path in PACKAGE.rglob("*.py"):
        source = path.read_text()
        uses = set(re.findall(r"\bivy\.(\w+)\(", source))
        assert uses <= allowed, f"{path.name} calls ivy.{sorted(uses - allowed)}"
        assert not re.search(r"from ivy_mechanics\._|import ivy_mechanics\._|ivy\.core\._", source)
        assert "framework ==" not in source and "backend ==" not in source
