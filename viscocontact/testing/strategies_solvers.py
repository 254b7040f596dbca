"""Test problems and hypothesis strategies for nonlinear solvers, for the package's tests and for
plugin authors who add a :class:`~viscocontact.solvers.base.NonlinearSolver`.

The problems imitate the contact-edge systems the solvers meet in viscocontact: a few to a few
dozen unknowns, each residual depending mostly on its own unknown (strongly diagonal Jacobian),
known roots, optional Jacobian / orientation / step bound.

* :class:`TanhSystem` — ``r_i = s_i·[tanh(u_i) + Σ_{j≠i} A_ij·sin(u_j)]``, ``u = (x - c)/w``, with
  the unique root ``x = c`` when every row sum ``Σ_j |A_ij| <= 0.5``.
* :class:`CoupledPair` — a 2×2 polynomial-exponential system with root (1, 1).
* :class:`NoRoot` — ``r_i = x_i² + 1``: no solver may claim convergence.
* :class:`FunctionProblem` — a problem from callables, exposing only the optional methods given
  (the protocol is duck-typed with ``hasattr``).
* :class:`RecordingProblem` — wraps a problem, counts and records every call, and can raise
  :class:`InjectedError` at the k-th residual call.
* :class:`SolverCase` — problem, start, known root, tolerances and the accuracy to expect.

Examples
--------
>>> from hypothesis import given, settings
>>> from viscocontact.solvers import Newton
>>> from viscocontact.testing.strategies_solvers import solver_cases
>>> @settings(max_examples=5, deadline=None)
... @given(solver_cases())
... def test_newton_finds_the_root(case):
...     res = Newton().solve(case.problem, case.x0, case.tolerances)
...     assert res.converged and case.is_near_root(res.x)
>>> test_newton_finds_the_root()
"""
from __future__ import annotations

from typing import Any, Callable

import attrs
import numpy as np
from hypothesis import strategies as st

from ..solvers.base import Tolerances

__all__ = ["CoupledPair", "FunctionProblem", "InjectedError", "NoRoot", "RecordingProblem",
           "SolverCase", "TanhSystem", "no_root_case", "solver_cases", "standard_cases",
           "tanh_systems"]

OPTIONAL_METHODS = ("jacobian", "merit", "orientation", "max_step")


def _ro(a) -> np.ndarray:
    arr = np.array(a, dtype=float, copy=True)
    arr.setflags(write=False)
    return arr


_ARRAY_EQ = attrs.cmp_using(eq=np.array_equal)


class FunctionProblem:
    """A nonlinear problem from callables; only the optional methods passed exist (``hasattr``).

    Parameters
    ----------
    residual : callable ``x -> (n,)``
    jacobian, merit, orientation : callable, optional
    max_step : callable ``x -> (n,)``, float or array, optional
        A number or array is turned into a constant bound.
    """

    def __init__(self, residual: Callable, *, jacobian: Callable | None = None,
                 merit: Callable | None = None, orientation: Callable | None = None,
                 max_step: Any = None):
        self.residual = residual
        if max_step is not None and not callable(max_step):
            bound = np.array(max_step, dtype=float)
            max_step = lambda x, _b=bound: np.broadcast_to(_b, np.shape(x)).copy()  # noqa: E731
        given = dict(jacobian=jacobian, merit=merit, orientation=orientation, max_step=max_step)
        self._optional = {k: v for k, v in given.items() if v is not None}

    def __getattr__(self, name):
        optional = self.__dict__.get("_optional", {})
        if name in optional:
            return optional[name]
        raise AttributeError(f"{type(self).__name__} has no {name!r}")

    def __repr__(self):
        return f"FunctionProblem(optional={sorted(self._optional)})"


class InjectedError(RuntimeError):
    """Raised by :class:`RecordingProblem` at the chosen residual call."""


