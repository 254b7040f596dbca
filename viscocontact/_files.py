"""Files written whole or not at all: through a temporary file in the same folder, then renamed."""
from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path


def publish(tmp, path) -> None:
    """Give ``tmp`` the mode of a newly created file (:func:`tempfile.mkstemp` makes it 0600),
    then move it to ``path``."""
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(tmp, 0o666 & ~umask)
    os.replace(tmp, path)


def write_atomic(path, data: bytes) -> None:
    """Write ``data`` to ``path`` through a temporary file in the same folder; no temporary file
    is left behind."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
        publish(tmp, path)
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)
        raise
