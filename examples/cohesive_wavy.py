"""The process zone against the virtual edge advance δX on the thesis's sinusoid: contact area Ã
(Fig. 4.7a) and reduced friction μ/√m2 (Fig. 4.10) against ζ under load control, with the
Maugis–Dugdale cohesive zone at several physical ranges h0 next to the energy-balance edge
condition at several δX.

The case is ``examples/scenes/thesis_wavy.toml`` (λ0 = 1 mm, Λ = 8 µm, E0 = 10 MPa, SLS β = 10,
Δγ = 0.01 J/m²: γ̃ = 1.5e-6, Λ̃ = 0.050265), 64 elements per contact, Newton. The cohesive
curves replace ``[adhesion]`` by ``kind = "maugis-dugdale"`` with ``physical.cohesive_range``
= h0 (``docs/cohesive.md``); their quasi-static zone is ``a0 = h̃0²/(4γ̃)`` (h̃0 = q0·h0), so
h0 = 3.9 nm and 12.3 nm have ``a0`` = 1e-4 and 1e-3, the δX of the energy-balance curves. Every
sweep runs upwards in ζ, each point continued from its neighbour, as in ``fig_4_7.py``; the
adhesionless curve is the twin of the first energy-balance sweep.

After the sweeps every converged single-contact point at the first load is solved once more
from its own edges to read its edge terms: the zone length ``d`` at each edge
(``effective_work·a0``; the first edge of the contact is the trailing, opening one, the second
the leading, closing one) and, for the energy balance, ``effective_work`` = Δγ_eff/Δγ. They go
to ``zones_<tag>.csv``.

Small default: h0 = 1 and 12.3 nm, δX = 0, 1e-4, 1e-3, ζ from 1e-6 to 1e4 one per decade,
p̃∞ = 0.3 (65 s on the 2-core machine). ``--full``: the size measured in ``docs/cohesive.md`` (h0 = 1, 2, 3.9, 6, 12.3,
30, 100 nm, 31 ζ, three per decade, p̃∞ = 0.3, 0.1, 0.6; at p̃∞ = 0.3 also ζ = 1e-8 and 1e-7
from first touch, ``*_low.h5``). Writes one study file per curve and load,
``cohesive_wavy_<dx0|dx1e-04|md1nm|...>_p<load>.h5`` (resumed when run again; the first
energy-balance file holds the adhesionless twin), ``zones_*.csv``, ``distances.csv`` (the
distances between each cohesive and each energy-balance curve) and ``cohesive_wavy.png``.

Usage: ``python examples/cohesive_wavy.py [--out DIR] [--full] [--ranges 1,10]
[--edge-perturbations 0,1e-4] [--zetas 1e-6:1e4:11] [--pressures 0.3,0.6]``
"""
from __future__ import annotations

import argparse
import csv
import math
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import _thesis_cases as cases  # noqa: E402

SIZES = {
    "small": {"ranges": "1,12.3", "dxs": "0,1e-4,1e-3", "zetas": "1e-6:1e4:11",
              "pressures": "0.3", "low": ""},
    "full": {"ranges": "1,2,3.9,6,12.3,30,100", "dxs": "0,1e-4,1e-3", "zetas": "1e-6:1e4:31",
             "pressures": "0.3,0.1,0.6", "low": "1e-8,1e-7"},
    "tiny": {"ranges": "12.3", "dxs": "1e-4", "zetas": "1e4", "pressures": "0.3", "low": ""},
}
ELEMENTS = 64
NM = 1e-9
#: Wall-time limit of one point (s); a point past it is stored as failed with that reason.
TIME_LIMIT = 300.0


def cohesive_scene(h0_nm: float):
    """The wavy case with the Maugis–Dugdale zone of range ``h0_nm`` nanometres."""
    from viscocontact.scene import Scene

    data = cases.scene("wavy").to_dict()
    data["adhesion"] = {"kind": "maugis-dugdale"}
    data["physical"] = {**data["physical"], "cohesive_range": h0_nm * NM}
    return Scene.from_dict(data)


def sweep(scene, args, load: float, *, pair: bool, zetas=None):
    """The load-controlled ζ-sweep of ``scene`` at p̃∞ = ``load`` (one study file per load),
    every point by the approach at its own ζ (the default history)."""
    from viscocontact.problem import Discretization
    from viscocontact.studies import Sweep

    return Sweep(scene=scene, zetas=cases.floats(args.zetas) if zetas is None else zetas,
                 loads=[load], control="mean_pressure", pair=pair,
                 discretization=Discretization(elements=ELEMENTS))


