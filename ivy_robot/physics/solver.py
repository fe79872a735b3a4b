"""The constraint solver: MuJoCo's ``mj_fwdConstraint`` (warm start, Newton, PGS) for every backend.

Input is what MuJoCo holds after ``mj_makeConstraint`` and ``mj_fwdAcceleration``, as a
:class:`ConstraintProblem` of arrays with any leading batch shape, plus the static kind of each
constraint row (:data:`ROW_EQUALITY`, :data:`ROW_FRICTION`, :data:`ROW_ONE_SIDED`; see
:func:`row_kinds`). Rows that do not exist in a batch element are masked by ``active``: they may
sit anywhere among the others and change nothing. Output is a :class:`ConstraintSolution`.

Both solvers minimise MuJoCo's convex cost of the accelerations ``qacc``::

    0.5 (qacc - qacc_smooth)' M (qacc - qacc_smooth) + sum_i s_i(J_i qacc - aref_i)

with ``s_i`` quadratic (``0.5 D jar^2``) on equality rows and on one-sided rows with ``jar < 0``,
zero on one-sided rows with ``jar >= 0``, and Huber-like on friction-loss rows (linear beyond
``|jar| >= R frictionloss``); the row forces are ``efc_force = -ds_i/djar``.

- ``"newton"``: Newton's method on ``qacc`` with the Hessian ``M + J' diag(D) J`` of the rows
  in their quadratic zone and an *exact* line search (the cost along the search direction is a
  piecewise quadratic with known breakpoints; see :func:`_line_search`), which lands where
  MuJoCo's iterative one does. It stops on MuJoCo's tests (scaled gradient, improvement and
  Newton decrement below the tolerance; MuJoCo can stop a little before the exact minimiser),
  or once a step leaves every row in its zone, which makes that step the exact minimiser (the
  cost is strictly convex). Batch elements that are done stop changing; the loop ends when all
  are done (``while_loop``, declared pure: a compiled loop on jax and tensorflow, torch's
  ``while_loop`` operator inside torch.compile, whose graph then holds the loop, its body traced
  once; a Python loop on numpy and eager torch). The loops' bodies close over no two views of
  one array (no transposes of the captured ``J``: :func:`~ivy_robot.physics._math.rmatvec`,
  :func:`~ivy_robot.physics._math.gram`) and no array made while tracing, as torch's operators
  require.
- ``"pgs"``: MuJoCo 4.0.1's projected Gauss-Seidel on the dual, iterate for iterate (it stops
  unconverged): its Nesterov momentum with gradient restarts, its row order (a Fisher-Yates
  shuffle of the rows at every sweep, drawn from its PCG32 generator with its fixed seed), its
  rejection of updates that raise the cost by more than ``1e-10``, and its stopping rule
  (improvement over the constrained dofs' inertia below the tolerance). The shuffles depend
  only on the number of active rows; they are tabulated once per ``(rows, iterations)`` in
  numpy. MuJoCo runs PGS per constraint island: this is its iteration for one island (one
  kinematic tree, as Gymnasium's robots, or islands disabled).

Gradients: the iterations run under ``stop_gradient``; the outputs are differentiated
implicitly, by one Newton step taken with gradients from the solution, with the rows' zones held
fixed (value unchanged; the derivative of the exact solution while no row changes zone), through
``ivy.with_gradient_of``: a function that takes no derivative does not compute the step (on
jax and torch; about a fifth of a compiled Hopper step on jax). For PGS
that is the derivative of the exact dual solution in the zones of the returned forces, not of the
truncated iteration.
"""

from __future__ import annotations

import functools
from typing import Any, NamedTuple

import numpy as np

from ivy.typing import Array
from ivy_robot.physics import _math as mt
from ivy_robot.physics import smooth

__all__ = [
    "ROW_EQUALITY",
    "ROW_FRICTION",
    "ROW_ONE_SIDED",
    "ConstraintProblem",
    "ConstraintSolution",
    "SolverOptions",
    "row_kinds",
    "solve",
]

ROW_EQUALITY = 0  # unbounded force, always quadratic
ROW_FRICTION = 1  # friction loss: force in [-frictionloss, frictionloss]
ROW_ONE_SIDED = 2  # joint and tendon limits, pyramidal and frictionless contact rows: force >= 0

# MuJoCo's mjtConstraint -> row kind (mjCNSTR_CONTACT_ELLIPTIC, 7, has no kind here)
_KIND_OF_MUJOCO_TYPE = {0: ROW_EQUALITY, 1: ROW_FRICTION, 2: ROW_FRICTION}
_KIND_OF_MUJOCO_TYPE.update({t: ROW_ONE_SIDED for t in (3, 4, 5, 6)})
_COST_INCREASE_REJECTED = 1e-10  # PGS undoes a row update that raises the cost by more


class ConstraintProblem(NamedTuple):
    """One constraint problem per batch element, as MuJoCo holds it after ``mj_makeConstraint``
    and ``mj_fwdAcceleration`` (leading batch shape ``[...]`` shared by every field)."""

    M: Array  # [..., nv, nv] joint-space inertia with armature (mj_fullM)
    qfrc_smooth: Array  # [..., nv]
    qacc_smooth: Array  # [..., nv]
    J: Array  # [..., nefc, nv] efc_J, dense
    D: Array  # [..., nefc] efc_D
    R: Array  # [..., nefc] efc_R
    aref: Array  # [..., nefc] efc_aref
    frictionloss: Array  # [..., nefc] efc_frictionloss (> 0 on friction-loss rows)
    active: Array  # [..., nefc] bool: the rows that exist


