#!/usr/bin/env bash
# Split renders merge into exactly the image one process renders (issue 14): sample ranges, crops,
# both together, with every AOV; and an interrupted render resumed. Each merged image is held to
# the single render per pixel and channel to 1e-6 relative (tests/compare_exact.py).
# usage: split_merge_test.sh PT
set -uo pipefail
pt=$(realpath "$1")
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
source "$root/tests/stop_part_way.sh"
fail=0
exact() { # NAME MERGED SINGLE
  if /usr/bin/python3 "$root/tests/compare_exact.py" "$2" "$3" >"$1.log"; then echo "ok   $1: $(cat "$1.log")"
  else echo "FAIL $1: $(cat "$1.log")"; fail=1; fi
}
run() { "$@" >/dev/null || { echo "FAIL: $*"; fail=1; }; }

# textured.obj: texture footprints follow the job's -spp, so a part that got them from its own
# range would differ.
scene=$root/scenes/textured.obj
common=(-spp 12 --res 48x36 --aov variance,albedo,normal,depth -q)
run "$pt" render "$scene" "${common[@]}" -o single.exr

# The SIMD kernels (AVX2 where the CPU has it, SSE2 forced by PT_SIMD) and one thread give the
# same image.
run env PT_SIMD=sse2 "$pt" render "$scene" "${common[@]}" --threads 1 -o sse2.exr
exact sse2_one_thread sse2.exr single.exr

run "$pt" render "$scene" "${common[@]}" --samples 0:5 -o r0.exr
run "$pt" render "$scene" "${common[@]}" --samples 5:12 -o r1.exr
run "$pt" merge r0.exr r1.exr --aov variance,albedo,normal,depth -q -o ranges.exr
exact ranges ranges.exr single.exr

run "$pt" render "$scene" "${common[@]}" --crop 0,0,48,20 -o c0.exr
run "$pt" render "$scene" "${common[@]}" --crop 0,20,48,36 -o c1.exr
run "$pt" merge c1.exr c0.exr --aov variance,albedo,normal,depth -q -o crops.exr
exact crops crops.exr single.exr

run "$pt" render "$scene" "${common[@]}" --crop 0,0,30,20 --samples 0:7 -o b0.exr
run "$pt" render "$scene" "${common[@]}" --crop 0,0,30,20 --samples 7:12 -o b1.exr
run "$pt" render "$scene" "${common[@]}" --crop 30,0,48,36 -o b2.exr
run "$pt" render "$scene" "${common[@]}" --crop 0,20,30,36 --samples 0:12 -o b3.exr
run "$pt" merge b0.exr b1.exr b2.exr b3.exr --aov variance,albedo,normal,depth -q -o both.exr
exact ranges_and_crops both.exr single.exr

# A gap is reported, and the image holds what there is.
"$pt" merge r1.exr -o gap.exr 2>gap.err >/dev/null
if grep -q "hold fewer than the job's 12 samples (the fewest 7); no whole-image part holds samples 0:5" gap.err; then
  echo "ok   gap reported"; else echo "FAIL gap: $(cat gap.err)"; fail=1; fi

