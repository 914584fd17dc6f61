#!/usr/bin/env bash
# One task of cluster/slurm/submit's array job: samples [i N / T, (i + 1) N / T) of every pixel,
# i = SLURM_ARRAY_TASK_ID, into PARTS/part-i.exr. A partial left by an earlier attempt that
# Slurm stopped (preemption, time limit) is resumed, not started over.
#   render_task.sh PARTS N T SCENE [pt render options...]
set -euo pipefail
parts=$1 spp=$2 tasks=$3
shift 3
i=${SLURM_ARRAY_TASK_ID:?not run as a task of a Slurm array job}
first=$((i * spp / tasks))
last=$(((i + 1) * spp / tasks))
part=$(printf '%s/part-%04d.exr' "$parts" "$i")
partial=${part%.exr}.partial.exr
resume=()
[[ -f "$partial" ]] && resume=(--resume "$partial")
echo "task $i of $tasks: samples $first:$last on $(hostname) -> $part"
# exec: Slurm's SIGTERM reaches pt itself, which writes the partial before it exits.
exec "${PT:-pt}" render "$@" --samples "$first:$last" "${resume[@]}" -q -o "$part"
