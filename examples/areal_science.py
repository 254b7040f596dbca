"""Areal contact of the thesis's rough spectrum: area, friction and patch anisotropy against ζ.

A 2D self-affine surface with the thesis's spectrum (§4.6: H = 0.8, N_q = 50, q0·h_rms = 0.01)
slides on a standard linear solid (β = 10) at p̃∞ = 0.3, adhesionless and with a Maugis-Dugdale
law (γ̃ = 2e-6, h̃0 = 0.006), ten realizations (seeds 0-9) on 256² cells, as a study
(``Sweep`` with ``seeds``: one HDF5 file, resumed when the script runs again). Beside it:

* the 1D profiles with the same H, N_q, rms and seeds, at the same nominal pressure p̄/E* as each
  areal realization (the 1D spectral method, adhesionless and with the same law);
* Persson's theory for the surface's own spectrum (``ArealSpectrum.from_surface``; the amplitudes
  are deterministic, only the phases depend on the seed) and for the profile's, at each
  realization's p̄/E*, averaged over the realizations;
* a grid check: seed 0 on 512² cells at three ζ;
* the patches' anisotropy of a band that starts above the cell's fundamental (``lowest = 4``,
  seeds 0-4, adhesionless), whose row of modes constant along the sliding direction holds 6 %
  of the height variance instead of 33 %.

Writes into ``--out`` (default ``.``): ``areal_science.h5`` (the study), ``areal_1d.json`` (the
1D points), ``areal_science.json`` (every number the page quotes), ``areal_science.png`` and
``areal_contact_map.png`` (seed 0 at ζ = 1, adhesionless). About 5 minutes on an idle core.

Usage: ``python examples/areal_science.py [--out DIR] [--workers N]``
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

import numpy as np

ZETAS = (1e-3, 1e-2, 0.1, 1.0, 10.0, 100.0, 1000.0)
SEEDS = tuple(range(10))
GRID, FINE = 256, 512
CHECK_ZETAS = (0.1, 1.0, 10.0)
LOWEST, LOWEST_SEEDS, LOWEST_ZETAS = 4.0, tuple(range(5)), (1e-3, 1.0, 1000.0)
SURFACE = {"kind": "self-affine", "hurst": 0.8, "scales": 50, "rms": 0.01}
ADHESION = {"kind": "maugis-dugdale", "gamma": 2e-6, "range": 0.006}
PRESSURE = 0.3
BETA = 10.0


def base_scene(grid: int = GRID, seed: int = 0, adhesion=None, zeta: float = 1.0,
               lowest: float = 1.0):
    """The areal scene (with the Maugis-Dugdale law unless ``adhesion`` says otherwise)."""
    from viscocontact.areal.scene import ArealScene

    return ArealScene.from_dict({
        "surface": {**SURFACE, "seed": seed, "grid": grid, "lowest": lowest},
        "rheology": {"kind": "standard-linear-solid", "beta": BETA},
        "adhesion": ADHESION if adhesion is None else adhesion,
        "load": {"mean_pressure": PRESSURE}, "sliding": {"zeta": zeta}})


def areal_study(out: Path, workers: int):
    """The ζ-sweep over the ten seeds, adhesive and adhesionless (resumed if the file exists)."""
    from viscocontact.studies import Sweep, run

    sweep = Sweep(scene=base_scene(), zetas=ZETAS, seeds=SEEDS, pair=True)
    return run(sweep, out / "areal_science.h5", resume=True, workers=workers)


def pressures() -> np.ndarray:
    """``p̄/E* = p̃∞ Λ̃/2`` of each realization (Λ̃ its highest point on the grid)."""
    return np.array([PRESSURE * base_scene(seed=s).amplitude / 2.0 for s in SEEDS])


def one_d(out: Path, p_star: np.ndarray) -> dict:
    """``{variant: (area fraction[seed, ζ], μ[seed, ζ])}`` of the 1D profiles at each
    realization's p̄/E* (cached in ``areal_1d.json``)."""
    import viscocontact as vc
    from viscocontact.profiles import SelfAffineProfile

    cache = out / "areal_1d.json"
    done = json.loads(cache.read_text()) if cache.exists() else {}
    for variant, adhesion in (("adhesionless", {"kind": "none"}), ("adhesive", ADHESION)):
        for seed, p in zip(SEEDS, p_star):
            amplitude = SelfAffineProfile(**{k: v for k, v in SURFACE.items() if k != "kind"},
                                          seed=seed).amplitude
            for zeta in ZETAS:
                key = f"{variant} {seed} {zeta:g}"
                if key in done:
                    continue
                r = vc.solve({"profile": {**SURFACE, "seed": seed},
                              "rheology": {"kind": "standard-linear-solid", "beta": BETA},
                              "adhesion": adhesion, "method": {"kind": "spectral"},
                              "load": {"mean_pressure": 2.0 * p / amplitude},
                              "sliding": {"zeta": zeta}})
                done[key] = {"converged": r.converged, "area": r.area / (2 * math.pi),
                             "friction": r.friction}
                cache.write_text(json.dumps(done))
    table = {}
    for variant in ("adhesionless", "adhesive"):
        rows = [[done[f"{variant} {s} {z:g}"] for z in ZETAS] for s in SEEDS]
        table[variant] = tuple(np.array([[c[q] if c["converged"] else np.nan for c in row]
                                         for row in rows]) for q in ("area", "friction"))
    return table


