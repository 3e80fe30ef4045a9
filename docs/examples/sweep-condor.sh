#!/bin/sh
# sweep-condor.sh PROCESS N: shard PROCESS+1 of N of a cuelab-cli sweep, for HTCondor (sweep.sub),
# whose $(Process) counts from 0. Uses the cores HTCondor granted (request_cpus).
set -eu
K=$(( $1 + 1 ))
exec cuelab-cli sweep cut.json --vary shot.heading=-3:3:1000 --vary shot.speed=1:4:100 \
    --goal pot:1@pocket-tr --shard "$K/$2" --jobs "${_CONDOR_NPROCS:-4}"
