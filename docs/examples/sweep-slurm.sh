#!/bin/bash
# A cuelab-cli sweep as a Slurm array job: task K of N prints shard K/N (docs/analysis.md).
#   mkdir -p logs && sbatch docs/examples/sweep-slurm.sh      then   cat out/shard-*.jsonl > sweep.jsonl
# Arguments, when given, replace the sweep below (SETUP and its options, without --shard and --jobs):
#   sbatch --array=1-4 docs/examples/sweep-slurm.sh shot.json --vary shot.heading=-1:1:9 --goal pot:1
#SBATCH --job-name=cuelab-sweep
#SBATCH --array=1-100
#SBATCH --cpus-per-task=8
#SBATCH --time=01:00:00
#SBATCH --output=logs/%x-%A_%a.err
set -euo pipefail
N=${SLURM_ARRAY_TASK_COUNT:-100}
K=${SLURM_ARRAY_TASK_ID}
if [ $# -gt 0 ]; then
  sweep=("$@")
else
  sweep=(cut.json
         --vary shot.heading=-3:3:1000 --vary shot.speed=1:4:100 --vary shot.side=-0.4:0.4:100
         --goal pot:1@pocket-tr,no-scratch)
fi
mkdir -p out
cuelab-cli sweep "${sweep[@]}" --shard "${K}/${N}" --jobs "${SLURM_CPUS_PER_TASK:-1}" > "out/shard-${K}.jsonl"
