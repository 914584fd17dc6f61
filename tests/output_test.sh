#!/usr/bin/env bash
# What pt promises about the files it writes ("Nothing lost" in docs/rendering.md): a write that fails
# at any step says so, exits non-zero and leaves the old file as it was and no temporary file; an
# output that cannot be created fails before rendering; an output is never also an input; a
# second Ctrl-C leaves nothing half-written; links and file modes behave as documented.
# The full-disk cases need a small tmpfs (root); they are skipped with a message otherwise.
# usage: output_test.sh PT
set -uo pipefail
pt=$(realpath "$1")
root=$(cd "$(dirname "$0")/.." && pwd)
scene="$root/scenes/cornell_box.obj"
tmp=$(mktemp -d)
full="$tmp/full"
cleanup() {
  mountpoint -q "$full" 2>/dev/null && umount "$full"
  chmod -R u+w "$tmp" 2>/dev/null
  rm -rf "$tmp"
}
trap cleanup EXIT
cd "$tmp" || exit 1
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}
# No temporary output file may be left anywhere under the folder.
no_temporaries() {
  local left
  left=$(find "$1" -name '.*.tmp-*' -o -name '.pt-tmp-*' 2>/dev/null)
  [[ -z "$left" ]] || fail "$2: left a temporary file: $left"
}
render() { "$pt" render "$scene" -spp 2 --res 32x32 "$@"; }

"$pt" render "$scene" -spp 4 --res 32x32 --aov variance -q -o a.exr > /dev/null || fail "cannot render a.exr"
"$pt" render "$scene" -spp 4 --res 32x32 --aov variance --seed 1 -q -o b.exr > /dev/null || fail "cannot render b.exr"

# 1. A full file system: every format and every command fails, keeps the old file, leaves nothing.
mkdir "$full"
if [[ $(id -u) -eq 0 ]] && mount -t tmpfs -o size=64k tmpfs "$full" 2>/dev/null; then
  render -q -o "$full/good.png" > /dev/null
  render -q -o "$full/good.exr" > /dev/null
  dd if=/dev/zero of="$full/fill" bs=4k 2>/dev/null
  for ext in png exr; do
    before=$(md5sum < "$full/good.$ext")
    got=$(render --res 128x128 -o "$full/good.$ext" 2>&1)
    status=$?
    [[ $status -eq 1 && "$got" == *"No space left on device"* && "$got" == *"the existing file is unchanged"* ]] ||
      fail "full_disk_$ext: exit $status: $got"
    [[ "$got" == *"-> $full"* ]] && fail "full_disk_$ext: reported success"
    [[ "$(md5sum < "$full/good.$ext")" == "$before" ]] || fail "full_disk_$ext: the old file changed"
    got=$(render --res 128x128 -o "$full/new.$ext" 2>&1)
    [[ $? -eq 1 && ! -e "$full/new.$ext" ]] || fail "full_disk_new_$ext: $got"
  done
  got=$("$pt" diff a.exr b.exr --heatmap "$full/h.png" 2>&1)
  [[ $? -eq 2 && "$got" == *"--heatmap: writing"*"No space left"* && ! -e "$full/h.png" ]] || fail "full_disk_heatmap: $got"
  got=$("$pt" diff a.exr b.exr -q --json "$full/r.json" 2>&1)
  [[ $? -eq 2 && "$got" == *"--json: writing"*"No space left"* && ! -e "$full/r.json" ]] || fail "full_disk_json: $got"
  no_temporaries "$full" full_disk
  umount "$full"
else
  echo "SKIP: full-disk cases need root and a tmpfs mount"
fi

# 2. Outputs that cannot be created fail before any work (these renders would take minutes).
long=$(printf 'n%.0s' $(seq 1 300))
start=$(date +%s)
got=$(timeout 60 "$pt" render "$scene" -spp 100000 --res 512x512 -o "$long.exr" 2>&1)
[[ $? -eq 2 && "$got" == *"longer than the file system allows"* ]] || fail "name_too_long: $got"
got=$(timeout 60 "$pt" diff a.exr b.exr --json /nonexistent/r.json 2>&1)
[[ $? -eq 2 && "$got" == *'folder "/nonexistent" does not exist'* && "$got" != *agree* ]] || fail "diff_json_folder: $got"
(( $(date +%s) - start < 30 )) || fail "late_failure: refusing an output took $(( $(date +%s) - start )) s"
# A name that fits while its temporary name (".NAME.tmp-PID") would not still works.
name250=$(printf 'm%.0s' $(seq 1 250)).exr
render -q -o "$name250" > /dev/null || fail "name_250: a valid name was refused"
[[ -s "$name250" ]] || fail "name_250: no file"
no_temporaries . name_250

