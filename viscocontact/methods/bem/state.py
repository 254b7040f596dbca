"""What an equilibrium step returns, and the log a solve keeps."""
from __future__ import annotations

import enum
from typing import Any

import attrs
import numpy as np

from ..._events import EventList


class Outcome(enum.Enum):
    """How an equilibrium step ended."""

    CONVERGED = "converged"
    NOT_CONVERGED = "not_converged"
    FULL_CONTACT = "full_contact"
    NO_CONTACT = "no_contact"


@attrs.frozen(kw_only=True, eq=False)
class State:
    """An equilibrium step's result: the outcome, the edges it ended at, the fixed-edge field
    solution and edge context there (``None`` without contacts), the largest edge residual, a
    message, and for a converged state (or one stopped at a birth or a split) the edge system it
    was solved with (its derivatives there give the path's tangent; its element counts, the
    refinement of a split)."""

    outcome: Outcome
    edges: np.ndarray
    fields: Any = None
    ctx: Any = None
    residual: float = 0.0
    message: str = ""
    system: Any = None
    #: a contact-set change the solve stopped at instead of making it (``Equilibrium.solve``
    #: with ``changes=False``): "birth", "merge", "detachment" or "split"; from the edges'
    #: motion (not converged) "cycle" (a split whose parts merge again) or "reborn" (contacts
    #: born at a rest state, or after every contact detached at a positive penetration, that
    #: are born there again when the motion comes back to that state); "" otherwise
    change: str = ""

    @property
    def converged(self) -> bool:
        return self.outcome is Outcome.CONVERGED

    @classmethod
    def full_contact(cls, message: str = "contact closed over the period") -> "State":
        return cls(outcome=Outcome.FULL_CONTACT, edges=np.zeros(0), message=message)

    @classmethod
    def no_contact(cls) -> "State":
        return cls(outcome=Outcome.NO_CONTACT, edges=np.zeros(0), message="no contact at this load")


class SolveLog:
    """Counters, events and the residual history of one solve (reported in the result)."""

    def __init__(self):
        self.iterations = 0
        self.evaluations = 0
        self.events: list[str] = EventList("bem")       # logged as they happen
        #: typed events of the path (``{"kind": ..., <values>}``; see :mod:`.approach`)
        self.records: list[dict] = []
        self.history: list[float] = []

    def event(self, text: str) -> None:
        self.events.append(text)

    def count(self, system, result=None) -> None:
        """Add a system's residual evaluations (and a solver result's iterations and history)."""
        self.evaluations += system.evaluations
        if result is not None:
            self.iterations += result.iterations
            self.history.extend(float(v) for v in result.residual_history)