def persson(p_star: np.ndarray, zetas: np.ndarray) -> dict:
    """Persson's area and μ for the surface's and the profile's spectra, averaged over the
    realizations' pressures: ``{label: (area[ζ], μ[ζ])}``."""
    from viscocontact.areal.surfaces import SelfAffineSurface
    from viscocontact.profiles import SelfAffineProfile
    from viscocontact.rheology import StandardLinearSolid
    from viscocontact.theories import ArealSpectrum, PerssonArealFriction

    params = {k: v for k, v in SURFACE.items() if k != "kind"}
    spectra = {"areal": ArealSpectrum.from_surface(SelfAffineSurface(**params)),
               "1D": ArealSpectrum.from_profile(SelfAffineProfile(**params))}
    out = {}
    for label, spectrum in spectra.items():
        theory = PerssonArealFriction(spectrum=spectrum,
                                      rheology=StandardLinearSolid(beta=BETA))
        out[label] = (np.mean([theory.area_fraction(zetas, p) for p in p_star], axis=0),
                      np.mean([theory.coefficient(zetas, p) for p in p_star], axis=0))
    return out


def grid_check(data) -> list[dict]:
    """Seed 0 on 512² against the study's 256² points: relative differences of A/A0 and μ."""
    table = {name: data.table(name) for name in ("area_fraction", "friction")}
    variants = list(data.axes()["variant"])
    rows = []
    for variant in variants:
        iv = variants.index(variant)
        adhesion = None if variant == "adhesive" else {"kind": "none"}
        for zeta in CHECK_ZETAS:
            iz = ZETAS.index(zeta)
            fine = base_scene(FINE, 0, adhesion, zeta).solve()
            coarse = [table[n][iv, 0, 0, iz] for n in ("area_fraction", "friction")]
            rows.append({"variant": variant, "zeta": zeta, "converged": fine.converged,
                         "area_256": coarse[0], "area_512": fine.extras["area_fraction"],
                         "friction_256": coarse[1], "friction_512": fine.friction,
                         "estimate_512": fine.error_estimate})
    return rows


def lowest_check() -> dict:
    """Patch alignment and elongation (mean and standard error over :data:`LOWEST_SEEDS`) and
    the area of the band from ``LOWEST``, adhesionless, with the variance share of the modes
    constant along the sliding direction (the row ``q̃x = 0``) of both bands."""
    from viscocontact.areal.report import areal_quantities
    from viscocontact.areal.surfaces import SelfAffineSurface

    params = {k: v for k, v in SURFACE.items() if k != "kind"}
    out: dict = {"lowest": LOWEST, "seeds": list(LOWEST_SEEDS), "zetas": list(LOWEST_ZETAS)}
    for lowest in (1.0, LOWEST):
        modes = SelfAffineSurface(**params, lowest=lowest).modes
        power = modes.amplitudes**2
        out[f"row share, lowest {lowest:g}"] = float(power[modes.kx == 0].sum() / power.sum())
    for name in ("patch_alignment", "patch_elongation", "area_fraction"):
        out[name], out[f"{name} standard error"] = [], []
    for zeta in LOWEST_ZETAS:
        values: dict = {"patch_alignment": [], "patch_elongation": [], "area_fraction": []}
        for seed in LOWEST_SEEDS:
            q = areal_quantities(base_scene(GRID, seed, {"kind": "none"}, zeta,
                                            LOWEST).solve(fields=True))
            for name in values:
                values[name].append(q[name])
        for name, v in values.items():
            out[name].append(float(np.mean(v)))
            out[f"{name} standard error"].append(
                float(np.std(v, ddof=1) / math.sqrt(len(v))) if len(v) > 1 else float("nan"))
    return out


