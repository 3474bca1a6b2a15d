#!/bin/bash
# critmoment CLI from the r38 snapshot, pinned to core 1
PYTHONPATH=/tmp/r38/robots/src exec taskset -c 1 /work/venv/bin/python -c "import sys; import critmoment; assert critmoment.__file__.startswith('/tmp/r38/robots/src'), critmoment.__file__; from critmoment.cli import run; sys.argv[0]='critmoment'; sys.exit(run())" "$@"
