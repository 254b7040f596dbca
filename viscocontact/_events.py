"""Solve events logged as they happen, so that a long solve reports its progress while it runs.

A method records what happens in a solve (a contact born, contacts merged, a grid refined) in
an event list that ends in the result's ``extras["events"]``; an :class:`EventList` is such a
list that also logs each event at INFO on the ``viscocontact.solve`` logger when it is added,
with the seconds since the solve began (``viscocontact -v solve`` shows them on stderr).
"""
from __future__ import annotations

import logging
import time

#: The logger of solve events (INFO, as they happen) and of unconverged solves (WARNING).
logger = logging.getLogger("viscocontact.solve")


class EventList(list):
    """A list of event texts that logs each one as it is appended (``method: [t s] text``)."""

    def __init__(self, method: str, events=()):
        super().__init__(events)
        self.method = method
        self.started = time.perf_counter()

    def append(self, text) -> None:
        if logger.isEnabledFor(logging.INFO):
            logger.info("%s: [%.1f s] %s", self.method, time.perf_counter() - self.started, text)
        super().append(text)

    def __reduce__(self):       # pickled (a study's worker processes) as the plain list it holds
        return list, (list(self),)
