"""Output folders checked before anything is computed: a command that cannot write its results
says so at once, not after the computation (nor as a "no such file")."""
from __future__ import annotations

import os
import tempfile
from pathlib import Path

from .errors import ValidationError


def check_folder(option: str, name, what: str) -> Path:
    """The folder ``name`` to write into (made later if missing), checked now.

    It must not be a file nor lie below one, and the folder itself or, when missing, its
    nearest existing parent must be writable by this process: the permission bits allow it and
    a folder can be made there (and is removed at once), which also catches what the bits do not
    show (a read-only or virtual file system, a full disk). Raises :class:`ValidationError`
    naming ``option`` otherwise; returns the path.
    """
    path = Path(name)
    for folder in (path, *path.absolute().parents):
        if folder.exists():
            if not folder.is_dir():
                raise ValidationError(option, str(name), f"{what} ({folder} is a file)")
            if not os.access(folder, os.W_OK | os.X_OK):
                raise ValidationError(option, str(name),
                                      f"{what} (no permission to write in {folder})")
            try:
                os.rmdir(tempfile.mkdtemp(prefix=".viscocontact-check-", dir=folder))
            except OSError as exc:
                raise ValidationError(option, str(name), f"{what} (cannot write in {folder}: "
                                      f"{exc.strerror or exc})") from None
            break
    return path
