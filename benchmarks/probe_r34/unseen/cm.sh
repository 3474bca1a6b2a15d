#!/bin/bash
# critmoment CLI from the r34 snapshot
PYTHONPATH=/tmp/r34/src exec /work/venv/bin/python -c "import sys; import critmoment; assert critmoment.__file__.startswith('/tmp/r34/src'), critmoment.__file__; from critmoment.cli import run; sys.argv[0]='critmoment'; sys.exit(run())" "$@"
