#!/usr/bin/env bash
# Slurm job array: vertex normals for every mesh listed in a file, one array task per chunk of
# CHUNK files, each task one shadetool call over its chunk (-j uses the task's cores).
#
#   ls meshes/*.obj > meshes.txt
#   n=$(wc -l < meshes.txt); sbatch --array=0-$(( (n + 99) / 100 - 1 )) examples/normals-slurm-array.sh meshes.txt out/
#
#SBATCH --job-name=shadetool-normals
#SBATCH --cpus-per-task=4
#SBATCH --mem=4G
#SBATCH --time=00:30:00
#SBATCH --output=shadetool-%A_%a.jsonl
set -euo pipefail
list=$1 out_dir=$2
chunk=${CHUNK:-100}
task=${SLURM_ARRAY_TASK_ID:-0}
mkdir -p "$out_dir"
mapfile -t files < <(tail -n +$(( task * chunk + 1 )) "$list" | head -n "$chunk")
[ "${#files[@]}" -gt 0 ] || exit 0
exec "${SHADETOOL:-shadetool}" normals "${files[@]}" --output-dir "$out_dir" --format ply \
  -j "${SLURM_CPUS_PER_TASK:-1}" --json --quiet
