"""Certification (``Sweep(certify=True)``): every adhesive point solved again under its history
with a tenth of the tolerance, the columns it records, their storage and their marks."""
from __future__ import annotations

import json
import math
import warnings

import attrs
import h5py
import numpy as np
import pytest

from viscocontact.errors import CertificationWarning, ValidationError
from viscocontact.plot_marks import JUMP_LABEL, RAMP_LABEL, UNCERTIFIED_LABEL
from viscocontact.plots import draw_sweep, plot_study
from viscocontact.studies import Sweep, certify, load_study, resume, run, storage
from viscocontact.studies.certify import (AREA_TOLERANCE, CERTIFY_COLUMNS, FRICTION_TOLERANCE,
                                          agrees)

ZETAS = [0.1, 1.0, 10.0]


@pytest.fixture(scope="module")
def certified(tmp_path_factory):
    """A wavy adhesive sweep with its adhesionless twin, certified, at three ζ."""
    from viscocontact.scene import Scene

    from .conftest import ADHESIVE, MESH

    sweep = Sweep(scene=Scene.from_toml(ADHESIVE), zetas=ZETAS, discretization=MESH,
                  certify=True)
    return run(sweep, tmp_path_factory.mktemp("cert") / "s.h5", progress=None)


def test_the_criterion_holds_the_acceptance_tolerances():
    assert agrees(1.0, 0.2, 1.0 + 0.9 * AREA_TOLERANCE, 0.2 * (1 + 0.9 * FRICTION_TOLERANCE))
    assert not agrees(1.0, 0.2, 1.0 + 1.1 * AREA_TOLERANCE, 0.2)
    assert not agrees(1.0, 0.2, 1.0, 0.2 * (1 + 1.1 * FRICTION_TOLERANCE))
    # a vanishing contact and friction are held to the floors 0.1 and 0.01, absolutely
    assert agrees(0.0, 0.0, 0.9e-4, 0.9e-4) and not agrees(0.0, 0.0, 1.1e-4, 0.0)
    assert not agrees(0.0, 0.0, 0.0, 1.1e-4)
    assert not agrees(1.0, 0.2, math.nan, 0.2) and not agrees(math.inf, 0.2, 1.0, 0.2)


def test_every_adhesive_point_of_a_wavy_sweep_is_certified(certified):
    p = certified.points
    adhesive = p["variant"] == "adhesive"
    assert adhesive.sum() == len(ZETAS) and p["converged"].all()
    assert p["certified"][adhesive].all()
    # the finer run is a second solve whose values the record keeps (NaN where not certified)
    for name, fine in (("area", "certified_area"), ("friction", "certified_friction")):
        assert np.isfinite(p[fine][adhesive]).all()
        assert agrees(*p["area"][adhesive][:1], *p["friction"][adhesive][:1],
                      *p["certified_area"][adhesive][:1], *p["certified_friction"][adhesive][:1])
        assert np.isnan(p[fine][~adhesive]).all()
    assert not p["certified"][~adhesive].any()      # unique equilibria: not certified
    assert certified.params["certify"] is True


def test_certification_leaves_the_points_alone(tmp_path, adhesive, mesh, certified):
    plain = run(Sweep(scene=adhesive, zetas=ZETAS, discretization=mesh, pair=False),
                tmp_path / "p.h5", progress=None)
    rows = certified.points["variant"] == "adhesive"
    assert np.array_equal(plain.points["area"], certified.points["area"][rows])
    assert not plain.points["certified"].any() and "certify" not in plain.params


def test_a_speed_ramp_is_certified_by_a_second_finer_ramp(tmp_path, adhesive, mesh, identical):
    ramp = {"name": "speed-ramp", "tolerance": 0.05}
    data = run(Sweep(scene=adhesive, zetas=[1.0, 1.5, 2.0], discretization=mesh, pair=False,
                     history=ramp, certify=True), tmp_path / "r.h5", progress=None)
    # stopped after its second point, the study resumes both paths where they stood
    cut = tmp_path / "cut.h5"
    cut.write_bytes(data.path.read_bytes())
    with h5py.File(cut, "r+") as f:
        f["points"].attrs["count"] = 2
        f.attrs["complete"] = False
    identical(resume(cut, progress=None).points, data.points)
    p = data.points
    assert p["converged"].all() and p["certified"].all()
    # the chain's first point carries both paths' states: the ramp's and the tenfold finer one
    first = np.flatnonzero(p["step"] == 0)[0]
    assert json.loads(p["ramp"][first])["step"] == pytest.approx(0.05)
    assert json.loads(p["certified_ramp"][first])["step"] == pytest.approx(0.005)
    assert all(json.loads(s)["step"] <= 0.25 / math.sqrt(10) for s in p["certified_ramp"])


