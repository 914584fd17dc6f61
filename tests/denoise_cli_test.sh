#!/usr/bin/env bash
# --denoise, pt merge --denoise and pt denoise as a user meets them: layers and metadata of a
# denoised file, pt diff reading its raw estimate, and each way the input or the library is wrong.
# Skipped (77) where OIDN is not installed, unless PT_REQUIRE_OIDN is set (CI sets it).
# usage: denoise_cli_test.sh PT
set -uo pipefail
pt=$1
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
source "$root/tests/expect_lib.sh"
channels() { oiiotool --info -v "$1" | grep "channel list" | sed 's/.*channel list: //'; }
meta() { oiiotool --info -v "$1" | grep "$2" | head -1; }
scene="$root/scenes/glass.obj"
small=(-spp 4 --res 48x36 -q)

# Without the library: a usage error before anything is loaded or written.
PT_OIDN_LIBRARY=$tmp/none.so expect 2 "tools/install-oidn" "$pt" render "$scene" "${small[@]}" --denoise -o "$tmp/x.exr"
[[ -e $tmp/x.exr ]] && { echo "FAIL: a render refused for its library left $tmp/x.exr"; failures=$((failures + 1)); }
PT_OIDN_LIBRARY=$tmp/none.so expect 2 "which does not exist" "$pt" denoise "$tmp/x.exr" -o "$tmp/y.exr"
libz=$(ldconfig -p | awk '/libz.so.1 /{print $NF; exit}')
PT_OIDN_LIBRARY=$libz expect 1 "is not Intel Open Image Denoise 2.x" "$pt" render "$scene" "${small[@]}" --denoise -o "$tmp/x.exr"
# A damaged library is refused with its name before dlopen, whose loader would otherwise touch
# the missing bytes and die of SIGBUS: the library cut short, or whole beside a core or device
# library cut short (laid out as tools/install-oidn lays them out, in a lib folder), a FIFO, a
# loop of links. In each command that opens it.
oidn=$root/.deps/oidn-2.5.1/lib
if [[ -f $oidn/libOpenImageDenoise.so.2.5.1 ]]; then
  for cut in main core device; do
    mkdir -p "$tmp/$cut/lib"
    cp "$oidn"/libOpenImageDenoise*.so.2.5.1 "$tmp/$cut/lib/"
    ln -s libOpenImageDenoise.so.2.5.1 "$tmp/$cut/lib/libOpenImageDenoise.so.2"
  done
  truncate -s 62000 "$tmp/main/lib/libOpenImageDenoise.so.2.5.1"
  truncate -s 4096 "$tmp/core/lib/libOpenImageDenoise_core.so.2.5.1"
  truncate -s 4096 "$tmp/device/lib/libOpenImageDenoise_device_cpu.so.2.5.1"
  mkfifo "$tmp/fifo.so"
  ln -s loop_b.so "$tmp/loop_a.so"
  ln -s loop_a.so "$tmp/loop_b.so"
  "$pt" render "$scene" "${small[@]}" --aov albedo,normal -o "$tmp/lib_in.exr" >/dev/null
  "$pt" render "$scene" "${small[@]}" --aov albedo,normal --samples 0:2 -o "$tmp/lib_part.exr" >/dev/null
  for lib in main core device; do
    file=$tmp/$lib/lib/libOpenImageDenoise.so.2
    want="is damaged (cut short?)"
    PT_OIDN_LIBRARY=$file expect 1 "$want" "$pt" render "$scene" "${small[@]}" --denoise -o "$tmp/lib_out.exr"
    PT_OIDN_LIBRARY=$file expect 1 "$want" "$pt" denoise "$tmp/lib_in.exr" -o "$tmp/lib_out.exr"
    PT_OIDN_LIBRARY=$file expect 1 "$want" "$pt" merge "$tmp/lib_part.exr" --denoise -o "$tmp/lib_out.exr"
  done
  PT_OIDN_LIBRARY=$tmp/fifo.so expect 1 "is not a regular file" timeout 20 "$pt" denoise "$tmp/lib_in.exr" -o "$tmp/lib_out.exr"
  PT_OIDN_LIBRARY=$tmp/loop_a.so expect 1 "is a loop of symbolic links" "$pt" denoise "$tmp/lib_in.exr" -o "$tmp/lib_out.exr"
  [[ -e $tmp/lib_out.exr ]] && { echo "FAIL: a refused library left $tmp/lib_out.exr"; failures=$((failures + 1)); }
fi
expect 2 "a part is denoised only once merged" "$pt" render "$scene" "${small[@]}" --denoise --samples 0:2 -o "$tmp/x.exr"

if ! "$pt" render "$scene" "${small[@]}" --denoise -o "$tmp/d.exr" 2>"$tmp/err.txt"; then
  if grep -q "tools/install-oidn" "$tmp/err.txt" && [[ -z ${PT_REQUIRE_OIDN:-} ]]; then
    echo "skipped: $(cat "$tmp/err.txt")"
    exit 77
  fi
  echo "FAIL: render --denoise: $(cat "$tmp/err.txt")"
  exit 1
