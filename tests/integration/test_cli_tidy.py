"""The command line fails tidily: one line and an exit code, never a traceback, and nothing
computed or created before its inputs, outputs and prerequisites are checked."""
from __future__ import annotations

import pytest

from viscocontact.cli import main
from viscocontact.studies import load_study

#: A wavy Maugis-Dugdale scene in SI units, its range given as ``physical.cohesive_range``.
MD_SI = """
[profile]
kind = "sinusoid"
[rheology]
kind = "standard-linear-solid"
beta = 10.0
[adhesion]
kind = "maugis-dugdale"
[load]
mean_pressure = 0.3
[sliding]
zeta = 1.0
[physical]
E0 = 1e7
poisson = 0.5
wavelength = 1e-3
amplitude = 8e-6
work_of_adhesion = 0.01
cohesive_range = 1e-7
"""


@pytest.mark.parametrize("key", ["cohesive_range = 1e-7", "cohesive_strength = 1e5"])
def test_a_sweep_of_an_si_maugis_dugdale_scene_runs_with_the_defaults(tmp_path, key):
    """The adhesionless twin drops ``physical.cohesive_range`` (or ``cohesive_strength``) with
    the work of adhesion."""
    scene = tmp_path / "md.toml"
    scene.write_text(MD_SI.replace("cohesive_range = 1e-7", key))
    out = tmp_path / "md_sweep.h5"
    assert main(["sweep", str(scene), "--zetas", "10", "--elements", "16", "--quiet",
                 "--out", str(out)]) == 0
    data = load_study(out)
    assert data.axes()["variant"] == ("adhesive", "adhesionless")
    assert data.points["converged"].all()


def _one_line(capsys) -> str:
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1, err
    return err


def test_ctrl_c_during_a_study_says_what_is_kept_and_how_to_resume(tmp_path, capsys,
                                                                     monkeypatch):
    """Ctrl-C after the first point: one line naming the file and the --resume command, exit
    130; the resumed study computes only the rest."""
    from viscocontact.studies import runner

    solve, calls = runner.solve_point, []

    def interrupted(*args):
        calls.append(args)
        if len(calls) == 2:
            raise KeyboardInterrupt
        return solve(*args)

    monkeypatch.setattr(runner, "solve_point", interrupted)
    scene = tmp_path / "md.toml"
    scene.write_text(MD_SI)
    out = tmp_path / "s.h5"
    argv = ["sweep", str(scene), "--zetas", "10", "--elements", "16", "--quiet", "--no-pair",
            "--loads", "0.2,0.3", "--out", str(out)]
    assert main(argv) == 130
    err = _one_line(capsys)
    assert str(out) in err and f"sweep --resume --out {out}" in err
    assert len(load_study(out)) == 1
    monkeypatch.setattr(runner, "solve_point", solve)
    assert main(["sweep", "--resume", "--out", str(out), "--quiet"]) == 0
    assert len(load_study(out)) == 2


def test_a_scheduler_without_distributed_is_said_before_any_file_is_made(tmp_path, capsys,
                                                                           monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "distributed", None)       # import distributed fails
    scene = tmp_path / "md.toml"
    scene.write_text(MD_SI)
    out = tmp_path / "s.h5"
    assert main(["sweep", str(scene), "--zetas", "10", "--quiet", "--scheduler",
                 "tcp://127.0.0.1:1", "--out", str(out)]) == 2
    assert "distributed" in _one_line(capsys)
    assert not list(tmp_path.glob("s.h5*"))


@pytest.mark.parametrize("command", [["validate", "--quick"], ["bench", "--quick"],
                                     ["study", "--quiet"]])
def test_an_unwritable_output_folder_is_said_before_computing(tmp_path, capsys, monkeypatch,
                                                              command):
    """A folder this process may not write in (faked, so that the test holds for root too)."""
    import os

    from viscocontact import _outputs

    locked = tmp_path / "locked"
    locked.mkdir()
    monkeypatch.setattr(_outputs.os, "access",
                        lambda path, mode: os.path.abspath(path) != str(locked))
    assert main([*command, "--out", str(locked / "new")]) == 2
    err = _one_line(capsys)
    assert "--out" in err and f"no permission to write in {locked}" in err
    assert not list(locked.iterdir())


