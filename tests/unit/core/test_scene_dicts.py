"""Any scene dict either builds a Scene or raises a ValidationError that names the key.

The dicts are valid scenes (every registered kind of every section, values in range, with or
without a ``[physical]`` table) changed by a few random mutations: a value replaced by one of
any type (numbers out of range, NaN, strings, lists, nested tables), a key or section removed,
a key of another kind or an unknown key added, a section that is not a table, a ``kind``
swapped. ``Scene.from_dict`` must never raise anything but ``ValidationError`` (a TypeError, a
KeyError or a numpy error would reach the user as a traceback), and the error's field must
name where the problem is.
"""
from __future__ import annotations

import warnings

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from viscocontact.errors import ValidationError
from viscocontact.scene import (COMPONENT_SECTIONS, PHYSICAL_KEYS, SECTIONS, TOP_LEVEL_KEYS,
                                Scene, _init_fields, _registry_for)


def _kind_fields(section: str) -> dict[str, list[str]]:
    registry, out = _registry_for(section), {}
    for name in registry.names():
        try:
            out[name] = sorted(_init_fields(registry.get(name)))
        except Exception:  # a plugin that does not load: its kind is still drawn
            out[name] = []
    return out


FIELDS = {section: _kind_fields(section) for section in COMPONENT_SECTIONS}
KEYS = {section: sorted({k for keys in kinds.values() for k in keys})
        for section, kinds in FIELDS.items()}
KEYS.update(load=["mean_pressure", "penetration"], sliding=["zeta"], physical=sorted(PHYSICAL_KEYS))

# Integers up to 10**4 and far beyond the float range (an OverflowError in float()); those in
# between are left out: a self-affine profile with 10**7 scales is valid but takes gigabytes
# to evaluate, which is a question of resources, not of validation.
integers = st.one_of(st.integers(-10**4, 10**4), st.sampled_from([2**64, 10**309, -10**400]))
scalars = st.one_of(st.none(), st.booleans(), integers, st.floats(), st.text(max_size=8))
anything = st.recursive(scalars, lambda inner: st.lists(inner, max_size=3)
                        | st.dictionaries(st.text(max_size=6), inner, max_size=3), max_leaves=8)
numbers = st.one_of(st.floats(-2.0, 2.0), st.sampled_from([0.0, 0.5, 1.0, -1.0, 1e-9, 1e9]),
                    st.integers(-3, 70), integers)
values = st.one_of(numbers, anything)
names = st.text(min_size=1, max_size=8)


def _profile():
    return st.one_of(
        st.fixed_dictionaries({"kind": st.just("sinusoid"), "amplitude": st.floats(0.01, 1.0)}),
        st.fixed_dictionaries({"kind": st.just("self-affine"), "hurst": st.floats(0.1, 1.0),
                               "scales": st.integers(1, 16), "rms": st.floats(0.01, 0.5)},
                              optional={"seed": st.integers(0, 9),
                                        "rolloff": st.floats(1.0, 1.0)}),
        st.integers(1, 4).flatmap(lambda n: st.fixed_dictionaries({
            "kind": st.just("measured"),
            "amplitudes": st.lists(st.floats(0.0, 0.2), min_size=n, max_size=n),
            "phases": st.lists(st.floats(0.0, 6.28), min_size=n, max_size=n),
            "length": st.floats(1e-4, 1.0)})))


def _rheology():
    return st.one_of(
        st.just({"kind": "elastic"}),
        st.fixed_dictionaries({"kind": st.just("standard-linear-solid"),
                               "beta": st.floats(1.0, 100.0)}),
        st.integers(1, 3).flatmap(lambda n: st.fixed_dictionaries({
            "kind": st.just("prony"),
            "moduli": st.lists(st.floats(0.1, 10.0), min_size=n, max_size=n),
            "times": st.lists(st.floats(0.1, 10.0), min_size=n, max_size=n, unique=True)})))


