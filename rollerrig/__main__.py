"""``python -m rollerrig``: the command line (rollerrig.cli)."""
import sys

from .cli import main

sys.exit(main())
