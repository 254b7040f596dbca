"""Contact sets: validity of an edge vector, merging, detaching, birth from interpenetration.

Edges are kept sorted, ``[X_1 < X_2 < X_3 < ...]``, within one period window starting at
``origin`` (the left edges lie in ``[origin, origin + 2π)``); the last contact may extend past the
window end but never reaches the first contact's left edge plus 2π.
"""
from __future__ import annotations

import numpy as np

TWO_PI = 2.0 * np.pi


class TopologyChange(Exception):
    """Raised inside a residual evaluation when the edge vector is no longer a valid contact set.

    ``edges`` is the repaired set (merged, detached) to restart from; ``full_contact`` is True
    when contacts closed over the whole period.
    """

    def __init__(self, reason: str, edges: np.ndarray, full_contact: bool = False):
        super().__init__(reason)
        self.reason = reason
        self.edges = np.asarray(edges, dtype=float)
        self.full_contact = full_contact


def repair(edges: np.ndarray, min_width: float, min_gap: float):
    """Merge touching/overlapping contacts and drop vanishing ones.

    Returns ``(edges, changed, reason, full_contact)``.
    """
    e = np.asarray(edges, dtype=float).copy()
    pairs = [[e[2 * j], e[2 * j + 1]] for j in range(len(e) // 2)]
    reasons = []
    # detach contacts that vanished (or turned inside out)
    kept = [p for p in pairs if p[1] - p[0] > min_width]
    if len(kept) < len(pairs):
        reasons.append(f"{len(pairs) - len(kept)} contact(s) detached")
    pairs = sorted(kept, key=lambda p: p[0])
    # merge overlapping neighbours
    merged: list[list[float]] = []
    for p in pairs:
        if merged and p[0] - merged[-1][1] <= min_gap:
            merged[-1][1] = max(merged[-1][1], p[1])
            reasons.append("contacts merged")
        else:
            merged.append(list(p))
    # across the period
    if len(merged) > 1 and merged[0][0] + TWO_PI - merged[-1][1] <= min_gap:
        last = merged.pop()
        merged[0] = [last[0], max(merged[0][1] + TWO_PI, last[1])]
        merged = [merged[0]] + merged[1:]
        merged.sort(key=lambda p: p[0])
        reasons.append("contacts merged across the period")
    full = any(p[1] - p[0] >= TWO_PI - min_gap for p in merged) or (
        len(merged) == 1 and merged[0][1] - merged[0][0] >= TWO_PI - min_gap)
    if full:
        reasons.append("contact closed over the period")
    out = np.array([v for p in merged for v in p], dtype=float)
    changed = bool(reasons) or out.shape != e.shape or full
    return out, changed, "; ".join(dict.fromkeys(reasons)), full


def negative_regions(x: np.ndarray, gap: np.ndarray, tol: float):
    """Intervals ``[a, b]`` of the sorted sample points where ``gap < -tol`` (zero crossings
    interpolated linearly)."""
    neg = gap < -tol
    out = []
    i = 0
    n = len(x)
    while i < n:
        if not neg[i]:
            i += 1
            continue
        j = i
        while j + 1 < n and neg[j + 1]:
            j += 1
        a = x[i] if i == 0 else x[i - 1] + (x[i] - x[i - 1]) * gap[i - 1] / (gap[i - 1] - gap[i])
        b = x[j] if j == n - 1 else x[j] + (x[j + 1] - x[j]) * gap[j] / (gap[j] - gap[j + 1])
        out.append((float(a), float(b), float(gap[i:j + 1].min())))
        i = j + 1
    return out


def expanded(edges: np.ndarray, factor: float = 0.5) -> np.ndarray:
    """Every contact widened outward by ``factor`` times its half-width (a jump guess)."""
    e = np.asarray(edges, dtype=float).copy()
    half = 0.5 * (e[1::2] - e[0::2])
    e[0::2] -= factor * half
    e[1::2] += factor * half
    return e
