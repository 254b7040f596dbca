"""The jump of a contact whose branch of equilibria has ended: overdamped edge motion.

Past a fold (a speed or a load at which its contact set has no equilibrium nearby) a contact
moves on its own until it finds one. A steady-state model has no dynamics of that motion, so the
rule is stated: every edge moves outward at a speed proportional to minus its residual (the
imbalance of its energy release rate against the work of adhesion, the residual of the
Griffith balance), at fixed speed ζ and fixed control, until the edges stop,

    dX_i/dt = -o_i r_i(X),   o_i = +1 for a right edge, -1 for a left one,

so that an edge whose residual is negative (it would advance, :meth:`Path.wants_to_grow`)
advances, and one with a positive residual recedes. The flow is integrated by linearly implicit
Euler steps, ``(I/h + O J) δ = -O r``, with the step ``h`` chosen by step doubling so that no edge
moves more than ``tolerance`` of its contact's half-width (or of the mean half-width, when that
is larger) away from the two half-steps; contacts that meet merge, contacts that vanish detach,
contacts that close over the period close. As the edges slow down the steps grow and become
Newton's; once ``max|r|`` has fallen to :data:`SETTLED` times the solver's tolerance, the
equilibrium solve (births, refinements) finishes from there.

The landing is the equilibrium at the end of this flow: a property of the state the jump starts
from, not of a search order; a tenth of the tolerance gives the same landing (tested).
"""
from __future__ import annotations

import attrs
import numpy as np

from ...contact.topology import TopologyChange, repair
from .sets import MIN_GAP, MIN_WIDTH, Control
from .state import Outcome, State

#: The flow ends, and the equilibrium solve finishes, once ``max|r|`` is below this many times
#: the solver's residual tolerance.
SETTLED = 1e3


@attrs.frozen
class RelaxFrom:
    """An initial contact set that asks a solve for the jump: the overdamped edge motion from
    ``edges`` at the problem's control (:class:`Relaxation`), then the equilibrium there.
    Pass it as ``ContactProblem.solve(initial=RelaxFrom(edges))``."""

    edges: np.ndarray = attrs.field(converter=lambda v: np.asarray(v, dtype=float).ravel())
    tolerance: float = 0.02


def _scale(x: np.ndarray) -> np.ndarray:
    half = 0.5 * (x[1::2] - x[0::2])
    return np.repeat(np.maximum(half, half.mean()), 2)


class Relaxation:
    """The overdamped edge motion of one solve (see the module docstring).

    Parameters
    ----------
    equilibrium : Equilibrium
    closed : ClosedContact
    tolerance : float
        Largest local error of a step, in half-widths.
    max_steps : int
        Accepted and rejected steps allowed before the motion is given up (None returned).
    """

    def __init__(self, equilibrium, closed, tolerance: float = 0.02, max_steps: int = 400):
        self.eq = equilibrium
        self.closed = closed
        self.tolerance = tolerance
        self.max_steps = max_steps

    def run(self, edges, control: Control) -> State:
        """The state the edges' motion from ``edges`` ends in (not converged, with the reason,
        when the motion does not end)."""
        systems: list = []
        try:
            return self._run(np.asarray(edges, dtype=float).copy(), control, systems)
        finally:
            self.eq.log.evaluations += sum(s.evaluations for s in systems)

    def _failed(self, x, why: str) -> State:
        return State(outcome=Outcome.NOT_CONVERGED, edges=x, message=f"the edges' overdamped "
                     f"motion {why}")

    def _run(self, x: np.ndarray, control: Control, systems: list) -> State:
        system = self.eq.system(control, x)
        systems.append(system)
        settled = SETTLED * self.eq.tolerances.residual
        h = None
        moved = 0
        for _ in range(self.max_steps):
            rj = self._linearised(system, x)
            if rj is None:
                return self._failed(x, "met a contact set without a valid field")
            r, J = rj
            if np.max(np.abs(r)) <= settled:
                break
            if h is None:       # the first step moves the fastest edge a twentieth of a scale
                h = 0.05 * float(np.min(_scale(x) / np.maximum(np.abs(r), 1e-300)))
            whole = self._step(r, J, h)
            first = self._step(r, J, 0.5 * h)
            middle = None if first is None else x + first
            rj_mid = None if middle is None else self._linearised(system, middle)
            if whole is None or first is None or middle is None or rj_mid is None:
                h *= 0.25
                continue
            second = self._step(rj_mid[0], rj_mid[1], 0.5 * h)
            if second is None:
                h *= 0.25
                continue
            error = float(np.max(np.abs(whole - first - second) / _scale(x)))
            if error > self.tolerance:
                h *= max(0.2, 0.9 * np.sqrt(self.tolerance / error))
                continue
            h *= min(4.0, 0.9 * np.sqrt(self.tolerance / max(error, 1e-300)))
            moved += 1
            x, changed, _, full = repair(middle + second, MIN_WIDTH, MIN_GAP)
            if full:
                if control.is_load and not self.closed.supports(control.value):
                    return self._failed(x, "closed the contact, which does not carry this "
                                           "load")
                self.eq.log.event("the edges' motion closed the contact")
                return State.full_contact()
            if not x.size:
                self.eq.log.event("the edges' motion detached every contact")
                return self.eq.solve(x, control)
            if changed:
                system = self.eq.system(control, x)
                systems.append(system)
        else:
            return self._failed(x, f"did not stop within {self.max_steps} steps")
        self.eq.log.event(f"the edges moved in {moved} steps of their overdamped motion")
        return self.eq.solve(x, control)

    def _linearised(self, system, x):
        """``(r, J)`` at ``x`` (None where ``x`` is no valid contact set)."""
        try:
            r = system.residual(x)
            if r is None or not np.all(np.isfinite(r)):
                return None
            J = system.jacobian(x)
        except TopologyChange:
            return None
        return r, J

    @staticmethod
    def _step(r, J, h):
        """The linearly implicit Euler move ``δ`` of ``dX/dt = -O r`` over ``h``."""
        o = np.tile([-1.0, 1.0], len(r) // 2)
        a = np.eye(len(r)) / h + o[:, None] * J
        try:
            move = np.linalg.solve(a, -o * r)
        except np.linalg.LinAlgError:
            return None
        return move if np.all(np.isfinite(move)) else None
