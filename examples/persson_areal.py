"""Persson's theory for an areal surface beside the 1D theory: contact area and friction against ζ.

The thesis's spectrum (H = 0.8, N_q = 50, q0·h_rms = 0.01) as an isotropic self-affine surface
(its cell's lattice of modes, and the continuous isotropic power law) and as a profile, on a
standard linear solid with β = E∞/E0 = 10, at two pressures ``p̄/E*``. The theory does not depend
on the seed (deterministic amplitudes). Writes ``persson_areal.png``.

Usage: ``python examples/persson_areal.py [--out DIR]``
"""
from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np


def curves(zetas: np.ndarray, pressures) -> dict:
    """``{label: (area[p, ζ], μ[p, ζ])}`` of the three theories."""
    from viscocontact.areal.surfaces import SelfAffineSurface
    from viscocontact.profiles import SelfAffineProfile
    from viscocontact.rheology import StandardLinearSolid
    from viscocontact.theories import ArealSpectrum, PerssonArealFriction

    sls = StandardLinearSolid(beta=10.0)
    spectra = {
        "areal (cell's modes)": ArealSpectrum.from_surface(
            SelfAffineSurface(hurst=0.8, scales=50, rms=0.01)),
        "areal (continuous, isotropic)": ArealSpectrum.isotropic_power_law(
            hurst=0.8, scales=50, rms=0.01),
        "profile (1D)": ArealSpectrum.from_profile(
            SelfAffineProfile(hurst=0.8, scales=50, rms=0.01)),
    }
    out = {}
    for label, spectrum in spectra.items():
        theory = PerssonArealFriction(spectrum=spectrum, rheology=sls)
        out[label] = (np.array([theory.area_fraction(zetas, p) for p in pressures]),
                      np.array([theory.coefficient(zetas, p) for p in pressures]))
    return out


def main(argv=None) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("."), help="output directory")
    args = parser.parse_args(argv)
    zetas = np.logspace(-3, 3, 121)
    pressures = (0.002, 0.01)
    data = curves(zetas, pressures)
    fig, (ax_a, ax_mu) = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
    styles = {"areal (cell's modes)": "-", "areal (continuous, isotropic)": ":",
              "profile (1D)": "--"}
    for label, (area, mu) in data.items():
        for i, p in enumerate(pressures):
            kw = dict(ls=styles[label], color=f"C{i}", label=f"{label}, p̄/E* = {p:g}")
            ax_a.semilogx(zetas, area[i], **kw)
            ax_mu.semilogx(zetas, mu[i], **kw)
    ax_a.set(xlabel="ζ = q0Vτ", ylabel="A/A0", title="contact area")
    ax_mu.set(xlabel="ζ = q0Vτ", ylabel="μ", title="viscoelastic friction")
    ax_mu.legend(fontsize=7, loc="upper right")
    args.out.mkdir(parents=True, exist_ok=True)
    path = args.out / "persson_areal.png"
    fig.savefig(path, dpi=120)
    return path


if __name__ == "__main__":
    print(main())
