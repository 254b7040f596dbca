"""Run the benchmark suite: ``python benchmarks/run.py [viscocontact bench options]``.

The same as ``viscocontact bench``, with ``--suite`` defaulting to this folder so that it works
from any working directory.
"""
import sys
from pathlib import Path

from viscocontact.cli import main

if __name__ == "__main__":
    argv = sys.argv[1:]
    if not any(a == "--suite" or a.startswith("--suite=") for a in argv):
        argv = ["--suite", str(Path(__file__).resolve().parent), *argv]
    sys.exit(main(["bench", *argv]))
