"""The package's size limits: no class over 300 lines and no function or method over 80, so that
each piece does one job. ``data/bench/peer_fft.py`` is exempt: it is a shipped copy of an
independent FFT code, the benchmarks' reference, kept as its authors wrote it."""
import ast
from pathlib import Path

import viscocontact

PACKAGE = Path(viscocontact.__file__).parent
EXEMPT = {PACKAGE / "data" / "bench" / "peer_fft.py"}
CLASS_LINES, FUNCTION_LINES = 300, 80


def _sizes():
    for path in sorted(PACKAGE.rglob("*.py")):
        if path in EXEMPT:
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, (ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)):
                yield path.relative_to(PACKAGE), node, node.end_lineno - node.lineno + 1


def test_no_class_over_300_lines_and_no_function_over_80():
    over = [f"{path}:{node.lineno} {node.name} ({n} lines)" for path, node, n in _sizes()
            if n > (CLASS_LINES if isinstance(node, ast.ClassDef) else FUNCTION_LINES)]
    assert not over, over
