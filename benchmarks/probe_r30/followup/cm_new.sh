#!/bin/bash
PYTHONPATH=/tmp/r30b/src exec /work/venv/bin/python -c "import sys; import critmoment; assert critmoment.__file__.startswith('/tmp/r30b/src'), critmoment.__file__; from critmoment.cli import run; sys.argv[0]='critmoment'; sys.exit(run())" "$@"
