"""The package ships ``py.typed``, so its annotations are a promise: mypy finds no error."""
from pathlib import Path

import pytest

import viscocontact


def test_mypy_finds_no_error_in_the_package(monkeypatch):
    api = pytest.importorskip("mypy.api")
    root = Path(viscocontact.__file__).parent
    assert (root / "py.typed").is_file()
    config = root.parent / "pyproject.toml"
    if not config.is_file():
        pytest.skip("the package is not installed from its source tree (no mypy configuration)")
    # by import name from the source tree: no crawl of the folders above it
    monkeypatch.setenv("MYPYPATH", str(root.parent))
    out, err, status = api.run(["-p", "viscocontact", "--config-file", str(config),
                                "--no-incremental"])
    assert status == 0, out + err
