"""The example scripts run and write what they promise."""
import runpy
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_fig_2_12_writes_png(tmp_path, monkeypatch):
    out = tmp_path / "fig.png"
    monkeypatch.setattr(sys, "argv", ["fig_2_12_green_function.py", "--out", str(out)])
    runpy.run_path(str(ROOT / "examples" / "fig_2_12_green_function.py"), run_name="__main__")
    assert out.stat().st_size > 10_000
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_the_areal_science_script_writes_its_study_numbers_and_figures(tmp_path,
                                                                        surface_registry):
    """``examples/areal_science.py`` on a small version of its study (2 seeds, ζ = 0.1 and 10,
    32² cells, the grid check on 64², without the cohesive law, whose solves take most of the
    script's time): the study file, the 1D points, the numbers and both figures."""
    import importlib.util
    import json

    spec = importlib.util.spec_from_file_location("areal_science",
                                                  ROOT / "examples" / "areal_science.py")
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    script.SEEDS, script.ZETAS, script.CHECK_ZETAS = (0, 1), (0.1, 10.0), (10.0,)
    script.GRID, script.FINE = 32, 64
    script.ADHESION = {"kind": "none"}
    script.LOWEST_SEEDS, script.LOWEST_ZETAS = (0,), (10.0,)
    numbers = script.main(["--out", str(tmp_path)])
    for name in ("areal_science.h5", "areal_1d.json", "areal_science.json",
                 "areal_science.png", "areal_contact_map.png"):
        assert (tmp_path / name).stat().st_size > 0, name
    assert json.loads((tmp_path / "areal_science.json").read_text())["zetas"] == [0.1, 10.0]
    assert numbers["adhesionless converged"] == [2, 2]
    # the areal area falls from ζ = 0.1 to 10 (the solid stiffens), as Persson's does
    assert numbers["adhesionless area_fraction"][1] < numbers["adhesionless area_fraction"][0]
    assert numbers["Persson areal area_fraction"][1] < numbers["Persson areal area_fraction"][0]
    assert len(numbers["grid_check"]) == 1
    assert numbers["lowest_check"]["row share, lowest 4"] < numbers["lowest_check"][
        "row share, lowest 1"]
