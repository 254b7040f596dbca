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


def test_a_sweep_of_an_si_maugis_dugdale_scene_runs_with_the_defaults(tmp_path):
    """The adhesionless twin drops ``physical.cohesive_range`` with the work of adhesion."""
    scene = tmp_path / "md.toml"
    scene.write_text(MD_SI)
    out = tmp_path / "md_sweep.h5"
    assert main(["sweep", str(scene), "--zetas", "10", "--elements", "16", "--quiet",
                 "--out", str(out)]) == 0
    data = load_study(out)
    assert data.axes()["variant"] == ("adhesive", "adhesionless")
    assert data.points["converged"].all()
