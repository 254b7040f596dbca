"""``viscocontact bench``: a tiny run into tmp_path, and one-line errors for bad options."""
import csv
import math
from pathlib import Path

import pytest

from viscocontact.reports import bench as benchmarking
from viscocontact.cli import main

SUITE = Path(__file__).resolve().parents[3] / "benchmarks"


def test_tiny_run_writes_table_and_plot(tmp_path, capsys):
    code = main(["bench", "--quick", "--suite", str(SUITE), "--out", str(tmp_path),
                 "--cases", "sinusoid-noadh-z1", "--solvers", "newton",
                 "--elements", "8,16", "--points", "128,512"])
    assert code == 0
    for name in ("bench.csv", "bench.md", "bench.png"):
        assert (tmp_path / name).stat().st_size > 0
    assert not list(tmp_path.glob(".*.tmp"))               # nothing half-written left over
    rows = list(csv.DictReader((tmp_path / "bench.csv").open()))
    assert {r["method"] for r in rows} == {"newton", "fft-pdas"}
    for r in rows:
        assert r["status"] == "converged"
        assert float(r["seconds"]) > 0 and float(r["area"]) > 0 and float(r["friction"]) > 0
        assert math.isfinite(float(r["err_area"])) and float(r["err_area"]) >= 0
    text = (tmp_path / "bench.md").read_text()
    assert "reference" in text and "| fft-pdas |" in text


@pytest.mark.parametrize("argv, option, allowed", [
    (["--repeats", "0"], "--repeats", "[1, 100]"),
    (["--budget", "-1"], "--budget", "(0, 3600]"),
    (["--cases", "nope"], "--cases", "one of"),
    (["--solvers", "gauss"], "--solvers", "one of"),
    (["--elements", "4"], "--elements", "[8, 4096]"),
    (["--points", "15"], "--points", "even integers"),
    (["--suite", "/no/such/folder"], "--suite", "/no/such/folder"),
])
def test_bad_option_is_one_line_exit_2(tmp_path, capsys, argv, option, allowed):
    code = main(["bench", "--out", str(tmp_path), *argv])
    err = capsys.readouterr().err.strip()
    assert code == 2
    assert len(err.splitlines()) == 1
    assert option in err and allowed in err


def test_suite_without_peer_is_rejected(tmp_path, capsys):
    assert main(["bench", "--suite", str(tmp_path), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert "--suite" in err and "peer_fft.py" in err


def test_reference_uses_richardson_only_for_a_sensible_order():
    rows = [dict(method="newton", resolution=n, status="converged", area=1.0 + 1.0 / n ** 2,
                 friction=0.1) for n in (16, 32, 64)]
    ref = benchmarking.reference(rows)
    assert ref["area"] == pytest.approx(1.0, abs=1e-12)
    assert "Richardson" in ref["kind"] and "friction: finest mesh" in ref["kind"]


def test_pareto_front():
    assert benchmarking.pareto([(1, 5), (2, 6), (3, 1), (0.5, 9)]) == [(0.5, 9), (1, 5), (3, 1)]


def test_bench_runs_outside_the_source_tree(tmp_path, monkeypatch, capsys):
    """Without ``--suite`` and without ``./benchmarks``, the FFT peer shipped with the package."""
    monkeypatch.chdir(tmp_path)
    assert main(["bench", "--quick", "--out", "out", "--cases", "sinusoid-noadh-z1",
                 "--solvers", "newton", "--elements", "8", "--points", "128"]) == 0
    rows = list(csv.DictReader((tmp_path / "out" / "bench.csv").open()))
    assert {r["method"] for r in rows} == {"newton", "fft-pdas"}
