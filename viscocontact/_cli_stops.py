"""What the command line does when it is stopped: Ctrl-C (one line saying what is kept, exit
130), a reader that closes the pipe early (quiet), and ``-v`` (the package's log on stderr)."""
from __future__ import annotations

import contextlib
import os
import sys
from typing import Iterator

PROG = "viscocontact"


class Interrupted(Exception):
    """Ctrl-C during a command; the message says what is kept (exit code 130)."""


@contextlib.contextmanager
def kept_on_interrupt(kind: str, out) -> Iterator[None]:
    """Turn Ctrl-C during a study into :class:`Interrupted` saying what the file keeps and how
    to go on (each finished point is in the file as soon as it is back)."""
    try:
        yield
    except KeyboardInterrupt:
        if not out.exists():
            raise Interrupted(f"interrupted before {out} was written") from None
        raise Interrupted(f"interrupted: the points finished so far are kept in {out}; go on "
                          f"with: {PROG} {kind} --resume --out {out}") from None


@contextlib.contextmanager
def verbose(on: bool) -> Iterator[None]:
    """``-v``: the package's INFO records (solve events as they happen) on stderr."""
    if not on:
        yield
        return
    import logging

    log = logging.getLogger("viscocontact")
    handler = logging.StreamHandler(sys.stderr)
    handler.setFormatter(logging.Formatter(f"{PROG}: %(message)s"))
    level = log.level
    log.addHandler(handler)
    log.setLevel(logging.INFO)
    try:
        yield
    finally:
        log.removeHandler(handler)
        log.setLevel(level)


def quiet_stdout() -> None:
    """After a closed pipe: point stdout at the null device, so that the interpreter's final
    flush of what is left does not fail again (Python's documented idiom for SIGPIPE)."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):   # no real stdout (captured): nothing to flush
        pass
