"""Files shipped with the package, so that the README's commands work after ``pip install``.

* ``scenes/``: copies of the source tree's ``examples/scenes/*.toml`` (a test keeps them equal).
  :func:`scene_path` resolves a name the README uses, ``examples/scenes/NAME.toml``, to the
  shipped copy when no such file exists where the command runs.
* ``bench/peer_fft.py``: a copy of ``benchmarks/peer_fft.py``, the uniform-grid FFT peer that
  ``viscocontact bench`` compares with (:func:`bench_suite`).
"""
from __future__ import annotations

from importlib import resources
from pathlib import Path

#: The relative folder of the example scenes in the source tree and in the README.
EXAMPLES = Path("examples", "scenes")


def _here() -> Path:
    return Path(str(resources.files(__name__)))


def example_scenes() -> dict[str, Path]:
    """``{name: path}`` of the shipped example scenes (``"sinusoid"``, ``"thesis_rough"``, ...)."""
    return {p.stem: p for p in sorted((_here() / "scenes").glob("*.toml"))}


def scene_path(path) -> Path:
    """``path``, or the shipped copy when ``path`` is ``examples/scenes/NAME.toml`` of an
    example scene and no such file exists here (the README's commands after an install)."""
    path = Path(path)
    if path.exists() or path.parent != EXAMPLES:
        return path
    shipped = example_scenes().get(path.stem)
    return shipped if shipped is not None and path.suffix == ".toml" else path


def bench_suite(folder=None) -> Path:
    """The folder holding ``peer_fft.py`` for ``viscocontact bench``: ``folder`` when given,
    else ``./benchmarks`` in a source tree, else the shipped copy."""
    if folder is not None:
        return Path(folder)
    local = Path("benchmarks")
    return local if (local / "peer_fft.py").is_file() else _here() / "bench"