@st.composite
def valid_scenes(draw) -> dict:
    """A scene dict that builds (up to the physical table, which may contradict it)."""
    out = {"profile": draw(_profile()), "rheology": draw(_rheology()),
           "load": draw(st.one_of(
               st.fixed_dictionaries({"mean_pressure": st.floats(-0.1, 1.0)}),
               st.fixed_dictionaries({"penetration": st.floats(-1.0, 2.0)}))),
           "sliding": {"zeta": draw(st.floats(0.0, 100.0))}}
    if draw(st.booleans()):
        out["kernel"] = draw(st.one_of(
            st.just({"kind": "half-plane"}),
            st.fixed_dictionaries({"kind": st.sampled_from(["confined-layer", "free-layer"]),
                                   "thickness": st.floats(0.1, 10.0)})))
    if draw(st.booleans()):
        out["adhesion"] = draw(st.one_of(
            st.just({"kind": "none"}),
            st.fixed_dictionaries({"kind": st.just("energy-balance"),
                                   "gamma": st.floats(1e-6, 1e-3)})))
    if draw(st.booleans()):
        out["solver"] = {"kind": draw(st.sampled_from(sorted(FIELDS["solver"])))}
    if draw(st.booleans()):
        out["poisson"] = draw(st.floats(-0.9, 0.5))
    if draw(st.sampled_from([False, False, True])):
        out["physical"] = draw(st.dictionaries(st.sampled_from(KEYS["physical"]),
                                               st.floats(1e-9, 1e7), max_size=4))
    return out


@st.composite
def scene_dicts(draw) -> dict:
    """:func:`valid_scenes` with 0 to 3 random mutations (see the module docstring)."""
    scene = draw(valid_scenes())
    for _ in range(draw(st.integers(0, 3))):
        what = draw(st.sampled_from(["value", "value", "drop", "key", "unknown", "section",
                                     "kind", "top"]))
        section = draw(st.sampled_from(sorted(SECTIONS)))
        table = scene.get(section)
        if what == "section":
            scene[section] = draw(values)
        elif what == "top":
            scene[draw(st.sampled_from([*TOP_LEVEL_KEYS, "unknown"]) | names)] = draw(values)
        elif not isinstance(table, dict):
            scene[section] = {}
        elif what == "value" and table:
            table[draw(st.sampled_from(sorted(table)))] = draw(values)
        elif what == "drop":
            if table and draw(st.booleans()):
                del table[draw(st.sampled_from(sorted(table)))]
            else:
                scene.pop(section)
        elif what == "key" and KEYS[section]:
            table[draw(st.sampled_from(KEYS[section]))] = draw(values)
        elif what == "unknown":
            table[draw(names)] = draw(values)
        elif what == "kind" and section in FIELDS:
            table["kind"] = draw(st.sampled_from(sorted(FIELDS[section])) | values)
    return scene


def _named(field: str, scene: dict) -> bool:
    """Whether a ValidationError's field names a place in the scene format or in ``scene``."""
    return field in scene or field.split(".")[0] in (*SECTIONS, *TOP_LEVEL_KEYS, "scene")


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(scene_dicts())
def test_a_scene_dict_builds_or_names_its_bad_key(scene):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")          # warnings about odd but legal values
        try:
            built = Scene.from_dict(scene)
        except ValidationError as exc:
            assert _named(exc.field, scene), (exc.field, str(exc))
            return
    assert isinstance(built, Scene)
    assert Scene.from_dict(built.to_dict()) == built            # what builds round-trips


GIANT = 10**400                                  # float(GIANT) raises OverflowError


@pytest.mark.parametrize("change,field", [
    ({"profile": {"kind": "sinusoid", "amplitude": GIANT}}, "profile.amplitude"),
    ({"rheology": {"kind": "prony", "moduli": [1.0, GIANT], "times": [1.0, 2.0]}},
     "rheology.moduli"),
    ({"poisson": GIANT}, "poisson"),
    ({"sliding": {"zeta": GIANT}}, "sliding.zeta"),
    ({"load": {"mean_pressure": -GIANT}}, "load.mean_pressure"),
    ({"physical": {"E0": GIANT}}, "physical.E0"),
    ({"profile": {"kind": "self-affine", "hurst": 0.8, "scales": 2**64, "rms": 0.1},
      "load": {}, "physical": {"mean_pressure": 1e5, "E0": 1e7, "wavelength": 1e-3}}, "profile"),
])
def test_integers_beyond_the_float_range_are_named(change, field):
    scene = {"profile": {"kind": "sinusoid", "amplitude": 0.1},
             "rheology": {"kind": "elastic"}, "load": {"mean_pressure": 0.1}} | change
    with pytest.raises(ValidationError) as info:
        Scene.from_dict(scene)
    assert info.value.field == field
