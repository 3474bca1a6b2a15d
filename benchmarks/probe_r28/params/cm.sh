#!/bin/bash
# run the critmoment CLI from the read-only snapshot
PYTHONPATH=/tmp/r28/src exec /work/venv/bin/python -c "import sys; from critmoment.cli import run; sys.argv[0]='critmoment'; sys.exit(run())" "$@"
