"""Output folders checked before anything is computed: a command that cannot write its results
says so at once, not after the computation (nor as a "no such file")."""
from __future__ import annotations

import os
from pathlib import Path

from .errors import ValidationError


def check_folder(option: str, name, what: str) -> Path:
    """The folder ``name`` to write into (made later if missing), checked now.

    It must not be a file nor lie below one, and the folder itself or, when missing, its
    nearest existing parent must be writable by this process. Raises :class:`ValidationError`
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
            break
    return path