class ConstraintSolution(NamedTuple):
    """The solver's output; keep ``qacc`` as the next call's ``qacc_warmstart`` (MuJoCo saves
    ``qacc`` of a step as ``qacc_warmstart``)."""

    qacc: Array  # [..., nv]
    efc_force: Array  # [..., nefc], 0 on inactive rows
    qfrc_constraint: Array  # [..., nv] = J' efc_force
    iterations: Array  # [...] int: iterations each batch element took


class SolverOptions(NamedTuple):
    """The solver's settings, as in ``mjModel.opt``.

    ``warmstart=False`` is MuJoCo's ``mjDSBL_WARMSTART``, ``islands=False`` its
    ``mjDSBL_ISLAND``. Both solvers' stopping tests scale by the inverse of the constrained
    dofs' inertia, as MuJoCo 4.0.1 does: ``1 / sum(diag(M))`` over the dofs of the kinematic
    trees that active rows touch (``dof_tree``: each dof's tree, MuJoCo's ``dof_treeid``; None:
    one tree) when ``islands``, over every dof otherwise.

    ``ls_iterations`` and ``ls_tolerance`` are kept for reference: the Newton line search is
    exact. So is ``meaninertia`` (``mjModel.stat.meaninertia``, MuJoCo 3's scale).
    """

    solver: str = "newton"  # "newton" or "pgs"
    iterations: int = 100
    tolerance: float = 1e-8
    ls_iterations: int = 50
    ls_tolerance: float = 0.01
    meaninertia: float = 1.0
    warmstart: bool = True
    islands: bool = True
    dof_tree: tuple[int, ...] | None = None

    @classmethod
    def from_mujoco(cls, model: Any) -> SolverOptions:
        """The options of a compiled ``mujoco.MjModel``; what this solver does not do is refused.

        Example:
            >>> options = SolverOptions.from_mujoco(mujoco.MjModel.from_xml_path(hopper_xml))
            >>> options.solver, options.iterations, options.tolerance
            ('newton', 100, 1e-08)
        """
        import mujoco  # the model is MuJoCo's

        opt = model.opt
        names = {
            int(mujoco.mjtSolver.mjSOL_PGS): "pgs",
            int(mujoco.mjtSolver.mjSOL_NEWTON): "newton",
        }
        if int(opt.solver) not in names:
            raise NotImplementedError(
                "constraint solver: MuJoCo's CG solver is not implemented; use Newton or PGS "
                "(model.opt.solver)"
            )
        if int(opt.noslip_iterations) > 0:
            raise NotImplementedError("constraint solver: the noslip solver is not implemented")
        if int(opt.cone) != int(mujoco.mjtCone.mjCONE_PYRAMIDAL):
            raise NotImplementedError(
                "constraint solver: elliptic friction cones are not implemented (pyramidal only)"
            )
        return cls(
            solver=names[int(opt.solver)],
            iterations=int(opt.iterations),
            tolerance=float(opt.tolerance),
            ls_iterations=int(opt.ls_iterations),
            ls_tolerance=float(opt.ls_tolerance),
            meaninertia=float(model.stat.meaninertia),
            warmstart=not int(opt.disableflags) & int(mujoco.mjtDisableBit.mjDSBL_WARMSTART),
            islands=not int(opt.disableflags) & int(mujoco.mjtDisableBit.mjDSBL_ISLAND),
            dof_tree=tuple(int(t) for t in model.dof_treeid),
        )


def row_kinds(efc_type: Any) -> np.ndarray:
    """Row kinds of MuJoCo's constraint types (``mjData.efc_type``, ``mjtConstraint`` codes).

    Args:
        efc_type: integer array of ``mjtConstraint`` codes.

    Returns:
        An int array of :data:`ROW_EQUALITY`, :data:`ROW_FRICTION` and :data:`ROW_ONE_SIDED`.

    Example:
        >>> row_kinds([0, 1, 3, 6, 6, 5])
        array([0, 1, 2, 2, 2, 2])
    """
    codes = np.asarray(efc_type, dtype=np.int64).reshape(-1)
    unknown = sorted({int(c) for c in codes} - set(_KIND_OF_MUJOCO_TYPE))
    if unknown:
        raise NotImplementedError(
            f"constraint solver: constraint types {unknown} are not implemented (elliptic "
            f"contact cones are mjCNSTR_CONTACT_ELLIPTIC = 7)"
        )
    return np.array([_KIND_OF_MUJOCO_TYPE[int(c)] for c in codes], dtype=np.int64)


