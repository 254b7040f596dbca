"""The areal spectral method: grid size against time, iterations and memory.

    python benchmarks/areal.py [--sizes 128,256,512,1024] [--zeta 1] [--load 1.0] [--seeds 0]
                               [--workers 2] [--repeats 1]
                               [--out benchmarks/results/raw/areal.json]

The scene of the acceptance run: an isotropic self-affine surface (H = 0.8, wavenumbers 1 to
``--q-max`` in units of q0, rms slope 0.1, seed 0 or each of ``--seeds``; the same surface
sampled on every grid) on a standard linear solid β = 10 at ζ = 1, adhesionless or with
``--adhesion`` (Maugis-Dugdale), load control (p̃∞ = 1: about 14 % contact without adhesion),
default tolerance. Each size is solved in a fresh process (so its peak resident memory is its
own), ``--repeats`` times; printed and written per size: wall and CPU seconds (medians), peak
memory, area fraction, μ, the error estimate, and per grid of the ladder the solver's iterations
(active-set steps) and operator products (FFT pairs), and the relative changes of Ã and μ from
each grid to the next (what the error estimate is made of). The machine's load average is
recorded beside them: on the shared two-core machine the wall time is the CPU time over the
share of a core the process got.
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import time
from pathlib import Path

import numpy as np


def self_affine(n: int, hurst: float = 0.8, q_max: float = 32.0, seed: int = 0,
                rms_slope: float = 0.1) -> np.ndarray:
    """``q0·h`` on ``n × n``: PSD ``∝ q^{-2(1+H)}`` for ``1 <= |q| <= q_max``, phases from the
    seed on a fixed 2048² spectrum (so every grid samples the same surface)."""
    rng = np.random.default_rng(seed)
    big = 2048
    phases = np.exp(2j * np.pi * rng.random((big, big // 2 + 1)))
    keep = int(q_max) + 1
    rows = np.r_[0:keep, big - keep + 1:big]
    qx = np.arange(keep, dtype=float)[None, :]
    qy = np.fft.fftfreq(big, 1.0 / big)[rows][:, None]
    q = np.hypot(qx, qy)
    amp = np.where((q >= 1) & (q <= q_max), np.maximum(q, 1.0) ** (-(1 + hurst)), 0.0)
    spec = np.zeros((n, n // 2 + 1), complex)
    small_rows = np.r_[0:keep, n - keep + 1:n]
    spec[small_rows, :keep] = amp * phases[rows][:, :keep]
    h = np.fft.irfft2(spec, (n, n))
    kx = np.fft.rfftfreq(n, 1.0 / n)[None, :]
    ky = np.fft.fftfreq(n, 1.0 / n)[:, None]
    gx = np.fft.irfft2(spec * 1j * kx, (n, n))
    gy = np.fft.irfft2(spec * 1j * ky, (n, n))
    return h * rms_slope / np.sqrt(np.mean(gx**2 + gy**2))


def one(n: int, zeta: float, load: float, workers: int, q_max: float, repeats: int,
        adhesion: str | None = None, seed: int = 0) -> dict:
    from viscocontact.adhesion import MaugisDugdale
    from viscocontact.areal.method import ArealSpectral
    from viscocontact.areal.problem import ArealProblem
    from viscocontact.rheology import StandardLinearSolid

    md = None
    if adhesion:
        gamma, reach = (float(v) for v in adhesion.split(","))
        md = MaugisDugdale(gamma=gamma, range=reach)
    prob = ArealProblem(surface=self_affine(n, q_max=q_max, seed=seed),
                        rheology=StandardLinearSolid(beta=10.0), zeta=zeta, mean_pressure=load,
                        adhesion=md)
    walls, cpus, result = [], [], None
    for _ in range(repeats):
        w, c = time.perf_counter(), time.process_time()
        result = ArealSpectral(workers=workers).solve(prob)
        walls.append(time.perf_counter() - w)
        cpus.append(time.process_time() - c)
    assert result is not None
    return {"points": n, "seed": seed, "wall_seconds": float(np.median(walls)),
            "cpu_seconds": float(np.median(cpus)),
            "peak_memory_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0,
            "converged": result.converged, "area_fraction": result.extras["area_fraction"],
            "friction": result.friction,
            "friction_dissipation": result.extras["friction_dissipation"],
            "error_estimate": result.extras["error_estimate"],
            "adhesion": adhesion or "",
            "patches": result.extras["patches"]["count"],
            "grids": [{k: (list(v) if isinstance(v, tuple) else v) for k, v in g.items()}
                      for g in result.extras["grids"]],
            "load_average": os.getloadavg()[0]}


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="128,256,512,1024")
    ap.add_argument("--zeta", type=float, default=1.0)
    ap.add_argument("--load", type=float, default=1.0)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--q-max", type=float, default=32.0)
    ap.add_argument("--seeds", default="0", help="surface seeds, comma-separated")
    ap.add_argument("--repeats", type=int, default=1)
    ap.add_argument("--adhesion", default="",
                    help="Maugis-Dugdale 'gamma,range' (γ̃, h̃0), e.g. 1e-4,3e-2; none by default")
    ap.add_argument("--out",
                    default=str(Path(__file__).parent / "results" / "raw" / "areal.json"))
    ap.add_argument("--one", type=int, help=argparse.SUPPRESS)
    ap.add_argument("--seed", type=int, default=0, help=argparse.SUPPRESS)
    args = ap.parse_args(argv)
    if args.one:
        print(json.dumps(one(args.one, args.zeta, args.load, args.workers, args.q_max,
                             args.repeats, args.adhesion or None, args.seed)))
        return
    rows = []
    print(f"{'cells':>11} {'wall s':>7} {'cpu s':>7} {'MB':>6} {'area':>7} {'mu':>8} "
          f"{'estimate':>8}  active-set steps / FFT pairs per grid   (load avg)")
    runs = [(int(n), int(seed)) for seed in args.seeds.split(",") for n in args.sizes.split(",")]
    for n, seed in runs:
        cmd = [sys.executable, __file__, "--one", str(n), "--seed", str(seed),
               "--zeta", str(args.zeta),
               "--load", str(args.load), "--workers", str(args.workers),
               "--q-max", str(args.q_max), "--repeats", str(args.repeats),
               "--adhesion", args.adhesion]
        done = subprocess.run(cmd, capture_output=True, text=True)
        if done.returncode != 0:
            why = (done.stderr.strip().splitlines() or ["no output"])[-1]
            rows.append({"points": n, "error": why})
            print(f"{n:>5}×{n:<5} failed: {why}", flush=True)
            continue
        row = json.loads(done.stdout.splitlines()[-1])
        rows.append(row)
        per = ", ".join(f"{g['points'][0]}: {g['iterations']}/{g['applications']}"
                        for g in row["grids"])
        print(f"{n:>5}×{n:<5} {row['wall_seconds']:7.2f} {row['cpu_seconds']:7.2f} "
              f"{row['peak_memory_mb']:6.0f} {row['area_fraction']:7.4f} {row['friction']:8.5f} "
              f"{row['error_estimate']:8.2g}  {per}   ({row['load_average']:.1f})", flush=True)
        print(f"{'':11} seed {seed}: changes of Ã, μ to each grid: {changes(row['grids'])}")
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = out.with_suffix(".tmp")
    tmp.write_text(json.dumps({"scene": {"hurst": 0.8, "q_max": args.q_max, "rms_slope": 0.1,
                                         "beta": 10.0, "zeta": args.zeta,
                                         "mean_pressure": args.load,
                                         "workers": args.workers, "cpus": os.cpu_count(),
                                         "seeds": args.seeds,
                                         "adhesion": args.adhesion},
                               "rows": rows}, indent=1))
    tmp.replace(out)


def changes(grids) -> str:
    """The relative changes of Ã and μ from each grid of a ladder to the next."""
    out = []
    for a, b in zip(grids, grids[1:]):
        da = abs(b["area"] - a["area"]) / abs(b["area"])
        dm = abs(b["friction"] - a["friction"]) / max(abs(b["friction"]), 1e-300)
        out.append(f"{b['points'][0]}: {da:.1e}, {dm:.1e}")
    return "; ".join(out)


if __name__ == "__main__":
    main()