# Interrupted and resumed: the partial of a render stopped by SIGTERM, finished by --resume,
# equals the render that was never stopped.
# resumed_exactly NAME SCENE [render options...]: stops `render SCENE` part-way into NAME.exr,
# resumes it, and holds it to the render never stopped.
resumed_exactly() {
  local name=$1 scene=$2 status
  shift 2
  stop_part_way "$pt" "$name.exr" "$scene" "$@"
  status=$?
  if [[ $status -eq 143 && -f $name.partial.exr && ! -f $name.exr ]]; then
    run "$pt" render "$scene" "$@" --resume "$name.partial.exr" -o "$name.exr"
    run "$pt" render "$scene" "$@" -o "${name}_never_stopped.exr"
    exact "${name}_resumed" "$name.exr" "${name}_never_stopped.exr"
    # Its samples are in NAME.exr now: the partial is gone, so a merge of the folder cannot count them twice.
    [[ ! -e $name.partial.exr ]] || { echo "FAIL $name resume: $name.partial.exr is still there"; fail=1; }
  elif [[ $status -eq 0 ]]; then
    echo "FAIL $name resume: the render finished within a second; this test needs it to be stopped part-way"; fail=1
  else
    echo "FAIL $name resume: exit status $status, partial $(ls "$name.partial.exr" 2>&1)"; fail=1
  fi
}
# 512 spp takes a few seconds on 2 cores.
resumed_exactly whole "$root/scenes/cornell_box.obj" -spp 512 --res 64x48 --aov variance -q
# Interrupted during the first pass (issue 35: nothing was kept, though the README promised half
# the work): the tiles finished are in the partial (pt:spp 0, pt:sppMax 1), the others hold no
# sample, and --resume finishes it into the image never stopped. One thread makes the first pass
# of 1536x1536 take about 6 s here, so each of stop_part_way's signals lands inside it.
first=(-spp 2 --res 1536x1536 --aov variance -q)
stop_part_way "$pt" early.exr "$root/scenes/cornell_box.obj" "${first[@]}" --threads 1
status=$?
if [[ $status -eq 143 && -f early.partial.exr && $(meta early.partial.exr pt:spp) == 0 && $(meta early.partial.exr pt:sppMax) == 1 ]]; then
  echo "ok   first pass interrupted: partial holds $(meta early.partial.exr pt:sppMean) samples a pixel on average"
  run "$pt" render "$root/scenes/cornell_box.obj" "${first[@]}" --resume early.partial.exr -o early.exr
  run "$pt" render "$root/scenes/cornell_box.obj" "${first[@]}" -o early_never_stopped.exr
  exact resumed_from_first_pass early.exr early_never_stopped.exr
else
  echo "FAIL first pass interrupted: exit status $status, partial $(ls early.partial.exr 2>&1), pt:spp $(meta early.partial.exr pt:spp 2>&1)"; fail=1
fi

# Path guiding (issue 38): every part learns the same guide from the whole image's first samples,
# keeping those of its own share, before it renders the rest of its share; so guided parts merge
# exactly, on any thread count (samples 0:5 are training's, 5:16 both training's and the
# render's), and a guided render stopped and resumed equals the one never stopped.
gscene=$root/scenes/glass.obj
guided=(-spp 16 --res 48x36 --aov variance -q --guide --guide-spp 7)
run "$pt" render "$gscene" "${guided[@]}" -o gsingle.exr
run "$pt" render "$gscene" "${guided[@]}" --threads 1 -o gone.exr
exact guided_one_thread gone.exr gsingle.exr
run "$pt" render "$gscene" "${guided[@]}" --samples 0:5 -o g0.exr
run "$pt" render "$gscene" "${guided[@]}" --samples 5:16 -o g1.exr
run "$pt" merge g0.exr g1.exr --aov variance -q -o granges.exr
exact guided_ranges granges.exr gsingle.exr
run "$pt" render "$gscene" "${guided[@]}" --crop 0,0,48,20 -o gc0.exr
run "$pt" render "$gscene" "${guided[@]}" --crop 0,20,48,36 --threads 1 -o gc1.exr
run "$pt" merge gc0.exr gc1.exr --aov variance -q -o gcrops.exr
exact guided_crops gcrops.exr gsingle.exr
# A part guided otherwise (or not at all) is another job: the merge refuses it, naming the field.
run "$pt" render "$gscene" -spp 16 --res 48x36 --aov variance -q --samples 5:16 -o plain1.exr
if "$pt" merge g0.exr plain1.exr -q -o mixed.exr 2>mixed.err >/dev/null; then
  echo "FAIL guided and unguided parts merged"; fail=1
elif grep -q "pt:guideSpp" mixed.err; then echo "ok   guided and unguided parts refused: $(head -c 160 mixed.err)"
else echo "FAIL guided and unguided parts: $(cat mixed.err)"; fail=1; fi
resumed_exactly guided "$gscene" -spp 512 --res 64x48 --aov variance -q --guide --guide-spp 15
exit $fail