def compute(study, path: Path, args):
    """:func:`_thesis_cases.compute` with a time limit per point (:data:`TIME_LIMIT`)."""
    from viscocontact.studies import run

    path.parent.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    progress = None if args.quiet else sys.stderr
    data = run(study, path, workers=args.workers, resume=not args.force,
               overwrite=args.force and path.exists(), progress=progress,
               time_limit=TIME_LIMIT)
    print(f"{path.name}: {len(data)} points, {len(data.failed)} not converged, "
          f"{time.perf_counter() - t0:.0f} s", flush=True)
    return data


def cohesive_family(h0: float, args, out: Path) -> list:
    """Per load, the sweep of range ``h0``: ``[StudyData, ...]``, one per load."""
    scene = cohesive_scene(h0)
    family = []
    for load in cases.floats(args.pressures):
        name = f"cohesive_wavy_{md_tag(h0)}_p{load:g}"
        family.append(compute(sweep(scene, args, load, pair=False), out / f"{name}.h5", args))
    return family


def md_tag(h0_nm: float) -> str:
    return f"md{h0_nm:g}nm"


def edge_rows(tag: str, family: list, path: Path, load: float) -> list[dict]:
    """The edge terms of every adhesive point of ``family`` at p̃∞ = ``load`` (the point of the
    first study that converged there), read from a solve started at the point's own edges
    (converged single-contact points only); rows already in ``path`` are not recomputed."""
    from viscocontact.problem import ContactProblem, Discretization
    from viscocontact.scene import Scene

    done = {}
    if path.exists():
        with path.open() as f:
            done = {(float(r["load"]), float(r["zeta"])): r for r in csv.DictReader(f)}
    chosen = {}                                   # (load, ζ) -> (data, row)
    for data in family:
        p = data.points
        for i in range(len(data)):
            if p["variant"][i] != "adhesive":
                continue
            key = (float(p["load"][i]), float(p["zeta"][i]))
            if key[0] != load:
                continue
            if key not in chosen or not chosen[key][0].points["converged"][chosen[key][1]]:
                chosen[key] = (data, i)
    rows = []
    for key in sorted(chosen, key=lambda k: (k[0], k[1])):
        if key in done:
            rows.append(done[key])
            continue
        data, i = chosen[key]
        p = data.points
        row = {"curve": tag, "load": key[0], "zeta": key[1], "area": float(p["area"][i]),
               "status": str(p["status"][i]), "started_from": str(p["started_from"][i]),
               "full_contact": bool(p["full_contact"][i]), "message": str(p["message"][i])}
        if p["converged"][i] and not p["full_contact"][i] and int(p["n_contacts"][i]) == 1:
            scene = Scene.from_dict({**data.scene.to_dict(), "load": {"mean_pressure": key[0]},
                                     "sliding": {"zeta": key[1]}})
            problem = ContactProblem.from_scene(
                scene, discretization=Discretization(elements=ELEMENTS))
            result = problem.solve(initial=np.asarray(p["edges"][i], float))
            terms = result.edge_terms
            a0 = getattr(scene.adhesion, "quasi_static_zone", math.nan)
            eff = np.asarray(terms.effective_work, float)
            row.update(resolved=bool(result.converged), area_again=float(result.area),
                       a0=a0, work_trailing=eff[0], work_leading=eff[1],
                       zone_trailing=eff[0] * a0, zone_leading=eff[1] * a0,
                       edge_perturbation=float(np.max(np.atleast_1d(
                           terms.edge_perturbation))))
        rows.append(row)
        print(f"  {tag} p={key[0]:g} ζ={key[1]:.3g}: "
              + ", ".join(f"{k}={v:.4g}" for k, v in row.items()
                          if isinstance(v, float) and k not in ("load", "zeta")), flush=True)
    fields = ["curve", "load", "zeta", "area", "status", "started_from", "full_contact",
              "resolved", "area_again", "a0", "work_trailing", "work_leading", "zone_trailing",
              "zone_leading", "edge_perturbation", "message"]
    with path.open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields)
        writer.writeheader()
        for r in rows:
            writer.writerow({k: r.get(k, "") for k in fields})
    return rows


