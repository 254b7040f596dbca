"""A result read in SI units is the scene's SI table read back (the two conversions are
inverse), and full contact is one wavelength."""
from __future__ import annotations

import math

import numpy as np
import pytest

import viscocontact as vc

SI = """
[profile]
kind = "sinusoid"
[rheology]
kind = "standard-linear-solid"
beta = 10.0
[sliding]
zeta = 1.0
[physical]
E0 = 1e7
poisson = 0.5
wavelength = 1e-3
amplitude = 8e-6
"""


def test_a_load_given_in_pascal_is_read_back_in_pascal():
    scene = vc.Scene.from_toml(SI + "mean_pressure = 1e5\n")
    result = vc.solve(scene)
    si = result.physical(scene)
    # the solve holds p̃∞ to its tolerance; the conversion back is exact
    assert si.mean_pressure == pytest.approx(1e5, rel=1e-9)
    assert si.contact_length == pytest.approx(result.area * 1e-3 / (2 * math.pi), rel=1e-15)
    assert si.contact_fraction == pytest.approx(result.area / (2 * math.pi), rel=1e-15)
    assert si.tangential_stress == pytest.approx(result.friction * 1e5, rel=1e-9)
    assert si.amplitude == pytest.approx(8e-6, rel=1e-15)
    assert np.allclose(si.edges, np.asarray(result.edges).reshape(-1, 2) * 1e-3 / (2 * math.pi),
                       rtol=1e-15, atol=0)


def test_a_penetration_given_in_metres_is_read_back_and_full_contact_is_one_wavelength():
    scene = vc.Scene.from_toml(SI + "penetration = 4e-6\n")
    assert vc.solve(scene).physical(scene).penetration == pytest.approx(4e-6, rel=1e-12)
    full = vc.Scene.from_toml(SI + "mean_pressure = 3e6\n")     # p̃∞ = 8.95: beyond closure
    si = vc.solve(full).physical(full)
    assert si.contact_length == pytest.approx(1e-3, rel=1e-12) and si.contact_fraction == 1.0


def test_a_dimensionless_scene_has_no_si_view():
    bare = SI.split("[physical]")[0].replace('kind = "sinusoid"',
                                             'kind = "sinusoid"\namplitude = 0.05')
    scene = vc.Scene.from_toml(bare + "[load]\nmean_pressure = 0.3\n")
    with pytest.raises(vc.ValidationError, match="physical.wavelength"):
        vc.solve(scene).physical(scene)


def test_solve_si_prints_the_si_view_or_says_what_is_missing(tmp_path, capsys):
    import json

    from viscocontact.cli import main

    scene = tmp_path / "si.toml"
    scene.write_text(SI + "mean_pressure = 1e5\n")
    assert main(["solve", str(scene), "--si", "--json"]) == 0
    si = json.loads(capsys.readouterr().out)["si"]
    assert si["mean_pressure"] == pytest.approx(1e5, rel=1e-9) and si["wavelength"] == 1e-3
    bare = tmp_path / "bare.toml"
    bare.write_text(SI.split("[physical]")[0].replace('kind = "sinusoid"',
                                                      'kind = "sinusoid"\namplitude = 0.05')
                    + "[load]\nmean_pressure = 0.3\n")
    assert main(["solve", str(bare), "--si"]) == 2
    captured = capsys.readouterr()
    assert captured.out == "" and "physical.wavelength" in captured.err


def test_a_studys_points_are_read_in_si_units_as_their_single_solves(tmp_path):
    """``StudyData.physical()``: every point of a sweep of an SI scene, in SI units, is what its
    own single solve gives through ``ContactResult.physical`` (the same conversion), and the load
    given in pascal comes back in pascal."""
    scene = vc.Scene.from_toml(SI + "mean_pressure = 1e5\n")
    zetas = [0.1, 1.0, 10.0]
    data = vc.run_study(vc.Sweep(scene=scene, zetas=zetas, pair=False), tmp_path / "s.h5",
                        progress=None)
    si = data.physical()
    assert set(si) == {"contact_length", "contact_fraction", "penetration", "mean_pressure",
                       "tangential_stress", "friction"}
    np.testing.assert_allclose(si["mean_pressure"], 1e5, rtol=1e-12)
    for row, zeta in enumerate(data.points["zeta"]):
        alone = vc.solve(scene.replace(zeta=float(zeta))).physical(scene)
        for key in si:
            assert si[key][row] == pytest.approx(getattr(alone, key), rel=1e-9), key
