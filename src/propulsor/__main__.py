"""``python -m propulsor …``: the command line (:mod:`propulsor.cli`)."""

import sys

from .collector import tune

tune()  # as the ``propulsor`` program (cli.run)

from .cli import main  # noqa: E402

sys.exit(main())
