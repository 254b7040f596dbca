"""Files shipped with the package: the example scenes and the bench peer, equal to the source
tree's, found by the README's paths after an install; no library module picks a backend."""
from __future__ import annotations

from pathlib import Path

from viscocontact import data
from viscocontact.scene import Scene

ROOT = Path(__file__).resolve().parents[3]


def test_the_shipped_files_are_the_source_trees():
    shipped = data.example_scenes()
    assert set(shipped) == {p.stem for p in (ROOT / "examples/scenes").glob("*.toml")}
    for name, path in shipped.items():
        assert path.read_bytes() == (ROOT / "examples/scenes" / f"{name}.toml").read_bytes()
    peer = data._here() / "bench" / "peer_fft.py"
    assert peer.read_bytes() == (ROOT / "benchmarks/peer_fft.py").read_bytes()


def test_the_readme_paths_work_in_any_folder(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert data.scene_path("examples/scenes/sinusoid.toml") == data.example_scenes()["sinusoid"]
    assert Scene.from_toml("examples/scenes/sinusoid.toml") == Scene.from_toml(
        ROOT / "examples/scenes/sinusoid.toml")
    assert data.scene_path("examples/scenes/nope.toml") == Path("examples/scenes/nope.toml")
    assert data.bench_suite() == data._here() / "bench"
    local = tmp_path / "examples/scenes"
    local.mkdir(parents=True)
    (local / "sinusoid.toml").write_text("x = 1")             # a local file wins
    assert data.scene_path("examples/scenes/sinusoid.toml") == Path("examples/scenes/sinusoid.toml")


def test_no_library_module_switches_the_matplotlib_backend():
    offenders = [str(p.relative_to(ROOT)) for p in (ROOT / "viscocontact").rglob("*.py")
                 if "matplotlib.use(" in p.read_text(encoding="utf-8")]
    assert offenders == []