# 3. An output that is also an input: exit 2 before any work, the input untouched.
/usr/bin/python3 -c "
import struct, zlib
def chunk(t, d): return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d))
raw = b''.join(b'\0' + b'\x80\x40\x20' * 4 for _ in range(4))
open('tex.png', 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', 4, 4, 8, 2, 0, 0, 0))
                            + chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b''))"
printf 'newmtl T\nmap_Kd tex.png\nnewcamera C\ncameraposition 0.3 0.3 3\ncameratarget 0.3 0.3 0\n' > tex.mtl
printf 'mtllib tex.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl T\nf 1/1 2/2 3/3\n' > tex.obj
tex_before=$(md5sum < tex.png)
ln -s tex.png link_to_tex.png
for out in tex.png link_to_tex.png; do
  got=$("$pt" render tex.obj -spp 1 --res 8x8 -o "$out" 2>&1)
  [[ $? -eq 2 && "$got" == *"is also an input"* ]] || fail "output_is_texture ($out): $got"
done
[[ "$(md5sum < tex.png)" == "$tex_before" ]] || fail "output_is_texture: the texture changed"
a_before=$(md5sum < a.exr)
got=$("$pt" diff a.exr b.exr --json a.exr 2>&1)
[[ $? -eq 2 && "$got" == *"is also an input"* ]] || fail "diff_json_is_input: $got"
got=$("$pt" diff b.exr a.exr --heatmap b.exr 2>&1)
[[ $? -eq 2 ]] || fail "diff_heatmap_is_input: $got"
[[ "$(md5sum < a.exr)" == "$a_before" ]] || fail "diff_json_is_input: a.exr changed"
got=$("$pt" render a.exr -o a.exr 2>&1)
[[ $? -eq 2 && "$got" == *"is also an input"* ]] || fail "output_is_scene: $got"

# 4. pt diff refuses what would block or never end, and images that do not match.
mkfifo fifo.exr
got=$(timeout 20 "$pt" diff fifo.exr a.exr 2>&1)
[[ $? -eq 2 && "$got" == *"not a regular file"* ]] || fail "diff_fifo: $got"
got=$(timeout 20 "$pt" diff /dev/zero a.exr 2>&1)
[[ $? -eq 2 && "$got" == *"not a regular file"* ]] || fail "diff_dev_zero: $got"
render -q --aov variance,depth -o c.exr > /dev/null
got=$("$pt" diff c.exr a.exr 2>&1)
[[ $? -eq 2 && "$got" == *"different channels"* ]] || fail "diff_channels: $got"
oiiotool a.exr b.exr --siappend -o multi.exr 2>/dev/null
if [[ -s multi.exr ]]; then
  got=$("$pt" diff multi.exr a.exr 2>&1)
  [[ $? -eq 2 && "$got" == *"has 2 parts"* ]] || fail "diff_multipart: $got"
fi

# 5. Symbolic links are written through; modes of replaced files are kept; new files get the umask.
mkdir real
render -q -o real/target.exr > /dev/null
ln -s real/target.exr via_link.exr
render -q --seed 9 -o via_link.exr > /dev/null || fail "symlink: render through a link failed"
[[ -L via_link.exr && "$(readlink via_link.exr)" == real/target.exr ]] || fail "symlink: the link was replaced"
oiiotool --info -v real/target.exr | grep -q "pt:seed: 9" || fail "symlink: the target was not updated"
no_temporaries . symlink
ln -s real/missing.exr dangling.exr
got=$(render -o dangling.exr 2>&1)
[[ $? -eq 2 && "$got" == *"symbolic link to a missing file"* ]] || fail "dangling_symlink: $got"
render -q -o mode.exr > /dev/null && chmod 640 mode.exr
render -q -o mode.exr > /dev/null
[[ $(stat -c %a mode.exr) == 640 ]] || fail "mode: a replaced file's mode became $(stat -c %a mode.exr)"
(umask 027 && render -q -o newmode.exr > /dev/null)
[[ $(stat -c %a newmode.exr) == 640 ]] || fail "mode: a new file under umask 027 got $(stat -c %a newmode.exr)"

# 6. Metadata: numbers as numbers, every option that changes the image, the scene as given and resolved.
"$pt" render "$scene" -spp 3 --res 16x16 --seed 5 --max-depth 7 --sampler random --light-sampling nee \
  --hemisphere uniform --clamp 10 --threads 1 -q -o meta.exr > /dev/null
info=$(oiiotool --info -v meta.exr)
for want in 'pt:spp: 3' 'pt:sppRequested: 3' 'pt:seed: 5' 'pt:maxDepth: 7' 'pt:sampler: "random"' \
  'pt:lightSampling: "nee"' 'pt:hemisphere: "uniform"' 'pt:clamp: 10' 'pt:threadsRequested: 1' 'pt:threads: 1' \
  "pt:scene: \"$scene\"" "pt:sceneResolved: \"$scene\""; do
  [[ "$info" == *"$want"* ]] || fail "metadata: no $want"
