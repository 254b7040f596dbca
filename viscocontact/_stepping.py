"""Step control of a continuation that retries a failed step with a shorter one."""
from __future__ import annotations

from typing import Callable


def march(attempt: Callable[[float], bool | None], *, smallest: float,
          most: int) -> tuple[bool, int]:
    """Advance a fraction ``t`` of the way from 0 to 1: ``attempt(t)`` tries to reach ``t``
    from the last ``t`` reached and returns True (reached), False (not reached: the step is
    halved) or None (stop). The first step is half the way, a step after one that succeeded
    doubles (up to the rest of the way), and the march gives up below ``smallest`` or after
    ``most`` attempts. Returns ``(reached 1, attempts made)``."""
    done, step, attempts = 0.0, 0.5, 0
    while attempts < most and step >= smallest:
        to = min(done + step, 1.0)
        attempts += 1
        verdict = attempt(to)
        if verdict is None:
            return False, attempts
        if not verdict:
            step *= 0.5
            continue
        if to >= 1.0:
            return True, attempts
        done, step = to, min(2.0 * step, 1.0 - to)
    return False, attempts
