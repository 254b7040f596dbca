"""The process zone against the virtual edge advance δX on the thesis's rough profile: reduced
friction μ/√m2 (Fig. 4.10a) and contact area Ã (Fig. 4.7a) against ζ under load control, with
Maugis–Dugdale cohesive zones of physical ranges h0 next to the energy-balance edge condition
at δX and the adhesionless curve, one column per load, the mean over realizations with its band.

The case is ``examples/scenes/thesis_rough.toml`` (H = 0.8, N_q = 50, r_rms = 10 µm,
λ0 = 6.28 mm, SLS β = 10, Δγ = 0.01 J/m²: γ̃ = 2.39e-7). The sweeps are those of
``fig_4_10.py`` (``--rough-cohesive-ranges``; the same files and names, run downwards in ζ, each
point continued from its neighbour, 32 elements per contact). The quasi-static zone of a range h0
is ``a0 = h̃0²/(4γ̃)`` (h̃0 = q0·h0): h0 = 1 nm gives a0 = 1.05e-6, h0 = 10 nm gives 1.05e-4, about
the δX = 1e-4 of the thesis's rough curves. On the sinusoid the range that matched δX had
``δX/a0 ≈ 3.9`` (``docs/cohesive.md``), which here is h0 ≈ 5 nm.

Small default: one realization, p̃∞ = 0.3, 11 ζ from 1e4 to 1e-6, h0 = 1 and 10 nm, δX = 1e-4.
``--full``: five realizations (seeds 0-4), 30 ζ, p̃∞ = 0.1, 0.3, 0.6, h0 = 1, 5 and 10 nm
(``docs/cohesive.md`` uses ``--seeds 0:20``). A point whose continuation ended before it (no
step of ζ reaches it from its neighbour) is solved from first touch and counted, as
``docs/studies.md`` describes; a point that did not converge at all is left out of its ζ's mean
(the CSV's ``count`` says how many realizations it holds). Writes the study files,
``cohesive_rough.csv`` (the means and 95 % bands per curve, load and ζ) and
``cohesive_rough.png``.

Usage: ``python examples/cohesive_rough.py [--out DIR] [--full] [--workers N] [--ranges 1,10]
[--edge-perturbations 1e-4] [--seeds 0:5] [--zetas 1e4:1e-6:30] [--pressures 0.1,0.3,0.6]``
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _thesis_cases as cases  # noqa: E402

SIZES = {
    "small": {"seeds": "0", "zetas": "1e4:1e-6:11", "pressures": "0.3", "ranges": "1,10",
              "dxs": "1e-4"},
    "full": {"seeds": "0:5", "zetas": "1e4:1e-6:30", "pressures": "0.1,0.3,0.6",
             "ranges": "1,5,10", "dxs": "1e-4"},
    "tiny": {"seeds": "0", "zetas": "1e3", "pressures": "0.3", "ranges": "1", "dxs": "1e-4"},
}
QUANTITIES = (("reduced_friction", "reduced friction μ/√m2"), ("area", "contact area Ã"))


def family(args) -> list:
    """The sweeps ``[(label, StudyData), ...]``: adhesionless first, then each δX, then each
    range (:func:`_thesis_cases.sweep_family`)."""
    size = SIZES[cases.size_name(args)]
    ns = argparse.Namespace(**vars(args))
    ns.rough_edge_perturbations = args.edge_perturbations or size["dxs"]
    ns.rough_cohesive_ranges = args.ranges or size["ranges"]
    ns.seeds = args.seeds or size["seeds"]
    ns.zetas = args.zetas or size["zetas"]
    ns.pressures = args.pressures or size["pressures"]
    ns.penetrations = None
    ns.history = "approach"
    return cases.sweep_family("rough", "mean_pressure", ns)


def rows(curves) -> list[dict]:
    """Mean and 95 % confidence band over the realizations that converged (``count`` of them) of
    each quantity per curve, load and ζ (:meth:`StudyData.band`; the adhesionless variant
    labelled "adhesionless")."""
    out = []
    for label, data in curves:
        axes = data.axes()
        bands = {q: data.band(q) for q, _ in QUANTITIES}
        for iv, variant in enumerate(axes["variant"]):
            name = label if variant == "adhesive" else "adhesionless"
            for il, load in enumerate(axes["load"]):
                for iz, zeta in enumerate(axes["zeta"]):
                    row = {"curve": name, "load": float(load), "zeta": float(zeta),
                           "count": int(bands["area"].count[iv, il, iz])}
                    for q, _ in QUANTITIES:
                        b = bands[q]
                        row[q] = float(b.mean[iv, il, iz])
                        row[f"{q}_lower"] = float(b.lower[iv, il, iz])
                        row[f"{q}_upper"] = float(b.upper[iv, il, iz])
                    out.append(row)
    return out


def plot(table: list[dict], path: Path) -> Path:
    from matplotlib.figure import Figure

    curves = list(dict.fromkeys(r["curve"] for r in table))
    loads = sorted({r["load"] for r in table})
    fig = Figure(figsize=(4.6 * len(loads), 7.0))
    axs = fig.subplots(2, len(loads), squeeze=False)
    for (q, ylabel), row_axes in zip(QUANTITIES, axs):
        for ax, load in zip(row_axes, loads):
            for i, name in enumerate(curves):
                pts = sorted((r for r in table if r["curve"] == name and r["load"] == load),
                             key=lambda r: r["zeta"])
                z = np.array([r["zeta"] for r in pts])
                mean = np.array([r[q] for r in pts])
                style = "--" if name == "adhesionless" else "-"
                color = "0.4" if name == "adhesionless" else f"C{i}"
                ax.plot(z, mean, style, marker="o", ms=2.5, color=color, label=name)
                lower = np.array([r[f"{q}_lower"] for r in pts])
                if q == "reduced_friction":       # log axis: a band reaching below 0 is cut
                    lower = np.maximum(lower, 1e-3 * mean)
                ax.fill_between(z, lower, [r[f"{q}_upper"] for r in pts], color=color,
                                alpha=0.15, lw=0)
            if q == "reduced_friction":
                ax.set_yscale("log")
                ax.set_ylim(1e-5, 20)
            ax.set_xscale("log")
            ax.set_xlabel("ζ = q0Vτ")
            ax.set_ylabel(ylabel)
            ax.set_title(f"p̃∞ = {load:g}", fontsize=10)
            ax.grid(alpha=0.3)
            ax.legend(fontsize=7)
    fig.suptitle("Thesis rough profile, load control: Maugis–Dugdale zones of range h0 against "
                 "the energy balance at δX (mean over realizations, 95 % band)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    return path


def main(argv=None) -> list[Path]:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    cases.common_arguments(parser)
    parser.add_argument("--ranges", default=None, help="cohesive ranges h0 in nm, e.g. 1,10")
    parser.add_argument("--edge-perturbations", default=None, help="δX values, e.g. 1e-4")
    parser.add_argument("--seeds", default=None, help="realizations, e.g. 0:5")
    parser.add_argument("--zetas", default=None, help="ζ list: 1e-3,1 or START:STOP:N")
    parser.add_argument("--pressures", default=None, help="p̃∞ list")
    args = parser.parse_args(argv)
    curves = family(args)
    table = rows(curves)
    out = Path(args.out)
    written = [data.path for _, data in curves]
    csv_path = out / "cohesive_rough.csv"      # derived from the study files: rewritten each run
    fields = list(table[0].keys())
    lines = [",".join(fields)] + [",".join(f"{r[k]:.9g}" if isinstance(r[k], float) else str(r[k])
                                          for k in fields) for r in table]
    csv_path.write_text("\n".join(lines) + "\n")
    written += [csv_path, plot(table, out / "cohesive_rough.png")]
    print(written[-1], flush=True)
    return written


if __name__ == "__main__":
    main()
