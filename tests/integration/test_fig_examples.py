"""The thesis-figure scripts (examples/fig_4_*.py, fig_pressure_gap.py, cohesive_wavy.py) run in
``--tiny`` configuration and write study files with finite numbers and PNG figures."""
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
PNG = b"\x89PNG\r\n\x1a\n"


def run_script(name, tmp_path, *args):
    env = dict(os.environ, MPLBACKEND="Agg", OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")
    proc = subprocess.run([sys.executable, str(ROOT / "examples" / name), "--tiny", "--quiet",
                           "--out", str(tmp_path), *args],
                          capture_output=True, text=True, env=env, timeout=300)
    assert proc.returncode == 0, proc.stderr[-3000:]
    return proc.stdout


def check_png(path):
    assert path.exists(), path
    assert path.read_bytes()[:8] == PNG
    assert 5_000 < path.stat().st_size < 200_000


def check_sweep(path, quantities=("area", "reduced_friction")):
    from viscocontact.studies import load_study

    data = load_study(path)
    assert data.kind == "sweep" and data.complete and len(data) > 0
    assert data.points["converged"].all(), data.points["message"]
    for q in quantities:
        assert np.isfinite(data.table(q)).all(), (path, q)
    return data


def test_fig_4_7_tiny_wavy_family(tmp_path):
    run_script("fig_4_7.py", tmp_path, "--profiles", "wavy", "--edge-perturbations", "1e-4,0")
    check_png(tmp_path / "fig_4_7_wavy.png")
    for control in ("mean_pressure", "penetration"):
        data = check_sweep(tmp_path / f"sweep_wavy_{control}_dx1e-04.h5")
        assert data.study.control == control
        assert set(data.axes()["variant"]) == {"adhesive", "adhesionless"}
    # the δX family: the limit δX = 0 without a second adhesionless twin
    data = check_sweep(tmp_path / "sweep_wavy_mean_pressure_dx0.h5")
    assert data.axes()["variant"] == ("adhesive",)
    assert (data.points["edge_perturbation"] == 0).all()


@pytest.mark.slow
def test_fig_4_7_tiny_rough(tmp_path):
    run_script("fig_4_7.py", tmp_path, "--profiles", "rough")
    check_png(tmp_path / "fig_4_7_rough.png")
    for control in ("mean_pressure", "penetration"):
        data = check_sweep(tmp_path / f"sweep_rough_{control}_dx1e-04.h5")
        assert data.axes()["seed"] == (0,) and data.axes()["variant"] == ("adhesive",)
        # the adhesionless rough curve is its own sweep, with the bisection solver
        data = check_sweep(tmp_path / f"sweep_rough_{control}_none.h5")
        assert data.axes()["variant"] == ("adhesionless",)
        assert data.scene.to_dict()["solver"]["kind"] == "bisection"


def test_fig_4_10_speed_ramp_writes_a_history_of_its_own(tmp_path):
    """``--history speed-ramp``: the adhesive sweep follows a slow change of speed (a file of
    its own); on the sinusoid, with one equilibrium per ζ, it ends where the approach does."""
    common = ("--profiles", "wavy", "--edge-perturbations", "1e-4", "--zetas", "1e3,10")
    run_script("fig_4_10.py", tmp_path, *common)
    run_script("fig_4_10.py", tmp_path, *common, "--history", "speed-ramp")
    approach = check_sweep(tmp_path / "sweep_wavy_mean_pressure_dx1e-04.h5")
    ramp = check_sweep(tmp_path / "sweep_wavy_mean_pressure_dx1e-04_ramp.h5")
    assert approach.study.history.name == "approach" and ramp.study.history.name == "speed-ramp"
    a, b = approach.table("area"), ramp.table("area")
    np.testing.assert_allclose(b, a, rtol=1e-7)


def test_fig_4_10_rough_cohesive_curve(tmp_path):
    """``--rough-cohesive-ranges``: a rough adhesive sweep with Maugis-Dugdale zones of that
    range (a file of its own), next to the energy-balance one, in the figure."""
    run_script("fig_4_10.py", tmp_path, "--profiles", "rough", "--rough-cohesive-ranges", "1")
    check_png(tmp_path / "fig_4_10.png")
    data = check_sweep(tmp_path / "sweep_rough_mean_pressure_md1nm.h5")
    scene = data.scene.to_dict()
    assert scene["adhesion"]["kind"] == "maugis-dugdale"
    assert scene["physical"]["cohesive_range"] == 1e-9
    check_sweep(tmp_path / "sweep_rough_mean_pressure_dx1e-04.h5")


def test_cohesive_rough_tiny(tmp_path):
    """examples/cohesive_rough.py: the adhesionless, energy-balance and Maugis-Dugdale rough
    sweeps, their means in a CSV and the figure."""
    run_script("cohesive_rough.py", tmp_path)
    check_png(tmp_path / "cohesive_rough.png")
    for tag in ("none", "dx1e-04", "md1nm"):
        check_sweep(tmp_path / f"sweep_rough_mean_pressure_{tag}.h5")
    lines = (tmp_path / "cohesive_rough.csv").read_text().splitlines()
    assert lines[0].startswith("curve,load,zeta,count,reduced_friction")
    assert {line.split(",")[0] for line in lines[1:]} == {"adhesionless", "δX = 0.0001",
                                                         "h0 = 1 nm"}


def test_fig_4_10_tiny_reuses_fig_4_7_sweeps(tmp_path):
    run_script("fig_4_7.py", tmp_path, "--edge-perturbations", "1e-4", "--profiles", "wavy")
    path = tmp_path / "sweep_wavy_mean_pressure_dx1e-04.h5"
    created = h5_attr(path, "created")
    out = run_script("fig_4_10.py", tmp_path, "--edge-perturbations", "1e-4", "--profiles",
                     "wavy")
    check_png(tmp_path / "fig_4_10.png")
    check_sweep(path)
    # the file was resumed with nothing left to compute, not written again
    assert "sweep_wavy_mean_pressure_dx1e-04.h5: 2 points" in out
    assert h5_attr(path, "created") == created


def h5_attr(path, name):
    import h5py

    with h5py.File(path, "r") as f:
        return f.attrs[name]


def check_cycles(path):
    from viscocontact.studies import load_study

    data = load_study(path)
    assert data.kind == "cycle" and data.complete
    converged = data.points["converged"]
    assert converged.any()
    for key in ("area", "mean_pressure", "penetration"):
        assert np.isfinite(data.points[key][converged]).all()
    metrics = data.metrics()
    assert np.isfinite(metrics["toughness"]).all()
    assert (metrics["toughness"] >= 0).all()
    return data


def test_fig_4_8_tiny_wavy(tmp_path):
    run_script("fig_4_8.py", tmp_path, "--profiles", "wavy")
    check_png(tmp_path / "fig_4_8_wavy.png")
    check_cycles(tmp_path / "cycles_wavy_zeta.h5")
    data = check_cycles(tmp_path / "cycles_wavy_gamma.h5")
    assert data.metrics()["gamma"].tolist() == [0.0]


@pytest.mark.slow
def test_fig_4_8_tiny_rough(tmp_path):
    run_script("fig_4_8.py", tmp_path)
    check_png(tmp_path / "fig_4_8_rough.png")
    check_cycles(tmp_path / "cycles_rough_zeta.h5")
    check_cycles(tmp_path / "cycles_rough_gamma.h5")


def test_fig_4_9_tiny(tmp_path):
    run_script("fig_4_9.py", tmp_path, "--profiles", "wavy")
    check_png(tmp_path / "fig_4_9.png")
    data = check_cycles(tmp_path / "toughness_wavy.h5")
    assert len(data.metrics()["zeta"]) == 2
    # adhesive wavy contact carries tension on the way out: some toughness
    assert (data.metrics()["toughness"] > 0).all()


def test_fig_pressure_gap_tiny(tmp_path):
    from viscocontact.studies import load_study

    run_script("fig_pressure_gap.py", tmp_path, "--profiles", "wavy")
    check_png(tmp_path / "fig_pressure_gap_wavy.png")
    data = check_sweep(tmp_path / "fields_wavy.h5")
    for row in range(len(data)):
        fields = data.fields(row)
        for key in ("x", "pressure", "gap"):
            assert np.isfinite(fields[key]).all()
        assert fields["gap"].min() >= -1e-8
    assert load_study(tmp_path / "fields_wavy.h5").points["converged"].all()


def test_cli_plot_draws_a_figure_study(tmp_path):
    run_script("fig_pressure_gap.py", tmp_path, "--profiles", "wavy")
    cli = Path(sys.executable).with_name("viscocontact")
    proc = subprocess.run([str(cli) if cli.exists() else "viscocontact", "plot",
                           str(tmp_path / "fields_wavy.h5"), "--out", str(tmp_path / "plots")],
                          capture_output=True, text=True, env=dict(os.environ, MPLBACKEND="Agg"))
    assert proc.returncode == 0, proc.stderr
    check_png(tmp_path / "plots" / "fields_wavy_area.png")
    check_png(tmp_path / "plots" / "fields_wavy_friction.png")


@pytest.mark.slow
def test_cohesive_wavy_tiny(tmp_path):
    out = run_script("cohesive_wavy.py", tmp_path)
    check_png(tmp_path / "cohesive_wavy.png")
    data = check_sweep(tmp_path / "cohesive_wavy_md12.3nm_p0.3.h5")
    assert data.scene.to_dict()["adhesion"]["kind"] == "maugis-dugdale"
    check_sweep(tmp_path / "cohesive_wavy_dx1e-04_p0.3.h5")
    # the zone lengths of the cohesive point: glassy, d/a0 below β = 10 at a finite contact
    import csv
    with (tmp_path / "zones_md12.3nm.csv").open() as f:
        (row,) = csv.DictReader(f)
    assert 5 < float(row["work_trailing"]) < 10 and 5 < float(row["work_leading"]) < 10
    assert "h0 = 12.3 nm vs δX = 0.0001" in out
