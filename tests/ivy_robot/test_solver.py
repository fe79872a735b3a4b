"""The constraint solver (``ivy_robot.physics.solver``) against MuJoCo's ``mj_fwdConstraint``.

Problems come from MuJoCo itself (``mj_forward`` at states with contacts and active joint limits:
robots lowered into the floor, joints pushed past their ranges, random velocities and controls),
several states batched in one problem whose rows sit in a padded layout, inactive rows with
garbage values interleaved. Newton on Gymnasium's hopper, walker2d, half_cheetah and ant; PGS on
the humanoid (MuJoCo's iterates are matched, not just its fixed point); a scene with friction
loss, an equality and limits under both solvers; warm starts from previous steps and cold
starts; gradients against central differences; compiled equals eager; float32. (torch.compile
of the solver, inside a step's RK4 scan: ``test_dynamics.py::test_first_use_inside_torch_compile``.)
"""

from __future__ import annotations

import os

import numpy as np
import pytest

import ivy
from ivy_robot.physics import solver as S
from tests.helpers import check_gradients, native, numpy_of
from tests.ivy_robot._models import gymnasium_models

mujoco = pytest.importorskip("mujoco")

GYMNASIUM = {os.path.basename(p)[:-4]: p for p in gymnasium_models()}
NEWTON_MODELS = ("hopper", "walker2d_v5", "half_cheetah", "ant")
TOL = 1e-10  # relative to the largest magnitude of the compared quantity
DECREMENT_STOPS = {"walker2d_v5": (510,), "ant": (796,)}  # steps of _trajectory

# Two arms (hinges and a slide with friction loss and limits, a joint equality coupling two
# hinges), a free box and a ball-jointed pendulum on a floor.
SCENE = """
<mujoco model="solver_scene">
  <option timestep="0.005"/>
  <worldbody>
    <geom type="plane" size="5 5 .1"/>
    <body name="arm" pos="0 0 .25">
      <joint name="h1" type="hinge" axis="0 1 0" frictionloss=".5" range="-20 20"/>
      <geom type="capsule" fromto="0 0 0 .3 0 0" size=".05"/>
      <body name="fore" pos=".3 0 0">
        <joint name="h2" type="hinge" axis="0 1 0" frictionloss=".3"/>
        <joint name="s2" type="slide" axis="1 0 0" frictionloss="1" range="-.05 .05"/>
        <geom type="capsule" fromto="0 0 0 .3 0 0" size=".05"/>
        <body name="hand" pos=".3 0 0">
          <joint name="h3" type="hinge" axis="0 0 1" range="-10 10" frictionloss=".2"/>
          <geom type="sphere" size=".06"/>
        </body>
      </body>
    </body>
    <body name="box" pos=".6 .6 .09">
      <freejoint/>
      <geom type="box" size=".1 .1 .1"/>
    </body>
    <body name="pendulum" pos="-.5 0 .5">
      <joint name="ball" type="ball" frictionloss=".1"/>
      <geom type="capsule" fromto="0 0 0 0 0 -.45" size=".03"/>
    </body>
  </worldbody>
  <equality>
    <joint joint1="h1" joint2="h3" polycoef="0 .5 0 0 0"/>
  </equality>
</mujoco>
"""


# ----------------------------------------------------------------------------------------------
# Problems from MuJoCo
# ----------------------------------------------------------------------------------------------


def _model(xml_or_path, solver=None, disable=()):
    if xml_or_path.lstrip().startswith("<"):
        model = mujoco.MjModel.from_xml_string(xml_or_path)
    else:
        model = mujoco.MjModel.from_xml_path(xml_or_path)
    model.opt.jacobian = mujoco.mjtJacobian.mjJAC_DENSE
    if solver is not None:
        model.opt.solver = solver
    for bit in disable:
        model.opt.disableflags |= int(getattr(mujoco.mjtDisableBit, bit))
    return model


