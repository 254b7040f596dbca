"""The equilibrium at one control value, contact-set changes included (thesis §4.4).

:class:`Equilibrium` holds what the solves of one problem share: the edge systems and their
shared evaluations, the residual's round-off floor, the births' regions and the growth of a
contact just born. One solve, its solver calls and the contact-set changes that restart them,
is a :class:`~.restarts.Restarts`.
"""
from __future__ import annotations

import attrs
import numpy as np

from ...contact.topology import TopologyChange, repair
from .restarts import REFINED_TENSION, Restarts
from .sets import MIN_GAP, MIN_WIDTH, Control
from .state import State
from .system import EdgeSystem, Evaluations

__all__ = ["Equilibrium", "REFINED_TENSION"]


class Equilibrium:
    """Equilibrium solves of one problem.

    Parameters
    ----------
    prep : Prepared
    spec : MeshSpec
    policy : MeshPolicy
        Element counts per contact (refinements are recorded on it).
    adhesion : AdhesionModel
    solver, fallback : NonlinearSolver
        The primary solver, and the one taken from where it stopped (or ``None``).
    tolerances : Tolerances
        Already scaled to the solid's stiffness (:func:`~.system.residual_scale`).
    max_restarts : int
    checks : Checks
    log : SolveLog
    """

    def __init__(self, *, prep, spec, policy, adhesion, solver, fallback, tolerances,
                 max_restarts, checks, log):
        self.prep = prep
        self.spec = spec
        self.policy = policy
        self.adhesion = adhesion
        self.solver = solver
        self.fallback = fallback
        self.tolerances = tolerances
        self.max_restarts = max_restarts
        self.checks = checks
        self.log = log
        self._noise: dict[tuple, float] = {}      # round-off floor per (edges, elements)
        self._evaluations = Evaluations()         # shared by the systems of its solves
        #: the last reason the adhesion model gave for a contact set it does not handle, in any
        #: system of this solve (None: none met)
        self.limitation: str | None = None

    @property
    def adhesive(self) -> bool:
        """Whether the adhesion model has a work of adhesion (adhesive contacts)."""
        return self.adhesion.work_of_adhesion > 0

    @property
    def analytic(self) -> bool:
        """Whether the adhesion model gives residual derivatives (analytic Jacobians)."""
        from ...adhesion.base import AdhesionModel

        return (type(self.adhesion).residual_derivatives
                is not AdhesionModel.residual_derivatives)

    @property
    def jacobian_solver(self) -> bool:
        """Whether the continuation's :attr:`corrector` asks for Jacobians (the built-in
        Newton, Broyden and nonlinear CG; a bisection march does not)."""
        from ...solvers._fd import FiniteDifferenceOptions

        return isinstance(self.corrector, FiniteDifferenceOptions)

    @property
    def corrector(self):
        """The solver of the continuation's steps (the approach's steps at a fixed control
        with the contact set held, and the settling solves of the edges' motion): the built-in
        Newton where the adhesion model gives analytic derivatives, else the scene's solver.

        A step's solve is a corrector: it starts within a fraction of a half-width of its
        root, and where it fails the continuation takes the failure for an event (a fold; a
        merge where its iterates cross a neck). With a march or a solver without a quadratic
        finish that failure was the solver's, not the branch's: on campaign seed 130 (a rough
        energy-balance contact, bisection) every step within 1e-4 of the load past
        p̃∞ = 0.123 merged two contacts 0.06 apart, and the motion, from where the climb
        bracketed that "merge", came to rest on the same branch, 1.4e-4 further, 1 s a step.
        The scene's solver solves the target and the solves from a caller's start."""
        if not self.analytic:
            return self.solver
        from ...solvers import Newton

        return Newton()

    def system(self, control: Control, edges, counts=None) -> EdgeSystem:
        """The edge system of ``edges`` (element counts from the mesh policy unless given)."""
        if counts is None:
            counts = self.policy.counts_for(edges)
        return EdgeSystem(self.prep, self.spec, self.adhesion, control, edges, counts,
                          on_limitation=self._limited, shared=self._evaluations)

    def _limited(self, reason: str) -> None:
        self.limitation = reason

    def evaluated(self, edges, control: Control):
        """``(fields, r)`` of ``edges`` at ``control``: the fields (None where the adhesion
        model has no field there) and the edge residuals; None when the edges are no valid
        contact set. A solve from ``edges`` at ``control`` right after takes this evaluation
        from the shared ones (:class:`~.system.Evaluations`)."""
        x = np.asarray(edges, dtype=float)
        system = self.system(control, x)
        try:
            fields, _, r = system.evaluate(x)
        except TopologyChange:
            return None
        self.log.evaluations += system.evaluations
        return fields, r

    def residual_at(self, edges, control: Control):
        """The edge residuals of ``edges`` (``None`` when they are no valid contact set)."""
        out = self.evaluated(edges, control)
        return None if out is None else out[1]

    def fields_at(self, edges, control: Control):
        """The fields of ``edges`` at ``control`` (None where they are no valid contact set or
        the adhesion model has no field there; :meth:`evaluated`)."""
        out = self.evaluated(edges, control)
        return None if out is None or not np.all(np.isfinite(out[1])) else out[0]

    def solve(self, edges, control: Control, use_fallback: bool = True,
              budget: int | None = None, refine: bool = True, polish: bool = True,
              fallback_budget: int | None = None, probation: int = 0,
              pace: tuple[float, ...] = (), reduction: float = 0.0,
              changes: bool = True, corrector: bool = False) -> State:
        """Equilibrium at ``control`` from ``edges`` (contact-set changes included).

        ``use_fallback = False`` skips the fallback march when the primary solver stops, and
        ``budget`` caps the residual evaluations of each solver call: the approach path uses both
        for its trial steps, since a solve that fails near a fold costs hundreds of evaluations
        while a halved step (and at the end the snap) finds the jump anyway. ``fallback_budget``
        caps the fallback's calls instead when given. ``probation`` sets
        :attr:`Tolerances.probation` for the primary solver's calls (not the fallback's): the
        approach's trial steps stop a solve that makes no progress and halve the step instead;
        ``pace`` sets :attr:`Tolerances.pace` with it for the first solver call, from the
        given edges (not for the calls after contacts are born or merge, whose starts are far
        from their roots and gain slowly at first).

        ``reduction``: each solver call converges once ``max|r|`` is below this fraction of its
        value at the call's start, or below the tolerance, whichever is larger (0: the
        tolerance; :meth:`reduced`). The approach's intermediate steps use it: their states are
        starts for the next step, whose prediction is further off than that.

        ``refine = False`` reports a contact whose small tension and split alternate as a cycle
        instead of refining it (:data:`REFINED_TENSION`): the approach's intermediate steps,
        where two contacts about to merge pass through a nearly vanishing pressure between them
        for a moment; a halved step gets past it, and a refinement would stay for the rest of
        the solve.

        ``polish``: a converged state is solved once more with the edge zones of its own edges
        (the zones are fixed within a solve, from the edges it starts at, so the discretisation
        would otherwise depend on the start by about 1e-7 in Ã); then the same root gives the same
        answer whatever the path and the solver. The approach's intermediate steps skip it.

        ``changes = False``: the contact set is held. Where the solve would change it (a birth,
        a merge, a detachment, a split), it stops and returns the state with
        :attr:`State.change` set (for a birth, the converged state of the held set, whose
        fields show where the profile penetrates): the approach locates the change along its path and
        makes it there.

        ``corrector``: solved by the continuation's :attr:`corrector` instead of the scene's
        solver.
        """
        return Restarts(self, control, use_fallback=use_fallback, budget=budget,
                        refine=refine, polish=polish, fallback_budget=fallback_budget,
                        probation=probation, pace=pace, reduction=reduction,
                        changes=changes, corrector=corrector).run(edges)

    def born(self, fields, outside=None) -> tuple[list, bool]:
        """The regions ``(a, b, depth)`` where contacts are born from the state of ``fields``,
        and whether they snapped in: where the profile penetrates, whatever the model makes of
        the gap elsewhere (Maugis-Dugdale: a gap below the range outside its zones, which a
        penetrating asperity also has around it); else, for a finite-range law, where a peak
        comes within the range. ``outside``: :meth:`Checks.gap_outside` when at hand."""
        xs, gap = self.checks.gap_outside(fields) if outside is None else outside
        regions = self.checks.births(fields, (xs, gap))
        if regions:
            return regions, False
        regions = self.adhesion.snap_in(xs, gap, fields)
        return regions, bool(regions)

    def grow(self, edges, control: Control, born) -> np.ndarray | None:
        """``edges`` with the contacts just born (``born``: their ``(a, b)``) widened while their
        edges want to grow (negative residual), each edge by steps that start at half the born
        contact's half-width and double each time (so that an edge stops within twice the
        distance it had to go); None when they close the contact over the period.

        An adhesive contact is born with the width of the region where the profile penetrates
        the check grid, far below its equilibrium: adhesion pulls it open at once (a JKR-like
        jump in). A solver bounded to steps of a fraction of the half-width took 20-90
        evaluations to widen it, or gave up when the jump reached a neighbour (the two merge);
        one residual per doubling brings it within a step of its equilibrium, or to the merge.
        """
        x = np.asarray(edges, dtype=float).copy()
        grow = np.zeros(len(x), dtype=bool)
        for a, b in born:
            at = np.flatnonzero(np.isclose(x[0::2], a, rtol=0, atol=1e-12)
                                & np.isclose(x[1::2], b, rtol=0, atol=1e-12))
            for j in at:
                grow[2 * j:2 * j + 2] = True
        outward = np.tile([-1.0, 1.0], len(x) // 2)
        unit = 0.5 * np.repeat(0.5 * (x[1::2] - x[0::2]), 2)   # half the born half-width
        factor = 1.0
        while np.any(grow) and factor < 1e6:
            r = self.residual_at(x, control)
            if r is None or not np.all(np.isfinite(r)):
                break
            grow &= r < 0
            if not np.any(grow):
                break
            trial = x + np.where(grow, factor * unit, 0.0) * outward
            merged, changed, _, full = repair(trial, MIN_WIDTH, MIN_GAP)
            if full:
                return None
            if changed:
                self.log.event("a contact just born jumped open and merged")
                return merged
            x, factor = trial, 2.0 * factor
        return x

    def noise_floor(self, system, x, tolerances):
        """``tolerances`` with the residual tolerance raised to the round-off floor of the edge
        residuals when that floor is higher.

        The floor is the largest change of any edge residual when every edge moves by a
        relative 1e-13 (far below any physical change), measured once per number of edges and
        elements per contact in a solve (one extra residual evaluation). Energy-balance
        residuals are differences of energies over δX and carry round-off of 1e-10 to 5e-9 on
        rough multi-contact meshes; asking a solver for less than that makes it wander at the
        floor until its budget runs out (200 evaluations for one approach step of the thesis
        rough profile at p̃∞ ≈ 0.4). The accepted floor is four times the measured change; the
        result reports the actual residual.
        """
        n = (len(x), system.counts)
        if n not in self._noise:
            self._noise[n] = self.noise(system, x)
        return self._raised(tolerances, 4.0 * self._noise[n])

    def _raised(self, tolerances, floor: float):
        if floor <= tolerances.residual:
            return tolerances
        if not any(e.startswith("residual tolerance raised") for e in self.log.events[-3:]):
            self.log.event(f"residual tolerance raised to the round-off floor {floor:.2g}")
        return attrs.evolve(tolerances, residual=floor)

    @staticmethod
    def noise(system, x) -> float:
        """The largest change of an edge residual when every edge moves by a relative 1e-13
        (one residual evaluation besides ``x``'s, which is last: a solver's next call finds it
        cached)."""
        r1 = system.residual(x * (1.0 + 1e-13))
        r0 = system.residual(x)
        with np.errstate(invalid="ignore"):      # inf - inf: a point a model rejects
            d = np.abs(r1 - r0)
        return float(np.max(d)) if np.all(np.isfinite(d)) else 0.0

    def stalled_at_floor(self, system, x, size: float, tolerances):
        """``tolerances`` raised to the round-off floor measured at ``x``, where a solver
        stalled at ``max|r| = size``, when ``size`` is within it (the solve is converged to what
        its residuals resolve); else None. The floor measured once for the contact set's size
        (:meth:`noise_floor`) is another state's, and it varies: on campaign seed 84 (a sinusoid
        on an SLS with β = 425) it was below 1e-9 at the first contact and 2.7e-7 near the
        target load, where a one-ulp move of an edge changed its residual by 3e-8 to 2.7e-7. The
        larger floor is kept for the contact set's size."""
        if not np.all(np.isfinite(x)):
            return None
        measured = self.noise(system, np.asarray(x, dtype=float))
        n = (len(x), system.counts)
        self._noise[n] = max(self._noise.get(n, 0.0), measured)
        floor = 4.0 * measured
        if not size <= floor:
            return None
        return self._raised(tolerances, floor)

    @staticmethod
    def reduced(system, x, tolerances, reduction: float):
        """``tolerances`` with the residual tolerance raised to ``reduction`` times ``max|r|`` at
        ``x`` (a solver call's start; the solver's first evaluation finds it cached) when that is
        higher; ``tolerances`` when ``reduction`` is 0 or the residual there is not finite."""
        if reduction <= 0.0:
            return tolerances
        r = system.residual(x)
        if not np.all(np.isfinite(r)):
            return tolerances
        goal = reduction * float(np.max(np.abs(r)))
        return tolerances if goal <= tolerances.residual else attrs.evolve(tolerances,
                                                                           residual=goal)

    def closes(self, edges, control: Control) -> bool:
        """Whether the fallback march from ``edges`` closes the contact over the period."""
        system = self.system(control, edges)
        try:
            self.fallback.solve(system, edges, self.tolerances)
        except TopologyChange as change:
            self.log.evaluations += system.evaluations
            return change.full_contact
        self.log.evaluations += system.evaluations
        return False
