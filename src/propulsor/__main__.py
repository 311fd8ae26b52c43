"""``python -m propulsor …``: the command line (:mod:`propulsor.cli`)."""

import sys

from .cli import main

sys.exit(main())
