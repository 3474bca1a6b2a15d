#!/bin/bash
PYTHONPATH=/tmp/r32/src exec nice -n 5 /work/venv/bin/python -c "import sys; import critmoment; assert critmoment.__file__.startswith('/tmp/r32/src'); from critmoment.cli import run; sys.argv[0]='critmoment'; sys.exit(run())" "$@"
