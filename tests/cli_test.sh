#!/usr/bin/env bash
# The pt command line as a user meets it: exit statuses, messages, output files and layers.
# usage: cli_test.sh PT
set -uo pipefail
pt=$1
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0

source "$root/tests/expect_lib.sh"

scene="$root/scenes/cornell_box.obj"
expect 0 "usage: pt <command>" "$pt" --help
expect 0 "--max-depth D" "$pt" render --help
expect 0 "--alpha A" "$pt" diff --help
expect 2 "usage: pt <command>" "$pt"
expect 2 "unknown command" "$pt" paint
expect 2 "missing the SCENE argument" "$pt" render
expect 2 "unknown option \"--bogus\"" "$pt" render "$scene" --bogus
expect 2 "option -spp: 0 is out of range" "$pt" render "$scene" -spp 0
expect 2 "option --spp: expected an integer, got \"many\"" "$pt" render "$scene" --spp many
expect 2 "option --res: expected WIDTHxHEIGHT" "$pt" render "$scene" --res 512
expect 2 "unknown extension \".tiff\"" "$pt" render "$scene" -o "$tmp/out.tiff"
expect 2 "does not exist" "$pt" render "$scene" -o "$tmp/no/such/dir/out.exr"
expect 2 "--aov needs an .exr output" "$pt" render "$scene" --aov variance -o "$tmp/out.png"
# An option a material model ignores says so (issue 37): glTF's BRDF keeps cosine sampling.
expect 0 "--hemisphere uniform: 6 of the scene's 6 materials (glTF metallic-roughness) ignore it" \
  "$pt" render "$root/scenes/gltf/spheres.gltf" --hemisphere uniform --res 16x16 -spp 1 -o "$tmp/hemisphere.exr"
expect 2 "no such camera" "$pt" render "$scene" --camera Nowhere -o "$tmp/out.exr"
# Time budgets and adaptive sampling: each bad value a usage error, with nothing written.
expect 2 "option --time: expected a time in seconds above 0, got 0" "$pt" render "$scene" --time 0 -o "$tmp/out.exr"
expect 2 "option --time: -1 is out of range" "$pt" render "$scene" --time -1 -o "$tmp/out.exr"
expect 2 "option --time: expected a finite number, got \"nan\"" "$pt" render "$scene" --time nan -o "$tmp/out.exr"
expect 2 "option --time: 4e7 is out of range [0, 3.1536e+07]" "$pt" render "$scene" --time 4e7 -o "$tmp/out.exr"
expect 2 "option --noise: expected a relative error in [1e-4, 1), such as 0.02, got 0" "$pt" render "$scene" --noise 0 -o "$tmp/out.exr"
expect 2 "option --noise: expected a relative error in [1e-4, 1), such as 0.02, got 1" "$pt" render "$scene" --noise 1 -o "$tmp/out.exr"
# Issue 35: values below the floor were taken as off (1e-50 rounds to 0 in float) or stored as 0.
expect 2 "option --noise: expected a relative error in [1e-4, 1), such as 0.02, got 1e-50 (below 1e-4 no pixel stops" "$pt" render "$scene" --noise 1e-50 --min-spp 4 -o "$tmp/out.exr"
expect 2 "option --noise: expected a relative error in [1e-4, 1), such as 0.02, got 1e-40 (below 1e-4" "$pt" render "$scene" --noise 1e-40 -o "$tmp/out.exr"
expect 2 "got 9.99e-05 (below 1e-4" "$pt" render "$scene" --noise 9.99e-5 -o "$tmp/out.exr"
# The default --min-spp (16) follows a smaller -spp; a typed one above -spp is refused.
expect 0 "8x8, 8 spp" "$pt" render "$scene" --noise 0.1 -spp 8 --res 8x8 -o "$tmp/min_spp_follows.exr"
expect 2 "option --noise: 2 is out of range [0, 1]" "$pt" render "$scene" --noise 2 -o "$tmp/out.exr"
expect 2 "option --noise: expected a finite number" "$pt" render "$scene" --noise inf -o "$tmp/out.exr"
expect 2 "--min-spp 64 is above -spp 32" "$pt" render "$scene" --noise 0.02 --min-spp 64 -spp 32 -o "$tmp/out.exr"
expect 2 "--min-spp needs --noise" "$pt" render "$scene" --min-spp 4 -o "$tmp/out.exr"
# --guide (issue 38): its training budget needs it, and is bounded.
expect 2 "--guide-spp needs --guide" "$pt" render "$scene" --guide-spp 3 -o "$tmp/out.exr"
expect 2 "option --guide-spp: 0 is out of range [1, 1023]" "$pt" render "$scene" --guide --guide-spp 0 -o "$tmp/out.exr"
expect 2 "option --guide-spp: 2000 is out of range [1, 1023]" "$pt" render "$scene" --guide --guide-spp 2000 -o "$tmp/out.exr"
expect 0 "guided (learnt from 3 spp" "$pt" render "$scene" --guide --guide-spp 3 -spp 4 --res 16x16 -o "$tmp/guided.exr"
expect 2 "--guide-spp 1023 is above -spp 4" "$pt" render "$scene" --guide --guide-spp 1023 -spp 4 --res 16x16 -o "$tmp/guided.exr"
# Where its regions learn that guiding does not pay, training stops after 7 of its 63 spp.
expect 0 "guided (learnt from 7 spp, stopped there, guiding 0 % of bounces" \
  "$pt" render "$root/scenes/glass.obj" --guide --guide-spp 63 -spp 64 --res 64x64 -o "$tmp/guided.exr"
