"""The command line: describe, plugins, --help and one-line errors with exit code 2."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from viscocontact.cli import SUBCOMMANDS, main

EXAMPLES = Path(__file__).resolve().parents[3] / "examples" / "scenes"

GROUP_KEYS = {"gamma", "Gamma", "amplitude", "m2", "zeta", "beta", "tabor", "tabor_glassy", "rms",
              "physical", "warnings"}


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def _reject(constant):
    raise AssertionError(f"{constant} is not JSON")


def strict(text: str):
    """``json.loads`` that refuses ``NaN``, ``Infinity`` and ``-Infinity`` (RFC 8259)."""
    return json.loads(text, parse_constant=_reject)


NO_CONTACT = ('[profile]\nkind = "sinusoid"\namplitude = 0.1\n'
              '[rheology]\nkind = "standard-linear-solid"\nbeta = 10.0\n'
              '[load]\npenetration = -0.5\n[sliding]\nzeta = 1.0\n')

LOW_TABOR = ('[profile]\nkind = "sinusoid"\n[rheology]\nkind = "elastic"\n'
             '[load]\npenetration = 0.5\n'
             '[physical]\nE0 = 2e11\nwavelength = 1e-4\namplitude = 1e-6\n'
             'work_of_adhesion = 0.01\n')


def test_describe_json_sinusoid(capsys):
    code, out, err = run(capsys, "describe", str(EXAMPLES / "sinusoid.toml"), "--json")
    assert code == 0 and err == ""
    groups = strict(out)
    assert GROUP_KEYS <= set(groups)
    assert groups["gamma"] == 1e-5 and groups["amplitude"] == 0.05
    assert groups["Gamma"] == pytest.approx(1e-5 / 0.05**2)
    assert groups["beta"] == 10.0 and groups["zeta"] == 0.01
    assert groups["tabor"] is None and groups["physical"] is None
    assert groups["mean_pressure"] == 0.3


def test_describe_json_thesis(capsys):
    code, out, err = run(capsys, "describe", str(EXAMPLES / "thesis_rough.toml"), "--json")
    assert code == 0
    groups = strict(out)
    assert groups["tabor"] == pytest.approx(383.0, rel=1e-3)
    assert groups["gamma"] == pytest.approx(2.387e-7, rel=1e-3)
    assert groups["hurst"] == 0.8 and groups["scales"] == 50
    assert groups["physical"]["E0"] == 1e7
    assert groups["rms"] == pytest.approx(2 * 3.141592653589793 / 6.28e-3 * 1e-5)


def test_describe_text(capsys):
    code, out, err = run(capsys, "describe", str(EXAMPLES / "thesis_rough.toml"))
    assert code == 0
    assert "gamma" in out and "tabor" in out and "physical:" in out and "383" in out


def test_describe_warns_on_small_tabor(capsys, tmp_path):
    scene = tmp_path / "hard.toml"
    scene.write_text(LOW_TABOR)
    code, out, err = run(capsys, "describe", str(scene), "--json")
    assert code == 0
    assert strict(out)["tabor"] < 3
    lines = err.splitlines()               # once, though building the scene warns too
    assert len(lines) == 1
    assert lines[0].startswith("viscocontact describe: warning: Tabor parameter")
    assert "< 3" in lines[0]


def test_other_commands_show_the_scene_warning_on_one_line(capsys, tmp_path):
    scene = tmp_path / "hard.toml"
    scene.write_text(LOW_TABOR)
    code, out, err = run(capsys, "solve", str(scene), "--explain")
    assert code == 0
    assert err.splitlines() == [line for line in err.splitlines()
                                if line.startswith("viscocontact solve: warning: Tabor")]
    assert len(err.splitlines()) == 1 and "< 3" in err


def test_solve_json_without_contact_is_strict_json(capsys, tmp_path):
    """No contact: the friction coefficient is undefined and the gap infinite; both are null,
    not NaN/Infinity, which strict JSON readers reject."""
    scene = tmp_path / "apart.toml"
    scene.write_text(NO_CONTACT)
    code, out, err = run(capsys, "solve", str(scene), "--json")
    assert code == 0
    result = strict(out)
    assert result["status"] == "no_contact" and result["area"] == 0.0
    assert result["friction"] is None and result["reduced_friction"] is None
    assert result["min_gap"] is None
    assert result["penetration"] == -0.5


def test_explain_json_is_strict_json(capsys, tmp_path):
    scene = tmp_path / "apart.toml"
    scene.write_text(NO_CONTACT)
    for path in (scene, EXAMPLES / "thesis_rough.toml"):
        code, out, err = run(capsys, "solve", str(path), "--explain", "--json")
        assert code == 0
        assert {"stage", "choice", "reason"} <= set(strict(out)[0])


def test_importing_the_main_module_runs_nothing(capsys, monkeypatch):
    """``import viscocontact.__main__`` (documentation tools, test collectors) must not run
    the command line; ``python -m viscocontact`` does (test below)."""
    import importlib
    import sys

    monkeypatch.setattr(sys, "argv", ["viscocontact", "solve", "no-such-scene.toml"])
    monkeypatch.delitem(sys.modules, "viscocontact.__main__", raising=False)
    module = importlib.import_module("viscocontact.__main__")
    assert module.main is main
    assert capsys.readouterr() == ("", "")


def test_plugins_json(capsys):
    code, out, err = run(capsys, "plugins", "--json")
    assert code == 0
    table = strict(out)
    assert set(table) == {"profiles", "rheologies", "kernels", "solvers", "adhesion", "methods",
                          "surfaces"}
    names = {group: {e["name"] for e in entries} for group, entries in table.items()}
    assert {"sinusoid", "self-affine", "measured"} <= names["profiles"]
    assert {"elastic", "standard-linear-solid", "prony"} <= names["rheologies"]
    assert {"half-plane", "confined-layer", "free-layer"} <= names["kernels"]
    assert {"newton", "broyden", "nonlinear-cg", "bisection"} <= names["solvers"]
    assert {"none", "energy-balance"} <= names["adhesion"]
    assert {"auto", "bem", "spectral"} <= names["methods"]
    entry = next(e for e in table["rheologies"] if e["name"] == "elastic")
    assert entry == {"name": "elastic", "distribution": "viscocontact"}


def test_plugins_text(capsys):
    code, out, err = run(capsys, "plugins")
    assert code == 0
    assert "rheologies:" in out and "standard-linear-solid" in out and "(viscocontact)" in out


@pytest.mark.parametrize("command", sorted(SUBCOMMANDS))
def test_every_subcommand_has_help(capsys, command):
    code, out, err = run(capsys, command, "--help")
    assert code == 0 and f"usage: viscocontact {command}" in out


def test_top_level_help_lists_subcommands(capsys):
    code, out, err = run(capsys, "--help")
    assert code == 0
    for command in SUBCOMMANDS:
        assert command in out


def _assert_one_line_error(code, err, *fragments):
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert "Traceback" not in err
    for fragment in fragments:
        assert fragment in lines[0]


def test_missing_file(capsys, tmp_path):
    code, out, err = run(capsys, "describe", str(tmp_path / "nope.toml"))
    _assert_one_line_error(code, err, "no such file", "nope.toml")


def test_toml_syntax_error(capsys, tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("[profile\nkind = 'sinusoid'\n")
    code, out, err = run(capsys, "describe", str(bad))
    _assert_one_line_error(code, err, "invalid TOML", "bad.toml")


@pytest.mark.parametrize("text,fragment", [
    ('[profile]\nkind = "sinusoid"\namplitude = 0.1\n[rheology]\nkind = "elastc"\n'
     '[load]\npenetration = 0.5\n', "rheology.kind"),
    ('[profile]\nkind = "sinusoid"\namplitude = 0.1\n[rheology]\nkind = "elastic"\n'
     '[load]\npenetration = 0.5\nmean_pressure = 0.1\n', "exactly one"),
    ('[profile]\nkind = "sinusoid"\namplitude = 0.1\n[rheology]\nkind = "elastic"\n'
     '[load]\npenetration = 0.5\n[sliding]\nzeta = -1.0\n', "sliding.zeta"),
])
def test_validation_error(capsys, tmp_path, text, fragment):
    scene = tmp_path / "scene.toml"
    scene.write_text(text)
    code, out, err = run(capsys, "describe", str(scene))
    _assert_one_line_error(code, err, fragment)
    assert out == ""


def test_directory_instead_of_file(capsys, tmp_path):
    code, out, err = run(capsys, "describe", str(tmp_path))
    _assert_one_line_error(code, err, "cannot read")


def test_usage_errors_exit_2(capsys):
    assert main(["frobnicate"]) == 2
    assert main([]) == 2
    assert main(["describe"]) == 2
    capsys.readouterr()


def test_python_dash_m_runs_the_command_line():
    """``python -m viscocontact`` is the ``viscocontact`` script (same output, same exit code)."""
    import subprocess
    import sys

    done = subprocess.run([sys.executable, "-m", "viscocontact", "describe", "--help"],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0 and "usage: viscocontact describe" in done.stdout
    bad = subprocess.run([sys.executable, "-m", "viscocontact", "solve", "no-such-scene.toml"],
                         capture_output=True, text=True, timeout=120)
    assert bad.returncode == 2 and "no-such-scene.toml" in bad.stderr


@pytest.mark.parametrize("value,fragment", [("16", "λ_min/16 = 0.00785"), ("none", None)])
def test_interior_resolution_reaches_the_mesh(capsys, value, fragment):
    """``--interior-resolution`` sets the rule the plan reports ('none' switches it off)."""
    code, out, _ = run(capsys, "solve", str(EXAMPLES / "thesis_rough.toml"), "--elements", "32",
                       "--interior-resolution", value, "--explain")
    mesh = next(line for line in out.splitlines() if line.startswith("mesh"))
    assert code == 0
    assert (fragment in mesh) if fragment else ("λ_min" not in mesh)


@pytest.mark.parametrize("value", ["0.5", "65", "abc", "nan"])
def test_bad_interior_resolution_names_the_option_and_range(capsys, value):
    code, _, err = run(capsys, "solve", str(EXAMPLES / "thesis_rough.toml"),
                       "--interior-resolution", value, "--explain")
    assert code == 2
    assert "--interior-resolution" in err and "[1, 64], or 'none'" in err
