#!/usr/bin/env bash
# The pt command line as a user meets it: exit statuses, messages, output files and layers.
# usage: cli_test.sh PT
set -uo pipefail
pt=$1
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0

# expect STATUS TEXT command...: the command exits with STATUS and prints TEXT (stdout or stderr).
expect() {
  local status=$1 text=$2
  shift 2
  local output
  output=$("$@" 2>&1)
  local got=$?
  if [[ $got -ne $status || "$output" != *"$text"* ]]; then
    echo "FAIL: $* -> exit $got (expected $status), output:"
    echo "$output" | head -5
    echo "  (expected to contain: $text)"
    failures=$((failures + 1))
  fi
}

scene="$root/scenes/cornell_box.obj"
expect 0 "usage: pt <command>" "$pt" --help
expect 0 "--max-depth D" "$pt" render --help
expect 0 "--alpha A" "$pt" diff --help
expect 2 "usage: pt <command>" "$pt"
expect 2 "unknown command" "$pt" paint
expect 2 "missing the SCENE argument" "$pt" render
expect 2 "unknown option \"bogus\"" "$pt" render "$scene" --bogus
expect 2 "option --spp: 0 is out of range" "$pt" render "$scene" -spp 0
expect 2 "option --spp: expected an integer, got \"many\"" "$pt" render "$scene" --spp many
expect 2 "option --res: expected WIDTHxHEIGHT" "$pt" render "$scene" --res 512
expect 2 "unknown extension \".tiff\"" "$pt" render "$scene" -o "$tmp/out.tiff"
expect 2 "does not exist" "$pt" render "$scene" -o "$tmp/no/such/dir/out.exr"
expect 2 "--aov needs an .exr output" "$pt" render "$scene" --aov variance -o "$tmp/out.png"
expect 2 "no such camera" "$pt" render "$scene" --camera Nowhere -o "$tmp/out.exr"
expect 1 "cannot open" "$pt" render "$tmp/missing.obj" -o "$tmp/out.exr"
[[ -e "$tmp/out.exr" ]] && { echo "FAIL: a failed render left $tmp/out.exr"; failures=$((failures + 1)); }

expect 0 "16x16, 4 spp" "$pt" render "$scene" -spp 4 --res 16x16 --aov variance,albedo,normal,depth -o "$tmp/a.exr"
channels=$(oiiotool --info -v "$tmp/a.exr" | grep "channel list")
for c in R G B variance.R albedo.G normal.Z depth.Z; do
  [[ "$channels" == *"$c"* ]] || { echo "FAIL: $c missing from $channels"; failures=$((failures + 1)); }
done
expect 0 "16x16, 4 spp" "$pt" render "$scene" -spp 4 --res 16x16 --camera Front -o "$tmp/a.png"

expect 0 "the images agree" "$pt" diff "$tmp/a.exr" "$tmp/a.exr" --heatmap "$tmp/heat.png" --json "$tmp/d.json"
[[ -s "$tmp/heat.png" && -s "$tmp/d.json" ]] || { echo "FAIL: heatmap or JSON missing"; failures=$((failures + 1)); }
expect 2 "cannot read" "$pt" diff "$tmp/missing.exr" "$tmp/a.exr"
"$pt" render "$scene" -spp 4 --res 8x8 --aov variance -q -o "$tmp/small.exr" >/dev/null
expect 2 "size mismatch" "$pt" diff "$tmp/small.exr" "$tmp/a.exr"
oiiotool "$tmp/a.exr" --mulc 1.5 -o "$tmp/bright.exr"
expect 1 "the images DIFFER" "$pt" diff "$tmp/bright.exr" "$tmp/a.exr"
expect 2 "expected TEST and REFERENCE" "$pt" diff "$tmp/a.exr"

if [[ $failures -gt 0 ]]; then
  echo "$failures command-line checks failed"
  exit 1
fi
echo "all command-line checks passed"