expect 2 "--noise decides per pixel from all of its samples" "$pt" render "$scene" --noise 0.02 --samples 0:8 -o "$tmp/out.exr"
expect 2 "unknown layer \"sp\"; known: variance, albedo, normal, depth, spp" "$pt" render "$scene" --aov sp -o "$tmp/out.exr"
expect 0 "--noise E" "$pt" render --help
expect 0 "--guide-spp N" "$pt" render --help
expect 0 "--time SECONDS" "$pt" render --help
expect 1 "cannot open" "$pt" render "$tmp/missing.obj" -o "$tmp/out.exr"
[[ -e "$tmp/out.exr" ]] && { echo "FAIL: a failed render left $tmp/out.exr"; failures=$((failures + 1)); }

expect 0 "16x16, 4 spp" "$pt" render "$scene" -spp 4 --res 16x16 --aov variance,albedo,normal,depth -o "$tmp/a.exr"
channels=$(oiiotool --info -v "$tmp/a.exr" | grep "channel list")
for c in R G B variance.R albedo.G normal.Z depth.Z; do
  [[ "$channels" == *"$c"* ]] || { echo "FAIL: $c missing from $channels"; failures=$((failures + 1)); }
done
# One sample has no variance estimate: the layer holds +inf (unknown) there, never 0 (certain),
# and pt diff refuses to compare it, naming the pixel.
expect 0 "8x8, 1 spp" "$pt" render "$scene" -spp 1 --res 8x8 --aov variance -o "$tmp/one.exr"
[[ $(oiiotool --stats "$tmp/one.exr" | grep InfCount) == *"0 0 0 64 64 64"* ]] ||
  { echo "FAIL: the variance of one sample: $(oiiotool --stats "$tmp/one.exr" | grep -E 'InfCount|Max')"; failures=$((failures + 1)); }
expect 2 "test image has no variance estimate (an infinite variance: a pixel of one sample; a variance needs two) at pixel (0, 0)" \
  "$pt" diff "$tmp/one.exr" "$tmp/one.exr"
expect 0 "16x16, 4 spp" "$pt" render "$scene" -spp 4 --res 16x16 --camera Front -o "$tmp/a.png"
expect 0 "8x8, 2 spp" "$pt" render "$scene" -spp 2 --res 8x8 --sky --sun-elevation 30 --sun-azimuth 250 --turbidity 4.5 --sky-scale 0.5 -o "$tmp/sky.exr"
"$pt" render "$scene" -spp 2 --res 8x8 --seed 3 -q -o "$tmp/ev0.exr" > /dev/null
expect 0 "8x8, 2 spp" "$pt" render "$scene" -spp 2 --res 8x8 --seed 3 --exposure 2 -o "$tmp/ev2.exr"
/usr/bin/python3 - "$tmp/ev0.exr" "$tmp/ev2.exr" <<'PY' || { echo "FAIL: --exposure 2 is not 4 times the image"; failures=$((failures + 1)); }
import sys, OpenImageIO as oiio, numpy as np
a, b = (oiio.ImageBuf(p).get_pixels(oiio.FLOAT)[:, :, :3] for p in sys.argv[1:3])
sys.exit(0 if np.allclose(b, 4 * a, rtol=1e-6, atol=1e-7) else 1)
PY
oiiotool --info -v "$tmp/ev2.exr" | grep -q "pt:exposure: 2" || { echo "FAIL: pt:exposure missing"; failures=$((failures + 1)); }
info=$(oiiotool --info -v "$tmp/sky.exr")
for attr in 'pt:environment: "preetham"' 'pt:sunElevation: 30' 'pt:sunAzimuth: 250' 'pt:turbidity: 4.5' 'pt:skyScale: 0.5'; do
  [[ "$info" == *"$attr"* ]] || { echo "FAIL: $attr missing from the sky render's metadata"; failures=$((failures + 1)); }
done

