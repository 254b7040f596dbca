"""The default study (the README's main job): a compact ζ-sweep of an adhesive wavy contact.

For a sinusoid on a standard linear solid (β = 10) at fixed mean pressure, contact area and
reduced friction are computed over ζ, adhesive and adhesionless side by side, each point solved
from first touch. It is an ordinary :class:`~viscocontact.studies.Sweep`: the results go to a
study file (``study.h5``, written point by point, readable with
:func:`~viscocontact.studies.load_study`) and are drawn by :func:`~viscocontact.plots.plot_study`
(``study_area.png``, ``study_friction.png``).
"""
from __future__ import annotations

import sys
from pathlib import Path

import attrs
import numpy as np


@attrs.frozen(kw_only=True)
class WavyStudy:
    """Area and friction against ζ for a sinusoid, adhesive and adhesionless.

    Parameters
    ----------
    amplitude : float
        Λ̃ = q0 Λ.
    Gamma : float
        Γ̃ = γ̃/Λ̃² of the adhesive curves.
    beta : float
        E∞/E0.
    mean_pressure : float
        p̃∞.
    zetas : tuple of float
        Dimensionless speeds.
    certify : bool
        Certify every adhesive point (:class:`~viscocontact.studies.Sweep` ``certify``).
    """

    amplitude: float = 0.1
    Gamma: float = 0.01
    beta: float = 10.0
    mean_pressure: float = 0.1
    zetas: tuple = tuple(np.logspace(-4, 3, 15).round(10))
    certify: bool = False

    def scene(self):
        """The adhesive base scene (Newton solver)."""
        from .scene import Scene

        return Scene.from_dict({
            "profile": {"kind": "sinusoid", "amplitude": self.amplitude},
            "rheology": {"kind": "standard-linear-solid", "beta": self.beta},
            "adhesion": {"kind": "energy-balance", "gamma": self.Gamma * self.amplitude**2},
            "solver": {"kind": "newton"},
            "load": {"mean_pressure": self.mean_pressure},
            "sliding": {"zeta": float(self.zetas[0])}})

    def sweep(self):
        """The sweep under the default history, the approach: every adhesive point loaded from
        first touch at its own ζ, adhesive and adhesionless."""
        from .studies import Sweep

        return Sweep(scene=self.scene(), zetas=[float(z) for z in self.zetas], pair=True,
                     certify=self.certify)

    def run(self, out=".", *, workers: int = 1, progress=sys.stderr) -> list[Path]:
        """Compute the study into ``out/study.h5`` (replacing it) and draw it; the files written."""
        from .plots import plot_study
        from .studies import run

        out = Path(out)
        out.mkdir(parents=True, exist_ok=True)
        data = run(self.sweep(), out / "study.h5", workers=workers, overwrite=True,
                   progress=progress)
        return [data.path, *plot_study(data, out, prefix="study")]
