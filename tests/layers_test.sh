#!/usr/bin/env bash
# No include runs up the layers (issue 37). renderer/'s folders, lowest first; a file may include
# its own folder and any folder before it, never one after. docs/architecture.md explains the order.
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
layers=(core simd sampling io image texture environment scene obj gltf load accel material light guide denoise render)

rank() { local i; for i in "${!layers[@]}"; do [[ ${layers[$i]} == "$1" ]] && { echo "$i"; return; }; done; echo -1; }

bad=0 count=0
cd "$root/renderer"
for dir in */; do
  dir=${dir%/}
  r=$(rank "$dir")
  if [[ $r -lt 0 ]]; then echo "layers: renderer/$dir is not in the list of layers" >&2; bad=1; continue; fi
  while IFS=: read -r file line inc; do
    count=$((count + 1))
    target=${inc%%/*}
    [[ $inc == */* ]] || continue  # same folder
    t=$(rank "$target")
    if [[ $t -lt 0 ]]; then echo "renderer/$file:$line: includes $inc, not in a known layer" >&2; bad=1
    elif [[ $t -gt $r ]]; then echo "renderer/$file:$line: $dir includes $inc, a layer above it" >&2; bad=1; fi
  done < <(grep -Hn '^#include "' "$dir"/* | sed -E 's/^([^:]*):([0-9]*):#include "([^"]*)".*/\1:\2:\3/')
done
[[ $count -gt 100 ]] || { echo "layers: only $count includes found; is $root the repository?" >&2; exit 1; }
[[ $bad -eq 0 ]] || exit 1
echo "layers: $count includes in renderer/, none runs upward (${layers[*]})"
