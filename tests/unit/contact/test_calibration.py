"""The shipped stress-intensity calibration tables (``viscocontact.contact.calibration``)."""
import numpy as np
import pytest

from viscocontact.contact import calibration
from viscocontact.contact._calibration_data import TABLES
from viscocontact.methods.bem.meshing import INTERIOR_CAP, Discretization


def test_every_shipped_mesh_type_has_its_table():
    assert set(TABLES) == set(calibration.SHIPPED)
    for key, ratios in TABLES.items():
        shape = (26, 7) if key[3] else (26,)
        assert np.shape(ratios) == shape
        assert np.all((np.array(ratios) > 0.9) & (np.array(ratios) < 1.1))   # about 0.94-1.01


def test_the_default_meshes_are_shipped():
    """The default discretisation's clustering and grading, every element count its interior
    refinement gives (doubling up to the cap)."""
    disc = Discretization()
    counts = [disc.elements * 2**k for k in range(8) if disc.elements * 2**k <= INTERIOR_CAP]
    for n in counts:
        for zones in (False, True):
            assert (n, float(disc.clustering), float(disc.grading), zones) in TABLES


def _conditions(key) -> np.ndarray:
    """cond(B) of the influence matrix behind each entry of the table ``key``."""
    from viscocontact.contact.mesh import MeshSpec, build_mesh
    from viscocontact.kernels.half_plane import HalfPlane
    from viscocontact.rheology.elastic import Elastic

    elements, exponent, grading, zones = key
    pk = HalfPlane().prepare(Elastic(), 0.0)

    def cond(a, smallest=None):
        mesh = build_mesh(np.array([-a, a]), MeshSpec(elements=elements, exponent=exponent,
                                                      grading=grading, smallest=smallest))
        return np.linalg.cond(pk.influence(mesh.mid, mesh.left, mesh.right))

    if not zones:
        return np.array([cond(a) for a in calibration._CAL_ALPHA])
    return np.array([[cond(a, rel * a) for rel in calibration._CAL_REL]
                     for a in calibration._CAL_ALPHA])


@pytest.mark.parametrize("zones", [False, True])
def test_a_shipped_table_is_what_the_module_computes(zones):
    """Each entry solves ``B σ = 1`` on a mesh whose edge elements reach 1e-9 of the
    half-width with zones (cond(B) up to 8.5e9), so the table is reproducible to the round-off
    of that solve, ``cond(B)·ε`` per entry, not to a fixed 1e-12: the shipped table and one
    computed with the numpy 2.4.6 wheels differ by up to 6.9e-8 at the smallest elements,
    0.21 cond(B)·ε (without zones, cond(B) up to 1.1e4: 5e-14)."""
    key = (64, 1.0, 1.15, zones)
    computed = calibration.calibration_ratios(*key)
    bound = _conditions(key) * np.finfo(float).eps
    assert np.all(np.abs(computed - np.array(TABLES[key])) <= bound)


def test_another_mesh_type_is_computed(monkeypatch):
    """A mesh type that is not shipped is computed on first use (and the interpolant matches
    the shipped one's when the numbers are the same)."""
    calibration._calibration_table.cache_clear()
    monkeypatch.setattr("viscocontact.contact._calibration_data.TABLES", {})
    try:
        computed = calibration._calibration_table(64, 1.0, 1.15, False)
    finally:
        calibration._calibration_table.cache_clear()
    shipped = calibration._calibration_table(64, 1.0, 1.15, False)
    x = np.log(np.geomspace(1e-3, 3.0, 17))
    assert np.max(np.abs(computed(x) - shipped(x))) < 1e-12


def test_write_shipped_writes_an_importable_module(tmp_path, monkeypatch):
    monkeypatch.setattr(calibration, "SHIPPED", ((8, 1.0, 1.15, False), (8, 1.0, 1.15, True)))
    path = tmp_path / "data.py"
    calibration.write_shipped(path)
    namespace = {}
    exec(path.read_text(), namespace)
    assert set(namespace["TABLES"]) == set(calibration.SHIPPED)
    assert np.allclose(namespace["TABLES"][(8, 1.0, 1.15, True)],
                       calibration.calibration_ratios(8, 1.0, 1.15, True), rtol=0, atol=1e-15)
    assert [p.name for p in tmp_path.iterdir()] == ["data.py"]
