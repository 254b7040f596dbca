"""The speed-ramp history: a continuation in log ζ at constant load, with events.

The ramp starts at the chain's first ζ from the approach at that speed and moves ζ in steps of
log ζ that it chooses itself:

* a step is predicted by the secant through the last two states of the same contact set and
  accepted when every converged edge lies within ``tolerance`` of its contact's half-width (or
  of the mean half-width, when that is larger) of the prediction; the next step grows or shrinks with the square root of the ratio (the secant's
  error is second order in the step), up to ``largest_step`` decades;
* a step that changes the contact set (an *event*: contacts born, lost by a merge or a
  detachment, the contact closing over the period or opening) is halved until it spans at most
  ``tolerance`` decades, which locates the event in ζ to that resolution, and then accepted;
* a step that does not converge, or lands more than ``tolerance`` away from its prediction, at
  the smallest step (a tenth of the event resolution) means the branch ends there (a fold in
  ζ): the contact *jumps*. The stated jump rule is the overdamped motion of the edges from the
  last state on the branch, at the speed just past the fold
  (:mod:`viscocontact.methods.bem.relax`): every edge moves at a speed proportional to its
  residual until the edges stop.

The requested ζ are recorded from this path without changing it (dense output): once the path
passes a recorded ζ, that point is solved from the two states that bracket it, with their
interpolation as the start. So the path, and with it every recorded value, does not depend on
which ζ are recorded, and a finer tolerance converges it (:meth:`SpeedRamp.refined`).

The path's state between two recorded points (:class:`RampState`) is stored with the first of
them (the ``ramp`` column), so that a resumed study continues the same path.
"""
from __future__ import annotations

import json
import math
from typing import Any, Callable

import attrs
import numpy as np

from .history import SpeedRamp


@attrs.frozen
class Closed:
    """The start of a solve from full contact (``ContactProblem.solve(initial=CLOSED)``)."""

    full_contact: bool = True
    edges: np.ndarray = attrs.field(factory=lambda: np.zeros(0))


CLOSED = Closed()


@attrs.frozen(kw_only=True)
class Node:
    """One equilibrium on the ramp's path: ``log10 ζ``, the flat edges, full contact."""

    log_zeta: float
    edges: tuple
    full: bool

    @property
    def zeta(self) -> float:
        return 10.0 ** self.log_zeta

    @property
    def n_contacts(self) -> int:
        return -1 if self.full else len(self.edges) // 2

    def start(self):
        """The contact set a solve starts from (full contact: a closed contact to open)."""
        return CLOSED if self.full else np.asarray(self.edges, dtype=float)

    @classmethod
    def of(cls, log_zeta: float, result) -> "Node":
        return cls(log_zeta=float(log_zeta), full=bool(result.full_contact),
                   edges=tuple(float(v) for v in np.asarray(result.edges, float).ravel()))


@attrs.frozen(kw_only=True)
class RampState:
    """Where the path stands: its last two nodes (the older may be None), the length of the
    next step (decades of ζ) and the ramp's direction (+1 up in ζ, -1 down; 0 before the
    path's first step, at the chain's first point)."""

    older: Node | None
    last: Node
    step: float
    direction: float = 0.0

    def heading(self, log_zeta: float) -> float:
        """The ramp's direction: its own once it has stepped (a recorded ζ that the path has
        already passed lies behind it, not ahead), else towards ``log_zeta``."""
        if self.direction:
            return self.direction
        return 1.0 if log_zeta > self.last.log_zeta else -1.0

    def to_json(self) -> str:
        def node(n):
            return None if n is None else [n.log_zeta, list(n.edges), n.full]
        return json.dumps({"older": node(self.older), "last": node(self.last),
                           "step": self.step, "direction": self.direction})

    @classmethod
    def from_json(cls, text: str) -> "RampState":
        data = json.loads(text)

        def node(v):
            return None if v is None else Node(log_zeta=v[0], edges=tuple(v[1]), full=v[2])
        older, step = node(data["older"]), data["step"]
        # a state written without its direction: a path that had stepped signed its step
        stepped = math.copysign(1.0, step) if older is not None else 0.0
        return cls(older=older, last=node(data["last"]), step=step,
                   direction=float(data.get("direction", stepped)))


def event(kind: str, zeta: float, before: Node, after: Node, **extra) -> dict[str, Any]:
    """A typed event record (JSON-ready): ``kind``, ``zeta`` and the contacts before and after
    (-1: full contact)."""
    return {"kind": kind, "zeta": float(zeta), "contacts": [before.n_contacts, after.n_contacts],
            **extra}


def set_change(before: Node, after: Node) -> str | None:
    """The kind of the contact-set change between two nodes, or None."""
    if before.full == after.full and before.n_contacts == after.n_contacts:
        return None
    if after.full:
        return "closure"
    if before.full:
        return "opening"
    return "birth" if after.n_contacts > before.n_contacts else "loss"


def predicted(older: Node | None, last: Node, log_zeta: float):
    """The secant prediction of the edges at ``log_zeta`` (the last edges when the last two
    nodes differ in contact set; :data:`CLOSED` from full contact)."""
    if last.full:
        return CLOSED
    x1 = np.asarray(last.edges, dtype=float)
    if older is None or set_change(older, last) is not None or older.log_zeta == last.log_zeta:
        return x1
    x0 = np.asarray(older.edges, dtype=float)
    t = (log_zeta - last.log_zeta) / (last.log_zeta - older.log_zeta)
    return x1 + t * (x1 - x0)


