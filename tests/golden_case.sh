#!/usr/bin/env bash
# One golden-image case from golden/manifest.txt: render it at the test sample count with pt
# render, then compare with its reference using pt diff. Exit 77 (skipped) if the scene is absent.
# usage: golden_case.sh PT NAME OUT_DIR      (PT_GOLDEN_SEED overrides the seed, to probe flakiness)
set -uo pipefail
pt=$1 name=$2 out=$3
root=$(cd "$(dirname "$0")/.." && pwd)
line=$(awk -v n="$name" '$1 == n' "$root/golden/manifest.txt")
if [[ -z "$line" ]]; then echo "golden: no case $name in golden/manifest.txt"; exit 1; fi
read -r _ scene camera res _ test_spp reference extra <<< "$line"
[[ "$reference" == "-" ]] && reference=$name
if [[ ! -f "$root/$scene" ]]; then
  echo "golden: SKIPPED $name: $scene not found (the lab's scenes are expected in ../shared/scenes/lab)"
  exit 77
fi
mkdir -p "$out"
cd "$root" || exit 1 # paths among the options (--env MAP) are relative to the repository root
# shellcheck disable=SC2086
"$pt" render "$root/$scene" --camera "$camera" --res "$res" -spp "$test_spp" --seed "${PT_GOLDEN_SEED:-1}" \
  --aov variance -q $extra -o "$out/$name.exr" || exit 1
"$pt" diff "$out/$name.exr" "$root/golden/$reference.exr" --heatmap "$out/$name.heat.png" --json "$out/$name.json"