def solve(
    xp: Any,
    problem: ConstraintProblem,
    kinds: Any,
    qacc_warmstart: Array | None = None,
    options: SolverOptions | None = None,
) -> ConstraintSolution:
    """Solve the constraint problem: MuJoCo's ``mj_fwdConstraint`` for any batch shape.

    Args:
        xp: the backend namespace (``ivy.jax``, ``ivy.torch``, ...).
        problem: the :class:`ConstraintProblem`, float32 or float64.
        kinds: numpy int array *[nefc]* of row kinds, static (:func:`row_kinds`).
        qacc_warmstart: *[..., nv]* the previous accelerations (MuJoCo's ``qacc_warmstart``),
            or None for a cold start, as ``options.warmstart=False`` gives.
        options: :class:`SolverOptions` (:meth:`SolverOptions.from_mujoco`); None: the defaults
            (Newton, MuJoCo's default settings, ``meaninertia`` 1).

    Returns:
        The :class:`ConstraintSolution`.

    Example:
        The Hopper pressed 10 cm into the floor, against ``mj_forward``:

        >>> m = mujoco.MjModel.from_xml_path(hopper_xml)
        >>> d = mujoco.MjData(m)
        >>> d.qpos[1] = -0.1
        >>> mujoco.mj_forward(m, d)
        >>> p = forward(xp, model, make_data(xp, model, d.qpos, d.qvel))
        >>> problem = ConstraintProblem(
        ...     M=p.qM, qfrc_smooth=p.qfrc_smooth, qacc_smooth=p.qacc_smooth, J=p.efc_J,
        ...     D=p.efc_D, R=p.efc_R, aref=p.efc_aref, active=p.efc_active,
        ...     frictionloss=np.broadcast_to(model.rows.frictionloss, p.efc_D.shape))
        >>> sol = solve(xp, problem, model.fwd.row_kinds, None, SolverOptions.from_mujoco(m))
        >>> int(p.efc_active.sum()), bool(np.allclose(sol.qacc, d.qacc))
        (28, True)
        >>> bool(np.allclose(sol.qfrc_constraint, d.qfrc_constraint))
        True
    """
    options = SolverOptions() if options is None else options
    if options.solver not in ("newton", "pgs"):
        raise ValueError(
            f"constraint solver: solver must be 'newton' or 'pgs', got {options.solver!r}"
        )
    kinds = np.asarray(kinds, dtype=np.int64).reshape(-1)
    nv, nefc = int(problem.M.shape[-1]), int(problem.J.shape[-2])
    if kinds.shape != (nefc,):
        raise ValueError(f"constraint solver: kinds has shape {kinds.shape}, expected ({nefc},)")
    batch = _batch_shape(problem, qacc_warmstart)
    flat = _flatten(xp, problem, batch, nv, nefc)
    start = None
    if qacc_warmstart is not None and options.warmstart:
        start = xp.reshape(xp.broadcast_to(qacc_warmstart, (*batch, nv)), (-1, nv))

    still = _rows(xp, _stopped(xp, flat), kinds)
    if options.solver == "newton":
        qacc, jar, iterations = _newton(xp, still, start, options)
        zones = _zones(xp, still, jar)
        force = _forces(xp, still, jar, *zones)
    else:
        force, iterations = _pgs(xp, still, start, options)
        qacc = still.qacc_smooth + _solve_spd(xp, still.M, _matvec_T(xp, still.J, force))
        zones = _zones_of_forces(xp, still, force)
    # the derivatives of the exact solution, where a derivative is taken (see _implicit); the
    # iterations' own (through the warm start) are not taken
    qacc, force = xp.stop_gradient(qacc), xp.stop_gradient(force)
    qacc, force, qfrc = xp.with_gradient_of(
        (qacc, force, _matvec_T(xp, still.J, force)),
        functools.partial(_implicit, xp, kinds, options.solver == "newton"),
        (flat, qacc, force, zones),
    )
    unflat = functools.partial(_unflatten, xp, batch)
    return ConstraintSolution(
        unflat(qacc), unflat(force), unflat(qfrc), xp.reshape(iterations, batch)
    )


# ----------------------------------------------------------------------------------------------
# Rows: the problem flattened to one batch axis, inactive rows neutralised, zones' bounds
# ----------------------------------------------------------------------------------------------


class _Rows(NamedTuple):
    M: Array  # [B, nv, nv]
    qfrc_smooth: Array  # [B, nv]
    qacc_smooth: Array  # [B, nv]
    J: Array  # [B, n, nv], zero on inactive rows
    D: Array  # [B, n], zero on inactive rows
    R: Array  # [B, n], one on inactive rows
    aref: Array  # [B, n]
    floss: Array  # [B, n], frictionloss on friction rows, else 0
    low: Array  # [B, n] jar at or below it: the linear zone "below", force +floss (-inf: none)
    high: Array  # [B, n] jar at or above it: the zone "above", force -floss (0 on one-sided
    # rows: satisfied; inf: none)
    high_force: Array  # [B, n] the force above: -floss, 0 on one-sided rows
    active: Array  # [B, n] bool
    friction: Array  # [B, n] bool: active friction rows
    one_sided: Array  # [B, n] bool: active one-sided rows


def _batch_shape(problem: ConstraintProblem, qacc_warmstart) -> tuple:
    shapes = [tuple(problem.M.shape[:-2]), tuple(problem.J.shape[:-2])]
    shapes += [tuple(a.shape[:-1]) for a in problem[1:3] + problem[4:]]
    if qacc_warmstart is not None:
        shapes.append(tuple(qacc_warmstart.shape[:-1]))
    return tuple(np.broadcast_shapes(*shapes))


def _flatten(xp, problem: ConstraintProblem, batch, nv, nefc) -> ConstraintProblem:
    def flat(a, tail):
        return xp.reshape(xp.broadcast_to(a, (*batch, *tail)), (-1, *tail))

    return ConstraintProblem(
        flat(problem.M, (nv, nv)),
        flat(problem.qfrc_smooth, (nv,)),
        flat(problem.qacc_smooth, (nv,)),
        flat(problem.J, (nefc, nv)),
        *[flat(a, (nefc,)) for a in problem[4:]],
    )


def _unflatten(xp, batch, a):
    return xp.reshape(a, (*batch, *a.shape[1:]))


def _stopped(xp, problem: ConstraintProblem) -> ConstraintProblem:
    return ConstraintProblem(*[xp.stop_gradient(a) for a in problem[:-1]], problem.active)


def _rows(xp, p: ConstraintProblem, kinds: np.ndarray) -> _Rows:
    like = p.D
    active = xp.astype(p.active, xp.bool)
    friction = xp.logical_and(active, xp.constant(kinds == ROW_FRICTION, device=xp.dev(like)))
    one_sided = xp.logical_and(active, xp.constant(kinds == ROW_ONE_SIDED, device=xp.dev(like)))
    zero, one = xp.zeros_like(like), xp.ones_like(like)
    inf = xp.full_like(like, float("inf"))
    R = xp.where(active, p.R, one)
    floss = xp.where(friction, p.frictionloss, zero)
    return _Rows(
        M=p.M,
        qfrc_smooth=p.qfrc_smooth,
        qacc_smooth=p.qacc_smooth,
        J=xp.where(active[..., None], p.J, xp.zeros_like(p.J)),
        D=xp.where(active, p.D, zero),
        R=R,
        aref=xp.where(active, p.aref, zero),
        floss=floss,
        low=xp.where(friction, -R * floss, -inf),
        high=xp.where(friction, R * floss, xp.where(one_sided, zero, inf)),
        high_force=xp.where(friction, -floss, zero),
        active=active,
        friction=friction,
        one_sided=one_sided,
    )


