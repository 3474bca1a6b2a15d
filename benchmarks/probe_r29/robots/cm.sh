#!/bin/bash
# critmoment CLI from the r29 snapshot
PYTHONPATH=/tmp/r29/src exec /work/venv/bin/python -c "import sys; from critmoment.cli import run; sys.argv[0]='critmoment'; sys.exit(run())" "$@"
