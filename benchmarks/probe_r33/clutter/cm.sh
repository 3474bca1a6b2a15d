#!/bin/bash
# the CLI from the snapshot /tmp/r33/src2
PYTHONPATH=/tmp/r33/src2 exec taskset -c 1 /work/venv/bin/python -c "import sys; from critmoment.cli import run; sys.argv[0]='critmoment'; sys.exit(run())" "$@"
