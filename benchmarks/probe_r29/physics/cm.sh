#!/bin/bash
PYTHONPATH=/tmp/r29/src exec nice -n 5 /work/venv/bin/python -c "import sys; from critmoment.cli import run; sys.argv[0]='critmoment'; sys.exit(run())" "$@"
