"""The energy balance's power misfit against the edge advance δX and a fast arm's relaxation.

    python benchmarks/power_memory.py [--seed 266] [--out benchmarks/results/raw/power_memory.json]

The scene is a campaign scene (:func:`viscocontact.testing.campaign.draw`; by default seed 266,
a two-arm Prony solid at ζ = 4.6e-4 under the energy balance, on the half-plane instead of its
confined layer: the misfit is the same on both). Its fastest arm's relaxation time is scaled by
10, 1 and 0.1, so that the arm's relaxation length ζτ (the shortest of the solid, the width of a
trailing edge's boundary layer) sits above, near and below δX, and each is solved at the
default δX = 1e-4, at δX equal to that length and at δX = 0 (the closed form). Each row gives
μ, the dissipated power's friction (bulk and edge flux), their misfit relative to μ, the
campaign's allowance for it (:func:`viscocontact.testing.campaign.check`: the two error
estimates and 1 % of the energy through the tips) and whether the misfit is within it.
About a minute on two cores.
"""
from __future__ import annotations

import argparse
import copy
import json
from pathlib import Path

HERE = Path(__file__).resolve().parent
SCALES = (10.0, 1.0, 0.1)


def rows(seed: int):
    import viscocontact as vc
    from viscocontact.testing.campaign import check, draw

    base = draw(seed)
    base["kernel"] = {"kind": "half-plane"}
    rheology = base["rheology"]
    assert rheology["kind"] == "prony", f"seed {seed} is not a Prony solid: {rheology}"
    fast = min(range(len(rheology["times"])), key=lambda i: rheology["times"][i])
    zeta = float(base["sliding"]["zeta"])
    for scale in SCALES:
        table = copy.deepcopy(base)
        table["rheology"]["times"][fast] *= scale
        length = zeta * table["rheology"]["times"][fast]
        for dx in (1e-4, float(f"{length:.2g}"), 0.0):
            table["adhesion"]["edge_perturbation"] = dx
            scene = vc.Scene.from_dict(table)
            result = vc.solve(scene)
            failures, _, values = check(scene, result)
            mu = values["friction"]
            misfit = abs(mu - values["friction_dissipation"] - values["friction_edges"])
            row = {"time_scale": scale, "relaxation_length": length, "edge_perturbation": dx,
                   "converged": bool(result.converged), "area": float(result.area),
                   "friction": mu, "friction_dissipation": values["friction_dissipation"],
                   "friction_edges": values["friction_edges"], "misfit": misfit / abs(mu),
                   "allowed": values["power_allowed"] / abs(mu), "within": not failures}
            print(f"τ×{scale:<4g} relaxation {length:8.2g} δX {dx:8.2g}  Ã {row['area']:.4f}  "
                  f"μ {mu:.6f}  misfit {row['misfit']:.2g} (allowed {row['allowed']:.2g})"
                  f"{'' if row['within'] else '  beyond'}", flush=True)
            yield row


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, default=266)
    ap.add_argument("--out", type=Path, default=HERE / "results" / "raw" / "power_memory.json")
    args = ap.parse_args(argv)
    from viscocontact._files import write_atomic

    out = {"benchmark": "power_memory.py", "seed": args.seed, "rows": list(rows(args.seed))}
    write_atomic(args.out, (json.dumps(out, indent=1) + "\n").encode())
    print(f"written to {args.out}")


if __name__ == "__main__":
    main()