def curve(family, name: str, load: float, zetas, variant: str = "adhesive") -> np.ndarray:
    """Column ``name`` at p̃∞ = ``load`` against ``zetas``: at each ζ the value of the first
    study of ``family`` that converged there, NaN where none did."""
    zetas = list(zetas)
    out = np.full(len(zetas), np.nan)
    for data in family:
        if load not in data.study.loads or variant not in data.study.variants:
            continue
        table = data.table(name)[data.study.variants.index(variant),
                                 list(data.study.loads).index(load), 0, :]
        for iz, z in enumerate(data.study.zetas):
            if z in zetas and np.isnan(out[zetas.index(z)]):
                out[zetas.index(z)] = table[iz]
    return out


#: ζ windows of the curve distances: every ζ, and the rubbery-to-transition side where the
#: edge condition matters (ζ <= 1; above it every curve follows the bulk).
WINDOWS = {"all": math.inf, "zeta<=1": 1.0}


def distances(md, eb, loads, zetas, path: Path) -> list[dict]:
    """Distances of every cohesive curve to every energy-balance curve, per load and ζ window,
    over the ζ where both converged: RMS and largest |ΔÃ|, and of Δlog10(μ/√m2) where both
    are positive."""
    rows = []
    for mtag, mdata in md:
        for etag, edata in eb:
            for load in loads:
                a1, a2 = curve(mdata, "area", load, zetas), curve(edata, "area", load, zetas)
                f1 = curve(mdata, "reduced_friction", load, zetas)
                f2 = curve(edata, "reduced_friction", load, zetas)
                for window, top in WINDOWS.items():
                    both = np.isfinite(a1) & np.isfinite(a2) & (np.asarray(zetas) <= top)
                    da = a1[both] - a2[both]
                    pos = both & (f1 > 0) & (f2 > 0)
                    dl = np.log10(f1[pos]) - np.log10(f2[pos])
                    rows.append({
                        "cohesive": mtag, "energy_balance": etag, "load": load,
                        "window": window, "points": int(both.sum()),
                        "area_rms": float(np.sqrt(np.mean(da ** 2))) if da.size else math.nan,
                        "area_max": float(np.max(np.abs(da))) if da.size else math.nan,
                        "log_friction_rms": (float(np.sqrt(np.mean(dl ** 2))) if dl.size
                                             else math.nan),
                        "log_friction_max": (float(np.max(np.abs(dl))) if dl.size
                                             else math.nan)})
    with path.open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    return rows


