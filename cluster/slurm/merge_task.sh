#!/usr/bin/env bash
# The merge job of cluster/slurm/submit: runs after every render task succeeded.
#   merge_task.sh PARTS T OUT [pt merge options...]
set -euo pipefail
parts=$1 tasks=$2 out=$3
shift 3
files=()
for ((i = 0; i < tasks; i++)); do files+=("$(printf '%s/part-%04d.exr' "$parts" "$i")"); done
exec "${PT:-pt}" merge "${files[@]}" "$@" -o "$out"