class RecordingProblem:
    """Wrap ``problem``: count and record residual calls and ``max_step`` queries.

    Attributes
    ----------
    calls : int
        Number of ``residual`` calls so far.
    points : list of ndarray
        Copies of every x passed to ``residual``, in order.
    events : list of (str, ndarray)
        ``("residual", x)`` and ``("max_step", x)`` in call order.
    fail_at : int or None
        The ``fail_at``-th residual call (1-based) raises ``error`` instead of returning.
    """

    def __init__(self, problem: Any, *, fail_at: int | None = None,
                 error: BaseException | None = None):
        self.problem = problem
        self.fail_at = fail_at
        self.error = error if error is not None else InjectedError(f"injected at call {fail_at}")
        self.calls = 0
        self.points: list[np.ndarray] = []
        self.events: list[tuple[str, np.ndarray]] = []

    def residual(self, x):
        self.calls += 1
        x = np.array(x, dtype=float, copy=True)
        self.points.append(x)
        self.events.append(("residual", x))
        if self.fail_at is not None and self.calls == self.fail_at:
            raise self.error
        return self.problem.residual(x)

    def __getattr__(self, name):
        if name not in OPTIONAL_METHODS:
            raise AttributeError(name)
        inner = getattr(self.__dict__["problem"], name)  # AttributeError when absent
        if name != "max_step":
            return inner

        def max_step(x):
            self.events.append(("max_step", np.array(x, dtype=float, copy=True)))
            return inner(x)

        return max_step




@attrs.frozen(kw_only=True)
class TanhSystem:
    """``r_i = s_i·[tanh(u_i) + Σ_{j≠i} A_ij·sin(u_j)]`` with ``u = (x - c)/w``.

    Parameters
    ----------
    root : (n,) array
        The root ``c``.
    width : (n,) array
        ``w > 0``: the distance over which ``r_i`` saturates (scale of the unknowns).
    scale : (n,) array
        ``s ≠ 0``: residual scale; its sign is the orientation ``sign(∂r_i/∂x_i)``.
    coupling : (n, n) array
        ``A`` with zero diagonal and row sums ``Σ_j |A_ij| <= 0.5``, which makes ``x = c`` the
        only root (all roots have ``|tanh u_i| <= 0.5``, where the map is a contraction).
    """

    root: np.ndarray = attrs.field(converter=_ro, eq=_ARRAY_EQ)
    width: np.ndarray = attrs.field(converter=_ro, eq=_ARRAY_EQ)
    scale: np.ndarray = attrs.field(converter=_ro, eq=_ARRAY_EQ)
    coupling: np.ndarray = attrs.field(converter=_ro, eq=_ARRAY_EQ)

    @coupling.validator
    def _check(self, attribute, value):
        n = self.root.size
        if not (self.width.shape == self.scale.shape == (n,) and value.shape == (n, n)):
            raise ValueError("root, width, scale must be (n,) and coupling (n, n)")
        if np.any(self.width <= 0) or np.any(self.scale == 0):
            raise ValueError("width must be > 0 and scale non-zero")
        if np.any(np.diag(value) != 0) or np.max(np.sum(np.abs(value), axis=1)) > 0.5:
            raise ValueError("coupling needs a zero diagonal and row sums of |A_ij| <= 0.5")

    @property
    def size(self) -> int:
        return self.root.size

    def residual(self, x):
        u = (np.asarray(x, dtype=float) - self.root) / self.width
        return self.scale * (np.tanh(u) + self.coupling @ np.sin(u))

    def jacobian(self, x):
        u = (np.asarray(x, dtype=float) - self.root) / self.width
        e = np.exp(-2.0 * np.abs(u))
        sech2 = 4.0 * e / (1.0 + e) ** 2  # 1/cosh² without overflow
        J = self.coupling * (np.cos(u) / self.width)[None, :] + np.diag(sech2 / self.width)
        return self.scale[:, None] * J

    def orientation(self):
        return np.sign(self.scale)

    def root_atol(self, residual_tol: float) -> np.ndarray:
        """Bound on ``|x_i - c_i|`` once ``max|r| <= residual_tol`` (with a safety factor 4)."""
        k = float(np.max(np.sum(np.abs(self.coupling), axis=1))) if self.size else 0.0
        eps = residual_tol / float(np.min(np.abs(self.scale)))
        ulp = 8 * np.spacing(np.abs(self.root) + self.width)
        return 4.0 * self.width * eps / (1.0 - k) + ulp

    def as_problem(self, *, jacobian: bool = False, orientation: bool = False,
                   max_step=None) -> FunctionProblem:
        """A :class:`FunctionProblem` exposing only the chosen optional methods."""
        return FunctionProblem(self.residual, jacobian=self.jacobian if jacobian else None,
                               orientation=self.orientation if orientation else None,
                               max_step=max_step)