def plot(md, eb, loads, zetas, path: Path) -> Path:
    """One row per load: Ã against ζ, the same for ζ <= 0.1 (where the edge condition matters),
    and μ/√m2; energy balance thin with crosses, cohesive zones thick with dots (darker for
    longer ranges), adhesionless grey dashed; a failed point is a gap in its curve."""
    from matplotlib import colormaps
    from matplotlib.figure import Figure

    fig = Figure(figsize=(15, 0.5 + 3.9 * len(loads)))
    axs = fig.subplots(len(loads), 3, squeeze=False)
    shades = colormaps["viridis_r"](np.linspace(0.15, 0.95, max(len(md), 1)))
    low = np.asarray(zetas) <= 0.1
    for (ax_a, ax_z, ax_f), load in zip(axs, loads):
        curves = ([("adhesionless", eb[0][1], "adhesionless", dict(color="0.5", ls="--", lw=1))]
                  if eb else [])
        curves += [(f"energy balance, {tag}", data, "adhesive",
                    dict(color=("C3", "C1", "C0")[i % 3], lw=1, marker="x", ms=3.5))
                   for i, (tag, data) in enumerate(eb)]
        curves += [(f"Maugis–Dugdale, {tag}", data, "adhesive",
                    dict(color=shades[i], lw=1.6, marker="o", ms=2.5))
                   for i, (tag, data) in enumerate(md)]
        for label, data, variant, style in curves:
            area = curve(data, "area", load, zetas, variant)
            ax_a.plot(zetas, area, label=label, **style)
            if variant == "adhesive":
                ax_z.plot(np.asarray(zetas)[low], area[low], **style)
            ax_f.plot(zetas, curve(data, "reduced_friction", load, zetas, variant), **style)
        for ax, label in ((ax_a, "contact area Ã"),
                          (ax_z, "contact area Ã (adhesive, ζ ≤ 0.1)"),
                          (ax_f, "reduced friction μ/√m2")):
            ax.set_xscale("log")
            ax.set_xlabel("ζ = q0 V τ")
            ax.set_ylabel(label)
            ax.set_title(f"p̃∞ = {load:g}", fontsize=9)
            ax.grid(alpha=0.3)
        ax_f.set_yscale("log")
        ax_f.set_ylim(1e-5, 2)
        ax_a.legend(fontsize=6.5)
    fig.suptitle("Thesis sinusoid (γ̃ = 1.5e-6, β = 10), load control: Maugis–Dugdale range h0 "
                 "against the energy balance's edge advance δX", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    return path


def main(argv=None) -> list[Path]:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=".", help="folder for the .h5, .csv and PNG files")
    parser.add_argument("--full", action="store_true",
                        help="the size measured in docs/cohesive.md (hours on one core)")
    parser.add_argument("--workers", type=int, default=1, help="worker processes")
    parser.add_argument("--force", action="store_true",
                        help="replace study files that hold a different study")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    parser.add_argument("--tiny", action="store_true", help=argparse.SUPPRESS)  # tests
    parser.add_argument("--ranges", default=None, help="cohesive ranges h0 in nm, e.g. 1,10")
    parser.add_argument("--edge-perturbations", default=None,
                        help="δX (q0·δX) of the energy-balance curves; empty for none")
    parser.add_argument("--zetas", default=None, help="ζ list: 1e-3,1 or START:STOP:N")
    parser.add_argument("--pressures", default=None, help="p̃∞ list")
    parser.add_argument("--low-zetas", default=None,
                        help="ζ below the sweep's, each solved from first touch at the first "
                             "load (the rubbery end of the friction), e.g. 1e-8,1e-7")
    parser.add_argument("--no-zones", action="store_true", help="skip the edge-terms pass")
    args = parser.parse_args(argv)
    size = SIZES[cases.size_name(args)]
    args.zetas = args.zetas or size["zetas"]
    args.pressures = args.pressures or size["pressures"]
    ranges = cases.floats(args.ranges if args.ranges is not None else size["ranges"])
    dxs = cases.floats(args.edge_perturbations if args.edge_perturbations is not None
                       else size["dxs"])
    out = Path(args.out)
    written, eb, md = [], [], []
    loads, zetas = cases.floats(args.pressures), cases.floats(args.zetas)
    for i, dx in enumerate(dxs):
        family = []
        for load in loads:
            path = out / f"cohesive_wavy_{cases.dx_tag(dx)}_p{load:g}.h5"
            family.append(compute(sweep(cases.scene("wavy", edge_perturbation=dx), args, load,
                                        pair=i == 0), path, args))
            written.append(path)
        eb.append((f"δX = {dx:g}", family))
    for h0 in ranges:
        family = cohesive_family(h0, args, out)
        md.append((f"h0 = {h0:g} nm", family))
        written += [data.path for data in family]
    low = cases.floats(args.low_zetas if args.low_zetas is not None else size["low"])
    if low:
        scenes = ([(f"{cases.dx_tag(dx)}", cases.scene("wavy", edge_perturbation=dx), i == 0)
                   for i, dx in enumerate(dxs)]
                  + [(md_tag(h0), cohesive_scene(h0), False) for h0 in ranges])
        for tag, scene, pair in scenes:
            path = out / f"cohesive_wavy_{tag}_p{loads[0]:g}_low.h5"
            compute(sweep(scene, args, loads[0], pair=pair, zetas=low),
                    path, args)
            written.append(path)
    if not args.no_zones:
        for (label, data), h0 in zip(md, ranges):
            written.append(out / f"zones_{md_tag(h0)}.csv")
            edge_rows(label, data, written[-1], loads[0])
        for (label, data), dx in zip(eb, dxs):
            written.append(out / f"zones_{cases.dx_tag(dx)}.csv")
            edge_rows(label, data, written[-1], loads[0])
    if md and eb:
        written.append(out / "distances.csv")
        for row in distances(md, eb, loads, zetas, written[-1]):
            print(f"{row['cohesive']} vs {row['energy_balance']} (p̃∞ = {row['load']:g}, "
                  f"{row['window']}, {row['points']} ζ): ΔÃ rms {row['area_rms']:.4f} "
                  f"max {row['area_max']:.4f};"
                  f" Δlog10 μ rms {row['log_friction_rms']:.3f} max "
                  f"{row['log_friction_max']:.3f}", flush=True)
    written.append(plot(md, eb, sorted(loads), zetas, out / "cohesive_wavy.png"))
    print(written[-1], flush=True)
    return written


if __name__ == "__main__":
    main()