def _constrained_state(model, data, rng):
    """Joints pushed past their ranges, roots lowered into the floor, random velocities,
    controls and warm starts."""
    mujoco.mj_resetData(model, data)
    q = model.qpos0.copy()
    for j in range(model.njnt):
        adr, kind = model.jnt_qposadr[j], model.jnt_type[j]
        if kind == 0:  # free: low above the floor, tilted
            q[adr : adr + 3] = [*rng.normal(size=2) * 0.2, rng.uniform(0.0, 0.4)]
            quat = np.array([1.0, 0, 0, 0]) + rng.normal(size=4) * 0.4
            q[adr + 3 : adr + 7] = quat / np.linalg.norm(quat)
        elif kind in (2, 3) and model.jnt_limited[j]:
            lo, hi = model.jnt_range[j]
            q[adr] = rng.uniform(lo - 0.15 * (hi - lo), hi + 0.15 * (hi - lo))
        elif kind in (2, 3):
            q[adr] += rng.normal() * 0.3
    if model.jnt_type[0] != 0 and model.jnt_type[0] == 2:  # planar walkers: root z lowered
        q[1] -= rng.uniform(0.3, 1.0)
    data.qpos[:] = q
    data.qvel[:] = rng.normal(size=model.nv) * rng.choice([0.3, 2.0])
    data.ctrl[:] = rng.uniform(-1, 1, size=model.nu)
    data.qacc_warmstart[:] = rng.normal(size=model.nv) * rng.choice([0.0, 1.0, 30.0])


def _read(model, data):
    """MuJoCo's constraint problem and solution at ``data`` (after ``mj_forward``)."""
    nv, nefc = model.nv, data.nefc
    M = np.zeros((nv, nv))
    mujoco.mj_fullM(model, data, M)
    return dict(
        M=M,
        qfrc_smooth=data.qfrc_smooth.copy(),
        qacc_smooth=data.qacc_smooth.copy(),
        J=np.array(data.efc_J).reshape(nefc, nv),
        D=data.efc_D.copy(),
        R=data.efc_R.copy(),
        aref=data.efc_aref.copy(),
        frictionloss=data.efc_frictionloss.copy(),
        kinds=S.row_kinds(data.efc_type),
        qacc_warmstart=data.qacc_warmstart.copy(),
        qacc=data.qacc.copy(),
        efc_force=data.efc_force.copy(),
        qfrc_constraint=data.qfrc_constraint.copy(),
        iterations=int(data.solver_niter[0]),
    )


def _oracle(model, count, seed, steps=0, want=None):
    """``count`` problems at constrained states (after ``steps`` of ``mj_step`` from them, so
    that the warm start is the previous step's), with rows of each kind in ``want``."""
    data = mujoco.MjData(model)
    rng = np.random.default_rng(seed)
    found = []
    while len(found) < count:
        _constrained_state(model, data, rng)
        for _ in range(steps):
            mujoco.mj_step(model, data)
        mujoco.mj_forward(model, data)
        problem = _read(model, data)
        if data.nefc and all(k in problem["kinds"] for k in (want or ())):
            found.append(problem)
    return found


def _trajectory(model, at):
    """Problems along a trajectory (random controls, on and off every 100 steps, from the
    lowered initial state), at the steps ``at``: warm starts as a simulation has them."""
    data, rng, found = mujoco.MjData(model), np.random.default_rng(0), []
    mujoco.mj_resetData(model, data)
    data.qpos[1] -= 0.3
    for t in range(max(at) + 1):
        data.ctrl[:] = rng.uniform(-1, 1, size=model.nu) * (t % 200 < 100)
        mujoco.mj_step(model, data)
        if t in at:
            mujoco.mj_forward(model, data)
            found.append(_read(model, data))
    return found


