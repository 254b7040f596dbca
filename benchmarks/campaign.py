"""A randomised campaign over the whole scene space (``viscocontact.testing.campaign``).

Draws ``--scenes`` scenes from consecutive seeds, solves each in a fresh worker process (forked
from a warmed-up parent, ``--workers`` at a time) under ``--time-limit`` seconds (the solve's
cooperative deadline; a worker still running ``--grace`` seconds past it is killed), checks each
result (``check`` of the campaign module), writes one record per scene to ``--out`` and prints
pass counts and the median and largest time per scene by adhesion model, rheology, kernel,
control and solver.

    PYTHONPATH=. python benchmarks/campaign.py --scenes 300 --time-limit 30
    PYTHONPATH=. python benchmarks/campaign.py --scenes 300 --dense-solves 450
    PYTHONPATH=. python benchmarks/campaign.py --table      # the table of an existing file

``--long-limit S`` gives the scenes that reach the time limit a second solve with ``S`` seconds:
a slow scene is then told from one that does not converge, and its record keeps the first
time and message under ``"first"``. With ``--long-only`` that second pass runs on the
time-limited scenes of an existing ``--out`` and writes it back.

``--dense-solves N`` sets the limit to ``N`` times one ``numpy.linalg.solve`` of a 2000 × 2000
system on one BLAS thread, measured before the run (``adhesive_point.py``'s yardstick): the same
scenes then meet the same limit on a slower machine. 450 is the 45 s of the tables in
``docs/verification.md`` on the machine where the yardstick took about 0.10 s; on one where it
took 0.143 s, a 45 s limit lost scenes of 8-43 s there (the page gives the counts).
"""
from __future__ import annotations

import argparse
import json
import multiprocessing as mp
import os
import statistics
import sys
import time
from collections import defaultdict
from pathlib import Path

from viscocontact.testing.campaign import describe, draw, run_scene

DEFAULT_OUT = Path(__file__).resolve().parent / "results" / "raw" / "campaign.json"
GROUPS = ("adhesion", "rheology", "kernel", "control", "solver", "profile", "method")


def _child(seed: int, time_limit: float, conn) -> None:
    outcome = run_scene(draw(seed), time_limit=time_limit)
    conn.send(outcome.to_dict())
    conn.close()


def _record(seed: int, table: dict, out: dict) -> dict:
    """The seed, its drawn parameters (6 digits: ``draw(seed)`` gives them exactly) and its
    outcome."""
    return {"seed": seed, "scene": _rounded(table), **out}