def _matvec_T(xp, J, f):
    """``J' f`` for ``J`` *[B, n, nv]*, ``f`` *[B, n]*."""
    return mt.rmatvec(xp, J, f)


def _solve_spd(xp, A, rhs):
    """``A^-1 rhs`` for symmetric positive definite ``A`` *[B, nv, nv]* and ``rhs`` *[B, nv]*.

    A batched ``linalg.solve``, except where the compiler keeps loops only when declared pure
    (``compilation`` without ``compiled_loops``: torch), whose code generator fails on it inside
    the solver's loop operators: there an ``L D L'`` factorisation written element-wise
    (:func:`~ivy_robot.physics.smooth.ldl_factor`). Under XLA the element-wise factor runs as
    fast (15.0 against 14.6 us per Hopper state) but makes the programs of the solver's
    gradients slow to compile (jax: 185 s against 5 s for the gradient test)."""
    caps = xp.capabilities
    if caps.compilation and not caps.compiled_loops:
        plan = _factor_plan(int(A.shape[-1]))
        return smooth.ldl_solve(xp, plan, smooth.ldl_factor(xp, plan, A), rhs)
    return xp.linalg.solve(A, rhs[..., None])[..., 0]


@functools.cache
def _factor_plan(n: int):
    return smooth.factor_plan(n)


def _zones(xp, rows: _Rows, jar):
    """The rows' zones at ``jar = J qacc - aref`` (MuJoCo's constraint update): ``(below,
    above)``, *[B, n]* bools; a row in neither is quadratic (force ``-D jar``); below, its force
    is ``+frictionloss``; above, ``-frictionloss`` (0: a satisfied one-sided row)."""
    below = jar <= rows.low
    return below, xp.logical_and(jar >= rows.high, xp.logical_not(below))


def _forces(xp, rows: _Rows, jar, below, above):
    quadratic = xp.logical_not(xp.logical_or(below, above))
    return xp.where(quadratic, -rows.D * jar, xp.where(below, rows.floss, rows.high_force))


def _cost(xp, rows: _Rows, jar):
    """The rows' cost at ``jar``, summed per batch element."""
    return xp.sum(_row_costs(xp, rows, jar, *_zones(xp, rows, jar)), axis=-1)


def _zones_of_forces(xp, rows: _Rows, force):
    """The zones of dual forces: quadratic where a force lies strictly inside its bounds."""
    below = xp.logical_and(rows.friction, force >= rows.floss)
    above = xp.logical_or(
        xp.logical_and(rows.friction, force <= -rows.floss),
        xp.logical_and(rows.one_sided, force <= 0),
    )
    return below, above


def _total_cost(xp, rows: _Rows, qacc):
    """MuJoCo's cost of ``qacc`` (constraint cost plus the Gauss term), per batch element."""
    cost = _cost(xp, rows, mt.matvec(xp, rows.J, qacc) - rows.aref)
    Ma = mt.matvec(xp, rows.M, qacc)
    return cost + 0.5 * xp.sum((Ma - rows.qfrc_smooth) * (qacc - rows.qacc_smooth), axis=-1)


# ----------------------------------------------------------------------------------------------
# Newton
# ----------------------------------------------------------------------------------------------


def _newton(xp, rows: _Rows, start, options: SolverOptions):
    """Newton's method with exact line searches from the warm start; returns ``qacc``, its
    ``jar`` and the iterations per batch element.

    It stops where MuJoCo's does: at the start, when the scaled gradient and Newton decrement
    are both below the tolerance; after a step, when the scaled improvement, gradient or
    decrement is (scale: the inverse of the constrained dofs' inertia). It also stops after a
    step that changed no row's zone, which makes the new point the exact minimiser (MuJoCo would
    stop there at its next test), and where the line search cannot descend."""
    qacc = rows.qacc_smooth
    if start is not None:  # the cheaper of qacc_warmstart and qacc_smooth
        smooth_cost = _cost(xp, rows, mt.matvec(xp, rows.J, qacc) - rows.aref)
        worse = _total_cost(xp, rows, start) > smooth_cost
        qacc = xp.where(worse[:, None], qacc, start)
    jar = mt.matvec(xp, rows.J, qacc) - rows.aref
    inertia = _island_inertia(xp, rows, options)
    scale = 1.0 / xp.where(inertia > 0, inertia, xp.ones_like(inertia))
    tolerance = options.tolerance
    batch = qacc.shape[0]
    done = xp.zeros((batch,), dtype=xp.bool, device=xp.dev(qacc))
    count = xp.zeros((batch,), dtype=xp.int32, device=xp.dev(qacc))
    step = xp.zeros((), dtype=xp.int32, device=xp.dev(qacc))

    def keep_going(carry):
        done, step = carry[-3], carry[-1]
        return xp.logical_and(step < options.iterations, xp.any(xp.logical_not(done)))

    def iterate(carry):
        qacc, jar, below, above, improvement, done, count, step = carry
        gauss, grad, search = _newton_direction(xp, rows, qacc, jar, below, above)
        gradient = scale * xp.sqrt(xp.sum(grad * grad, axis=-1))
        decrement = xp.maximum(-0.5 * scale * xp.sum(grad * search, axis=-1), xp.zeros_like(scale))
        small = xp.logical_or(gradient < tolerance, decrement < tolerance)
        improved = xp.logical_and(improvement > 0, improvement < tolerance)
        first = xp.logical_and(gradient < tolerance, decrement < tolerance)
        done = xp.logical_or(done, xp.where(step == 0, first, xp.logical_or(small, improved)))

        Jv = mt.matvec(xp, rows.J, search)
        slope0 = xp.sum(gauss * search, axis=-1)
        curvature = xp.sum(search * mt.matvec(xp, rows.M, search), axis=-1)
        alpha = _line_search(xp, rows, jar, Jv, slope0, curvature)
        done = xp.logical_or(done, xp.logical_not(alpha > 0))  # no descent
        new_jar = jar + alpha[:, None] * Jv
        new_below, new_above = _zones(xp, rows, new_jar)
        decrease = _cost_decrease(xp, rows, jar, new_jar, alpha, slope0, curvature)
        settled = xp.all(xp.logical_and(new_below == below, new_above == above), axis=-1)
        keep = done[:, None]
        return (
            xp.where(keep, qacc, qacc + alpha[:, None] * search),
            xp.where(keep, jar, new_jar),
            xp.where(keep, below, new_below),
            xp.where(keep, above, new_above),
            xp.where(done, improvement, scale * decrease),
            xp.logical_or(done, settled),
            count + xp.astype(xp.logical_not(done), xp.int32),
            step + 1,
        )

    zero = xp.zeros_like(scale)
    carry = (qacc, jar, *_zones(xp, rows, jar), zero, done, count, step)
    qacc, *_, count, _ = xp.while_loop(keep_going, iterate, carry, pure=True)
    # rows that exist in no batch element: MuJoCo's shortcut qacc = qacc_smooth
    qacc = xp.where(xp.any(rows.active, axis=-1)[:, None], qacc, rows.qacc_smooth)
    return qacc, mt.matvec(xp, rows.J, qacc) - rows.aref, count