def test_a_failed_certification_warns_and_says_so(tmp_path, adhesive, mesh, monkeypatch):
    monkeypatch.setattr(certify, "AREA_TOLERANCE", 0.0)     # nothing agrees to round-off
    monkeypatch.setattr(certify, "AREA_FLOOR", 0.0)
    sweep = Sweep(scene=adhesive, zetas=[1.0], discretization=mesh, pair=False, certify=True)
    with pytest.warns(CertificationWarning, match="not certified: with a tenth"):
        data = run(sweep, tmp_path / "f.h5", progress=None)
    p = data.points
    assert p["converged"].all() and not p["certified"].any()
    assert np.isfinite(p["certified_area"]).all()
    assert "not certified" in p["message"][0]


def test_bad_certify_options(adhesive):
    with pytest.raises(ValidationError, match="path_step"):
        Sweep(scene=adhesive, zetas=ZETAS, certify=True, discretization={"path_step": 5e-4})


def test_the_columns_round_trip_and_older_files_read_with_defaults(tmp_path, certified):
    path = tmp_path / "old.h5"
    path.write_bytes(certified.path.read_bytes())
    again = load_study(path)
    for name in CERTIFY_COLUMNS:
        a, b = certified.points[name], again.points[name]
        assert np.array_equal(a, b, equal_nan=a.dtype.kind == "f"), name
    with h5py.File(path, "r+") as f:                  # a file written before certification
        for name in CERTIFY_COLUMNS:
            del f["points"][name]
    old = load_study(path)
    assert not old.points["certified"].any()
    assert np.isnan(old.points["certified_area"]).all()
    assert np.isnan(old.points["certified_friction"]).all()
    assert (old.points["certified_ramp"] == "").all()
    storage.rewrite(path)                             # a resume writes them with the defaults
    with h5py.File(path, "r") as f:
        assert all(name in f["points"] for name in CERTIFY_COLUMNS)


def test_plots_mark_jumps_ramp_events_and_failed_certifications(tmp_path, certified):
    from matplotlib.figure import Figure

    points = {k: v.astype("U200") if v.dtype.kind == "U" else v.copy()   # room for new text
              for k, v in certified.points.items()}
    adhesive = np.flatnonzero(points["variant"] == "adhesive")
    jumped, failed = adhesive[0], adhesive[1]
    points["events"][jumped] = json.dumps([{"kind": "fold", "penetration": 0.1},
                                           {"kind": "jump", "penetration": 0.1}])
    points["certified"][failed] = False
    ramped = adhesive[2]
    points["history"][ramped] = "speed-ramp"
    points["events"][ramped] = json.dumps([{"kind": "birth", "zeta": 3.0, "contacts": [1, 2]}])
    data = attrs.evolve(certified, points=points)

    ax = Figure().subplots()
    draw_sweep(ax, data, "area")
    lines = {line.get_label(): line for line in ax.get_lines()}
    assert list(lines[JUMP_LABEL].get_xdata()) == [points["zeta"][jumped]]
    assert list(lines[UNCERTIFIED_LABEL].get_xdata()) == [points["zeta"][failed]]
    assert lines[UNCERTIFIED_LABEL].get_markeredgecolor() == "red"
    birth = lines[RAMP_LABEL.format(kind="birth")]
    assert list(birth.get_xdata()) == [3.0]
    # on the curve: between the adhesive points at ζ = 1 and 10, linear in log ζ
    a1, a10 = points["area"][adhesive[1]], points["area"][adhesive[2]]
    assert birth.get_ydata()[0] == pytest.approx(a1 + (a10 - a1) * math.log10(3.0))

    plain = Figure().subplots()                       # the file as computed: nothing to mark
    draw_sweep(plain, certified, "area")
    labels = [line.get_label() for line in plain.get_lines()]
    assert not {JUMP_LABEL, UNCERTIFIED_LABEL} & set(labels)
    assert all(f.exists() for f in plot_study(data, tmp_path))


def test_the_command_line_certifies(tmp_path, capsys):
    from viscocontact.cli import build_parser, main
    from viscocontact.study import WavyStudy

    from .conftest import ADHESIVE

    scene = tmp_path / "wavy.toml"
    scene.write_text(ADHESIVE)
    out = tmp_path / "s.h5"
    with warnings.catch_warnings():
        warnings.simplefilter("error", CertificationWarning)
        assert main(["sweep", str(scene), "--zetas", "1", "--no-pair", "--elements", "32",
                     "--certify", "--quiet", "--out", str(out)]) == 0
    assert "every converged adhesive point" in capsys.readouterr().out
    data = load_study(out)
    assert data.params["certify"] is True and data.points["certified"].all()
    assert build_parser().parse_args(["study", "--certify"]).certify
    assert WavyStudy(certify=True).sweep().certify
