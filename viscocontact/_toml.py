"""A tiny TOML writer for scene files (reading uses the standard library's :mod:`tomllib`).

Writes what a scene needs and nothing more: top-level scalars, then tables (nested tables as
``[a.b]``) of strings, booleans, integers, floats (``repr`` precision, so that a round trip is
exact, with ``inf``/``nan`` spelt the TOML way) and (nested) lists of those. ``None`` values are
omitted, since TOML has no null.
"""
from __future__ import annotations

import json
import math
import re
from typing import Any, Mapping

import numpy as np

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(key: str) -> str:
    if not isinstance(key, str):
        raise TypeError(f"TOML keys must be strings, got {key!r}")
    return key if _BARE_KEY.match(key) else _string(key)


def _string(text: str) -> str:
    """A TOML basic string: JSON's escapes are TOML's, and DEL (U+007F), a control character
    that TOML forbids raw but JSON leaves as it is, is escaped too."""
    return json.dumps(text, ensure_ascii=False).replace("\x7f", "\\u007F")


def _value(value: Any) -> str:
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        v = float(value)
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(value, str):
        return _string(value)
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_value(v) for v in value if v is not None) + "]"
    raise TypeError(f"cannot write {type(value).__name__} value {value!r} to TOML")


def _is_table(value: Any) -> bool:
    return isinstance(value, Mapping)


def _write_table(lines: list[str], path: list[str], table: Mapping[str, Any]) -> None:
    scalars = [(k, v) for k, v in table.items() if not _is_table(v) and v is not None]
    tables = [(k, v) for k, v in table.items() if _is_table(v)]
    if path and (scalars or not tables):
        if lines:
            lines.append("")
        lines.append("[" + ".".join(_key(p) for p in path) + "]")
    for k, v in scalars:
        lines.append(f"{_key(k)} = {_value(v)}")
    for k, v in tables:
        _write_table(lines, path + [k], v)


def dumps(data: Mapping[str, Any]) -> str:
    """TOML text for a mapping of scalars and (nested) mappings of scalars and lists.

    Examples
    --------
    >>> print(dumps({"a": 1, "t": {"x": 0.1, "s": "hi", "l": [1.0, 2.5]}}), end="")
    a = 1
    <BLANKLINE>
    [t]
    x = 0.1
    s = "hi"
    l = [1.0, 2.5]
    """
    lines: list[str] = []
    _write_table(lines, [], data)
    return "\n".join(lines) + "\n"