def _newton_direction(xp, rows: _Rows, qacc, jar, below, above):
    """At ``qacc`` (its ``jar`` and zones given): the Gauss term's gradient ``M qacc -
    qfrc_smooth``, the cost's gradient and the Newton direction ``-H^-1 grad``."""
    quadratic = xp.logical_not(xp.logical_or(below, above))
    force = xp.where(quadratic, -rows.D * jar, xp.where(below, rows.floss, rows.high_force))
    gauss = mt.matvec(xp, rows.M, qacc) - rows.qfrc_smooth
    grad = gauss - _matvec_T(xp, rows.J, force)
    H = rows.M + mt.gram(xp, rows.J, xp.where(quadratic, rows.D, xp.zeros_like(rows.D)))
    return gauss, grad, -_solve_spd(xp, H, grad)


def _row_costs(xp, rows: _Rows, jar, below, above):
    fl = rows.floss
    linear = -0.5 * rows.R * fl * fl + xp.where(below, -fl, fl) * jar
    quadratic = xp.logical_not(xp.logical_or(below, above))
    return xp.where(quadratic, 0.5 * rows.D * jar * jar, linear)


def _cost_decrease(xp, rows: _Rows, jar, new_jar, alpha, slope0, curvature):
    """``cost(old) - cost(new)`` along the line, summed term by term (a row that stays
    quadratic: ``-D alpha Jv (jar + alpha Jv / 2)``), without the totals' cancellation."""
    zones, new_zones = _zones(xp, rows, jar), _zones(xp, rows, new_jar)
    change = _row_costs(xp, rows, new_jar, *new_zones) - _row_costs(xp, rows, jar, *zones)
    both = xp.logical_not(xp.logical_or(xp.logical_or(*zones), xp.logical_or(*new_zones)))
    moved = new_jar - jar
    change = xp.where(both, rows.D * moved * (jar + 0.5 * moved), change)
    gauss = alpha * slope0 + 0.5 * alpha * alpha * curvature
    return -(gauss + xp.sum(change, axis=-1))


def _directional(xp, rows: _Rows, jar, Jv, below, above):
    """Each row's term ``a + alpha b`` of the cost's derivative along the search direction, with
    the rows in the given zones; returns ``(a, b)``."""
    quadratic = xp.logical_not(xp.logical_or(below, above))
    linear = rows.floss * Jv
    a = xp.where(quadratic, rows.D * jar * Jv, xp.where(below, -linear, linear))
    b = xp.where(quadratic, rows.D * Jv * Jv, xp.zeros_like(jar))
    return a, b


def _line_search(xp, rows: _Rows, jar, Jv, slope0, curvature):
    """The exact minimiser ``alpha >= 0`` of the cost along ``qacc + alpha search``.

    The derivative along the line, ``slope0 + alpha curvature`` plus the rows' terms, is
    continuous, piecewise linear and increasing, with a kink where a row crosses a zone boundary
    (one-sided rows at ``jar = 0``, friction rows at ``jar = -+R frictionloss``). The segment
    between two crossings where it vanishes is found, then the root is solved there from the
    rows' zones in that segment, summed afresh (no accumulated rounding). Finding the segment:

    - where the backend compiles loops (``xp.capabilities.compiled_loops``: jax, tensorflow), a
      walk over the segments from ``alpha = 0`` that stops at the first whose root lies before
      its end: one step per crossing passed, a loop while any batch element walks on (few
      steps in practice, each a pass over the rows; no sort, which is slow on XLA's CPU);
    - elsewhere (torch, numpy), in one pass: the crossings sorted, the changes of slope summed
      along them, the first segment whose end has a non-negative derivative (no loop: eager
      torch would wait on its test at every step).

    Args:
        jar: *[B, n]* ``J qacc - aref``; ``Jv``: *[B, n]* ``J search``.
        slope0, curvature: *[B]* the Gauss term's derivative at 0 and second derivative.
    """
    line = _Line(xp, rows, jar, Jv, slope0, curvature)
    if xp.capabilities.compiled_loops:
        return line.walk()
    return line.root(line.sorted_segment())[0]


