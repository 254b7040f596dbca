"""The default study (the README's main job): a compact ζ-sweep of an adhesive wavy contact.

For a sinusoid on a standard linear solid (β = 10) at fixed mean pressure, contact area and
reduced friction are computed over ζ, adhesive and adhesionless side by side, each point solved
from first touch. Results are written to an HDF5 file (atomically: a temporary file renamed when
complete) and drawn as PNG plots.
"""
from __future__ import annotations

import os
import time
from pathlib import Path

import attrs
import numpy as np

from .adhesion import EnergyBalance, NoAdhesion
from .problem import ContactProblem
from .profiles.sinusoid import Sinusoid
from .rheology.sls import StandardLinearSolid
from .solvers.newton import Newton


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
    """

    amplitude: float = 0.1
    Gamma: float = 0.01
    beta: float = 10.0
    mean_pressure: float = 0.1
    zetas: tuple = tuple(np.logspace(-4, 3, 15).round(10))

    def problems(self):
        rheology = StandardLinearSolid(beta=self.beta)
        for label, adhesion in (("adhesionless", NoAdhesion()),
                                ("adhesive", EnergyBalance(gamma=self.Gamma * self.amplitude**2))):
            yield label, [ContactProblem(profile=Sinusoid(amplitude=self.amplitude),
                                         rheology=rheology, solver=Newton(), adhesion=adhesion,
                                         mean_pressure=self.mean_pressure, zeta=float(z))
                          for z in self.zetas]

    def run(self, log=print) -> dict:
        """Solve every point from first touch (adhesive equilibria are path dependent: continuing
        from the neighbouring ζ can land on another branch, so the default study does not)."""
        out = {"zeta": np.array(self.zetas, dtype=float)}
        for label, problems in self.problems():
            rows = []
            for prob in problems:
                t0 = time.perf_counter()
                res = prob.solve()
                rows.append((res.area, res.mean_pressure, res.penetration, res.friction,
                             res.reduced_friction, float(res.converged), float(res.full_contact)))
                log(f"{label:>12} ζ = {prob.zeta:9.3g}: Ã = {res.area:.5f}  μ/√m2 = "
                    f"{res.reduced_friction:.4f}  {res.status.value}  "
                    f"({time.perf_counter() - t0:.1f} s)")
            arr = np.array(rows)
            out[label] = {k: arr[:, i] for i, k in enumerate(
                ("area", "mean_pressure", "penetration", "friction", "reduced_friction",
                 "converged", "full_contact"))}
        return out


def write_h5(path: Path, study: WavyStudy, results: dict) -> None:
    """Write the study atomically (temporary file, then rename)."""
    import h5py

    from . import __version__

    tmp = path.with_name(path.name + ".tmp")
    with h5py.File(tmp, "w") as f:
        f.attrs["viscocontact_version"] = __version__
        f.attrs["study"] = "wavy-zeta-sweep"
        for k, v in attrs.asdict(study).items():
            f.attrs[k] = np.asarray(v)
        f["zeta"] = results["zeta"]
        for label in ("adhesionless", "adhesive"):
            g = f.create_group(label)
            for k, v in results[label].items():
                g[k] = v
    os.replace(tmp, path)


def plot(path: Path, results: dict) -> list[Path]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    files = []
    for key, ylabel, name in (("area", "contact area Ã", "study_area.png"),
                              ("reduced_friction", "reduced friction μ/√m2", "study_friction.png")):
        fig, ax = plt.subplots(figsize=(6, 4))
        for label, style in (("adhesive", "-o"), ("adhesionless", "--s")):
            r = results[label]
            ok = r["converged"] > 0
            ax.semilogx(results["zeta"][ok], r[key][ok], style, ms=3, label=label)
        ax.set_xlabel("ζ = q0 V τ")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
        ax.legend()
        fig.tight_layout()
        out = path / name
        fig.savefig(out, dpi=120)
        plt.close(fig)
        files.append(out)
    return files
