#!/bin/bash
# usage: runq.sh NAME...  (2 in parallel); trajectory: v/NAME/traj.npz, else aloha_s0.npz / panda_s0.npz by prefix
cd "$(dirname "$0")"
for n in "$@"; do
  if [ -f v/$n/traj.npz ]; then t=v/$n/traj.npz; elif [[ $n == a_* ]]; then t=aloha_s0.npz; else t=panda_s0.npz; fi
  echo "v/$n $t"
done | xargs -P 2 -L 1 ./run1.sh > /dev/null 2>&1