def _padded(problems, rng, spare=2):
    """The problems as one batch in a static row layout: a block of slots per kind (MuJoCo's
    order: equality, friction, one-sided), each problem's rows in order on a random subset of
    its block's slots, the other slots inactive and filled with garbage. Returns the layout's
    kinds, the batched arrays and where each problem's rows went."""
    counts = [max(int(np.sum(p["kinds"] == k)) for p in problems) + spare for k in range(3)]
    kinds = np.concatenate([np.full(c, k) for k, c in enumerate(counts)])
    n, nv, batch = len(kinds), problems[0]["M"].shape[0], len(problems)
    out = dict(
        J=rng.normal(size=(batch, n, nv)),
        D=rng.uniform(1, 1e3, size=(batch, n)),
        R=rng.uniform(0, 1, size=(batch, n)),
        aref=rng.normal(size=(batch, n)) * 5,
        frictionloss=rng.uniform(0, 2, size=(batch, n)),
        active=np.zeros((batch, n), bool),
        slots=[],
    )
    for b, p in enumerate(problems):
        slots = np.zeros(len(p["kinds"]), np.int64)
        for k in range(3):
            mine = np.flatnonzero(p["kinds"] == k)
            slots[mine] = np.sort(rng.choice(np.flatnonzero(kinds == k), len(mine), replace=False))
        for key in ("J", "D", "R", "aref", "frictionloss"):
            out[key][b, slots] = p[key]
        out["active"][b, slots] = True
        out["slots"].append(slots)
    for key in ("M", "qfrc_smooth", "qacc_smooth", "qacc_warmstart"):
        out[key] = np.stack([p[key] for p in problems])
    return kinds, out


def _problem(arrays, backend, dtype=np.float64):
    fields = S.ConstraintProblem._fields
    return S.ConstraintProblem(
        *[
            native(arrays[k] if k == "active" else np.asarray(arrays[k], dtype), backend)
            for k in fields
        ]
    )


def _assert_matches(solution, problems, layout, rtol=TOL):
    """The batched solution equals MuJoCo's for every problem (forces at the problem's slots,
    zero on inactive slots)."""
    qacc, force = numpy_of(solution.qacc), numpy_of(solution.efc_force)
    qfrc = numpy_of(solution.qfrc_constraint)
    for b, p in enumerate(problems):
        slots = layout["slots"][b]
        rest = np.setdiff1d(np.arange(force.shape[-1]), slots)
        assert np.all(force[b, rest] == 0)
        for got, want in ((qacc[b], p["qacc"]), (force[b, slots], p["efc_force"])):
            np.testing.assert_allclose(got, want, rtol=0, atol=rtol * max(1.0, np.abs(want).max()))
        want = p["qfrc_constraint"]
        np.testing.assert_allclose(qfrc[b], want, rtol=0, atol=rtol * max(1.0, np.abs(want).max()))


def _maybe_compiled(backend, fn):
    """``fn`` compiled where the backend compiles loops (jax's and tensorflow's eager loops
    dispatch every operation: slow)."""
    return ivy.compile_fn(fn) if ivy.framework_handler.capabilities(backend).compiled_loops else fn


def _solve(backend, options, problems, seed=0, compiled=None, dtype=np.float64):
    """Solve the problems batched in a padded layout (compiled: see :func:`_maybe_compiled`)."""
    kinds, layout = _padded(problems, np.random.default_rng(seed))
    problem = _problem(layout, backend, dtype)
    warm = native(layout["qacc_warmstart"].astype(dtype), backend)
    xp = getattr(ivy, backend)

    def run(problem, warm):
        return S.solve(xp, problem, kinds, warm, options)

    if compiled is None:
        return _maybe_compiled(backend, run)(problem, warm), layout
    return (ivy.compile_fn(run) if compiled else run)(problem, warm), layout


