r"""The two states the spectral method answers without a grid solve: closed contact and no contact.

They follow the conventions of :class:`~viscocontact.problem.ContactProblem`: a closed contact
(``u = w`` over the whole period) has the stress of the kernel's Fourier multiplier,
``σ̂_m = -m r̂_m/(S_m K(m))`` for ``m >= 1`` and ``σ̂_0 = -p̃∞``, area ``2π``, one contact and no
edges; the penetration and load are tied by the mean displacement ``Δ̃ = 1 - r̂_0 - 2π c0 p̃∞``
(so an incompressible solid, ``c0 = 0``, closes at one penetration only, where it carries any
load from ``max σ̃_osc`` up: the penetration-controlled answer there is the least, the limit of
the partial contacts). It is the solution of an adhesionless scene when it carries no tension,
``p̃∞ >= max σ̃_osc``. Without load or penetration there is no contact.
"""
from __future__ import annotations

from typing import Any

import attrs
import numpy as np
import scipy.fft

from ...contact import closure
from ...kernels.clausen import TWO_PI
from ...result import ContactResult, SolveStatus
from .grid import uniform_heights

#: Points on which the closed contact is evaluated at least (a spectral profile is exact on any
#: grid with more than twice its highest wavenumber).
CLOSED_POINTS = 2048


@attrs.frozen(kw_only=True, eq=False)
class ClosedContact:
    """The closed contact of a profile on a kernel (oscillating part; the mean is the load)."""

    shape: Any                  # NormalizedProfile (its profile is duck-typed)
    x: np.ndarray
    mean_height: float          # r̂_0
    stress: np.ndarray          # σ̃_osc, zero mean, tensile positive
    heights: np.ndarray         # r̃
    mean_compliance: float      # c0
    loss: np.ndarray            # Im K(m), m = 1 … n/2

    @classmethod
    def of(cls, shape, kernel, points: int = 0) -> "ClosedContact":
        """The closed contact of a :class:`~viscocontact.contact.fields.NormalizedProfile` on a
        prepared kernel, on ``max(points, CLOSED_POINTS)`` points from the peak minus π."""
        n = max(int(points), CLOSED_POINTS)
        start = shape.peak_position - np.pi
        x = start + TWO_PI * np.arange(n) / n
        r = uniform_heights(shape.profile, start, n) / shape.amplitude
        rh = scipy.fft.rfft(r) / n
        m = np.arange(rh.size, dtype=float)
        sig = np.zeros_like(rh)
        sig[1:] = -m[1:] * rh[1:] / np.asarray(kernel.multiplier(m[1:]))
        return cls(shape=shape, x=x, mean_height=float(rh[0].real),
                   stress=scipy.fft.irfft(sig * n, n), heights=r,
                   mean_compliance=float(kernel.mean),
                   loss=np.asarray(kernel.multiplier(m[1:])).imag)

    @property
    def closing_load(self) -> float:
        """The least ``p̃∞`` that the closed contact carries without tension."""
        return float(np.max(self.stress))

    def load_at(self, penetration: float) -> float:
        """``p̃∞`` of the closed contact at ``Δ̃`` (NaN when ``c0 = 0``)."""
        return closure.load_at(penetration, self.mean_height, self.mean_compliance)

    def closes(self, mean_pressure=None, penetration=None) -> bool:
        """Whether the adhesionless solution at this load or penetration is the closed contact."""
        return closure.closes(self.closing_load, self.mean_height, self.mean_compliance,
                              mean_pressure, penetration)

    def result(self, m2: float, common: dict, mean_pressure=None, penetration=None,
               fields: bool = False, message: str = "contact closed over the period",
               strength: float = 0.0, friction_floor: float = 1e-2):
        """The :class:`ContactResult` of the closed contact (as the BEM reports it, with the
        dissipated power and the estimates of :func:`~viscocontact.contact.closure.estimates`,
        μ's relative to ``max(|μ|, friction_floor·√m2)``); it fails where it would carry more
        tension than ``strength``."""
        c0 = self.mean_compliance
        if mean_pressure is not None:
            pm = float(mean_pressure)
            pen = 1.0 - self.mean_height - TWO_PI * c0 * pm
        else:
            pen = float(penetration)
            if c0 == 0.0 and not closure.at_closing_penetration(pen, self.mean_height):
                return ContactResult(
                    area=TWO_PI, mean_pressure=np.nan, penetration=pen, friction=np.nan,
                    reduced_friction=np.nan, n_contacts=1, edges=np.zeros((0, 2)),
                    full_contact=True, converged=False, status=SolveStatus.FAILED,
                    message="full contact on an incompressible solid fixes the penetration at "
                            f"{1.0 - self.mean_height:.6g}; another one cannot be imposed",
                    residual=np.inf, min_gap=0.0, **common)
            if c0 == 0.0:
                # at its one penetration the closed contact carries any load from the closing
                # load up; the partial contacts close at that load (Westergaard's p̃∞ = 1 at
                # Δ̃ = 1), as the BEM reports it
                pm = self.closing_load - strength
                message += closure.AT_CLOSING_PENETRATION
            else:
                pm = self.load_at(pen)
        from .estimate import friction_scale

        sigma = self.stress - pm
        mu, found = closure.estimates(self.stress, self.shape.profile.slopes(self.x), self.loss,
                                      self.shape.amplitude, pm,
                                      lambda f: friction_scale(f, m2, friction_floor))
        common["extras"].update(found)
        ok = bool(np.all(sigma <= strength + 1e-9))
        fld = ({"x": self.x, "pressure": -sigma, "displacement": self.heights - 1.0 + pen,
                "gap": np.zeros_like(self.x)} if fields else None)
        return ContactResult(
            area=TWO_PI, mean_pressure=float(pm), penetration=float(pen), friction=mu,
            reduced_friction=mu / np.sqrt(m2), n_contacts=1, edges=np.zeros((0, 2)),
            full_contact=True, converged=ok,
            status=SolveStatus.CONVERGED if ok else SolveStatus.FAILED,
            message=message if ok else (
                "full contact would carry tension without adhesion" if strength == 0.0 else
                f"full contact would carry tension {float(np.max(sigma)):.6g} beyond the "
                f"cohesive stress {strength:.6g}"),
            residual=0.0, min_gap=0.0, fields=fld, **common)


def no_contact_result(common: dict, penetration=None) -> ContactResult:
    """No contact (``p̃∞ <= 0`` or ``Δ̃ <= 0`` without adhesion), as the BEM reports it."""
    return ContactResult(area=0.0, mean_pressure=0.0,
                         penetration=np.nan if penetration is None else float(penetration),
                         friction=np.nan, reduced_friction=np.nan, n_contacts=0,
                         edges=np.zeros((0, 2)), full_contact=False, converged=True,
                         status=SolveStatus.NO_CONTACT, message="no contact at this load",
                         residual=0.0, min_gap=np.inf, **common)
