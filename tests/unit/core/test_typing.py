"""The package ships ``py.typed``, so its annotations are a promise: mypy finds no error."""
from pathlib import Path

import pytest

import viscocontact


def test_mypy_finds_no_error_in_the_package():
    api = pytest.importorskip("mypy.api")
    root = Path(viscocontact.__file__).parent
    assert (root / "py.typed").is_file()
    if not (root.parent / "pyproject.toml").is_file():
        pytest.skip("the package is not installed from its source tree (no mypy configuration)")
    out, err, status = api.run([str(root), "--config-file",
                                str(root.parent / "pyproject.toml"), "--no-incremental"])
    assert status == 0, out + err