def _rounded(value):
    if isinstance(value, dict):
        return {k: _rounded(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_rounded(v) for v in value]
    if isinstance(value, float):
        return float(f"{value:.6g}")
    return value


def _killed(seed: int, seconds: float) -> dict:
    return {"outcome": "time-limit", "message": f"killed {seconds:.0f} s after its start",
            "failures": [f"killed after {seconds:.0f} s"], "warnings": [],
            "seconds": round(seconds, 3), "method": "", "power_tolerance": ""}


def run(seeds, *, workers: int, time_limit: float, grace: float, progress=print,
        save=None) -> list[dict]:
    """One record per seed (in seed order), each solved in its own forked process; ``save``
    is called with the records so far after every tenth."""
    ctx = mp.get_context("fork")
    pending = list(seeds)
    running: dict[int, tuple] = {}
    records: dict[int, dict] = {}
    while pending or running:
        while pending and len(running) < workers:
            seed = pending.pop(0)
            recv, send = ctx.Pipe(duplex=False)
            proc = ctx.Process(target=_child, args=(seed, time_limit, send), daemon=True)
            proc.start()
            send.close()
            running[seed] = (proc, recv, time.monotonic())
        for seed, (proc, recv, start) in list(running.items()):
            elapsed = time.monotonic() - start
            out = None
            if recv.poll():
                try:
                    out = recv.recv()
                except EOFError:
                    out = {"outcome": "error", "message": "worker died", "seconds": elapsed,
                           "failures": [f"worker died (exit code {proc.exitcode})"]}
            elif not proc.is_alive():
                out = {"outcome": "error", "message": f"worker exit code {proc.exitcode}",
                       "seconds": elapsed, "failures": [f"worker exit code {proc.exitcode}"]}
            elif elapsed > time_limit + grace:
                proc.kill()
                out = _killed(seed, elapsed)
            if out is not None:
                proc.join(5)
                recv.close()
                del running[seed]
                records[seed] = _record(seed, draw(seed), out)
                progress(f"seed {seed:4d} {records[seed]['outcome']:14s} "
                         f"{'pass' if not records[seed]['failures'] else 'FAIL'} "
                         f"{records[seed]['seconds']:7.1f} s  {_label(draw(seed))}")
                if save is not None and len(records) % 10 == 0:
                    save([records[s] for s in sorted(records)])
        time.sleep(0.05)
    return [records[s] for s in sorted(records)]


def long_pass(records: list[dict], *, workers: int, long_limit: float, grace: float,
              progress=print) -> list[dict]:
    """``records`` with their time-limited scenes solved again under ``long_limit``: each
    such record is replaced by the second one, which keeps the first one's time and message
    under ``"first"``."""
    slow = [r for r in records if r["outcome"] == "time-limit" and "first" not in r]
    if not slow:
        return records
    first = {r["seed"]: {"seconds": r["seconds"], "message": r["message"]} for r in slow}
    again = run([r["seed"] for r in slow], workers=workers, time_limit=long_limit,
                grace=grace, progress=progress)
    redone = {r["seed"]: {**r, "first": first[r["seed"]]} for r in again}
    return [redone.get(r["seed"], r) for r in records]


def _label(scene: dict) -> str:
    labels = describe(scene)
    return " ".join(labels[g] for g in GROUPS[:5])


def _labelled(records: list[dict]) -> list[dict]:
    return [{**describe(r["scene"]), **r} for r in records]


def table(records: list[dict]) -> str:
    """Pass counts, outcomes and time per scene by component."""
    records = _labelled(records)
    lines = [f"{len(records)} scenes, {sum(not r['failures'] for r in records)} pass; "
             f"outcomes: {dict(_count(r['outcome'] for r in records))}; power balance checked "
             f"against the estimate {sum(r.get('power_tolerance') == 'estimate' for r in records)}"
             f", the fallback {sum(r.get('power_tolerance') == 'fallback' for r in records)}", ""]
    slow = sum("first" in r for r in records)
    if slow:
        lines[0] += (f"; {slow} solved again under the long limit after the first, "
                     f"{sum('first' in r and not r['failures'] for r in records)} passing")
    head = (f"| {'group':<14} | {'value':<22} | scenes | pass | conv | outside | scene | "
            f"refused | path | limit | other | median s | max s |")
    for group in GROUPS:
        lines += [head, "|" + "|".join("-" * (len(c)) for c in head.split("|")[1:-1]) + "|"]
        by = defaultdict(list)
        for r in records:
            by[r.get(group) or "-"].append(r)
        for value in sorted(by):
            rs = by[value]
            n = _count(r["outcome"] for r in rs)
            secs = [r["seconds"] for r in rs]
            other = len(rs) - sum(n[k] for k in ("converged", "outside-model", "scene",
                                                 "refused", "path", "time-limit"))
            passed = sum(not r["failures"] for r in rs)
            lines.append(
                f"| {group:<14} | {value:<22} | {len(rs):6d} | {passed:4d} "
                f"| {n['converged']:4d} | {n['outside-model']:7d} | {n['scene']:5d} | "
                f"{n['refused']:7d} | {n['path']:4d} | {n['time-limit']:5d} | {other:5d} | "
                f"{statistics.median(secs):8.2f} | {max(secs):5.1f} |")
        lines.append("")
    return "\n".join(lines)


def _count(items) -> defaultdict:
    out: defaultdict = defaultdict(int)
    for item in items:
        out[item] += 1
    return out


def _warm_up() -> None:
    """Load the compiled code once in the parent, so that the forked workers share it."""
    import viscocontact as vc

    for table in ({"profile": {"kind": "sinusoid", "amplitude": 0.05},
                   "rheology": {"kind": "standard-linear-solid", "beta": 10.0},
                   "adhesion": {"kind": "energy-balance", "gamma": 1e-6},
                   "load": {"mean_pressure": 0.3}, "sliding": {"zeta": 1.0}},
                  {"profile": {"kind": "self-affine", "hurst": 0.8, "scales": 10, "rms": 0.01},
                   "rheology": {"kind": "standard-linear-solid", "beta": 10.0},
                   "load": {"mean_pressure": 0.3}, "sliding": {"zeta": 1.0}}):
        vc.solve(table)


def _write(path: Path, records: list[dict], *, workers: int, time_limit: float,
           wall: float, long_limit: float | None = None) -> None:
    """The records and the run's settings as JSON, written whole (a temporary file moved in
    place)."""
    from viscocontact import __version__

    head = {"version": __version__, "scenes": len(records), "workers": workers,
            "time_limit": time_limit, "long_limit": long_limit,
            "wall_seconds": round(wall, 1)}
    lines = ",\n".join(json.dumps(r, ensure_ascii=False, allow_nan=False,
                                  separators=(",", ":")) for r in records)
    text = json.dumps(head)[:-1] + ', "records": [\n' + lines + "\n]}\n"   # a record a line
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(".tmp")
    tmp.write_text(text, encoding="utf-8")
    tmp.replace(path)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", type=int, default=300)
    ap.add_argument("--first-seed", type=int, default=0)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--time-limit", type=float, default=30.0, help="seconds per scene")
    ap.add_argument("--dense-solves", type=float, default=None,
                    help="the limit in units of a 2000 x 2000 dense solve measured before the "
                         "run (instead of --time-limit)")
    ap.add_argument("--grace", type=float, default=60.0,
                    help="seconds past the limit before a worker is killed")
    ap.add_argument("--long-limit", type=float, default=None,
                    help="seconds of a second solve of each scene that reaches the limit")
    ap.add_argument("--long-only", action="store_true",
                    help="only the second pass, on the time-limited scenes of --out")
    ap.add_argument("--out", type=Path, default=DEFAULT_OUT)
    ap.add_argument("--table", action="store_true", help="print the table of --out and exit")
    args = ap.parse_args(argv)
    if args.table:
        print(table(json.loads(args.out.read_text(encoding="utf-8"))["records"]))
        return 0
    from threadpoolctl import threadpool_limits

    # one thread per worker, the workers share the cores (numba reads its count when loaded)
    for var in ("NUMBA_NUM_THREADS", "VISCOCONTACT_THREADS"):
        os.environ.setdefault(var, "1")
    threadpool_limits(limits=1)
    if args.dense_solves is not None:
        sys.path.insert(0, str(Path(__file__).resolve().parent))
        from adhesive_point import dense_solve_seconds

        unit = dense_solve_seconds()
        args.time_limit = args.dense_solves * unit
        print(f"limit {args.dense_solves:g} dense solves of {unit:.3f} s: "
              f"{args.time_limit:.1f} s a scene", flush=True)
    if args.long_only and args.long_limit is None:
        ap.error("--long-only needs --long-limit")
    _warm_up()
    t0 = time.monotonic()
    seeds = range(args.first_seed, args.first_seed + args.scenes)
    earlier = 0.0

    def save(records):
        _write(args.out, records, workers=args.workers, time_limit=args.time_limit,
               wall=earlier + time.monotonic() - t0, long_limit=args.long_limit)

    def progress(line):
        print(line, flush=True)

    if args.long_only:
        head = json.loads(args.out.read_text(encoding="utf-8"))
        records, earlier = head["records"], head["wall_seconds"]
        args.time_limit = head["time_limit"]          # the first pass's, as recorded
    else:
        records = run(seeds, workers=args.workers, time_limit=args.time_limit,
                      grace=args.grace, progress=progress, save=save)
        save(records)
    if args.long_limit is not None:
        records = long_pass(records, workers=args.workers, long_limit=args.long_limit,
                            grace=args.grace, progress=progress)
        save(records)
    wall = earlier + time.monotonic() - t0
    print(f"\nwall time {wall:.0f} s on {args.workers} workers\n")
    print(table(records))
    return 0


if __name__ == "__main__":
    sys.exit(main())