def _side_by_side(groups):
    """Problems of several models in one batch: each model's dofs in a block of their own
    (the other blocks: unit inertia, no forces, nothing constrains them), each block one tree
    (the constrained dofs' inertia, which scales the stopping tests, is then the model's own).
    Returns the problems and the dofs' trees."""
    sizes = [group[0]["M"].shape[0] for group in groups]
    nv, offsets = sum(sizes), np.cumsum([0, *sizes])
    out = []
    for k, group in enumerate(groups):
        mine = slice(offsets[k], offsets[k + 1])
        for problem in group:
            wide = dict(problem, M=np.eye(nv), J=np.zeros((len(problem["D"]), nv)))
            wide["M"][mine, mine] = problem["M"]
            wide["J"][:, mine] = problem["J"]
            for key in ("qfrc_smooth", "qacc_smooth", "qacc_warmstart", "qacc", "qfrc_constraint"):
                wide[key] = np.zeros(nv)
                wide[key][mine] = problem[key]
            out.append(wide)
    return out, tuple(int(k) for k, size in enumerate(sizes) for _ in range(size))


@pytest.fixture(scope="module")
def oracles():
    """Problems per case, made once for the module."""
    cache = {}

    def get(name):
        if name not in cache:
            cache[name] = _make(name)
        return cache[name]

    return get


def _make(name):
    """``(options, problems)`` of a case."""
    if name == "newton":  # Gymnasium's Newton models and the scene, two states each
        groups = []
        for i, model_name in enumerate(NEWTON_MODELS):
            model = _model(GYMNASIUM[model_name])
            groups.append(_oracle(model, 2, seed=i))
            if model_name in DECREMENT_STOPS:  # MuJoCo stops on its Newton decrement there,
                groups[-1] += _trajectory(model, DECREMENT_STOPS[model_name])  # 5e-6 from the end
        # several trees: MuJoCo's Newton then runs per island, unless disabled
        groups.append(_oracle(_model(SCENE, disable=["mjDSBL_ISLAND"]), 2, seed=1, want=(0, 1, 2)))
        problems, trees = _side_by_side(groups)
        return S.SolverOptions.from_mujoco(model)._replace(dof_tree=trees), problems
    if name in NEWTON_MODELS:
        model = _model(GYMNASIUM[name])
        return S.SolverOptions.from_mujoco(model), _oracle(model, 3, seed=NEWTON_MODELS.index(name))
    if name == "humanoid":  # PGS, warm started by the previous steps, islands as MuJoCo has them
        model = _model(GYMNASIUM["humanoid"])  # (the second state stops at 38 iterations, which a
        problems = _oracle(model, 2, seed=11, steps=2)  # scale by meaninertia * nv misses)
        return S.SolverOptions.from_mujoco(model), problems
    if name == "scene_pgs":  # several trees: MuJoCo's PGS then runs per island unless disabled
        model = _model(SCENE, solver=mujoco.mjtSolver.mjSOL_PGS, disable=["mjDSBL_ISLAND"])
        return S.SolverOptions.from_mujoco(model), _oracle(model, 3, seed=2, want=(0, 1, 2))
    if name == "scene_cold":
        disable = ["mjDSBL_ISLAND", "mjDSBL_WARMSTART"]
        model = _model(SCENE, solver=mujoco.mjtSolver.mjSOL_PGS, disable=disable)
        return S.SolverOptions.from_mujoco(model), _oracle(model, 2, seed=3, want=(1, 2))
    raise KeyError(name)


# ----------------------------------------------------------------------------------------------
# Against MuJoCo
# ----------------------------------------------------------------------------------------------


def test_newton_matches_mujoco(backend, oracles):
    """hopper, walker2d, half_cheetah, ant and the scene (friction loss, an equality, limits),
    two states each, and two states of trajectories where MuJoCo stops before the exact
    minimiser, in one batch (:func:`_side_by_side`); MuJoCo's iterations too."""
    options, problems = oracles("newton")
    kinds = set(np.concatenate([p["kinds"] for p in problems]))
    assert kinds == {S.ROW_EQUALITY, S.ROW_FRICTION, S.ROW_ONE_SIDED}
    solution, layout = _solve(backend, options, problems)
    _assert_matches(solution, problems, layout)
    assert list(numpy_of(solution.iterations)) == [p["iterations"] for p in problems]


