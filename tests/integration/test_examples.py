"""The example scripts run and write what they promise."""
import runpy
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_fig_2_12_writes_png(tmp_path, monkeypatch):
    out = tmp_path / "fig.png"
    monkeypatch.setattr(sys, "argv", ["fig_2_12_green_function.py", "--out", str(out)])
    runpy.run_path(str(ROOT / "examples" / "fig_2_12_green_function.py"), run_name="__main__")
    assert out.stat().st_size > 10_000
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
