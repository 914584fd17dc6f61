#!/usr/bin/env bash
# Time budgets and adaptive sampling (issue 27): --time stops at a pass boundary and gives the
# image of -spp N for the N it reached; --noise gives the same image on any --threads, each pixel
# between --min-spp and -spp samples; adaptive crops merge; an interrupted adaptive render resumed
# equals the one never stopped.
# usage: adaptive_test.sh PT
set -uo pipefail
pt=$(realpath "$1")
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
source "$root/tests/stop_part_way.sh"
fail=0
ok() { echo "ok   $*"; }
bad() { echo "FAIL $*"; fail=1; }
exact() { # NAME A B
  if /usr/bin/python3 "$root/tests/compare_exact.py" "$2" "$3" >"$1.log"; then ok "$1: $(cat "$1.log")"
  else bad "$1: $(cat "$1.log")"; fi
}
run() { "$@" >/dev/null || bad "$*"; }
# sppstats FILE: fewest, most and mean of the spp layer.
sppstats() {
  /usr/bin/python3 -c "
import OpenImageIO as o,sys
b=o.ImageBuf(sys.argv[1]); s=b.spec(); n=list(s.channelnames).index('spp.Z')
p=b.get_pixels(o.FLOAT)[:,:,n]; print(int(p.min()), int(p.max()), float(p.mean()))" "$1"
}
scene=$root/scenes/cornell_box.obj

# --time: stops by itself, within the budget and a pass, at a whole number of samples per pixel
# that -spp N reproduces.
run "$pt" render "$scene" --res 64x48 --time 2 --aov spp -q -o timed.exr
n=$(meta timed.exr pt:spp) seconds=$(meta timed.exr pt:renderSeconds) out=$(meta timed.exr pt:outOfTime)
read -r lo hi _ < <(sppstats timed.exr)
if [[ $lo == "$n" && $hi == "$n" && $n -ge 2 && $out == 1 ]] && /usr/bin/python3 -c "import sys; sys.exit(not float('$seconds') <= 2.5)"; then
  ok "time: $n spp in $seconds s of a 2 s budget"
else bad "time: spp $lo..$hi (pt:spp $n), $seconds s, pt:outOfTime $out"; fi
run "$pt" render "$scene" --res 64x48 -spp "$n" --aov spp -q -o fixed.exr
exact time_equals_spp timed.exr fixed.exr
# A cap reached before the time runs out ends the render there.
run "$pt" render "$scene" --res 16x16 --time 600 -spp 8 -q -o capped.exr
[[ $(meta capped.exr pt:spp) == 8 && $(meta capped.exr pt:outOfTime) == 0 ]] && ok "time: -spp caps it" || bad "time cap"

# --noise: the same image on one thread and on two, SSE2 and AVX2.
adaptive=(--res 64x48 --noise 0.05 --min-spp 8 -spp 256 --aov spp,variance -q)
run "$pt" render "$scene" "${adaptive[@]}" -o noise2.exr
run env PT_SIMD=sse2 "$pt" render "$scene" "${adaptive[@]}" --threads 1 -o noise1.exr
exact noise_threads noise1.exr noise2.exr
read -r lo hi mean < <(sppstats noise2.exr)
converged=$(meta noise2.exr pt:converged)
if [[ $lo -ge 8 && $hi -le 256 && $lo -lt $hi && $converged -gt 0 ]]; then
  ok "noise: $lo to $hi spp per pixel (mean $mean), $converged of 3072 pixels converged"
else bad "noise: spp $lo..$hi, converged $converged"; fi
# Each pixel holds samples 0 .. n-1: one that stopped at n equals -spp n there. The light's pixels
# (flat white, no variance) stop at --min-spp.
run "$pt" render "$scene" --res 64x48 -spp 8 -q -o eight.exr
/usr/bin/python3 - noise2.exr eight.exr <<'PY' && ok "noise: pixels that stopped at 8 equal -spp 8" || bad "noise: pixels that stopped at 8 differ from -spp 8"
import OpenImageIO as o, sys, numpy as np
a = o.ImageBuf(sys.argv[1]); b = o.ImageBuf(sys.argv[2])
names = list(a.spec().channelnames)
pa, pb = a.get_pixels(o.FLOAT), b.get_pixels(o.FLOAT)
at8 = pa[:, :, names.index("spp.Z")] == 8
print(f"{int(at8.sum())} pixels at 8 spp")
sys.exit(not (at8.sum() > 0 and np.allclose(pa[at8][:, :3], pb[at8][:, :3], rtol=1e-6, atol=0)))
PY