def test_pgs_matches_mujoco_iterates_on_the_humanoid(backend, oracles):
    """MuJoCo's PGS stops after 50 iterations, unconverged: the same iterates are required, and
    the same stopping rule (its improvement over the trace of the island's inertia)."""
    options, problems = oracles("humanoid")
    assert options.solver == "pgs"
    assert max(p["iterations"] for p in problems) == options.iterations  # not converged
    solution, layout = _solve(backend, options, problems)
    _assert_matches(solution, problems, layout)
    assert list(numpy_of(solution.iterations)) == [p["iterations"] for p in problems]


def test_pgs_friction_loss_equality_and_limits(backend, oracles):
    options, problems = oracles("scene_pgs")
    solution, layout = _solve(backend, options, problems)
    _assert_matches(solution, problems, layout)


def test_warm_start_choice_and_cold_start(oracles):
    """Newton starts from the cheaper of the warm start and qacc_smooth (the result is the
    minimiser either way; the iterations are MuJoCo's); cold starts (MuJoCo's
    mjDSBL_WARMSTART, or no warm start given) for both solvers."""
    options, problems = oracles("hopper")
    solution, layout = _solve("numpy", options, problems)
    assert list(numpy_of(solution.iterations)) == [p["iterations"] for p in problems]
    cold = options._replace(warmstart=False)
    _assert_matches(_solve("numpy", cold, problems)[0], problems, layout)
    options, problems = oracles("scene_cold")
    assert not options.warmstart
    solution, layout = _solve("numpy", options, problems)
    _assert_matches(solution, problems, layout)


def test_float32_batch_shapes_and_rows_that_exist_nowhere(backend, oracles):
    """float32; a leading batch shape [2, 1] and an unbatched inertia; an element without active
    rows gets qacc_smooth and zero forces."""
    options, problems = oracles("hopper")
    nv = problems[0]["M"].shape[0]
    kinds, layout = _padded(problems[:2], np.random.default_rng(3))
    layout["active"][1] = False
    layout["M"] = layout["M"][0]
    layout["qacc_smooth"][1] = np.linalg.solve(layout["M"], layout["qfrc_smooth"][1])
    arrays = {k: v[:, None] if k not in ("M", "slots") else v for k, v in layout.items()}
    problem = _problem(arrays, backend, np.float32)
    xp = getattr(ivy, backend)
    solution = _maybe_compiled(backend, lambda p: S.solve(xp, p, kinds, None, options))(problem)
    assert numpy_of(solution.qacc).dtype == np.float32
    assert tuple(solution.qacc.shape) == (2, 1, nv)
    assert tuple(solution.iterations.shape) == (2, 1)
    squeezed = S.ConstraintSolution(*[a[:, 0] for a in solution])
    _assert_matches(S.ConstraintSolution(*[a[:1] for a in squeezed]), problems[:1], layout, 1e-4)
    qacc_smooth = layout["qacc_smooth"][1].astype(np.float32)
    np.testing.assert_allclose(numpy_of(solution.qacc)[1, 0], qacc_smooth, rtol=1e-6)
    assert np.all(numpy_of(solution.efc_force)[1] == 0)


# ----------------------------------------------------------------------------------------------
# Gradients and compilation
# ----------------------------------------------------------------------------------------------