fi
[[ $(channels "$tmp/d.exr") == "R, G, B, noisy.R, noisy.G, noisy.B" ]] || { echo "FAIL: channels $(channels "$tmp/d.exr")"; failures=$((failures + 1)); }
meta "$tmp/d.exr" "pt:denoiser" | grep -q "OIDN 2.5.1 RT, quality high, albedo and normal prefiltered" ||
  { echo "FAIL: pt:denoiser: $(meta "$tmp/d.exr" pt:denoiser)"; failures=$((failures + 1)); }
expect 0 "denoised in" "$pt" render "$scene" -spp 4 --res 48x36 --denoise --aov albedo,normal,variance -o "$tmp/da.exr"
expect 0 "-> $tmp/d.png" "$pt" render "$scene" "${small[@]}" --denoise -o "$tmp/d.png"

# pt diff compares the raw estimate: the denoised render and a plain one of the same seed agree exactly.
"$pt" render "$scene" -spp 4 --res 48x36 -q --aov albedo,normal,variance -o "$tmp/raw.exr" >/dev/null
expect 0 "is denoised; comparing its raw estimate" "$pt" diff "$tmp/da.exr" "$tmp/raw.exr"
expect 0 "relative MSE 0," "$pt" diff "$tmp/da.exr" "$tmp/raw.exr"

# pt denoise: from the feature layers; again from a denoised file's raw estimate, to the same picture.
expect 0 "pt denoise: 48x36" "$pt" denoise "$tmp/raw.exr" -o "$tmp/pd.exr"
# Its metadata is written back with the types it was read with: OpenImageIO's debug output (on
# wherever OPENIMAGEIO_DEBUG is set) said OpenEXR threw on every pt denoise before.
OPENIMAGEIO_DEBUG=1 "$pt" denoise "$tmp/raw.exr" -o "$tmp/pd_debug.exr" >/dev/null 2>"$tmp/debug.txt"
grep -q "OIIO DEBUG" "$tmp/debug.txt" && { echo "FAIL: pt denoise made OpenImageIO complain: $(head -2 "$tmp/debug.txt")"; failures=$((failures + 1)); }
expect 0 "was denoised already" "$pt" denoise "$tmp/pd.exr" -o "$tmp/pd2.exr"
expect 0 "relative MSE 0," "$pt" diff "$tmp/pd.exr" "$tmp/da.exr"
python3 "$root/tests/compare_exact.py" "$tmp/pd.exr" "$tmp/pd2.exr" >/dev/null 2>&1 ||
  oiiotool "$tmp/pd.exr" --ch R,G,B "$tmp/pd2.exr" --ch R,G,B --diff >/dev/null ||
  { echo "FAIL: denoising a denoised file again changed the picture"; failures=$((failures + 1)); }
"$pt" render "$scene" "${small[@]}" --aov albedo -o "$tmp/alb.exr" >/dev/null
"$pt" render "$scene" "${small[@]}" -o "$tmp/plain.exr" >/dev/null
expect 1 "has no albedo layer (albedo.R, albedo.G, albedo.B)" "$pt" denoise "$tmp/plain.exr" -o "$tmp/y.exr"
expect 1 "has no normal layer (normal.X, normal.Y, normal.Z)" "$pt" denoise "$tmp/alb.exr" -o "$tmp/y.exr"
# Channels are read by name: a file without an R, G, B picture is refused, naming what it has,
# never denoised from its albedo; a channel beside R, G, B (A) is kept as it was.
features=albedo.R,albedo.G,albedo.B,normal.X,normal.Y,normal.Z
oiiotool "$tmp/raw.exr" --ch $features -o "$tmp/ch_none.exr"
oiiotool "$tmp/raw.exr" --ch beauty.R=R,beauty.G=G,beauty.B=B,$features -o "$tmp/ch_layer.exr"
oiiotool "$tmp/raw.exr" --ch Y=R,$features -o "$tmp/ch_y.exr"
oiiotool "$tmp/raw.exr" --ch R,G,$features -o "$tmp/ch_rg.exr"
oiiotool "$tmp/raw.exr" --ch R,G,B,A=0.5,$features -o "$tmp/ch_rgba.exr"
expect 1 "has no R, G or B channel (its channels: albedo.R" "$pt" denoise "$tmp/ch_none.exr" -o "$tmp/y.exr"
expect 1 "has no R, G or B channel (its channels: albedo.R, albedo.G, albedo.B, beauty.R" "$pt" denoise "$tmp/ch_layer.exr" -o "$tmp/y.exr"
expect 1 "has a grey picture (Y) and no R, G, B channels" "$pt" denoise "$tmp/ch_y.exr" -o "$tmp/y.exr"
expect 1 "has R and G but no B" "$pt" denoise "$tmp/ch_rg.exr" -o "$tmp/y.exr"
expect 2 "has no R, G or B channel" "$pt" diff "$tmp/ch_none.exr" "$tmp/raw.exr"
expect 0 "pt denoise: 48x36" "$pt" denoise "$tmp/ch_rgba.exr" -o "$tmp/rgba.exr"
[[ $(channels "$tmp/rgba.exr") == "R, G, B, A, albedo.R, albedo.G, albedo.B, noisy.R, noisy.G, noisy.B, normal.X, normal.Y, normal.Z" ]] ||
  { echo "FAIL: pt denoise of R, G, B, A wrote $(channels "$tmp/rgba.exr")"; failures=$((failures + 1)); }