def prediction_error(guess, node: Node) -> float:
    """The largest edge move from ``guess`` to ``node``, in units of its contact's half-width
    or of the mean half-width when that is larger (a narrow contact's edges are held to the
    contact area's resolution, not to their own width)."""
    if isinstance(guess, Closed) or node.full or len(node.edges) != len(guess):
        return 0.0
    x = np.asarray(node.edges, dtype=float)
    half = 0.5 * (x[1::2] - x[0::2])
    scale = np.repeat(np.maximum(half, half.mean()), 2)
    return float(np.max(np.abs(x - guess) / np.maximum(scale, 1e-12), initial=0.0))


Solve = Callable[[float, "np.ndarray | None"], Any]


@attrs.define
class Ramp:
    """The march of one chain's path; ``solve(zeta, start)`` is the equilibrium at ζ from a
    flat contact set (None: the approach from first touch)."""

    history: SpeedRamp
    solve: Solve
    direction: float
    events: list = attrs.Factory(list)
    solves: int = 0
    evaluations: int = 0

    def _solve(self, zeta: float, start):
        result = self.solve(zeta, start)
        self.solves += 1
        self.evaluations += int(result.function_evaluations)
        return result

    def advance(self, state: RampState) -> tuple[RampState, Any]:
        """One accepted step from ``state``: the new state and the result of its node."""
        ramp, h = self.history, abs(state.step)     # a state written before: a signed step
        last = state.last
        while True:
            target = last.log_zeta + self.direction * h
            guess = predicted(state.older, last, target)
            result = self._solve(10.0 ** target, guess)
            node = Node.of(target, result) if result.converged else None
            error = prediction_error(guess, node) if node is not None else math.inf
            change = None if node is None else set_change(last, node)
            smallest = h <= ramp.smallest_step * (1 + 1e-9)
            if node is not None and change is None and error <= ramp.tolerance:
                grow = 2.0 if error == 0 else min(2.0, 0.9 * math.sqrt(ramp.tolerance / error))
                nxt = min(ramp.largest_step, h * max(grow, 0.5))
                return RampState(older=last, last=node, step=nxt,
                                 direction=self.direction), result
            if node is not None and change is not None and h <= ramp.tolerance * (1 + 1e-9):
                self.events.append(event(change, 10.0 ** target, last, node))
                return RampState(older=last, last=node, step=ramp.tolerance,
                                 direction=self.direction), result
            if smallest:
                return self.jump(last, target, result)
            h = max(ramp.smallest_step, 0.5 * h if node is None or change is not None
                    else h * max(0.25, 0.9 * math.sqrt(ramp.tolerance / error)))

    def jump(self, last: Node, target: float, failed) -> tuple[RampState, Any]:
        """The branch ends between ``last`` and ``target``: the edges' overdamped motion from
        ``last`` at ``target`` (from full contact: its opening)."""
        from ..methods.bem.relax import RelaxFrom

        start = (last.start() if last.full
                 else RelaxFrom(np.asarray(last.edges), tolerance=self.history.tolerance))
        result = self._solve(10.0 ** target, start)
        if not result.converged:
            raise RampFailed(f"the speed ramp's branch ends at ζ = {last.zeta:.6g} and the "
                             f"contact's jump at ζ = {10.0 ** target:.6g} did not converge "
                             f"({result.message}; the last step: {failed.message})", result)
        node = Node.of(target, result)
        self.events.append(event("jump", 10.0 ** target, last, node,
                                 area=[None, float(result.area)]))
        return RampState(older=None, last=node, step=self.history.tolerance,
                         direction=self.direction), result

    def record(self, state: RampState, zeta: float) -> tuple[RampState, Any]:
        """March until the path reaches or passes ``zeta``, then solve the recorded point from
        the two nodes that bracket it; the path's state after the march and the result."""
        goal = math.log10(zeta)
        before = state.older
        while self.direction * (goal - state.last.log_zeta) > 0:
            before = state.last
            state, result = self.advance(state)
            if state.last.log_zeta == goal:
                return state, result
        if state.older is None:      # a jump: the goal lies past the fold
            before = None
        return state, self.between(before, state.last, goal)

    def between(self, a: Node | None, b: Node, goal: float):
        """The recorded point at ``goal`` between the path's nodes ``a`` and ``b`` (the
        interpolation of their edges as the start when they share a contact set, else the
        nearer node's edges; from ``b`` when ``a`` is None)."""
        start: np.ndarray | None
        if a is not None and set_change(a, b) is None and not a.full:
            t = (goal - a.log_zeta) / (b.log_zeta - a.log_zeta)
            start = (1 - t) * np.asarray(a.edges) + t * np.asarray(b.edges)
        elif a is not None and abs(goal - a.log_zeta) < abs(b.log_zeta - goal):
            start = a.start()
        else:
            start = b.start()
        return self._solve(10.0 ** goal, start)


class RampFailed(RuntimeError):
    """The ramp cannot go on: its branch ended and the jump's approach did not converge."""

    def __init__(self, message: str, result):
        super().__init__(message)
        self.result = result
