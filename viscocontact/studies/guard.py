"""Guards of a study file against faults: one writer at a time, no write cut short by a signal.

* :func:`exclusive` — while a study is computed into ``s.h5`` its process holds an OS lock
  (``flock``; ``msvcrt.locking`` on Windows) on the lock file ``s.h5.lock`` next to it. A second
  process that would compute into the same file (``--resume``, ``--force``, or a new study)
  stops at once with :class:`~viscocontact.studies.StudyFileError` naming the process that holds
  it. The OS drops the lock when the holder dies, so the lock file a killed run leaves behind is
  harmless; the next run takes it over and removes it when it ends. Readers (``load_study``,
  ``viscocontact plot``) take no lock.
* :func:`signals_deferred` — ``SIGINT``, ``SIGTERM`` and ``SIGHUP`` that arrive while a point is
  appended are held until the append has finished and the file is closed, then delivered as
  usual, so a terminated study leaves a consistent file that includes the point being written.
  ``SIGKILL`` cannot be held: a kill in the middle of an append leaves the rows of that point
  uncounted (ignored, and overwritten on resume; see :mod:`~viscocontact.studies.storage`).
"""
from __future__ import annotations

import contextlib
import os
import signal
import sys
import threading
from pathlib import Path
from types import ModuleType
from typing import Iterator

fcntl: ModuleType | None
try:
    import fcntl
except ImportError:  # pragma: no cover - Windows
    fcntl = None

#: Signals held during an append (those that exist on this platform).
HELD_SIGNALS = tuple(getattr(signal, name) for name in ("SIGINT", "SIGTERM", "SIGHUP")
                     if hasattr(signal, name))


def lock_path(path) -> Path:
    """The lock file of study file ``path`` (``s.h5`` -> ``s.h5.lock``)."""
    path = Path(path)
    return path.with_name(path.name + ".lock")


def _try_lock(fd: int) -> bool:
    if fcntl is not None:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            return False
        return True
    if sys.platform != "win32":  # pragma: no cover - neither fcntl nor msvcrt: no guard
        return True
    try:  # pragma: no cover - Windows
        import msvcrt

        msvcrt.locking(fd, msvcrt.LK_NBLCK, 1)
    except ImportError:  # pragma: no cover - neither: no guard
        return True
    except OSError:  # pragma: no cover
        return False
    return True  # pragma: no cover


def _holder(lock: Path) -> str:
    try:
        text = lock.read_text(encoding="utf-8").strip()
    except OSError:
        text = ""
    return f"process {text}" if text.isdigit() else "another process"


@contextlib.contextmanager
def exclusive(path) -> Iterator[None]:
    """Hold the lock of study file ``path`` for the block (see the module docstring).

    Raises
    ------
    StudyFileError
        Another process holds the lock (it is computing into the same file), or the lock file
        cannot be created.
    """
    from ..errors import StudyFileError

    lock = lock_path(path)
    while True:
        try:
            fd = os.open(lock, os.O_RDWR | os.O_CREAT, 0o644)
        except OSError as exc:
            raise StudyFileError(f"cannot create the lock file {lock} of {path}: "
                                 f"{exc.strerror or exc}") from exc
        if not _try_lock(fd):
            os.close(fd)
            raise StudyFileError(
                f"{path} is being computed by {_holder(lock)} (it holds {lock}); two processes "
                "must not write one study file: wait for it to end, or stop it and use --resume")
        try:  # the previous holder may have removed the file between our open and our lock
            same = os.path.samestat(os.fstat(fd), os.stat(lock))
        except OSError:
            same = False
        if same:
            break
        os.close(fd)
    try:
        os.ftruncate(fd, 0)
        os.write(fd, str(os.getpid()).encode())
        yield
    finally:
        with contextlib.suppress(OSError):  # removed while still held: no one can take it
            os.unlink(lock)                  # over between the unlink and the close
        os.close(fd)


@contextlib.contextmanager
def signals_deferred() -> Iterator[None]:
    """Hold :data:`HELD_SIGNALS` during the block and deliver them after it.

    Acts in the main thread only (Python runs signal handlers there); elsewhere the block runs
    unguarded. A handler installed by the caller is restored, and a held signal then reaches it.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    held: list[int] = []
    previous = {}
    for signum in HELD_SIGNALS:
        try:
            previous[signum] = signal.signal(signum, lambda s, frame: held.append(s))
        except (OSError, ValueError):  # pragma: no cover - not settable here
            continue
    try:
        yield
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, signal.SIG_DFL if handler is None else handler)
        for signum in dict.fromkeys(held):
            signal.raise_signal(signum)
