#!/bin/bash
PYTHONPATH=/tmp/r34/src exec taskset -c 0 /work/venv/bin/python -c "import critmoment,sys; assert critmoment.__file__.startswith('/tmp/r34/src'); from critmoment.cli import main; sys.argv[0]='critmoment'; sys.exit(main())" "$@"
