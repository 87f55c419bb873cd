"""`python -m ttsgc`: the same as the `ttsgc` command."""

import sys

from ttsgc.cli import main

sys.exit(main())
