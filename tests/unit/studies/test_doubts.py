"""A study keeps each point's doubts in its record and says once how many points have them,
instead of one warning per solve of every path."""
import warnings
from pathlib import Path

import attrs

from viscocontact.errors import ModelValidityWarning, held, warn_user
from viscocontact.scene import Load, Scene
from viscocontact.studies import Sweep, run

SCENE = Path(__file__).resolve().parents[3] / "examples" / "scenes" / "thesis_wavy.toml"


def test_held_warnings_are_kept_and_others_shown():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        with held(ModelValidityWarning) as kept:
            warn_user("outside the model: a reason", ModelValidityWarning)
            warn_user("something else", UserWarning)
        warn_user("outside the model: after", ModelValidityWarning)
    assert kept == ["outside the model: a reason"]
    assert [str(w.message) for w in caught] == ["something else", "outside the model: after"]


def test_a_study_says_once_how_many_points_lie_outside_the_model(tmp_path):
    """The wavy scene at ζ = 1e-5 (a memory length of 0.1 δX: outside the model) and 1e-2
    (inside): one warning, and the point's message says why."""
    scene = attrs.evolve(Scene.from_toml(SCENE), load=Load(mean_pressure=0.1), physical=None)
    study = Sweep(scene=scene, zetas=[1e-5, 1e-2], loads=[0.1], pair=False)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        data = run(study, tmp_path / "s.h5", progress=None)
    doubts = [str(w.message) for w in caught if issubclass(w.category, ModelValidityWarning)]
    assert doubts == ["1 of 2 points lie outside the model: their 'message' column says why "
                      "(docs/edges.md)"]
    messages = {float(z): str(m) for z, m in zip(data.points["zeta"], data.points["message"])}
    assert "outside the model: " in messages[1e-5] and "δX" in messages[1e-5]
    assert "outside the model" not in messages[1e-2]