def summary(data, oned: dict, p_star: np.ndarray, check: list) -> dict:
    """Every number the page quotes (means over the realizations, NaN-free counts)."""
    out: dict = {"zetas": list(ZETAS), "pressure_over_estar": [float(p) for p in p_star],
                 "grid_check": check}
    variants = list(data.axes()["variant"])
    for name in ("area_fraction", "friction", "friction_dissipation", "patch_elongation",
                 "patch_orientation", "patch_alignment", "n_contacts", "error_estimate"):
        band = data.band(name)
        for iv, variant in enumerate(variants):
            out[f"{variant} {name}"] = band.mean[iv, 0].tolist()
            out[f"{variant} {name} half-width"] = (band.upper[iv, 0] - band.mean[iv, 0]).tolist()
            if name == "area_fraction":
                out[f"{variant} converged"] = band.count[iv, 0].tolist()
    for variant, (area, mu) in oned.items():
        out[f"1D {variant} area_fraction"] = np.nanmean(area, axis=0).tolist()
        out[f"1D {variant} friction"] = np.nanmean(mu, axis=0).tolist()
        out[f"1D {variant} converged"] = np.isfinite(area).sum(axis=0).tolist()
    zetas = np.asarray(ZETAS)
    for label, (area, mu) in persson(p_star, zetas).items():
        out[f"Persson {label} area_fraction"] = area.tolist()
        out[f"Persson {label} friction"] = mu.tolist()
    return out


def figure(data, oned: dict, p_star: np.ndarray, path: Path) -> Path:
    """Area, friction and patch anisotropy against ζ (areal bands, 1D means, Persson)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    zetas = np.asarray(ZETAS)
    dense = np.logspace(-3, 3, 61)
    theory = persson(p_star, dense)
    variants = list(data.axes()["variant"])
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.9), constrained_layout=True)
    colors = {"adhesionless": "C0", "adhesive": "C3"}
    for iv, variant in enumerate(variants):
        c = colors[variant]
        for ax, name in zip(axes[:2], ("area_fraction", "friction")):
            band = data.band(name)
            ax.fill_between(zetas, band.lower[iv, 0], band.upper[iv, 0], color=c, alpha=0.25)
            ax.semilogx(zetas, band.mean[iv, 0], "o-", color=c, label=f"areal, {variant}")
        area, mu = oned[variant]
        axes[0].semilogx(zetas, np.nanmean(area, axis=0), "s--", color=c, mfc="none",
                         label=f"1D, {variant}")
        axes[1].semilogx(zetas, np.nanmean(mu, axis=0), "s--", color=c, mfc="none")
        axes[1].semilogx(zetas, data.band("friction_dissipation").mean[iv, 0], "x", color=c,
                         ms=8, label="dissipated power / p̄" if iv == 0 else None)
        for name, style in (("patch_alignment", "o-"), ("patch_elongation", "^:")):
            band = data.band(name)
            value = band.mean[iv, 0] - (1.0 if name == "patch_elongation" else 0.0)
            axes[2].semilogx(zetas, value, style, color=c,
                             label=f"{'alignment' if 'align' in name else 'elongation - 1'}, "
                                   f"{variant}")
    for label, style in (("areal", "k-"), ("1D", "k:")):
        axes[0].semilogx(dense, theory[label][0], style, lw=1, label=f"Persson, {label}")
        axes[1].semilogx(dense, theory[label][1], style, lw=1)
    axes[2].axhline(0.0, color="0.6", lw=0.8)
    axes[0].set(xlabel="ζ = q0Vτ", ylabel="A/A0", title="contact area")
    axes[1].set(xlabel="ζ = q0Vτ", ylabel="μ", title="friction")
    axes[2].set(xlabel="ζ = q0Vτ", title="patches: alignment with sliding, elongation")
    for ax in axes:
        ax.legend(fontsize=7)
    fig.savefig(path, dpi=80)
    plt.close(fig)
    return path


def contact_map(path: Path) -> Path:
    """Seed 0 at ζ = 1, adhesionless: the contact map and the pressure."""
    from viscocontact.areal.plots import plot_contact

    result = base_scene(GRID, 0, {"kind": "none"}, 1.0).solve(fields=True)
    return plot_contact(result, path, title="seed 0, ζ = 1, adhesionless, 256² cells")


def main(argv=None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("."), help="output directory")
    parser.add_argument("--workers", type=int, default=1, help="processes of the study")
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    started = time.perf_counter()
    data = areal_study(args.out, args.workers)
    print(f"areal study: {time.perf_counter() - started:.0f} s", file=sys.stderr)
    p_star = pressures()
    oned = one_d(args.out, p_star)
    print(f"1D: {time.perf_counter() - started:.0f} s", file=sys.stderr)
    check = grid_check(data)
    numbers = summary(data, oned, p_star, check)
    numbers["lowest_check"] = lowest_check()
    numbers["seconds"] = time.perf_counter() - started
    (args.out / "areal_science.json").write_text(json.dumps(numbers, indent=1))
    figure(data, oned, p_star, args.out / "areal_science.png")
    contact_map(args.out / "areal_contact_map.png")
    print(f"done: {time.perf_counter() - started:.0f} s", file=sys.stderr)
    return numbers


if __name__ == "__main__":
    main()
