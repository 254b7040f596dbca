"""``python -m viscocontact``: the command line, as the ``viscocontact`` script."""
import sys

from .cli import main

sys.exit(main())
