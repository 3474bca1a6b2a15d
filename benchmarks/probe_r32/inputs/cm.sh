#!/bin/bash
PYTHONPATH=/tmp/r32/src exec /work/venv/bin/python -c "import sys, critmoment; assert critmoment.__file__.startswith('/tmp/r32/src'), critmoment.__file__; from critmoment.cli import run; sys.argv[0]='critmoment'; sys.exit(run())" "$@"