done
[[ "$info" =~ pt:renderSeconds:\ [0-9.e-]+$'\n' ]] || fail "metadata: pt:renderSeconds is not a number"

# 7. Ctrl-C twice, the second while the partial image is being written: no temporary file is left,
# what happened is said, and any partial image that exists is whole.
set -m # job control: a script's background jobs otherwise start with SIGINT ignored
for delay in 0.00 0.02 0.05 0.1 0.2 4; do
  rm -f twice.partial.exr
  "$pt" render "$scene" -spp 100000 --res 1024x1024 --aov variance,albedo,normal,depth -q -o twice.exr 2> twice.txt &
  pid=$!
  sleep 2
  kill -INT $pid
  sleep $delay
  kill -INT $pid 2>/dev/null
  wait $pid
  status=$?
  [[ $status -eq 130 ]] || fail "second_sigint after $delay s: exit $status"
  grep -q -e "second signal" -e "interrupted" twice.txt || fail "second_sigint after $delay s: said nothing: $(cat twice.txt)"
  no_temporaries . "second_sigint after $delay s"
  [[ -e twice.exr ]] && fail "second_sigint after $delay s: wrote twice.exr"
  if [[ -e twice.partial.exr ]]; then
    oiiotool --info -v twice.partial.exr 2>/dev/null | grep -q "pt:interrupted: 1" ||
      fail "second_sigint after $delay s: twice.partial.exr is not a whole image"
  fi
done

# 8. A signal before rendering begins (a scene still loading) quits at once: nothing is written,
# no temporary file is left, and the message says the render never began (issue 24: pt went on
# loading and building the BVH, then said it was interrupted while rendering).
/usr/bin/python3 -c "
n = 1000
print('mtllib $(dirname "$scene")/cornell_box.mtl')
print('\n'.join('v %d %d 0' % (i % n, i // n) for i in range(n * n)))
print('\n'.join('f %d %d %d' % (i + 1, i + 2, i + n + 1) for i in range(n * n - n - 1)))" > big.obj
"$pt" render big.obj -spp 1 --res 8x8 -q -o loading.exr 2> loading.txt &
pid=$!
# Signalled once pt has read the scene's 34 MB and parses them (a second more with the BVH): its
# shared libraries take half a second to load, and before main no handler is installed.
for i in $(seq 1 1000); do
  read=$(awk '/^rchar/ {print $2}' /proc/$pid/io 2>/dev/null)
  [[ -z "$read" || $read -gt 30000000 ]] && break
  sleep 0.01
done
kill -TERM $pid
start=$(date +%s%N)
wait $pid
status=$?
(( ($(date +%s%N) - start) / 1000000 < 2000 )) || fail "signal_while_loading: took more than 2 s to stop"
[[ $status -eq 143 ]] || fail "signal_while_loading: exit $status, expected 143"
grep -q "interrupted before rendering began; nothing was written" loading.txt || fail "signal_while_loading: $(cat loading.txt)"
[[ -e loading.exr || -e loading.partial.exr ]] && fail "signal_while_loading: wrote an image"
no_temporaries . "signal_while_loading"

# 9. pt merge stopped by a signal while it writes: no temporary file and no output (it left
# .OUT.tmp-PID behind before it handled signals).
"$pt" render "$scene" -spp 2 --res 1536x1536 --max-depth 1 --samples 0:1 -q -o big_a.exr > /dev/null
"$pt" render "$scene" -spp 2 --res 1536x1536 --max-depth 1 --samples 1:2 -q -o big_b.exr > /dev/null
for sig in INT TERM; do
  "$pt" merge big_a.exr big_b.exr --aov variance -o merged_$sig.exr 2> merge_$sig.txt &
  pid=$!
  for i in $(seq 1 3000); do ls -a | grep -q "^\.merged_$sig\.exr\.tmp-" && break; sleep 0.005; done
  kill -$sig $pid
  wait $pid
  status=$?
  want=$([[ $sig == INT ]] && echo 130 || echo 143)
  if [[ $status -eq 0 ]]; then
    echo "note: merge_signal_$sig: the merge finished before the signal; nothing to check"
    continue
  fi
  [[ $status -eq $want ]] || fail "merge_signal_$sig: exit $status, expected $want"
  grep -q "pt merge: interrupted; nothing was written" merge_$sig.txt || fail "merge_signal_$sig: $(cat merge_$sig.txt)"
  [[ -e merged_$sig.exr ]] && fail "merge_signal_$sig: wrote merged_$sig.exr"
  no_temporaries . "merge_signal_$sig"
done
set +m

if [[ $failures -gt 0 ]]; then
  echo "$failures output checks failed"
  exit 1
fi
echo "all output checks passed"
