#!/bin/bash
# builds truth.py (probe_r31/tasks/truth.py with the snapshot's models path) beside this script
B=$(cd "$(dirname "$0")/../.." && pwd)
sed 's#/tmp/r31/src/models#/tmp/r38/tasks/src/models#' "$B/probe_r31/tasks/truth.py" > "$(dirname "$0")/truth.py"
# and ana_region.py from probe_r31/tasks's (only the snapshot path differs)
sed 's#/tmp/r31/src#/tmp/r38/tasks/src#' "$B/probe_r31/tasks/ana_region.py" > "$(dirname "$0")/ana_region.py"
