#!/bin/bash
# critmoment CLI from the snapshot /tmp/r33/src
exec env PYTHONPATH=/tmp/r33/src /work/venv/bin/python -c "
import sys, critmoment
assert critmoment.__file__.startswith('/tmp/r33/src'), critmoment.__file__
from critmoment.cli import run; sys.argv[0]='critmoment'; sys.exit(run())" "$@"