@attrs.frozen(kw_only=True)
class CoupledPair:
    """``r = [x1² + x2 - 2, exp(x2 - 1) + 2·x2 + x1 - 4]``, root (1, 1) (another near
    x1 ≈ -0.7 is not reached from starts near (1, 1)); ``J(1,1) = [[2, 1], [1, 3]]``."""

    def residual(self, x):
        x1, x2 = np.asarray(x, dtype=float)
        return np.array([x1 * x1 + x2 - 2.0, np.exp(x2 - 1.0) + 2.0 * x2 + x1 - 4.0])

    def jacobian(self, x):
        x1, x2 = np.asarray(x, dtype=float)
        return np.array([[2.0 * x1, 1.0], [1.0, np.exp(x2 - 1.0) + 2.0]])

    def orientation(self):
        return np.ones(2)


@attrs.frozen(kw_only=True)
class NoRoot:
    """``r_i = x_i² + 1 > 0`` everywhere: a solver must not report convergence."""

    def residual(self, x):
        x = np.asarray(x, dtype=float)
        return x * x + 1.0


@attrs.frozen(kw_only=True, eq=False)
class SolverCase:
    """A problem with a known root.

    Attributes
    ----------
    problem : object
        Implements the :class:`~viscocontact.solvers.base.NonlinearProblem` protocol.
    x0, root : ndarray
        Start and known root.
    tolerances : Tolerances
        What to pass to ``solve`` (budgets generous enough for every built-in solver).
    root_atol : ndarray
        Expected ``|x_i - root_i|`` bound once ``max|r| <= tolerances.residual``.
    name : str
    """

    problem: Any
    x0: np.ndarray = attrs.field(converter=_ro)
    root: np.ndarray = attrs.field(converter=_ro)
    tolerances: Tolerances
    root_atol: np.ndarray = attrs.field(converter=_ro)
    name: str = ""

    def is_near_root(self, x) -> bool:
        return bool(np.all(np.abs(np.asarray(x) - self.root) <= self.root_atol))


DEFAULT_TOLERANCES = Tolerances(residual=1e-9, max_iterations=2000, max_evaluations=50_000)


def _normalise(raw: np.ndarray, k: float, width) -> np.ndarray:
    """Zero diagonal, row sums of |A_ij| scaled to k, then ``A_ij *= min(1, w_j/w_i)`` so that
    the Jacobian stays diagonally dominant by rows (``Σ_j |J_ij| <= k·|J_ii|`` at the root)
    whatever the widths."""
    a = np.array(raw, dtype=float)
    np.fill_diagonal(a, 0.0)
    rows = np.sum(np.abs(a), axis=1, keepdims=True)
    a = np.where(rows > 0, a * k / np.where(rows > 0, rows, 1.0), 0.0)
    w = np.asarray(width, dtype=float)
    return a * np.minimum(1.0, w[None, :] / w[:, None])


@st.composite
def tanh_systems(draw, min_size: int = 1, max_size: int = 12, max_coupling: float = 0.3,
                 width_decades: tuple[float, float] = (0.0, 0.0),
                 scale_decades: tuple[float, float] = (0.0, 0.0),
                 root_range: tuple[float, float] = (-5.0, 5.0),
                 negative_scales: bool = False) -> TanhSystem:
    """:class:`TanhSystem` with random roots, log-uniform widths and scales, and a coupling
    matrix whose row sums of ``|A_ij|`` are at most ``max_coupling`` (<= 0.5)."""
    n = draw(st.integers(min_size, max_size))
    floats = lambda lo, hi: st.floats(lo, hi, allow_nan=False, allow_infinity=False)  # noqa: E731
    root = draw(st.lists(floats(*root_range), min_size=n, max_size=n))
    width = [10.0 ** e for e in draw(st.lists(floats(*width_decades), min_size=n, max_size=n))]
    scale = [10.0 ** e for e in draw(st.lists(floats(*scale_decades), min_size=n, max_size=n))]
    if negative_scales:
        signs = draw(st.lists(st.sampled_from([-1.0, 1.0]), min_size=n, max_size=n))
        scale = [s * g for s, g in zip(scale, signs)]
    raw = np.array(draw(st.lists(floats(-1.0, 1.0), min_size=n * n, max_size=n * n))).reshape(n, n)
    k = draw(floats(0.0, max_coupling))
    return TanhSystem(root=root, width=width, scale=scale, coupling=_normalise(raw, k, width))


