"""``viscocontact solve | describe | sweep`` of areal scenes (``[surface]``), and the study file
of a ζ-sweep over realizations: HDF5 round trip and resume."""
from __future__ import annotations

import json

import h5py
import numpy as np
import pytest

from viscocontact.areal.scene import ArealScene
from viscocontact.areal.surfaces import SelfAffineSurface
from viscocontact.cli import main
from viscocontact.studies import COLUMNS, Sweep, load_study, run
from viscocontact.studies.point import AREAL_COLUMNS, TIMING_COLUMNS

pytestmark = pytest.mark.usefixtures("surface_registry")

SCENE = """
[surface]
kind = "self-affine"
hurst = 0.8
scales = 12
rms = 0.01
seed = 0
grid = 64

[rheology]
kind = "standard-linear-solid"
beta = 10.0

[adhesion]
kind = "maugis-dugdale"
gamma = 2e-6
range = 0.006

[load]
mean_pressure = 0.3

[sliding]
zeta = 1.0
"""
#: The same surface without adhesion (the studies' tests: a few times faster).
DRY = SCENE.replace('kind = "maugis-dugdale"\ngamma = 2e-6\nrange = 0.006', 'kind = "none"')


@pytest.fixture
def scene(tmp_path):
    path = tmp_path / "areal.toml"
    path.write_text(SCENE)
    return path


