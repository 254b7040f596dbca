"""Put the source tree's ``benchmarks/`` folder on ``sys.path`` (``peer_fft`` is a plain module)."""
import sys
from pathlib import Path

BENCHMARKS = Path(__file__).resolve().parents[3] / "benchmarks"
if str(BENCHMARKS) not in sys.path:
    sys.path.insert(0, str(BENCHMARKS))
