"""The result of one contact solve: a fixed schema, an enum status, a message, extras."""
from __future__ import annotations

import enum
from typing import TYPE_CHECKING, Any

import attrs
import numpy as np

if TYPE_CHECKING:
    from .units import PhysicalResult


class SolveStatus(enum.Enum):
    """Outcome of a solve."""

    CONVERGED = "converged"
    NOT_CONVERGED = "not_converged"
    NO_CONTACT = "no_contact"
    FAILED = "failed"


@attrs.frozen(kw_only=True, repr=False)
class ContactResult:
    """Equilibrium of one scene (dimensionless, equation 4.17).

    Attributes
    ----------
    area : float
        ``Ã = q0·(total contact length per period)``; 2π in full contact.
    mean_pressure, penetration : float
        ``p̃∞`` and ``Δ̃``.
    friction : float
        Viscoelastic friction coefficient μ (eq. 4.16), positive when it opposes sliding.
    reduced_friction : float
        ``μ/√m2`` (eq. 4.59).
    n_contacts : int
    edges : ndarray, shape (n_contacts, 2)
        ``[X̃_start, X̃_end]`` of each contact (empty in full contact).
    full_contact : bool
    converged : bool
    status : SolveStatus
    message : str
    residual : float
        Largest edge residual (stress-intensity units).
    iterations, function_evaluations : int
        Totals over the whole solve (all load steps and topology restarts).
    zeta, edge_perturbation : float
        ``ζ`` and the ``q0·δX`` of the adhesion model (0 without adhesion or in the limit).
    min_gap : float
        Smallest gap between solid and profile outside the contacts on the check grid (>= 0 means
        no interpenetration).
    edge_terms : EdgeTerms or None
        Per-edge ``δŨ/δX̃``, ``δL̃_P/δX̃``, effective work of adhesion, ``K̃`` (on request).
    fields : dict or None
        ``x``, ``pressure``, ``displacement``, ``gap`` arrays (on request).
    extras : dict
        Solver diagnostics: ``method`` and ``error_estimate`` (see the properties of the same
        names), ``events`` (topology changes, refinements), ``residual_history``,
        ``seconds`` and, for a solve that ends with contacts, ``conformity`` (the largest
        departure of the discrete solid from the profile inside the contacts, between
        collocation points, in units of the profile amplitude: a discretisation error).
        The power balance in friction units: ``friction_dissipation`` (the bulk dissipation
        over V·load) plus ``friction_edges`` (the net energy flux into the edges'
        square-root singularities, ``K_e K̃²/4`` into each trailing edge and out of each leading
        one) equals ``friction`` to discretisation error. ``outside_model`` is the reason why
        the result lies where its adhesion model does not hold (``""`` where it holds; the
        message says it too): with a finite edge advance δX, where the bulk dissipation misses
        more than 2 % of the friction (``docs/edges.md``, "Friction and dissipated power at
        edges").
    """

    area: float
    mean_pressure: float
    penetration: float
    friction: float
    reduced_friction: float
    n_contacts: int
    edges: np.ndarray
    full_contact: bool
    converged: bool
    status: SolveStatus
    message: str
    residual: float
    iterations: int
    function_evaluations: int
    zeta: float
    edge_perturbation: float
    min_gap: float
    edge_terms: Any = None
    fields: Any = None
    extras: dict = attrs.field(factory=dict)

    @property
    def method(self) -> str:
        """The registered name of the :class:`~viscocontact.methods.base.SolutionMethod` that
        computed this result (``extras["method"]``; ``""`` when unknown)."""
        return str(self.extras.get("method", ""))

    @property
    def error_estimate(self) -> float:
        """The method's estimate of the relative discretisation error of Ã and μ
        (``extras["error_estimate"]``; NaN when the method gives none)."""
        return float(self.extras.get("error_estimate", float("nan")))

    def physical(self, scene) -> "PhysicalResult":
        """This result of ``scene`` in SI units (contact length, edges and penetration in m,
        pressures in Pa), from the scene's ``[physical]`` table
        (:func:`~viscocontact.units.physical_result`)."""
        from .units import physical_result

        return physical_result(self, scene)

    def to_dict(self, *, with_fields: bool = False) -> dict:
        """The result as plain Python data (the keys of ``viscocontact solve --json``).

        Numbers are Python floats and ints; NaN and inf are kept as floats (a friction
        coefficient without contact is NaN, the gap without contact inf): :meth:`to_json` writes
        them as ``null``.
        """
        out = {
            "area": self.area, "mean_pressure": self.mean_pressure,
            "penetration": self.penetration, "friction": self.friction,
            "reduced_friction": self.reduced_friction, "n_contacts": self.n_contacts,
            "edges": [[float(a), float(b)] for a, b in np.asarray(self.edges).reshape(-1, 2)],
            "full_contact": self.full_contact, "converged": self.converged,
            "status": self.status.value, "message": self.message, "residual": self.residual,
            "iterations": self.iterations, "function_evaluations": self.function_evaluations,
            "zeta": self.zeta, "edge_perturbation": self.edge_perturbation,
            "min_gap": self.min_gap,
            "method": self.method, "error_estimate": self.error_estimate,
        }
        out = {k: v.item() if isinstance(v, np.generic) else v for k, v in out.items()}
        if self.edge_terms is not None:
            t = self.edge_terms
            out["edge_terms"] = {
                "stored": t.stored.tolist(), "nonconservative": t.nonconservative.tolist(),
                "target": t.target, "effective_work": [float(v) for v in t.effective_work],
                "stress_intensity": t.stress_intensity.tolist(),
                "edge_perturbation": t.edge_perturbation}
        if with_fields and self.fields is not None:
            out["fields"] = {k: np.asarray(v).tolist() for k, v in self.fields.items()}
        return out

    def to_json(self, **kw) -> str:
        """Strict JSON text of :meth:`to_dict` (``kw`` are its keywords): every non-finite number
        (NaN friction without contact, infinite gap) is written ``null``."""
        from ._json import dumps

        return dumps(self.to_dict(**kw))

    def __repr__(self) -> str:
        method = self.extras.get("method") if isinstance(self.extras, dict) else None
        contacts = "full contact" if self.full_contact else (
            f"{self.n_contacts} contact{'s' if self.n_contacts != 1 else ''}")
        text = (f"<ContactResult {self.status.value}: Ã={self.area:.6g}, "
                f"p̃∞={self.mean_pressure:.6g}, Δ̃={self.penetration:.6g}, "
                f"μ={self.friction:.6g}, {contacts}")
        return text + (f", method={method!r}>" if method is not None else ">")
