"""Tabulate the recorded benchmark results of ``benchmarks/results/``.

Every file there is a table of measurements, one row each, with the columns ``date`` (ISO day the
measurement was made, may be empty), ``commit`` (the measured code, may be empty), ``benchmark``,
``quantity``, ``value`` (a number) and ``unit``; CSV files have them as a header, JSON files are a
list of such records. This script selects rows and prints them::

    python benchmarks/results_table.py                              # what the files hold, per benchmark
    python benchmarks/results_table.py --benchmark "performance: 9" # the rows of one benchmark
    python benchmarks/results_table.py --quantity "crowded" --unit s --since 2026-11-27
    python benchmarks/results_table.py --commit 04cb580 --format markdown
    python benchmarks/results_table.py --benchmark fig_4_10 --plot times.png   # value against date

Filters are case-insensitive substrings (``--since``/``--until``: ISO dates, inclusive).
"""
from __future__ import annotations

import argparse
import csv
import json
import sys
from collections import defaultdict
from pathlib import Path
from typing import Iterable, Sequence

RESULTS = Path(__file__).resolve().parent / "results"
COLUMNS = ("date", "commit", "benchmark", "quantity", "value", "unit")


class ResultsError(ValueError):
    """A results file that does not follow the schema (names the file, row and column)."""


def _record(raw: dict, where: str) -> dict:
    missing = [c for c in COLUMNS if c not in raw]
    if missing:
        raise ResultsError(f"{where}: missing column(s) {', '.join(missing)}; expected {COLUMNS}")
    try:
        value = float(raw["value"])
    except (TypeError, ValueError):
        raise ResultsError(f"{where}: value = {raw['value']!r} is not a number") from None
    date = str(raw["date"] or "")
    if date and not (len(date) == 10 and date[4] == date[7] == "-"):
        raise ResultsError(f"{where}: date = {date!r} is not an ISO day (YYYY-MM-DD) or empty")
    return {"date": date, "commit": str(raw["commit"] or ""), "benchmark": str(raw["benchmark"]),
            "quantity": str(raw["quantity"]), "value": value, "unit": str(raw["unit"] or "")}


def load(paths: Iterable[Path] | None = None) -> list[dict]:
    """The rows of the given files (default: every ``*.csv`` and ``*.json`` of ``results/``)."""
    if paths is None:
        paths = sorted([*RESULTS.glob("*.csv"), *RESULTS.glob("*.json")])
    rows: list[dict] = []
    for path in map(Path, paths):
        if path.suffix == ".json":
            records = json.loads(path.read_text(encoding="utf-8"))
            if not isinstance(records, list):
                raise ResultsError(f"{path.name}: expected a JSON list of records")
        else:
            with path.open(newline="", encoding="utf-8") as handle:
                records = list(csv.DictReader(handle))
        rows += [_record(r, f"{path.name} row {i + 1}") for i, r in enumerate(records)]
    return rows


def select(rows: Sequence[dict], *, benchmark: str = "", quantity: str = "", commit: str = "",
           unit: str = "", since: str = "", until: str = "") -> list[dict]:
    """Rows whose fields contain the given substrings (case-insensitive), dated within
    ``[since, until]`` (undated rows pass only when neither is given)."""
    def has(text: str, part: str) -> bool:
        return part.lower() in text.lower()

    out = []
    for row in rows:
        if not (has(row["benchmark"], benchmark) and has(row["quantity"], quantity)
                and row["commit"].startswith(commit) and (not unit or row["unit"] == unit)):
            continue
        if (since or until) and not row["date"]:
            continue
        if (since and row["date"] < since) or (until and row["date"] > until):
            continue
        out.append(row)
    return out


def summary(rows: Sequence[dict]) -> list[dict]:
    """One line per benchmark: its row count, dates and commits."""
    groups: dict[str, list[dict]] = defaultdict(list)
    for row in rows:
        groups[row["benchmark"]].append(row)
    out = []
    for name, members in groups.items():
        dates = sorted({r["date"] for r in members if r["date"]})
        commits = sorted({r["commit"] for r in members if r["commit"]})
        out.append({"benchmark": name, "rows": len(members),
                    "dates": f"{dates[0]} … {dates[-1]}" if len(dates) > 1 else "".join(dates),
                    "commits": ", ".join(commits)})
    return out


def format_table(rows: Sequence[dict], columns: Sequence[str], markdown: bool = False) -> str:
    """The rows as an aligned text table or a Markdown table."""
    def text(value) -> str:
        return f"{value:.6g}" if isinstance(value, float) else str(value)

    cells = [[text(r[c]) for c in columns] for r in rows]
    if markdown:
        lines = ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
        lines += ["| " + " | ".join(c.replace("|", "\\|") for c in row) + " |" for row in cells]
        return "\n".join(lines)
    widths = [max([len(c)] + [len(row[i]) for row in cells]) for i, c in enumerate(columns)]
    lines = ["  ".join(c.ljust(w) for c, w in zip(columns, widths))]
    lines += ["  ".join(v.ljust(w) for v, w in zip(row, widths)) for row in cells]
    return "\n".join(line.rstrip() for line in lines)


def plot(rows: Sequence[dict], path: Path) -> None:
    """``value`` against ``date``, one series per (quantity, unit)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from datetime import date

    series: dict[tuple[str, str], list[tuple]] = defaultdict(list)
    for row in rows:
        if row["date"]:
            series[(row["quantity"], row["unit"])].append(
                (date.fromisoformat(row["date"]), row["value"]))
    fig, ax = plt.subplots(figsize=(7, 4))
    for (quantity, unit), points in sorted(series.items()):
        points.sort()
        ax.plot([p[0] for p in points], [p[1] for p in points], "o-",
                label=f"{quantity[:40]} ({unit})")
    ax.set_xlabel("date")
    ax.set_ylabel("value")
    if len(series) <= 12:
        ax.legend(fontsize=6)
    fig.autofmt_xdate()
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("files", nargs="*", type=Path, help="results files (default: results/)")
    for name in ("benchmark", "quantity", "commit", "unit", "since", "until"):
        parser.add_argument(f"--{name}", default="")
    parser.add_argument("--format", choices=("text", "markdown", "csv"), default="text")
    parser.add_argument("--plot", type=Path, help="also draw value against date into this PNG")
    args = parser.parse_args(argv)
    try:
        rows = load(args.files or None)
    except (OSError, ResultsError) as exc:
        print(f"results_table: {exc}", file=sys.stderr)
        return 2
    filters = {k: getattr(args, k) for k in ("benchmark", "quantity", "commit", "unit", "since",
                                             "until")}
    chosen = select(rows, **filters)
    columns: Sequence[str] = COLUMNS
    table = chosen
    if not any(filters.values()):
        table, columns = summary(chosen), ("benchmark", "rows", "dates", "commits")
    if args.format == "csv":
        writer = csv.DictWriter(sys.stdout, fieldnames=columns, lineterminator="\n")
        writer.writeheader()
        writer.writerows(table)
    else:
        print(format_table(table, columns, markdown=args.format == "markdown"))
    if args.plot:
        plot(chosen, args.plot)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except BrokenPipeError:      # the reader stopped early (``| head``): not an error
        sys.stderr.close()
        sys.exit(0)