class _Line:
    """The cost along a search direction: its zone crossings and the derivative's segments."""

    def __init__(self, xp, rows: _Rows, jar, Jv, slope0, curvature):
        self.xp, self.rows, self.jar, self.Jv = xp, rows, jar, Jv
        self.slope0, self.curvature = slope0, curvature
        self.inf = xp.full_like(jar, float("inf"))
        moving = Jv != 0
        self.step = xp.where(moving, Jv, xp.ones_like(Jv))
        self.up = Jv > 0

        def crossing(level):
            alpha = (level - jar) / self.step
            ahead = xp.logical_and(xp.logical_and(moving, xp.isfinite(level)), alpha > 0)
            return xp.where(ahead, alpha, self.inf)

        self.at_low, self.at_high = crossing(rows.low), crossing(rows.high)
        # zones just after alpha = 0 (0 below, 1 quadratic, 2 above; a row on a boundary takes
        # the side it moves to); a zone changes by one in the direction of motion at each
        # crossing passed
        below = xp.logical_or(
            jar < rows.low, xp.logical_and(jar == rows.low, xp.logical_not(self.up))
        )
        above = xp.logical_or(
            jar > rows.high, xp.logical_and(jar == rows.high, xp.logical_not(Jv < 0))
        )
        self.start = xp.where(below, 0, xp.where(above, 2, 1))

    def segment(self, lo):
        """The derivative ``a + alpha b`` on the segment that starts at ``lo`` *[B]*, and the
        segment's end: ``(a, b, end)``."""
        xp, lo = self.xp, self.xp.reshape(lo, (-1, 1))
        passed = xp.astype(self.at_low <= lo, self.start.dtype) + xp.astype(
            self.at_high <= lo, self.start.dtype
        )
        zone = xp.where(self.up, self.start + passed, self.start - passed)
        a_rows, b_rows = _directional(xp, self.rows, self.jar, self.Jv, zone == 0, zone == 2)
        later = xp.minimum(
            xp.where(self.at_low > lo, self.at_low, self.inf),
            xp.where(self.at_high > lo, self.at_high, self.inf),
        )
        a = self.slope0 + xp.sum(a_rows, axis=-1)
        return a, self.curvature + xp.sum(b_rows, axis=-1), xp.min(later, axis=-1)

    def root(self, lo):
        """The root of the derivative in the segment starting at ``lo``, within the segment;
        also whether it lies there, and the segment's end: ``(alpha, inside, end)``."""
        xp = self.xp
        a, b, end = self.segment(lo)
        positive = b > 0
        root = xp.where(positive, -a / xp.where(positive, b, xp.ones_like(b)), lo)
        return xp.minimum(xp.maximum(root, lo), end), root <= end, end

    def walk(self):
        xp = self.xp

        def walking(carry):
            return xp.any(xp.logical_not(carry[2]))

        def step(carry):
            lo, alpha, done = carry
            root, inside, end = self.root(lo)
            found = xp.logical_and(xp.logical_not(done), inside)
            alpha = xp.where(found, root, alpha)
            lo = xp.where(xp.logical_or(done, found), lo, end)
            return lo, alpha, xp.logical_or(done, found)

        zero = xp.zeros_like(self.slope0)
        done = xp.zeros(self.slope0.shape, dtype=xp.bool, device=xp.dev(zero))
        return xp.while_loop(walking, step, (zero, zero, done), pure=True)[1]

    def sorted_segment(self):
        """The start of the segment where the derivative vanishes, from the sorted crossings:
        the first segment whose derivative at its end is non-negative."""
        xp, rows, jar, Jv = self.xp, self.rows, self.jar, self.Jv
        sign = xp.where(self.up, xp.ones_like(Jv), -xp.ones_like(Jv))
        quad_a, quad_b, linear = rows.D * jar * Jv, rows.D * Jv * Jv, rows.floss * Jv
        # change of (a, b) at a crossing of the low boundary (below <-> quadratic) and of the
        # high one (quadratic <-> above), moving in the direction of sign
        da = xp.concat([sign * (quad_a + linear), sign * (linear - quad_a)], axis=-1)
        db = xp.concat([sign * quad_b, -sign * quad_b], axis=-1)
        crossings = xp.concat([self.at_low, self.at_high], axis=-1)
        ahead = xp.isfinite(crossings)
        da, db = xp.where(ahead, da, xp.zeros_like(da)), xp.where(ahead, db, xp.zeros_like(db))
        a0, b0, _ = self.segment(xp.zeros_like(self.slope0))
        order = xp.argsort(crossings, axis=-1)
        ends = xp.take_along_axis(crossings, order, axis=-1)
        # segment k runs from the k-th crossing (0 for k = 0) to the next (inf after the last)
        a = a0[:, None] + xp.cumsum(xp.take_along_axis(da, order, axis=-1), axis=-1)
        b = b0[:, None] + xp.cumsum(xp.take_along_axis(db, order, axis=-1), axis=-1)
        a, b = xp.concat([a0[:, None], a], axis=-1), xp.concat([b0[:, None], b], axis=-1)
        ends = xp.concat([ends, self.inf[:, :1]], axis=-1)
        last = xp.isinf(ends)
        rising = xp.logical_or(last, a + xp.where(last, xp.zeros_like(ends), ends) * b >= 0)
        first = xp.argmax(xp.astype(rising, xp.int32), axis=-1)[:, None]
        starts = xp.concat([xp.zeros_like(ends[:, :1]), ends[:, :-1]], axis=-1)
        return xp.take_along_axis(starts, first, axis=-1)[:, 0]


# ----------------------------------------------------------------------------------------------
# PGS
# ----------------------------------------------------------------------------------------------

_PCG_MULTIPLIER = 6364136223846793005
_MASK64 = (1 << 64) - 1