def test_solve_json_is_the_scene_solve(scene, capsys):
    assert main(["solve", str(scene), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    direct = ArealScene.from_toml(SCENE).solve(fields=True)
    assert out["method"] == "areal-spectral" and out["converged"]
    assert out["area_fraction"] == direct.extras["area_fraction"]
    assert out["friction"] == direct.friction and out["n_contacts"] == direct.n_contacts
    assert out["grid"] == "64×64" and out["cells_per_zone"] == pytest.approx(45.8, abs=0.1)
    areas = out["patch_areas"]
    assert len(areas) == out["n_contacts"] and areas == sorted(areas, reverse=True)
    assert out["friction_dissipation"] == pytest.approx(out["friction"], rel=0.1)


def test_the_patch_areas_add_up_to_the_loaded_cells(scene, capsys):
    """Adhesionless, the contact cells are the loaded ones: the size distribution's sum is
    their area (cells of (2π/64)², areas written to 6 digits)."""
    scene.write_text(DRY)
    assert main(["solve", str(scene), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    direct = ArealScene.from_toml(scene).solve(fields=True)
    cells = np.count_nonzero(direct.fields["pressure"] > 0)
    assert sum(out["patch_areas"]) == pytest.approx(cells * (2 * np.pi / 64) ** 2, rel=1e-5)
    assert out["cells_per_zone"] is None            # NaN: no cohesive law


def test_solve_text_and_fields(scene, capsys):
    assert main(["solve", str(scene)]) == 0
    text = capsys.readouterr().out
    assert "area_fraction" in text and "patch_alignment" in text and "grid" in text
    assert main(["solve", str(scene), "--json", "--fields"]) == 0
    fields = json.loads(capsys.readouterr().out)["fields"]
    assert np.shape(fields["pressure"]) == (64, 64) and len(fields["x"]) == 64


def test_solve_plot_draws_the_contact_map(scene, tmp_path, capsys):
    scene.write_text(DRY)
    png = tmp_path / "contact.png"
    assert main(["solve", str(scene), "--json", "--plot", str(png)]) == 0
    assert json.loads(capsys.readouterr().out)["converged"]        # stdout stays JSON
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert main(["solve", str(scene), "--plot", str(tmp_path / "no" / "c.png")]) == 2
    assert "--plot" in capsys.readouterr().err


def test_explain_prints_the_plan(scene, capsys):
    assert main(["solve", str(scene), "--explain"]) == 0
    text = capsys.readouterr().out
    for stage in ("grid", "memory", "memory check", "time", "adhesion"):
        assert any(line.startswith(stage) for line in text.splitlines()), stage
    assert "45.8 cells per quasi-static zone" in text
    coarse = scene.with_name("coarse.toml")
    coarse.write_text(SCENE.replace("grid = 64", "grid = 32"))
    assert main(["solve", str(coarse), "--explain", "--json"]) == 0
    steps = {s["stage"]: s for s in json.loads(capsys.readouterr().out)}
    assert "UNDER-RESOLVED" in steps["adhesion"]["reason"]
    assert main(["solve", str(coarse), "--json"]) in (0, 1)    # converged or not: the warning
    assert "warning: the cohesive zone q0a0 = 4.5 spans 22.9 cells" in capsys.readouterr().err


def test_a_scene_beyond_its_memory_is_refused_with_the_figure(scene, capsys):
    big = scene.with_name("big.toml")
    big.write_text(SCENE.replace("grid = 64", "grid = 256")
                   + '\n[method]\nkind = "areal-spectral"\nmax_memory = 1e6\n')
    assert main(["solve", str(big), "--explain"]) == 0
    assert "REFUSED: 29 MB needed for 256×256 cells" in capsys.readouterr().out
    assert main(["solve", str(big)]) == 2
    assert ">= 2.88e+07 bytes for a 256×256 grid" in capsys.readouterr().err


@pytest.mark.parametrize("option", [["--elements", "16"], ["--si"], ["--kernel-tolerance",
                                                                     "1e-3"]])
def test_one_d_options_are_refused(scene, capsys, option):
    assert main(["solve", str(scene), *option]) == 2
    assert "areal scene" in capsys.readouterr().err


def test_describe_and_cycle(scene, capsys):
    assert main(["describe", str(scene), "--json"]) == 0
    groups = json.loads(capsys.readouterr().out)
    assert groups["surface"] == "self-affine" and groups["grid"] == "64×64"
    assert groups["quasi_static_zone"] == pytest.approx(0.006**2 / (4 * 2e-6))
    assert groups["rms"] == pytest.approx(0.01, rel=1e-12)
    assert main(["cycle", str(scene), "--max-penetration", "1", "--step", "0.1"]) == 2
    assert "cycles of areal scenes" in capsys.readouterr().err


def test_sweep_over_realizations_and_its_file(scene, tmp_path, capsys):
    scene.write_text(DRY)
    out = tmp_path / "areal_sweep.h5"
    assert main(["sweep", str(scene), "--zetas", "0.1,10", "--realizations", "2", "--quiet",
                 "--no-pair", "--fields", "--out", str(out)]) == 0
    assert "A/A0" in capsys.readouterr().out
    data = load_study(out)
    assert data.areal and data.complete and len(data) == 4
    assert isinstance(data.scene, ArealScene)
    table = data.table("area_fraction")
    assert table.shape == (1, 1, 2, 2) and np.isfinite(table).all()
    # each point is the scene's own solve at its seed and ζ
    base = ArealScene.from_toml(DRY)
    for iseed, seed in enumerate((0, 1)):
        for iz, zeta in enumerate((0.1, 10.0)):
            surface = SelfAffineSurface(**_surface_params(base, seed))
            direct = base.replace(surface=surface, zeta=zeta).solve()
            assert table[0, 0, iseed, iz] == direct.extras["area_fraction"]
            assert data.table("friction")[0, 0, iseed, iz] == direct.friction
    fields = data.fields(0)
    assert fields["pressure"].shape == (64, 64) and fields["y"].shape == (64,)
    assert main(["plot", str(out), "--out", str(tmp_path / "figures")]) == 0
    assert (tmp_path / "figures" / "areal_sweep_area.png").stat().st_size > 10_000
    with h5py.File(out) as f:       # x and y are the dimension scales of the 2D fields
        group = f["fields/000000"]
        assert group["pressure"].dims[0][0].name.endswith("/y")
        assert group["pressure"].dims[1][0].name.endswith("/x")


def _surface_params(scene, seed):
    params = dict(scene.to_dict()["surface"])
    params.pop("kind")
    params.pop("grid")
    return {**params, "seed": seed}


def test_an_interrupted_areal_study_resumes_to_the_same_points(tmp_path):
    """A study cut after two points (as a kill leaves it: ``count`` lowered) is resumed: the
    points are computed again and equal those of the uninterrupted run."""
    sweep = Sweep(scene=ArealScene.from_toml(DRY), zetas=[0.1, 10.0], seeds=[0, 1],
                  pair=False)
    whole = run(sweep, tmp_path / "whole.h5", progress=None)
    cut = tmp_path / "cut.h5"
    run(sweep, cut, progress=None)
    with h5py.File(cut, "r+") as f:
        f["points"].attrs["count"] = 2
        f.attrs["complete"] = False
    resumed = run(sweep, cut, resume=True, progress=None)
    assert resumed.complete and len(resumed) == len(whole) == 4
    a, b = whole.points, resumed.points
    order_a, order_b = (np.lexsort((p["step"], p["chain"])) for p in (a, b))
    for key in COLUMNS:
        if key in TIMING_COLUMNS or key == "edges":
            continue
        x, y = a[key][order_a], b[key][order_b]
        assert np.array_equal(x, y, equal_nan=x.dtype.kind == "f"), key
    assert set(AREAL_COLUMNS) <= set(COLUMNS)
    assert np.isfinite(a["patch_elongation"]).all() and (a["percolating"] >= 0).all()


def test_a_sweep_refuses_what_an_areal_scene_cannot_take(scene, capsys):
    assert main(["sweep", str(scene), "--zetas", "0.1,10", "--history", "speed-ramp",
                 "--quiet"]) == 2
    assert "sweep.history" in capsys.readouterr().err
    assert main(["sweep", str(scene), "--zetas", "0.1,10", "--elements", "16", "--quiet"]) == 2
    assert "sweep.discretization" in capsys.readouterr().err


def _installed_surfaces() -> bool:
    from viscocontact import _registry

    return bool(_registry.REGISTRIES["surfaces"].names())


@pytest.mark.skipif(not _installed_surfaces(),
                    reason="worker processes read the installed entry points, and the installed "
                           "metadata has no viscocontact.surfaces group (reinstall the checkout)")
def test_an_areal_study_in_worker_processes_gives_the_serial_points(tmp_path):
    sweep = Sweep(scene=ArealScene.from_toml(DRY), zetas=[0.1, 10.0], seeds=[0, 1], pair=False)
    serial = run(sweep, tmp_path / "serial.h5", progress=None)
    pooled = run(sweep, tmp_path / "pooled.h5", workers=2, progress=None)
    a, b = serial.points, pooled.points
    order_a, order_b = (np.lexsort((p["step"], p["chain"])) for p in (a, b))
    for key in ("area_fraction", "friction", "patch_areas", "mean_gap", "dissipated_power"):
        assert np.array_equal(a[key][order_a], b[key][order_b]), key
