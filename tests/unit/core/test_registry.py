"""The entry-point registry, with fake ``importlib.metadata.EntryPoint`` objects (no install)."""
from __future__ import annotations

import importlib
import sys
import uuid
import warnings
from importlib import metadata
from importlib.metadata import EntryPoint

import pytest

from viscocontact import _registry
from viscocontact._registry import Registry
from viscocontact.errors import PluginError, PluginWarning

GROUP = "viscocontact.things"


@pytest.fixture
def plugin_module(tmp_path, monkeypatch):
    """A fresh importable module holding a good subclass, a non-subclass and a broken sibling."""
    name = f"vc_fake_plugin_{uuid.uuid4().hex[:8]}"
    (tmp_path / f"{name}.py").write_text(
        "class Base:\n    pass\n"
        "class Good(Base):\n    pass\n"
        "class NotAComponent:\n    pass\n")
    (tmp_path / f"{name}_broken.py").write_text("raise ImportError('boom: missing dependency')\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    yield name
    for mod in (name, f"{name}_broken"):
        sys.modules.pop(mod, None)


class Base:
    """Stand-in base class for registries whose entries are never loaded."""


def make_registry(eps, module=None):
    """A registry over fake entry points; the base class is ``module.Base`` when given."""
    base = (lambda: importlib.import_module(module).Base) if module else (lambda: Base)
    return Registry(GROUP, base, entry_points=lambda: list(eps))


def ep(name, value):
    return EntryPoint(name=name, value=value, group=GROUP)


def test_names_import_nothing():
    reg = make_registry([ep("b", "no_such_module_anywhere:Thing"), ep("a", "another_missing:X")])
    assert reg.names() == ["a", "b"]
    assert "a" in reg and "zzz" not in reg
    assert [d["name"] for d in reg.describe()] == ["a", "b"]
    assert reg.describe()[0]["value"] == "another_missing:X"
    assert "no_such_module_anywhere" not in sys.modules


def test_lazy_load_and_cache(plugin_module):
    reg = make_registry([ep("good", f"{plugin_module}:Good")], plugin_module)
    assert reg.names() == ["good"]
    assert plugin_module not in sys.modules
    cls = reg.get("good")
    assert plugin_module in sys.modules
    assert cls.__name__ == "Good" and issubclass(cls, sys.modules[plugin_module].Base)
    assert reg["good"] is cls  # cached, __getitem__ alias


def test_non_subclass_rejected(plugin_module):
    reg = make_registry([ep("bad", f"{plugin_module}:NotAComponent")], plugin_module)
    with pytest.raises(PluginError, match="not a subclass of .*Base"):
        reg.get("bad")


def test_unknown_name_lists_names_and_suggests():
    reg = make_registry([ep("sinusoid", "m:A"), ep("self-affine", "m:B")])
    with pytest.raises(PluginError) as info:
        reg.get("sinusiod")
    message = str(info.value)
    assert "'self-affine'" in message and "'sinusoid'" in message
    assert "did you mean 'sinusoid'?" in message


def test_unknown_name_without_close_match_has_no_hint():
    reg = make_registry([ep("sinusoid", "m:A")])
    with pytest.raises(PluginError) as info:
        reg.get("qqqqqqq")
    assert "did you mean" not in str(info.value)


def test_broken_plugin_fails_only_when_asked(plugin_module):
    reg = make_registry([ep("good", f"{plugin_module}:Good"),
                         ep("broken", f"{plugin_module}_broken:Thing")], plugin_module)
    assert reg.names() == ["broken", "good"]
    assert reg.get("good").__name__ == "Good"
    with pytest.raises(PluginError, match="'broken'.*failed to load.*boom") as info:
        reg.get("broken")
    assert isinstance(info.value.__cause__, ImportError)


def distribution(root, name, entries):
    """An installed-looking distribution ``name`` (a ``.dist-info`` folder under ``root``)
    registering ``entries`` (``{entry name: target}``) in GROUP; its entry points carry it as
    ``ep.dist``, as ``importlib.metadata.entry_points()`` gives them."""
    info = root / f"{name.replace('-', '_')}-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: {name}\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text(
        f"[{GROUP}]\n" + "".join(f"{k} = {v}\n" for k, v in entries.items()))
    return list(metadata.PathDistribution(info).entry_points.select(group=GROUP))


def test_first_registration_wins_and_the_clash_is_warned(tmp_path):
    """Two distributions registering one name for different classes: the first found is used,
    and a warning names both distributions and says which one is used; once per registry."""
    eps = (distribution(tmp_path, "pkg-first", {"x": "first_mod:A", "y": "first_mod:Y"})
           + distribution(tmp_path, "pkg-second", {"x": "second_mod:B"}))
    reg = make_registry(eps)
    with pytest.warns(PluginWarning) as record:
        names = reg.names()
    assert names == ["x", "y"]
    assert len(record) == 1
    message = str(record[0].message)
    assert "'x'" in message and GROUP in message
    assert "by pkg-first (first_mod:A), which is used" in message
    assert "by pkg-second (second_mod:B), which is ignored" in message
    assert reg.describe()[0] == {"name": "x", "distribution": "pkg-first", "value": "first_mod:A"}
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        reg.names()                     # already said: no second warning from this registry
    assert "second_mod" not in sys.modules and "first_mod" not in sys.modules


def test_same_target_registered_twice_is_not_a_clash(tmp_path):
    eps = (distribution(tmp_path, "pkg-one", {"x": "mod:A"})
           + distribution(tmp_path, "pkg-two", {"x": "mod:A"}))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert make_registry(eps).describe() == [{"name": "x", "distribution": "pkg-one",
                                                  "value": "mod:A"}]


def test_clash_without_distribution_metadata_is_still_named():
    reg = make_registry([ep("x", "first_mod:A"), ep("x", "second_mod:B")])
    with pytest.warns(PluginWarning, match="unknown distribution"):
        assert reg.describe() == [{"name": "x", "distribution": None, "value": "first_mod:A"}]


def test_name_of(plugin_module):
    reg = make_registry([ep("good", f"{plugin_module}:Good")], plugin_module)
    cls = reg.get("good")
    assert reg.name_of(cls()) == "good"
    assert reg.name_of(cls) == "good"
    with pytest.raises(PluginError, match="not registered"):
        reg.name_of(sys.modules[plugin_module].Base())


def test_name_of_tolerates_spaces_in_value(plugin_module):
    reg = make_registry([ep("good", f"{plugin_module} : Good")], plugin_module)
    assert reg.name_of(reg.get("good")) == "good"


def test_module_registries_hold_builtins():
    assert set(_registry.REGISTRIES) == {"profiles", "rheologies", "kernels", "solvers", "adhesion",
                                         "methods", "surfaces"}
    assert {"sinusoid", "self-affine"} <= set(_registry.profiles.names())
    assert {"elastic", "standard-linear-solid", "prony"} <= set(_registry.rheologies.names())
    assert {"half-plane", "confined-layer", "free-layer"} <= set(_registry.kernels.names())
    assert {"newton", "broyden", "nonlinear-cg", "bisection"} <= set(_registry.solvers.names())
    assert {"none", "energy-balance"} <= set(_registry.adhesion.names())
    entry = next(d for d in _registry.profiles.describe() if d["name"] == "sinusoid")
    assert entry["distribution"] == "viscocontact"