# Crops of an adaptive render, each adaptive over its own pixels, merge without a "fewer samples" warning.
run "$pt" render "$scene" "${adaptive[@]}" --crop 0,0,64,20 -o c0.exr
run "$pt" render "$scene" "${adaptive[@]}" --crop 0,20,64,48 -o c1.exr
if "$pt" merge c0.exr c1.exr --aov spp -o merged.exr 2>merge.err >/dev/null && [[ ! -s merge.err ]]; then
  ok "noise: crops merge quietly"; else bad "noise crops: $(cat merge.err)"; fi

# The merge says what pt render says of pixels that differ (issue 35: it wrote the fewest as
# pt:spp alone and "8 of 256 spp in every pixel"): pt:sppMax, pt:sppMean, pt:converged and the range.
"$pt" merge c0.exr c1.exr -o merged_meta.exr > merge.out 2>&1
read -r lo hi mean < <(sppstats merged.exr)
c0=$(meta c0.exr pt:converged) c1=$(meta c1.exr pt:converged)
if [[ $(meta merged_meta.exr pt:spp) == "$lo" && $(meta merged_meta.exr pt:sppMax) == "$hi" && $lo -lt $hi &&
      $(meta merged_meta.exr pt:converged) == $((c0 + c1)) ]] && grep -q "$lo to $hi of 256 spp (mean" merge.out &&
   grep -q "$((c0 + c1)) of 3072 pixels converged" merge.out &&
   /usr/bin/python3 -c "import sys; sys.exit(not abs(float('$(meta merged_meta.exr pt:sppMean)') - $mean) < 1e-3)"; then
  ok "noise: merged crops record $lo to $hi spp (mean $mean), $((c0 + c1)) converged"
else bad "noise merge metadata: $(cat merge.out); pt:spp $(meta merged_meta.exr pt:spp) pt:sppMax $(meta merged_meta.exr pt:sppMax) pt:converged $(meta merged_meta.exr pt:converged)"; fi

# pt diff weighs each pixel by its own count, so an adaptive render's variance layer comes with its
# spp layer even where --aov does not name it; an image whose pixels differ without that layer is
# refused (exit 2) rather than compared as if every pixel held the fewest.
run "$pt" render "$scene" --res 64x48 --noise 0.05 --min-spp 8 -spp 256 --aov variance -q -o var_only.exr
channels=$(/usr/bin/python3 -c "import OpenImageIO as o,sys; print(','.join(o.ImageInput.open(sys.argv[1]).spec().channelnames))" var_only.exr)
[[ $channels == *spp.Z* ]] && ok "noise: --aov variance brings the spp layer ($channels)" || bad "noise: --aov variance wrote $channels"
oiiotool var_only.exr --ch R,G,B,variance.R,variance.G,variance.B -o no_counts.exr
got=$("$pt" diff no_counts.exr var_only.exr 2>&1)
[[ $? -eq 2 && $got == *"no_counts.exr: its pixels hold different sample counts (pt:spp 8, pt:sppMax "*"no spp layer"* ]] &&
  ok "noise: pt diff refuses counts it cannot know" || bad "noise: pt diff without the spp layer: $got"

# Interrupted and resumed: equals the adaptive render never stopped.
long=(--res 64x48 --noise 0.004 --min-spp 16 -spp 2048 --aov spp -q)
stop_part_way "$pt" whole.exr "$scene" "${long[@]}"
status=$?
if [[ $status -eq 143 && -f whole.partial.exr ]]; then
  run "$pt" render "$scene" "${long[@]}" --resume whole.partial.exr -o whole.exr
  run "$pt" render "$scene" "${long[@]}" -o never_stopped.exr
  exact noise_resumed whole.exr never_stopped.exr
elif [[ $status -eq 0 ]]; then
  bad "noise resume: the render finished within a second; this test needs it stopped part-way"
else bad "noise resume: exit status $status"; fi
exit $fail