oiiotool "$tmp/rgba.exr" --ch A --printstats 2>/dev/null | grep -q "Max: 0.500000" ||
  { echo "FAIL: the A channel did not come through pt denoise as it was"; failures=$((failures + 1)); }
expect 2 "expected high, balanced or fast" "$pt" denoise "$tmp/raw.exr" --quality best -o "$tmp/y.exr"
[[ -e $tmp/y.exr ]] && { echo "FAIL: a refused pt denoise left $tmp/y.exr"; failures=$((failures + 1)); }

# A split render is denoised once merged, from the parts' first-hit sums.
"$pt" render "$scene" "${small[@]}" --aov albedo,normal --samples 0:2 -o "$tmp/p0.exr" >/dev/null
"$pt" render "$scene" "${small[@]}" --aov albedo,normal --samples 2:4 -o "$tmp/p1.exr" >/dev/null
expect 0 "denoised in" "$pt" merge "$tmp/p0.exr" "$tmp/p1.exr" --denoise -o "$tmp/m.exr"
expect 0 "relative MSE 0," "$pt" diff "$tmp/m.exr" "$tmp/d.exr"
expect 1 "is a part of a split render" "$pt" denoise "$tmp/p0.exr" -o "$tmp/y.exr"
"$pt" render "$scene" "${small[@]}" --samples 0:2 -o "$tmp/q0.exr" >/dev/null
expect 1 "has no first-hit sums; --denoise" "$pt" merge "$tmp/q0.exr" --denoise -o "$tmp/y.exr"

# A signal at any moment of pt denoise: what it prints is what happened. OUT holds an old file;
# "nothing was written" must leave it, and a replaced OUT must be said to be written whole
# (before, 3 in 60 signals in the last ~20 ms replaced OUT and said nothing was written).
# SIGTERM: a background job's SIGINT is ignored. The signals fall from 0.6 to 1.1 times the
# shortest of three whole runs after the start, where the output is written.
took=999999999 # microseconds
for i in 1 2 3; do
  start=$(date +%s%N)
  "$pt" denoise "$tmp/raw.exr" -o "$tmp/sig.exr" -q >/dev/null
  t=$((($(date +%s%N) - start) / 1000))
  ((t < took)) && took=$t
done
lies=0
for i in $(seq 1 40); do
  echo old >"$tmp/sig.exr"
  "$pt" denoise "$tmp/raw.exr" -o "$tmp/sig.exr" -q >/dev/null 2>"$tmp/sig.txt" &
  pid=$!
  sleep "$(awk -v t="$took" -v i="$i" 'BEGIN { printf "%.6f", t * (0.6 + 0.5 * i / 40) / 1e6 }')"
  kill -TERM $pid 2>/dev/null
  wait $pid
  status=$?
  replaced=$([[ $(head -c 3 "$tmp/sig.exr") == old ]] && echo no || echo yes)
  if grep -q "nothing was written" "$tmp/sig.txt" && [[ $replaced == yes ]]; then lies=$((lies + 1)); fi
  if grep -q "written whole" "$tmp/sig.txt" && [[ $replaced == no ]]; then lies=$((lies + 1)); fi
  if [[ $status -eq 0 && $replaced == no ]]; then lies=$((lies + 1)); fi
done
[[ $lies -eq 0 ]] || { echo "FAIL: $lies of 40 interrupted pt denoise runs said other than what they did"; failures=$((failures + 1)); }

# An interrupted --denoise render writes its raw partial, never a denoised one.
"$pt" render "$scene" -spp 100000 --res 256x256 --threads 1 --denoise -q -o "$tmp/long.exr" &
pid=$!
sleep 2
kill -TERM $pid
wait $pid
[[ -e $tmp/long.partial.exr && ! -e $tmp/long.exr ]] || { echo "FAIL: no partial after an interrupt"; failures=$((failures + 1)); }
if [[ -e $tmp/long.partial.exr ]] && oiiotool --info -v "$tmp/long.partial.exr" | grep -q "pt:denoiser\|noisy"; then
  echo "FAIL: the partial of an interrupted --denoise render is denoised"
  failures=$((failures + 1))
fi

if [[ $failures -ne 0 ]]; then
  echo "$failures check(s) failed"
  exit 1
fi
echo "all denoise command-line checks passed"
