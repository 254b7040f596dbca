"""A study killed mid-run keeps its finished points; resuming it gives the uninterrupted result."""
import os
import signal
import subprocess
import sys

from viscocontact.studies import Sweep, load_study, resume, run

ZETAS = "1e-2:1e2:9"


def test_kill_reopen_resume(tmp_path, adhesionless, mesh, identical):
    scene = tmp_path / "scene.toml"
    scene.write_text(adhesionless.to_toml())
    path = tmp_path / "killed.h5"
    proc = subprocess.Popen(
        [sys.executable, "-m", "viscocontact.cli", "sweep", str(scene), "--zetas", ZETAS,
         "--elements", str(mesh["elements"]), "--out", str(path)],
        stderr=subprocess.PIPE, stdout=subprocess.DEVNULL, text=True,
        env=dict(os.environ, PYTHONUNBUFFERED="1"))
    try:
        finished = 0
        for line in proc.stderr:                       # one progress line per finished point
            if line.startswith("sweep "):
                finished += 1
            if finished == 3:
                break
        proc.send_signal(signal.SIGKILL)
    finally:
        proc.wait(timeout=60)
        proc.stderr.close()
    assert proc.returncode == -signal.SIGKILL

    partial = load_study(path)                          # readable after the kill
    assert not partial.complete and 3 <= len(partial) < 9
    resumed = resume(path, progress=None)
    assert resumed.complete and len(resumed) == 9
    assert resumed.points["step"].tolist() == list(range(9))    # nothing computed twice

    from viscocontact.studies.base import parse_numbers

    sweep = Sweep(scene=adhesionless, zetas=parse_numbers("--zetas", ZETAS, log=True),
                  discretization=mesh)
    assert resumed.study == sweep
    whole = run(sweep, tmp_path / "whole.h5", progress=None)
    identical(resumed.points, whole.points)
