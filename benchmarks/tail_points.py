"""Re-solve the slowest points of a study file with this tree, next to what the file recorded.

    python benchmarks/tail_points.py STUDY.h5 [--top 25] [--variant adhesive] [--csv FILE]

A ζ-sweep's time sits in a tail of points (the full Fig. 4.10 set: 7 % of the points took 65 %
of the solve time). This takes the ``--top`` points of the file with the largest recorded
``seconds``, rebuilds each exactly as the sweep did (its scene, its predicted start from the
stored neighbours: :meth:`Sweep.next_point`), solves it with this tree and prints, per point,
the recorded and the new residual evaluations and seconds and the relative change of Ã and μ.

Evaluations are the comparison that does not depend on the machine's load (the recorded seconds
come from another run, maybe with other jobs beside it); the yardstick of the dense solve
(``adhesive_point.dense_solve_seconds``) is timed at the start and printed, so that seconds can
be read as dense solves.
"""
from __future__ import annotations

import argparse
import csv
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from adhesive_point import dense_solve_seconds  # noqa: E402


def main(argv=None) -> int:
    from viscocontact.studies import load_study
    from viscocontact.studies.point import COLUMNS, solve_point

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("study", type=Path)
    parser.add_argument("--top", type=int, default=25)
    parser.add_argument("--variant", default="adhesive")
    parser.add_argument("--csv", type=Path, default=None, help="also write the table here")
    args = parser.parse_args(argv)

    data = load_study(args.study)
    study = data.study
    frame = data.to_dataframe()
    frame = frame[frame.variant == args.variant]
    chains = {c.index: c for c in study.chains()}
    slowest = frame.sort_values("seconds", ascending=False).head(args.top)
    dense = dense_solve_seconds()
    print(f"dense 2000x2000 solve: {dense:.3f} s")
    header = ("seed", "load", "zeta", "status", "n_contacts", "evals_before", "evals_after",
              "seconds_before", "seconds_after", "area_change", "friction_change")
    print(" ".join(f"{h:>14}" for h in header))
    rows = []
    for _, point in slowest.iterrows():
        chain = chains[int(point.chain)]
        stored = frame[frame.chain == point.chain].sort_values("step")
        records = [{c: r[c] for c in COLUMNS} for _, r in stored.iterrows()]
        scene, spec, initial = study.next_point(chain, records[:int(point.step)])
        t0 = time.perf_counter()
        new = solve_point(scene, spec, initial)
        seconds = time.perf_counter() - t0
        row = (int(point.seed), float(point.load), float(point.zeta), new["status"],
               int(new["n_contacts"]), int(point.function_evaluations),
               int(new["function_evaluations"]), float(point.seconds), seconds,
               float(new["area"] / point.area - 1.0),
               float(new["reduced_friction"] / point.reduced_friction - 1.0))
        rows.append(row)
        print(" ".join(f"{v:>14.4g}" if isinstance(v, float) else f"{v!s:>14}" for v in row),
              flush=True)
    if rows:
        before = sum(r[5] for r in rows), sum(r[7] for r in rows)
        after = sum(r[6] for r in rows), sum(r[8] for r in rows)
        print(f"total: {before[0]} -> {after[0]} evaluations, {before[1]:.0f} s -> {after[1]:.0f} s "
              f"({after[1] / dense:.0f} dense solves); largest |ΔÃ/Ã| "
              f"{max(abs(r[9]) for r in rows):.2g}, |Δμ/μ| {max(abs(r[10]) for r in rows):.2g}")
    if args.csv is not None:
        with open(args.csv, "w", newline="") as f:
            writer = csv.writer(f)
            writer.writerow(header)
            writer.writerows(rows)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
