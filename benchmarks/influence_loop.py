"""The compiled influence-coefficient loop against the numpy loop, on the meshes of a real solve.

    python benchmarks/influence_loop.py [--seed 12] [--every 10] [--repeats 3]

Solves the rough adhesive point of ``adhesive_point.py`` (seed ``--seed``) once and records
every table-backed element-integral call it makes (points and element ends; every ``--every``-th
is kept). Then times, alternately and in the same process, the compiled loop
(:meth:`KernelTable.element_integrals`, what the solver uses) and the numpy loop over row blocks
(the same table's look-ups behind a lambda, which the dispatch does not recognise), and prints
seconds, nanoseconds per coefficient and the largest difference between the two, relative to the
largest coefficient.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from adhesive_point import problem  # noqa: E402


def record_calls(seed: int, every: int):
    """``(kernel, name, points, left, right)`` of the table-backed calls of one solve."""
    from viscocontact.contact import edges, fields
    from viscocontact.kernels import prepared

    calls = []
    original = prepared.element_integrals

    def spy(function, points, left, right, *args, **kwargs):
        owner = getattr(function, "__self__", None)
        if getattr(owner, "table", None) is not None:
            calls.append((owner, function.__name__, np.array(points), np.array(left),
                          np.array(right)))
        return original(function, points, left, right, *args, **kwargs)

    modules = (prepared, fields, edges)
    for module in modules:
        module.element_integrals = spy
    try:
        problem(seed, crowded=False).solve()
    finally:
        for module in modules:
            module.element_integrals = original
    return calls[::every]


def main(argv=None) -> None:
    from viscocontact.kernels.prepared import element_integrals

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, default=12)
    ap.add_argument("--every", type=int, default=10)
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args(argv)
    calls = record_calls(args.seed, args.every)
    entries = sum(p.size * a.size for _, _, p, a, _ in calls)

    def compiled():
        return [element_integrals(getattr(k, name), p, a, b) for k, name, p, a, b in calls]

    def numpy_loop():
        out = []
        for k, name, p, a, b in calls:
            f = k.table.pair if name == "antiderivative_pair" else k.table.antiderivative
            out.append(element_integrals(lambda x, f=f: f(x), p, a, b))
        return out

    diff = max(float(np.max(np.abs(c - n)) / max(np.max(np.abs(n)), 1e-300))
               for c, n in zip(compiled(), numpy_loop()))
    times = {"compiled": [], "numpy": []}
    for _ in range(args.repeats):
        for name, run in (("numpy", numpy_loop), ("compiled", compiled)):
            t = time.perf_counter()
            run()
            times[name].append(time.perf_counter() - t)
    print(f"seed {args.seed}: {len(calls)} calls, {entries} coefficients "
          f"(every {args.every}th call of the solve)")
    for name, ts in times.items():
        best = min(ts)
        print(f"{name:>9}: {best:.3f} s (best of {args.repeats}), "
              f"{best / entries * 1e9:.1f} ns per coefficient")
    print(f"numpy / compiled: {min(times['numpy']) / min(times['compiled']):.2f}x; "
          f"largest difference {diff:.1e} of the largest coefficient")


if __name__ == "__main__":
    main()
