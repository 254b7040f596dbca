"""Plotting is library code: it writes its figures without touching the caller's matplotlib
state (backend, pyplot's open figures)."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from viscocontact.testing.scenes import WAVY

PNG = b"\x89PNG\r\n\x1a\n"

SCENE = WAVY

CALLER = r"""
import sys
import matplotlib
matplotlib.use("svg")                         # the caller's choice, not Agg
import numpy as np
from viscocontact.plots import plot_solution_fields

x = np.linspace(-np.pi, np.pi, 65)
fields = {"x": x, "pressure": np.maximum(np.cos(x), 0.0), "gap": np.maximum(-np.cos(x), 0.0)}
out = sys.argv[1]
plot_solution_fields([{"fields": fields, "label": "a"}], out + "/first.png")
assert "matplotlib.pyplot" not in sys.modules, "pyplot imported by the library"
assert matplotlib.get_backend() == "svg", matplotlib.get_backend()

import matplotlib.pyplot as plt               # a caller with a figure of its own open
mine = plt.figure()
plot_solution_fields([{"fields": fields, "label": "a"}], out + "/second.png")
assert matplotlib.get_backend() == "svg", matplotlib.get_backend()
assert plt.get_fignums() == [mine.number] and plt.gcf() is mine
print("ok")
"""


def test_drawing_keeps_the_callers_backend_and_figures(tmp_path):
    done = subprocess.run([sys.executable, "-c", CALLER, str(tmp_path)], capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "ok"
    for name in ("first.png", "second.png"):
        assert (tmp_path / name).read_bytes()[:8] == PNG


def test_plot_study_writes_pngs_and_leaves_pyplot_alone(tmp_path, monkeypatch):
    """... and each figure names its scene (the file, β, p̃∞; Γ̃ when adhesive) and labels Ã
    with the value of full contact (2π)."""
    import matplotlib

    from viscocontact import plots
    from viscocontact.plots import plot_study
    from viscocontact.scene import Scene
    from viscocontact.studies import Sweep, run

    data = run(Sweep(scene=Scene.from_toml(SCENE), zetas=[0.1, 1.0],
                     discretization={"elements": 32}), tmp_path / "s.h5", progress=None)
    backend = matplotlib.get_backend()
    pyplot = sys.modules.get("matplotlib.pyplot")
    open_figures = pyplot.get_fignums() if pyplot is not None else []
    save, drawn = plots._save, []
    monkeypatch.setattr(plots, "_save",
                        lambda fig, *a, **k: drawn.append(fig) or save(fig, *a, **k))
    files = plot_study(data, tmp_path / "png")
    assert [f.name for f in files] == ["s_area.png", "s_friction.png"]
    for fig in drawn:
        title = fig.axes[0].get_title()
        assert title.startswith("s — sinusoid") and "β = 10" in title and "p̃∞ = 0.1" in title
        assert "Γ̃" not in title                    # adhesionless: no Γ̃ to name
    assert "2π: full contact" in drawn[0].axes[0].get_ylabel()
    for f in files:
        assert Path(f).read_bytes()[:8] == PNG
    assert matplotlib.get_backend() == backend
    if pyplot is not None:
        assert pyplot.get_fignums() == open_figures


def test_a_result_is_drawn_with_its_scene(tmp_path, monkeypatch):
    """``plot_solution_fields`` takes a ContactResult; the figure names the scene (β, p̃∞) and
    labels the curve with Ã and where full contact is (2π)."""
    import pytest

    import viscocontact as vc
    from viscocontact import plots

    scene = vc.Scene.from_toml(SCENE)
    result = vc.solve(scene, fields=True)
    drawn = []
    monkeypatch.setattr(plots, "_save", lambda fig, path, dpi=90: drawn.append(fig) or path)
    plots.plot_solution_fields(result, tmp_path / "f.png", scene=scene)
    top = drawn[0].axes[0]
    assert "β = 10" in top.get_title() and "p̃∞ = " in top.get_title()
    assert "(2π: full)" in top.get_legend().get_texts()[0].get_text()
    with pytest.raises(vc.ValidationError, match=r"solutions\[0\].*fields=True"):
        plots.plot_solution_fields(vc.solve(scene), tmp_path / "g.png")


def test_an_adhesive_scene_is_named_with_its_gamma():
    from viscocontact import data
    from viscocontact.plots import scene_label
    from viscocontact.scene import Scene

    label = scene_label(Scene.from_toml(data.example_scenes()["sinusoid"]))
    assert label == "sinusoid, β = 10, p̃∞ = 0.3, Γ̃ = 0.004"      # γ̃/Λ̃² = 1e-5/0.05²
