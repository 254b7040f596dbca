r"""The :class:`SolutionMethod` interface: how an equilibrium is computed.

A :class:`~viscocontact.problem.ContactProblem` is a value (profile, rheology, kernel, adhesion,
load, ζ, discretization); a method turns it into a :class:`~viscocontact.result.ContactResult`.
Methods register in the entry-point group ``viscocontact.methods`` like every other component,
and the scene chooses one in ``[method] kind = ...`` (``"auto"`` lets the plan choose).

Contract for implementers
-------------------------
1. A frozen attrs class, keyword-only, validated at construction; class attribute :attr:`name`
   is the registered name, written into every result as ``extras["method"]``.
2. :meth:`unsupported` returns why the method cannot solve a problem (``None`` when it can),
   e.g. an adhesive scene for a method without edge energy balance. It must be cheap: the
   planner asks it for every problem.
3. :meth:`solve` returns a :class:`~viscocontact.result.ContactResult` with the same schema as
   every other method: ``extras["method"]`` (the name) and ``extras["error_estimate"]`` (the
   estimated relative discretisation error of the area and friction, NaN when the method has
   no estimate). ``initial`` is a previous result or an array of contact edges to start from
   (a warm start along a sweep; a method may ignore it), ``prepared`` the problem's
   :class:`Prepared` tables when the caller has them.
4. :meth:`plan_steps` describes what a solve will compute (``solve --explain``).
"""
from __future__ import annotations

import abc
from typing import Any, ClassVar

import attrs


@attrs.frozen(kw_only=True, eq=False)
class Prepared:
    """What a problem precomputes once for its method: the kernel's tables, the normalised
    profile (a :class:`~viscocontact.contact.fields.NormalizedProfile`) and its m2
    (:meth:`ContactProblem.prepare <viscocontact.problem.ContactProblem.prepare>`)."""

    kernel: Any                 # the kernel's prepared tables (duck-typed)
    shape: Any
    m2: float


class SolutionMethod(abc.ABC):
    """How an equilibrium is computed; see the module docstring for the contract."""

    name: ClassVar[str] = ""

    def unsupported(self, problem) -> str | None:
        """Why this method cannot solve ``problem`` (``None``: it can)."""
        return None

    @abc.abstractmethod
    def solve(self, problem, initial=None, *, fields: bool = False, prepared=None):
        """The equilibrium of ``problem`` (a :class:`~viscocontact.result.ContactResult`)."""

    def plan_steps(self, problem, prepared) -> tuple:
        """:class:`~viscocontact.plan.PlanStep` values describing a solve (default: none)."""
        return ()
