#!/bin/bash
# critmoment CLI from the snapshot /tmp/r35/src, pinned to core 0
exec taskset -c 0 env PYTHONPATH=/tmp/r35/src /work/venv/bin/python -c "
import sys, critmoment
assert critmoment.__file__.startswith('/tmp/r35/src'), critmoment.__file__
from critmoment.cli import main; sys.exit(main(sys.argv[1:]))" "$@"
