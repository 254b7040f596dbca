"""``viscocontact solve SCENE.toml --json``: the result's public keys and the exit status."""
import json

import pytest

from viscocontact.cli import main

KEYS = {"area", "mean_pressure", "penetration", "friction", "reduced_friction", "n_contacts",
        "edges", "full_contact", "converged", "residual", "iterations"}

SCENE = """
[profile]
kind = "sinusoid"
amplitude = 0.1
[rheology]
kind = "standard-linear-solid"
beta = 10.0
[adhesion]
kind = "energy-balance"
gamma = 1e-4
[solver]
kind = "newton"
[load]
mean_pressure = 0.1
[sliding]
zeta = 1.0
"""


def test_solve_json(tmp_path, capsys):
    path = tmp_path / "s.toml"
    path.write_text(SCENE)
    assert main(["solve", str(path), "--json", "--fields"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert KEYS <= set(out)
    assert out["converged"] is True and out["n_contacts"] == 1 and not out["full_contact"]
    assert len(out["edges"]) == 1 and out["edges"][0][0] < out["edges"][0][1]
    # edges are reported in [0, 2π) (shifted from the solve's frame), so equal to rounding
    assert out["area"] == pytest.approx(out["edges"][0][1] - out["edges"][0][0], rel=1e-13)
    assert out["friction"] > 0 and out["edge_perturbation"] == 1e-4
    terms = out["edge_terms"]
    for s, n in zip(terms["stored"], terms["nonconservative"]):
        assert abs(s + n - terms["target"]) < 1e-3 * terms["target"]
    f = out["fields"]
    assert len(f["x"]) == len(f["pressure"]) == len(f["gap"]) > 100
    assert min(f["gap"]) > -1e-9


def test_solve_plot_draws_pressure_and_gap(tmp_path, capsys):
    path = tmp_path / "s.toml"
    path.write_text(SCENE)
    png = tmp_path / "fields.png"
    assert main(["solve", str(path), "--json", "--plot", str(png)]) == 0
    assert "fields" not in json.loads(capsys.readouterr().out)   # drawn, not printed
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 10_000


def test_solve_full_contact_is_a_legitimate_answer(tmp_path, capsys):
    path = tmp_path / "s.toml"
    path.write_text(SCENE.replace("gamma = 1e-4", "gamma = 5e-3").replace("zeta = 1.0", "zeta = 0.1"))
    assert main(["solve", str(path), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["full_contact"] is True and out["edges"] == [] and out["converged"] is True
    assert abs(out["area"] - 2 * 3.141592653589793) < 1e-12


def test_solve_bad_scene_exit_code(tmp_path, capsys):
    path = tmp_path / "s.toml"
    path.write_text(SCENE.replace("beta = 10.0", "beta = -1"))
    assert main(["solve", str(path)]) == 2
    assert "beta" in capsys.readouterr().err