expect 0 "the images agree" "$pt" diff "$tmp/a.exr" "$tmp/a.exr" --heatmap "$tmp/heat.png" --json "$tmp/d.json"
[[ -s "$tmp/heat.png" && -s "$tmp/d.json" ]] || { echo "FAIL: heatmap or JSON missing"; failures=$((failures + 1)); }
expect 0 "HDR-FLIP 0.0000" "$pt" diff "$tmp/a.exr" "$tmp/a.exr"
grep -q '"flip_mean": 0,' "$tmp/d.json" || { echo "FAIL: flip_mean of identical images is not 0"; failures=$((failures + 1)); }
expect 2 "cannot read" "$pt" diff "$tmp/missing.exr" "$tmp/a.exr"
"$pt" render "$scene" -spp 4 --res 8x8 --aov variance -q -o "$tmp/small.exr" >/dev/null
expect 2 "size mismatch" "$pt" diff "$tmp/small.exr" "$tmp/a.exr"
oiiotool "$tmp/a.exr" --mulc 1.5 -o "$tmp/bright.exr"
expect 1 "the images DIFFER" "$pt" diff "$tmp/bright.exr" "$tmp/a.exr"
expect 2 "--ppd: 0 is out of range" "$pt" diff "$tmp/bright.exr" "$tmp/a.exr" --ppd 0
expect 2 "expected TEST and REFERENCE" "$pt" diff "$tmp/a.exr"
# A comparison that cannot fail must not pass: an image smaller than the blocks is tested whole.
"$pt" render "$scene" -spp 16 --res 4x4 --aov variance -q -o "$tmp/tiny.exr" >/dev/null
"$pt" render "$scene" -spp 16 --res 4x4 --max-depth 0 --aov variance -q -o "$tmp/tiny_lamp.exr" >/dev/null
expect 1 "the images DIFFER" "$pt" diff "$tmp/tiny_lamp.exr" "$tmp/tiny.exr"
expect 1 "its smallest blocks are 16 pixels a side (the whole image)" "$pt" diff "$tmp/bright.exr" "$tmp/a.exr" --block 4096

# --clamp bounds every sample, so every pixel mean, and says so in the summary.
expect 0 "clamped (--clamp biases the image)" "$pt" render "$scene" -spp 8 --res 32x32 --clamp 0.25 -o "$tmp/clamp.exr"
max=$(oiiotool --stats "$tmp/clamp.exr" | awk '/Stats Max/ {print ($3 > $4 ? ($3 > $5 ? $3 : $5) : ($4 > $5 ? $4 : $5)); exit}')
awk -v m="$max" 'BEGIN {exit !(m <= 0.25 + 1e-6)}' || { echo "FAIL: --clamp 0.25 left a pixel at $max"; failures=$((failures + 1)); }

# The progress line on a terminal: the sample count, and never wider than the terminal (30 here).
if command -v script > /dev/null; then
  script -qc "stty cols 30; '$pt' render '$scene' -spp 256 --res 96x96 -o '$tmp/progress.exr'" /dev/null > "$tmp/tty.txt" 2>&1
  segments=$(tr '\r' '\n' < "$tmp/tty.txt" | sed 's/\x1b\[K//g' | grep 'spp  ')
  [[ -n "$segments" ]] || { echo "FAIL: no progress line with the sample count: $(head -c 300 "$tmp/tty.txt")"; failures=$((failures + 1)); }
  widest=$(echo "$segments" | awk '{ if (length($0) > w) w = length($0) } END { print w + 0 }')
  [[ $widest -le 29 ]] || { echo "FAIL: a progress line is $widest columns on a 30-column terminal"; failures=$((failures + 1)); }
else
  echo "SKIP: progress line (no script command)"
fi

# SIGINT and SIGTERM: the render stops, the finished samples go to OUT.partial.EXT, OUT is untouched.
# Job control on: a script's background jobs otherwise start with SIGINT ignored, which pt
# respects, as a user's shell script would expect.
set -m
for sig in INT TERM; do
  cp "$tmp/a.exr" "$tmp/keep.exr"
  before=$(md5sum < "$tmp/keep.exr")
  "$pt" render "$scene" -spp 100000 --res 64x64 -q -o "$tmp/keep.exr" 2> "$tmp/stop.txt" &
  pid=$!
  sleep 3
  kill -$sig $pid
  wait $pid
  status=$?
  want=$([[ $sig == INT ]] && echo 130 || echo 143)
  [[ $status -eq $want ]] || { echo "FAIL: SIG$sig: exit $status, expected $want"; failures=$((failures + 1)); }
  grep -q "interrupted after" "$tmp/stop.txt" || { echo "FAIL: SIG$sig: $(cat "$tmp/stop.txt")"; failures=$((failures + 1)); }
  [[ "$(md5sum < "$tmp/keep.exr")" == "$before" ]] || { echo "FAIL: SIG$sig replaced the output"; failures=$((failures + 1)); }
  oiiotool --info -v "$tmp/keep.partial.exr" 2>/dev/null | grep -q 'pt:interrupted: 1' ||
    { echo "FAIL: SIG$sig: no partial image"; failures=$((failures + 1)); }
  rm -f "$tmp/keep.partial.exr"
done
set +m

if [[ $failures -gt 0 ]]; then
  echo "$failures command-line checks failed"
  exit 1
fi
echo "all command-line checks passed"
