"""`python -m ttsgc`: the same as the `ttsgc` command. A warm server (`ttsgc serve`) is tried first, with the
standard library only; the command line is parsed and run here when none answers."""

import sys

from ttsgc.forward import forward

code = forward(sys.argv[1:])
if code is None:
    from ttsgc.cli import exit_process, main

    exit_process(main(sys.argv[1:]))
sys.exit(code)
