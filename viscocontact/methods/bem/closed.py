"""The closed (full-contact) state: ``ũ = w`` over the whole period, stresses from the Fourier
multiplier of the kernel."""
from __future__ import annotations

import functools

import numpy as np

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
    """

    def __init__(self, prep, check_points: int, origin: float, adhesive: bool):
        self.prep = prep
        self.points = max(check_points, 1024)
        self.origin = origin
        self.adhesive = adhesive

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
        c0 = self.prep.kernel.mean
        return -(penetration - 1.0 + rh[0].real) / (2 * np.pi * c0) if c0 != 0 else np.nan

    def supports(self, mean_pressure: float) -> bool:
        """Whether full contact carries ``mean_pressure`` without tension (always with adhesion)."""
        if self.adhesive:
            return True
        return mean_pressure >= float(np.max(self.stress[3]))

    def holds(self, control: Control) -> bool:
        """Whether a closed contact stays closed under ``control`` (without adhesion: while it
        carries no tension)."""
        if self.adhesive:
            return True
        if control.is_load:
            return self.supports(control.value)
        return self.mean_pressure_at(control.value) >= float(np.max(self.stress[3]))

    def result(self, control: Control, message: str, want_fields: bool, common: dict):
        """The :class:`ContactResult` of full contact under ``control``."""
        shape = self.prep.shape
        x, rh, sig_h, _ = self.stress
        n = len(x)
        c0 = self.prep.kernel.mean
        if control.is_load:
            pm = control.value
            pen = 1.0 - rh[0].real + 2 * np.pi * c0 * (-pm)
        else:
            pen = control.value
            if c0 == 0.0:
                if abs(pen - (1.0 - rh[0].real)) > 1e-9:
                    return ContactResult(
                        area=2 * np.pi, mean_pressure=np.nan, penetration=pen, friction=np.nan,
                        reduced_friction=np.nan, n_contacts=1, edges=np.zeros((0, 2)),
                        full_contact=True, converged=False, status=SolveStatus.FAILED,
                        message="full contact on an incompressible solid fixes the penetration "
                                f"at {1.0 - rh[0].real:.6g}; a larger one cannot be imposed",
                        residual=np.inf, min_gap=0.0, **common)
                pm = np.nan
            else:
                pm = -(pen - 1.0 + rh[0].real) / (2 * np.pi * c0)
        sig_h = sig_h.copy()
        sig_h[0] = -pm
        sigma = np.fft.irfft(sig_h * n, n)
        r = shape.heights(x)
        slopes = shape.profile.slopes(x)
        mu = (float(np.mean(sigma * slopes) / pm)
              if abs(pm) > 1e-12 * float(np.mean(np.abs(sigma))) else np.nan)
        sqrt_m2 = np.sqrt(self.prep.m2)
        ok = self.adhesive or bool(np.all(sigma <= 1e-9))
        fld = ({"x": x, "pressure": -sigma, "displacement": r - 1.0 + pen,
                "gap": np.zeros_like(x)} if want_fields else None)
        return ContactResult(
            area=2 * np.pi, mean_pressure=float(pm), penetration=float(pen), friction=mu,
            reduced_friction=mu / sqrt_m2, n_contacts=1, edges=np.zeros((0, 2)), full_contact=True,
            converged=ok, status=SolveStatus.CONVERGED if ok else SolveStatus.FAILED,
            message=message if ok else "full contact would carry tension without adhesion",
            residual=0.0, min_gap=0.0, fields=fld, **common)
