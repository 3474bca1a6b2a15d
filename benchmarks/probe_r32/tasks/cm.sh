#!/bin/bash
PYTHONPATH=/tmp/r32/src exec /work/venv/bin/python -c "import sys; from critmoment.cli import run; sys.argv[0]='critmoment'; sys.exit(run())" "$@"
