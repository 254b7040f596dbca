"""JSON output: strict (RFC 8259) text, with ``null`` for every non-finite number.

Python's :func:`json.dumps` writes ``NaN`` and ``Infinity`` by default, which no strict reader
(``jq``, JavaScript's ``JSON.parse``, most languages' libraries) accepts. Everything viscocontact
writes as JSON goes through :func:`dumps`: NaN and ±inf become ``null`` (a friction coefficient
without contact, an infinite gap without contact), numpy scalars and arrays become numbers and
lists.
"""
from __future__ import annotations

import enum
import json
import math
from typing import Any, Mapping


def plain(value: Any) -> Any:
    """``value`` as JSON-ready Python data, with ``None`` for non-finite floats."""
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return value
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, int):
        return value
    if isinstance(value, enum.Enum):
        return plain(value.value)
    if isinstance(value, Mapping):
        return {str(k): plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if hasattr(value, "tolist"):        # numpy scalars and arrays, without importing numpy
        return plain(value.tolist())
    return value                        # json.dumps rejects what it cannot write


def dumps(value: Any, **options: Any) -> str:
    """Strict JSON text of ``value`` (``options`` go to :func:`json.dumps`: ``indent``,
    ``ensure_ascii``, ...)."""
    return json.dumps(plain(value), allow_nan=False, **options)
