"""Exceptions and warnings raised by viscocontact.

Every error about user input is a :class:`ValidationError` whose message names the field, the
offending value and the allowed range, so that a scene file can be fixed without reading a traceback.
A computation stopped by a :func:`~viscocontact.deadline.deadline` raises
:class:`TimeLimitExceeded`. Warnings the user must see are subclasses of
:class:`ViscoContactWarning`, issued with :func:`warnings.warn` (filter them with the standard
:mod:`warnings` machinery).
"""
from __future__ import annotations

import contextlib
import contextvars
import sys
import warnings
from types import FrameType
from typing import Iterator


class ViscoContactError(Exception):
    """Base class of all viscocontact errors."""


class ValidationError(ViscoContactError, ValueError):
    """Bad input: the message names the field, the value and what is allowed.

    Parameters
    ----------
    field : str
        Dotted name of the field (``"rheology.beta"``).
    value : object
        The rejected value.
    allowed : str
        Human-readable description of the allowed values (``"> 1"``, ``"one of ['a', 'b']"``).
    """

    def __init__(self, field: str, value: object, allowed: str):
        self.field = field
        self.value = value
        self.allowed = allowed
        super().__init__(f"{field} = {value!r} is not allowed: expected {allowed}")


class PluginError(ViscoContactError, LookupError):
    """A component name is unknown, or its plugin failed to load."""


class ConvergenceError(ViscoContactError):
    """A solve did not converge; ``result`` holds the partial (unconverged) result."""

    def __init__(self, message: str, result: object = None):
        super().__init__(message)
        self.result = result


class TimeLimitExceeded(ViscoContactError):
    """A computation ran past the wall-time limit of an enclosing
    :func:`~viscocontact.deadline.deadline`.

    Parameters
    ----------
    seconds : float
        The limit that was reached (s).
    """

    def __init__(self, seconds: float):
        self.seconds = seconds
        super().__init__(f"time limit of {seconds:g} s reached")

    def __reduce__(self):  # pickles with its limit (process pools, Dask)
        return type(self), (self.seconds,)


class ViscoContactWarning(UserWarning):
    """Base class of the warnings viscocontact issues."""


class PluginWarning(ViscoContactWarning):
    """Two installed distributions register the same component name; one of them is ignored."""


class ModelValidityWarning(ViscoContactWarning):
    """The scene lies where an assumption of the model is doubtful (e.g. a Tabor parameter
    below 3: infinitely short-range adhesion does not hold)."""


class AccuracyWarning(ViscoContactWarning):
    """A converged result whose error estimate exceeds the tolerance asked for: the discrete
    equations are solved, but the discretisation error is larger than requested (the finest
    grid the plan allows was reached); ``extras["error_estimate"]`` gives it."""


def warn_accuracy(result) -> None:
    """An :class:`AccuracyWarning` when ``result`` converged without meeting its tolerance
    (``extras["tolerance_met"]`` false)."""
    if result.converged and result.extras.get("tolerance_met", True) is False:
        warn_user(f"{result.method or 'solve'}: {result.message}", AccuracyWarning)


class CertificationWarning(ViscoContactWarning):
    """A study point does not agree with the same point reached with a tenth of its history's
    tolerance (``Sweep(certify=True)``): it is not converged in the continuation's step."""


def _internal(frame) -> bool:
    """Whether a frame runs viscocontact's or attrs' code (``attrs.evolve``, generated
    ``__init__``)."""
    name = frame.f_globals.get("__name__") or ""
    return (name.partition(".")[0] in ("viscocontact", "attr", "attrs")
            or frame.f_code.co_filename.startswith("<attrs generated"))


#: The words a result's message carries when it lies outside the model (the reason follows).
OUTSIDE_MODEL = "outside the model"

#: The warnings that :func:`held` keeps in this context instead of showing: (categories, list).
_HELD: contextvars.ContextVar = contextvars.ContextVar("viscocontact_held", default=None)


@contextlib.contextmanager
def held(*categories: type[Warning]) -> Iterator[list[str]]:
    """Within the block, :func:`warn_user`'s warnings of ``categories`` are kept in the yielded
    list (their messages) instead of shown: a study stores a point's doubts in its record and
    says once how many points have them, rather than once per solve. Per thread and task (a
    context variable), so concurrent points keep their own."""
    kept: list[str] = []
    token = _HELD.set((categories, kept))
    try:
        yield kept
    finally:
        _HELD.reset(token)


def warn_user(message: str, category: type[Warning]) -> None:
    """``warnings.warn`` attributed to the first caller outside viscocontact and attrs, so that
    the warning names the user's line (and the default filter shows it once per line); kept
    instead within :func:`held` of its category."""
    holding = _HELD.get()
    if holding is not None and issubclass(category, holding[0]):
        holding[1].append(message)
        return
    level = 2
    frame: FrameType | None = sys._getframe(1)
    while frame is not None and _internal(frame):
        frame, level = frame.f_back, level + 1
    warnings.warn(message, category, stacklevel=level if frame is not None else 2)


class StudyFileError(ViscoContactError):
    """A study file that cannot be used: not HDF5, damaged, foreign, or of another study; an output
    path that cannot hold one; a file another process is computing into; a failed write."""