@pytest.mark.parametrize("command", [["validate", "--quick"], ["bench", "--quick"],
                                     ["study", "--quiet"]])
def test_a_folder_the_permissions_allow_but_the_file_system_refuses_is_said_before_computing(
        tmp_path, capsys, monkeypatch, command):
    """A read-only or virtual file system (``/proc`` for root) passes a permission check; the
    folder is tried (made and removed) before anything is computed. Before, ``validate`` computed
    its cases and then failed with "no such file"."""
    import errno

    from viscocontact import _outputs

    def refused(**kwargs):
        raise OSError(errno.EROFS, "Read-only file system")

    monkeypatch.setattr(_outputs.tempfile, "mkdtemp", refused)
    assert main([*command, "--out", str(tmp_path / "new")]) == 2
    err = _one_line(capsys)
    assert "--out" in err and f"cannot write in {tmp_path}: Read-only file system" in err
    assert not list(tmp_path.iterdir())


def test_solve_plot_into_a_folder_that_refuses_is_said_before_solving(tmp_path, capsys,
                                                                     monkeypatch):
    import errno

    from viscocontact import _outputs
    from viscocontact.problem import ContactProblem

    def refused(**kwargs):
        raise OSError(errno.EROFS, "Read-only file system")

    def not_to_be_solved(*args, **kwargs):
        raise AssertionError("solved before the --plot file was checked")

    monkeypatch.setattr(_outputs.tempfile, "mkdtemp", refused)
    monkeypatch.setattr(ContactProblem, "solve", not_to_be_solved)
    scene = tmp_path / "md.toml"
    scene.write_text(MD_SI)
    assert main(["solve", str(scene), "--plot", str(tmp_path / "f.png")]) == 2
    err = _one_line(capsys)
    assert "--plot" in err and f"cannot write in {tmp_path}: Read-only file system" in err


def test_checking_a_folder_leaves_nothing_behind(tmp_path):
    from viscocontact._outputs import check_folder

    assert check_folder("--out", tmp_path / "a" / "b", "a folder") == tmp_path / "a" / "b"
    assert not list(tmp_path.iterdir())


def test_validate_needs_an_out_folder_outside_a_source_tree(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["validate", "--quick"]) == 2
    assert "--out" in _one_line(capsys) and not list(tmp_path.iterdir())


def test_a_pipe_closed_by_its_reader_ends_quietly(tmp_path):
    """``viscocontact solve ... --json | head -c 400``: no traceback, exit 141.

    The reader's end is closed before the command writes, so the write meets the closed pipe
    on every machine (a reader that stops after 400 bytes races the writer: an output smaller
    than the pipe's buffer may be written whole before the reader closes)."""
    import os
    import subprocess
    import sys

    scene = tmp_path / "wavy.toml"
    scene.write_text(MD_SI.replace('kind = "maugis-dugdale"', 'kind = "none"').replace(
        "work_of_adhesion = 0.01\ncohesive_range = 1e-7\n", ""))
    code = ("import sys; from viscocontact.cli import main\n"
            "sys.exit(main(['solve', sys.argv[1], '--json', '--fields']))")
    read_end, write_end = os.pipe()
    os.close(read_end)                            # the reader has stopped
    try:
        proc = subprocess.run([sys.executable, "-c", code, str(scene)], stdout=write_end,
                              stderr=subprocess.PIPE, timeout=300)
    finally:
        os.close(write_end)
    err = proc.stderr.decode()
    assert proc.returncode == 141 and err == "", err


def test_ctrl_c_during_a_solve_is_one_line(tmp_path, capsys, monkeypatch):
    from viscocontact.problem import ContactProblem

    def stopped(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(ContactProblem, "solve", stopped)
    scene = tmp_path / "md.toml"
    scene.write_text(MD_SI)
    assert main(["solve", str(scene)]) == 130
    assert _one_line(capsys) == "viscocontact solve: interrupted"
