#!/bin/bash
# critmoment CLI from the r37 snapshot, pinned to core 1
PYTHONPATH=/tmp/r37/src exec taskset -c 1 /work/venv/bin/python -c "import sys; import critmoment; assert critmoment.__file__.startswith('/tmp/r37/src'), critmoment.__file__; from critmoment.cli import run; sys.argv[0]='critmoment'; sys.exit(run())" "$@"
