#!/bin/bash
# the critmoment CLI from the snapshot /tmp/r37/src, pinned to core 1
export PYTHONPATH=/tmp/r37/src
/work/venv/bin/python -c 'import critmoment,sys; assert critmoment.__file__.startswith("/tmp/r37/src"), critmoment.__file__' || exit 99
exec taskset -c 1 /work/venv/bin/python -m critmoment.cli "$@"
