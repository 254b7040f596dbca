"""The closed (full-contact) state: ``ũ = w`` over the whole period, stresses from the Fourier
multiplier of the kernel."""
from __future__ import annotations

import functools

import numpy as np

from ...contact import closure
from ...contact.topology import TWO_PI
from ...result import ContactResult, SolveStatus
from .sets import Control


class ClosedContact:
    """Full contact of one prepared problem.

    Parameters
    ----------
    prep : Prepared
    check_points : int
        At least 1024 grid points carry the closed stress.
    origin : float
        Left end of the period window.
    adhesive : bool
        Whether the interface carries tension (adhesion closes any tensile stretch).
    strength : float
        The largest tension the closed interface carries when ``adhesive``
        (:meth:`AdhesionModel.closed_strength`; unbounded by default).
    """

    def __init__(self, prep, check_points: int, origin: float, adhesive: bool,
                 strength: float = np.inf):
        self.prep = prep
        self.points = max(check_points, 1024)
        self.origin = origin
        self.adhesive = adhesive
        self.strength = float(strength) if adhesive else 0.0

    @functools.cached_property
    def stress(self):
        """Grid ``x``, profile spectrum and the zero-mean stress ``σ̃_osc``."""
        shape = self.prep.shape
        n = self.points
        x = self.origin + TWO_PI * np.arange(n) / n
        rh = np.fft.rfft(shape.heights(x)) / n       # r̃ = Σ rh_m e^{imx} + c.c.
        m = np.arange(len(rh), dtype=float)
        sig_h = np.zeros_like(rh)
        sig_h[1:] = -m[1:] * rh[1:] / self.prep.kernel.multiplier(m[1:])   # û = -(S K/m) σ̂
        return x, rh, sig_h, np.fft.irfft(sig_h * n, n)

    def mean_pressure_at(self, penetration: float) -> float:
        """``p̃∞`` of the closed contact at a penetration (NaN on an incompressible solid)."""
        _, rh, _, _ = self.stress
        return closure.load_at(penetration, rh[0].real, self.prep.kernel.mean)

    @property
    def closing_load(self) -> float:
        """The least ``p̃∞`` that full contact carries without tension (``max σ̃_osc``)."""
        return float(np.max(self.stress[3]))

    def largest_tension(self, mean_pressure: float) -> float:
        """The largest tensile stress of full contact at ``mean_pressure``."""
        return self.closing_load - mean_pressure

    def supports(self, mean_pressure: float) -> bool:
        """Whether full contact carries ``mean_pressure`` with no tension above the interface's
        strength (none without adhesion; always with adhesion of vanishing range)."""
        if self.strength == np.inf:      # adhesion of vanishing range
            return True
        return self.largest_tension(mean_pressure) <= self.strength

    def closes(self, control: Control) -> bool:
        """Whether the adhesionless equilibrium under ``control`` is the closed contact
        (:func:`~viscocontact.contact.closure.closes`)."""
        _, rh, _, _ = self.stress
        return closure.closes(self.closing_load, rh[0].real, self.prep.kernel.mean,
                              **control.fields_kwargs())

    def possible(self, control: Control) -> bool:
        """Whether full contact can be the state under ``control`` at all: on an incompressible
        solid (``c0 = 0``) in penetration control only at its closing penetration (below it
        the mean gap, which the penetration fixes there, is positive: a gap of that volume
        stays open somewhere), and elsewhere where it carries the load (:meth:`holds`)."""
        if not control.is_load and self.prep.kernel.mean == 0.0:
            return bool(closure.at_closing_penetration(control.value, self.stress[1][0].real))
        return bool(self.holds(control))

    def holds(self, control: Control) -> bool:
        """Whether a closed contact stays closed under ``control`` (while its tension stays
        within the interface's strength: none without adhesion)."""
        if self.strength == np.inf:      # adhesion of vanishing range
            return True
        if control.is_load:
            return self.supports(control.value)
        return self.supports(self.mean_pressure_at(control.value))

    def result(self, control: Control, message: str, want_fields: bool, common: dict):
        """The :class:`ContactResult` of full contact under ``control``."""
        shape = self.prep.shape
        x, rh, sig_h, oscillating = self.stress
        c0 = self.prep.kernel.mean
        if control.is_load:
            pm = control.value
            pen = 1.0 - rh[0].real + 2 * np.pi * c0 * (-pm)
        else:
            pen = control.value
            if c0 == 0.0:
                closing = 1.0 - rh[0].real
                why = None
                if not closure.at_closing_penetration(pen, rh[0].real):
                    why = (f"full contact on an incompressible solid fixes the penetration at "
                           f"{closing:.6g}; another one cannot be imposed")
                elif self.adhesive:
                    why = (f"full contact on an incompressible solid holds at the penetration "
                           f"{closing:.6g} under any load it carries, so the penetration does "
                           "not fix the load: give the mean pressure instead")
                if why is not None:
                    return ContactResult(
                        area=2 * np.pi, mean_pressure=np.nan, penetration=pen, friction=np.nan,
                        reduced_friction=np.nan, n_contacts=1, edges=np.zeros((0, 2)),
                        full_contact=True, converged=False, status=SolveStatus.FAILED,
                        message=why, residual=np.inf, min_gap=0.0, **common)
                # without adhesion the closed contact at its one penetration carries any load
                # from the closing load up; the partial contacts close at that load as the
                # penetration reaches it (Westergaard's p̃∞ = 1 at Δ̃ = 1), so that is the answer
                pm = self.closing_load
                message += closure.AT_CLOSING_PENETRATION
            else:
                pm = closure.load_at(pen, rh[0].real, c0)
        from .estimate import friction_scale

        sigma = oscillating - pm
        loss = self.prep.kernel.multiplier(np.arange(1, len(sig_h), dtype=float)).imag
        mu, found = closure.estimates(oscillating, shape.profile.slopes(x), loss,
                                      shape.amplitude, pm,
                                      lambda f: friction_scale(f, self.prep.m2))
        sqrt_m2 = np.sqrt(self.prep.m2)
        ok = bool(np.all(sigma <= self.strength + 1e-9))
        common["extras"].update(found)
        r = shape.heights(x)
        fld = ({"x": x, "pressure": -sigma, "displacement": r - 1.0 + pen,
                "gap": np.zeros_like(x)} if want_fields else None)
        return ContactResult(
            area=2 * np.pi, mean_pressure=float(pm), penetration=float(pen), friction=mu,
            reduced_friction=mu / sqrt_m2, n_contacts=1, edges=np.zeros((0, 2)), full_contact=True,
            converged=ok, status=SolveStatus.CONVERGED if ok else SolveStatus.FAILED,
            message=message if ok else (
                "full contact would carry tension without adhesion" if not self.adhesive else
                f"full contact would carry a tension of {float(np.max(sigma)):.4g}, above the "
                f"strength {self.strength:.4g} of the closed interface"),
            residual=0.0, min_gap=0.0, fields=fld, **common)
