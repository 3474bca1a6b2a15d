#!/bin/bash
# critmoment CLI from the r33 snapshot
PYTHONPATH=/tmp/r33/src exec /work/venv/bin/python -c "import sys; import critmoment; assert critmoment.__file__.startswith('/tmp/r33/src'), critmoment.__file__; from critmoment.cli import run; sys.argv[0]='critmoment'; sys.exit(run())" "$@"
