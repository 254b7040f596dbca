"""The measures of an areal solution: row-wise sub-cell area against the 1D edges, cell rises,
periodic patches and their moments."""
import numpy as np
import pytest

from viscocontact.areal.results import (cell_rise, patch_statistics, periodic_labels,
                                        row_lengths)
from viscocontact.methods.spectral.edges import contact_edges

TWO_PI = 2 * np.pi


def test_row_lengths_are_the_1d_contact_lengths_row_by_row():
    rng = np.random.default_rng(3)
    n = 64
    p = np.where(rng.random((20, n)) < 0.6, rng.random((20, n)), 0.0)
    p[0] = 0.0                       # no contact
    p[1] = 1.0 + rng.random(n)       # a closed row
    p[2, :] = 0.0
    p[2, [0, 1, 2, 3, 62, 63]] = [1.0, 0.8, 0.5, 0.2, 0.3, 0.9]     # a run across the boundary
    gap = np.where(p > 0, 0.0, rng.random((20, n)))
    h = TWO_PI / n
    got = row_lengths(p, gap, h)
    for row in range(20):
        if p[row].all():
            want = TWO_PI
        else:
            edges = contact_edges(0.0, h, p[row], gap[row])
            want = min(float(np.sum(edges[:, 1] - edges[:, 0])), TWO_PI) if edges.size else 0.0
        assert got[row] == pytest.approx(want, rel=1e-13, abs=1e-13)


def test_cell_rise_is_exact_for_a_band_limited_surface():
    nx, ny = 32, 8
    x = TWO_PI * np.arange(nx) / nx
    y = TWO_PI * 2.0 * np.arange(ny) / ny
    h = np.sin(3 * x)[None, :] * np.cos(y)[:, None]
    for step in (1, 2, 4):
        half = step * np.pi / nx
        xs, ys = x[::step], y[::step]
        want = (np.sin(3 * (xs + half)) - np.sin(3 * (xs - half)))[None, :] * np.cos(ys)[:, None]
        assert np.allclose(cell_rise(h, step, axis=1), want, atol=1e-14)


def test_patches_join_across_the_periodic_boundaries():
    m = np.zeros((16, 20), bool)
    m[0:2, 0:2] = m[-1:, 0:2] = m[0:2, -2:] = m[-1:, -2:] = True   # one patch at the 4 corners
    m[6:9, 8:11] = True
    labels, n = periodic_labels(m)
    assert n == 2
    assert len(set(labels[m & (labels > 0)][:1]) | {labels[0, 0], labels[-1, -1],
                                                    labels[0, -1], labels[-1, 0]}) == 1
    stats = patch_statistics(m)
    hx, hy = TWO_PI / 20, TWO_PI / 16
    assert np.allclose(stats.areas, np.array([12, 9]) * hx * hy)
    assert stats.percolating == 0 and stats.summary()["count"] == 2


def test_orientation_and_elongation_of_an_ellipse():
    """A rasterised ellipse with axes 24 and 6 cells turned by 30°: its major axis within 2°
    of 30° from the sliding direction x, its elongation within 3 % of 4; measured from a
    sliding direction along y the angle is -60°."""
    n = 128
    jj, ii = np.mgrid[0:n, 0:n]
    t = np.radians(30.0)
    u = (ii - 40) * np.cos(t) + (jj - 70) * np.sin(t)
    v = -(ii - 40) * np.sin(t) + (jj - 70) * np.cos(t)
    m = (u / 24) ** 2 + (v / 6) ** 2 <= 1
    m = np.roll(m, 80, axis=1)                 # across the boundary: joined, still one patch
    stats = patch_statistics(m)
    assert stats.count == 1
    assert np.degrees(stats.orientations[0]) == pytest.approx(30.0, abs=2.0)
    assert stats.elongations[0] == pytest.approx(4.0, rel=3e-2)
    assert stats.alignment == pytest.approx(stats.anisotropy[0] * np.cos(np.radians(60)),
                                            rel=0.1)
    across = patch_statistics(m, direction=np.pi / 2)
    assert np.degrees(across.orientations[0]) == pytest.approx(-60.0, abs=2.0)


def test_a_band_across_the_cell_percolates():
    m = np.zeros((16, 16), bool)
    m[:, 3:6] = True
    stats = patch_statistics(m)
    assert stats.percolating == 1 and np.isnan(stats.orientations[0])
    assert patch_statistics(np.zeros((8, 8), bool)).summary()["count"] == 0


def test_contact_images_are_written(tmp_path):
    pytest.importorskip("matplotlib")
    from viscocontact.areal.method import ArealSpectral
    from viscocontact.areal.plots import plot_contact
    from viscocontact.areal.problem import ArealProblem
    from viscocontact.rheology import Elastic

    x = np.arange(32) * TWO_PI / 32
    h = 0.1 * (np.cos(x)[None, :] + np.cos(2 * x)[:, None])
    prob = ArealProblem(surface=h, rheology=Elastic(), mean_pressure=0.05)
    path = plot_contact(ArealSpectral().solve(prob, fields=True), tmp_path / "contact.png")
    assert path.stat().st_size > 1000
    with pytest.raises(ValueError, match="fields=True"):
        plot_contact(ArealSpectral().solve(prob), tmp_path / "none.png")


def test_area_is_the_same_whichever_way_the_grid_is_turned():
    """Turning the fields by 90° with the sliding direction, or mirroring them against a
    reversed sliding direction, leaves the area: the lines along the sliding direction are
    scanned, and which end of a run leads follows it."""
    from viscocontact.areal.results import area_fraction

    rng = np.random.default_rng(5)
    y, x = np.mgrid[0:48, 0:64]
    blob = (np.cos(2 * np.pi * x / 64) + 0.7 * np.cos(2 * np.pi * 2 * y / 48 + 1)
            + 0.1 * rng.random(x.shape))
    p = np.maximum(blob - 0.8, 0.0)
    g = np.where(p > 0, 0.0, 0.8 - blob + 0.01)
    a = area_fraction(p, g)
    assert 0.05 < a < 0.5 and a != np.mean(p > 0)
    assert a == pytest.approx(np.mean(row_lengths(p, g, TWO_PI / 64)) / TWO_PI, rel=1e-14)
    assert area_fraction(p.T, g.T, np.pi / 2) == pytest.approx(a, rel=1e-14)
    assert area_fraction(p[:, ::-1], g[:, ::-1], np.pi) == pytest.approx(a, rel=1e-14)
    assert area_fraction(p.T[::-1], g.T[::-1], -np.pi / 2) == pytest.approx(a, rel=1e-14)