def _pcg32_stream(count: int) -> list[int]:
    """The first ``count`` outputs of MuJoCo's PGS generator (PCG32, state 0, increment 1,
    advanced once after seeding)."""
    state, increment = 0, 1
    out = []
    for i in range(count + 1):
        old = state
        state = (old * _PCG_MULTIPLIER + increment) & _MASK64
        shifted = (((old >> 18) ^ old) >> 27) & 0xFFFFFFFF
        rotation = old >> 59
        value = ((shifted >> rotation) | (shifted << ((-rotation) & 31))) & 0xFFFFFFFF
        if i:  # the first output is drawn at seeding
            out.append(value)
    return out


@functools.lru_cache(maxsize=16)
def _shuffle_table(rows: int, iterations: int) -> np.ndarray:
    """``table[n, k]``: the order in which PGS visits ``n`` active rows at iteration ``k``
    (positions among the active rows; positions ``>= n`` hold themselves). Int32
    *[rows + 1, iterations, rows]*."""
    stream = np.array(_pcg32_stream(max(iterations * max(rows - 1, 0), 1)), dtype=np.uint64)
    table = np.zeros((rows + 1, iterations, rows), dtype=np.int32)
    order = np.tile(np.arange(rows, dtype=np.int32), (rows + 1, 1))
    counts = np.arange(rows + 1)
    lanes = np.arange(rows + 1)
    for k in range(iterations):
        for t in range(rows - 1):  # swap i = n-1-t with a draw j <= i, for every n at once
            i = counts - 1 - t
            live = i >= 1
            draw = stream[np.minimum(k * np.maximum(counts - 1, 0) + t, len(stream) - 1)]
            j = (draw % np.maximum(i + 1, 1).astype(np.uint64)).astype(np.int64)
            i, j, lane = i[live], j[live], lanes[live]
            order[lane, i], order[lane, j] = order[lane, j], order[lane, i].copy()
        table[:, k] = order
    return table


def _pgs(xp, rows: _Rows, start, options: SolverOptions):
    """MuJoCo's PGS iterations from the warm start; returns the forces and iterations."""
    like = rows.D
    batch, n = like.shape
    MinvJT = xp.linalg.solve(rows.M, xp.matrix_transpose(rows.J))
    AR = xp.matmul(rows.J, MinvJT) + _diag(xp, rows.R)
    b = mt.matvec(xp, rows.J, rows.qacc_smooth) - rows.aref
    force = xp.zeros_like(like)
    if start is not None:  # warm forces unless their dual cost is positive
        warm_jar = mt.matvec(xp, rows.J, start) - rows.aref
        warm = _forces(xp, rows, warm_jar, *_zones(xp, rows, warm_jar))
        dual = xp.sum(warm * b, axis=-1) + 0.5 * xp.sum(warm * xp.matvec(AR, warm), axis=-1)
        force = xp.where((dual > 0)[:, None], force, warm)

    ARinv = 1.0 / _diagonal(xp, AR)
    inf = xp.full_like(like, float("inf"))
    lowest = xp.where(
        rows.friction, -rows.floss, xp.where(rows.one_sided, xp.zeros_like(like), -inf)
    )
    highest = xp.where(rows.friction, rows.floss, inf)
    # per row: b, 1/AR_ii, MuJoCo's AR_ii = 1/(1/AR_ii), the force's bounds
    params = xp.stack([b, ARinv, 1.0 / ARinv, lowest, highest], axis=1)  # [B, 5, n]
    count = xp.sum(xp.astype(rows.active, xp.int32), axis=-1)
    active_first = xp.argsort(
        xp.astype(xp.logical_not(rows.active), xp.int32), axis=-1, stable=True
    )
    table = xp.constant(_shuffle_table(n, options.iterations), device=xp.dev(like))
    inertia = _island_inertia(xp, rows, options)
    scale = 1.0 / xp.where(inertia > 0, inertia, xp.ones_like(inertia))
    most = xp.max(count)

    batch_index = xp.arange(batch, device=xp.dev(like))
    params = xp.permute_dims(params, (0, 2, 1))  # [B, n, 5]

    def sweep(force, step):
        """One Gauss-Seidel sweep in this iteration's order: each visit gathers one row of
        ``AR`` per batch element (whole rows: contiguous slices) and writes one force per
        element by scatters (no gather of every element, no work per element of a masked
        select over the whole forces, which XLA fused with the update's arithmetic)."""
        visits = xp.take(table[:, step], count, axis=0)  # positions among the active rows
        order = xp.take_along_axis(active_first, visits, axis=-1)  # rows, in visiting order
        order = xp.stack([xp.broadcast_to(batch_index[:, None], order.shape), order], axis=-1)

        def keep_going(carry):
            return carry[0] < most

        def visit(carry):
            c, force, improvement = carry
            at = order[:, c]  # [B, 2]: (element, row)
            p = xp.gather_nd(params, at)  # [B, 5]
            res = p[:, 0] + xp.sum(xp.gather_nd(AR, at) * force, axis=-1)
            old = xp.gather_nd(force, at)
            new = xp.minimum(xp.maximum(old - res * p[:, 1], p[:, 3]), p[:, 4])
            delta = new - old
            change = 0.5 * delta * delta * p[:, 2] + delta * res
            kept = xp.logical_and(c < count, change <= _COST_INCREASE_REJECTED)
            # the visited force replaced exactly: its old value out (to 0), the new one in
            value = xp.where(kept, new, old)
            force = (force - xp.scatter_nd(at, old, (batch, n))) + xp.scatter_nd(
                at, value, (batch, n)
            )
            improvement = improvement - xp.where(kept, change, xp.zeros_like(change))
            return c + 1, force, improvement

        start = (
            xp.zeros((), dtype=count.dtype, device=xp.dev(like)),
            force,
            xp.zeros_like(b[:, 0]),
        )
        return xp.while_loop(keep_going, visit, start, pure=True)[1:]

    def keep_going(carry):
        return xp.logical_and(carry[-1] < options.iterations, xp.any(xp.logical_not(carry[3])))

    def iterate(carry):
        force, previous, restarts, done, iterations, step = carry
        k = xp.astype(restarts, like.dtype)
        beta = xp.where(step > 0, (k - 1.0) / (k + 2.0), xp.zeros_like(k))
        momentum = beta > 0
        pushed = _project(xp, rows, force + beta[:, None] * (force - previous))
        extrapolated = xp.where(momentum[:, None], pushed, force)
        swept, improvement = sweep(extrapolated, step)
        correction = xp.sum((swept - extrapolated) * (extrapolated - force), axis=-1)
        restart = xp.logical_and(step > 0, correction < 0)
        new_restarts = xp.where(restart, xp.zeros_like(restarts), restarts + 1)
        finished = improvement * scale < options.tolerance
        keep = done[:, None]
        return (
            xp.where(keep, force, swept),
            xp.where(keep, previous, force),
            xp.where(done, restarts, new_restarts),
            xp.logical_or(done, finished),
            iterations + xp.astype(xp.logical_not(done), xp.int32),
            step + 1,
        )

    zeros_int = xp.zeros((batch,), dtype=xp.int32, device=xp.dev(like))
    step0 = xp.zeros((), dtype=xp.int32, device=xp.dev(like))
    done = xp.zeros((batch,), dtype=xp.bool, device=xp.dev(like))
    carry = (force, force, zeros_int, done, zeros_int, step0)
    force, _, _, _, iterations, _ = xp.while_loop(keep_going, iterate, carry, pure=True)
    return force, iterations