def _gradient_case(diff_backend, problems, options, inputs):
    """Gradients with respect to ``inputs`` (the fields the solver reads: Newton's minimiser
    depends on ``qfrc_smooth`` and not on ``qacc_smooth``, PGS's the other way round). Each
    input is passed divided by 1e-3 of its magnitude, so that the finite differences' step
    (1e-5) is a relative change of 1e-8: the solution is piecewise smooth, with strong
    curvature in M, J and D."""
    kinds, layout = _padded(problems, np.random.default_rng(4), spare=1)
    xp = getattr(ivy, diff_backend)
    fixed = {k: native(layout[k], diff_backend) for k in S.ConstraintProblem._fields}
    warm = native(layout["qacc_warmstart"], diff_backend)
    scales = {k: 1e-3 * max(np.abs(layout[k]).max(), 1e-3) for k in inputs}

    def fn(*arrays):
        given = dict(fixed, **{k: a * scales[k] for k, a in zip(inputs, arrays)})
        given["M"] = 0.5 * (given["M"] + xp.matrix_transpose(given["M"]))  # stays symmetric
        solution = S.solve(xp, S.ConstraintProblem(**given), kinds, warm, options)
        return xp.concat([solution.qacc, solution.efc_force, solution.qfrc_constraint], axis=-1)

    fn = _maybe_compiled(diff_backend, fn)  # also the finite differences' evaluations
    arrays = [layout[k] / scales[k] for k in inputs]
    check_gradients(diff_backend, fn, arrays, n_directions=2, rtol=1e-6)


def test_newton_gradients_match_finite_differences(diff_backend, oracles):
    options, problems = oracles("newton")
    problems = problems[-2:]  # the scene's: every row kind
    inputs = ("M", "qfrc_smooth", "J", "D", "aref", "frictionloss")  # (R: zone boundaries only)
    _gradient_case(diff_backend, problems, options, inputs)


def test_pgs_gradients_match_finite_differences(diff_backend, oracles):
    """The implicit derivative of the exact dual solution, where PGS converges (this problem:
    in 4 iterations, to rounding). The dual reads R (``AR = J M^-1 J' + diag(R)``), not D."""
    options, problems = oracles("scene_pgs")
    options = options._replace(iterations=100, tolerance=1e-15)
    inputs = ("M", "qacc_smooth", "J", "R", "aref", "frictionloss")
    _gradient_case(diff_backend, problems[1:2], options, inputs)


def test_compiled_equals_eager(graph_backend, oracles):
    options, problems = oracles("hopper")
    eager, _ = _solve(graph_backend, options, problems, compiled=False)
    compiled, _ = _solve(graph_backend, options, problems, compiled=True)
    for a, b in zip(compiled, eager):
        np.testing.assert_allclose(numpy_of(a), numpy_of(b), rtol=1e-12, atol=1e-9)


# ----------------------------------------------------------------------------------------------
# Model reading
# ----------------------------------------------------------------------------------------------


def test_row_kinds_and_options_from_mujoco():
    assert list(S.row_kinds([0, 1, 2, 3, 4, 5, 6])) == [0, 1, 1, 2, 2, 2, 2]
    with pytest.raises(NotImplementedError, match="elliptic"):
        S.row_kinds([7])
    humanoid = S.SolverOptions.from_mujoco(_model(GYMNASIUM["humanoid"]))
    assert (humanoid.solver, humanoid.iterations, humanoid.warmstart) == ("pgs", 50, True)
    assert humanoid.meaninertia == pytest.approx(8.18573621113506)
    assert humanoid.islands and humanoid.dof_tree == (0,) * 23
    for attribute, value, message in (
        ("solver", mujoco.mjtSolver.mjSOL_CG, "CG"),
        ("cone", mujoco.mjtCone.mjCONE_ELLIPTIC, "elliptic"),
        ("noslip_iterations", 3, "noslip"),
    ):
        model = _model(GYMNASIUM["hopper"])
        setattr(model.opt, attribute, value)
        with pytest.raises(NotImplementedError, match=message):
            S.SolverOptions.from_mujoco(model)
    cold = _model(GYMNASIUM["hopper"], disable=["mjDSBL_WARMSTART", "mjDSBL_ISLAND"])
    assert not S.SolverOptions.from_mujoco(cold).warmstart
    assert not S.SolverOptions.from_mujoco(cold).islands
