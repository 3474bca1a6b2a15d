#!/bin/bash
# usage: runq.sh NAME...   runs run1.sh on each, one at a time
cd "$(dirname "$0")"
for n in "$@"; do ./run1.sh "$n"; done