def _island_inertia(xp, rows: _Rows, options: SolverOptions):
    """The sum of the inertia matrix's diagonal over the constrained dofs *[B]*: the dofs of
    the trees that active rows touch (MuJoCo's island, where there is one) or every dof."""
    diagonal = _diagonal(xp, rows.M)
    if not options.islands:
        return xp.sum(diagonal, axis=-1)
    nv = rows.M.shape[-1]
    tree = (0,) * nv if options.dof_tree is None else tuple(int(t) for t in options.dof_tree)
    if len(tree) != nv:
        raise ValueError(f"constraint solver: dof_tree has {len(tree)} dofs, expected {nv}")
    # tree by tree (static Python indices, no constant arrays: inside torch.compile's loop
    # operators an array made while tracing becomes a constant of the body that inductor
    # does not bind); a tree of -1, a static dof, is no tree
    touched = xp.sum(xp.abs(rows.J), axis=-2) > 0  # [B, nv]
    zero = xp.zeros_like(diagonal[..., 0])
    total = zero
    for k in sorted(set(tree) - {-1}):
        dofs = [i for i, t in enumerate(tree) if t == k]
        hit, inertia = touched[..., dofs[0]], diagonal[..., dofs[0]]
        for i in dofs[1:]:
            hit, inertia = xp.logical_or(hit, touched[..., i]), inertia + diagonal[..., i]
        total = total + xp.where(hit, inertia, zero)
    return total


def _project(xp, rows: _Rows, force):
    """Forces clipped to their bounds (friction boxes, one-sided rows non-negative)."""
    boxed = xp.minimum(xp.maximum(force, -rows.floss), rows.floss)
    force = xp.where(rows.friction, boxed, force)
    return xp.where(rows.one_sided, xp.maximum(force, xp.zeros_like(force)), force)


def _diag(xp, v):
    """Diagonal matrices *[B, n, n]* of vectors *[B, n]*."""
    n = v.shape[-1]
    eye = xp.eye(n, dtype=v.dtype, device=xp.dev(v))
    return v[..., None] * eye


def _diagonal(xp, A):
    return xp.linalg.diagonal(A)


# ----------------------------------------------------------------------------------------------
# Implicit differentiation
# ----------------------------------------------------------------------------------------------


def _implicit(xp, kinds, newton: bool, problem: ConstraintProblem, qacc, force, zones):
    """One Newton step of the convex problem from its (stopped) solution, its zones held:
    ``(qacc, efc_force, qfrc_constraint)`` with the derivatives of the exact solution, which
    :func:`solve` gives to the solver's results (``xp.with_gradient_of``: computed only where a
    derivative is taken). Its value is the solution's up to the solver's tolerance.

    The Gauss term pulls towards ``qfrc_smooth`` for Newton (MuJoCo's primal) and ``M
    qacc_smooth`` for PGS (its dual); the quadratic rows' stiffness is ``efc_D`` for Newton and
    ``1 / efc_R`` for PGS, whose dual reads R."""
    rows = _rows(xp, problem, kinds)
    gauss = rows.qfrc_smooth if newton else mt.matvec(xp, rows.M, rows.qacc_smooth)
    D = rows.D if newton else 1.0 / rows.R
    below, above = zones
    quadratic = xp.logical_not(xp.logical_or(below, above))
    linear = xp.where(below, rows.floss, rows.high_force)
    D = xp.where(quadratic, D, xp.zeros_like(D))
    jar = mt.matvec(xp, rows.J, qacc) - rows.aref
    row_force = xp.where(quadratic, -D * jar, linear)
    grad = mt.matvec(xp, rows.M, qacc) - gauss - _matvec_T(xp, rows.J, row_force)
    stepped = qacc - _solve_spd(xp, rows.M + mt.gram(xp, rows.J, D), grad)
    stepped_force = xp.where(quadratic, -D * (mt.matvec(xp, rows.J, stepped) - rows.aref), linear)
    return stepped, stepped_force, _matvec_T(xp, rows.J, stepped_force)