@st.composite
def solver_cases(draw, systems: st.SearchStrategy[TanhSystem] | None = None,
                 max_offset: float = 1.0, with_jacobian: st.SearchStrategy[bool] | None = None,
                 with_max_step: st.SearchStrategy[bool] | None = None,
                 tolerances: Tolerances = DEFAULT_TOLERANCES) -> SolverCase:
    """:class:`SolverCase` for a :class:`TanhSystem` started at ``x0 = c + w·u0`` with
    ``|u0_i| <= max_offset`` (1 keeps undamped Newton in its basin).

    The Jacobian is exposed or not (``with_jacobian``, random by default); ``orientation`` is
    exposed when some scale is negative or at random; a step bound ``max_step = b·w`` with
    ``b`` in [0.05, 1] is added when ``with_max_step`` draws True.
    """
    system = draw(systems if systems is not None else tanh_systems())
    n = system.size
    u0 = np.array(draw(st.lists(st.floats(-max_offset, max_offset), min_size=n, max_size=n)))
    jac = draw(with_jacobian if with_jacobian is not None else st.booleans())
    orient = bool(np.any(system.scale < 0)) or draw(st.booleans())
    bound = None
    if draw(with_max_step if with_max_step is not None else st.booleans()):
        bound = draw(st.floats(0.05, 1.0)) * system.width
    problem = system.as_problem(jacobian=jac, orientation=orient, max_step=bound)
    return SolverCase(problem=problem, x0=system.root + system.width * u0, root=system.root,
                      tolerances=tolerances, root_atol=system.root_atol(tolerances.residual),
                      name=f"tanh(n={n}, jacobian={jac}, max_step={bound is not None})")


def _coupling(n: int, k: float, seed: int, width=None) -> np.ndarray:
    raw = np.random.default_rng(seed).uniform(-1.0, 1.0, (n, n))
    return _normalise(raw, k, np.ones(n) if width is None else width)


def standard_cases(tolerances: Tolerances = DEFAULT_TOLERANCES) -> list[SolverCase]:
    """Deterministic cases used by :func:`~viscocontact.testing.conformance_solvers.check_solver`:
    a scalar equation, a coupled diagonal-dominant system with and without Jacobian, one with
    unknowns of very different scales (and negative orientations), a 2×2 system, and a system
    with a step bound. Every built-in solver with default options solves them all."""
    cases = []
    one = TanhSystem(root=[0.3], width=[1.0], scale=[1.0], coupling=[[0.0]])
    cases.append(SolverCase(problem=one.as_problem(), x0=[-0.4], root=one.root,
                            tolerances=tolerances, root_atol=one.root_atol(tolerances.residual),
                            name="tanh(n=1)"))
    n = 8
    sys8 = TanhSystem(root=np.linspace(-1.0, 2.0, n), width=np.ones(n), scale=np.ones(n),
                      coupling=_coupling(n, 0.3, 1))
    u0 = 0.6 * np.cos(np.arange(n))
    for jac in (False, True):
        cases.append(SolverCase(problem=sys8.as_problem(jacobian=jac), x0=sys8.root + u0,
                                root=sys8.root, tolerances=tolerances,
                                root_atol=sys8.root_atol(tolerances.residual),
                                name=f"tanh(n=8, jacobian={jac})"))
    widths = [0.02, 0.5, 2.0, 10.0]
    scaled = TanhSystem(root=[1e-3, 0.5, 20.0, 100.0], width=widths, scale=[0.3, -1.0, 3.0, -1.0],
                        coupling=_coupling(4, 0.3, 2, widths))
    cases.append(SolverCase(problem=scaled.as_problem(orientation=True),
                            x0=scaled.root + scaled.width * np.array([0.5, -0.4, 0.3, -0.5]),
                            root=scaled.root, tolerances=tolerances,
                            root_atol=scaled.root_atol(tolerances.residual),
                            name="tanh(n=4, unknowns 1e-3..1e2, widths 0.02..10)"))
    pair = CoupledPair()
    cases.append(SolverCase(problem=pair, x0=[1.3, 0.8], root=[1.0, 1.0], tolerances=tolerances,
                            root_atol=np.full(2, 10 * tolerances.residual), name="coupled pair"))
    cases.append(SolverCase(problem=sys8.as_problem(max_step=0.05), x0=sys8.root + u0,
                            root=sys8.root, tolerances=tolerances,
                            root_atol=sys8.root_atol(tolerances.residual),
                            name="tanh(n=8, max_step=0.05)"))
    return cases


def no_root_case(n: int = 3, tolerances: Tolerances | None = None) -> SolverCase:
    """:class:`NoRoot` from ``x0 = 0.5`` with a small budget; ``root`` is NaN."""
    tol = tolerances or Tolerances(residual=1e-9, max_iterations=50, max_evaluations=2000)
    return SolverCase(problem=NoRoot(), x0=np.full(n, 0.5), root=np.full(n, np.nan),
                      tolerances=tol, root_atol=np.zeros(n), name="no root")
