#!/bin/bash
PYTHONPATH=/tmp/r38/tasks/src exec taskset -c 0 /work/venv/bin/python -m critmoment.cli "$@"
