#!/usr/bin/env bash
# Bad input meets a clear message and nothing else: every case below is a file or a command line
# a user could really produce. Each must end with the expected exit status (1 bad input, 2 bad
# usage, 0 where a warning and a documented fallback are the right answer), print the expected
# text (naming the file and line for text formats), never crash, and never leave an output file
# behind when it fails.
# usage: bad_input_test.sh PT
set -uo pipefail
pt=$(realpath "$1")
tmp=$(mktemp -d)
trap 'chmod -R u+w "$tmp" 2>/dev/null; rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

# check NAME STATUS TEXT pt-arguments...: runs pt with a fresh output path out/NAME.exr (unless
# the arguments name one) and checks status, text, and that a failed run wrote nothing.
check() {
  local name=$1 status=$2 text=$3
  shift 3
  mkdir -p out
  local output got
  output=$(timeout 120 "$pt" "$@" 2>&1)
  got=$?
  if [[ $got -ne $status ]]; then
    fail "$name: exit $got, expected $status; output: $(echo "$output" | head -3)"
  elif [[ "$output" != *"$text"* ]]; then
    fail "$name: output does not contain \"$text\": $(echo "$output" | head -3)"
  elif [[ "$output" == *"terminate called"* || "$output" == *"Segmentation"* || "$output" == *"Aborted"* ]]; then
    fail "$name: crashed: $output"
  fi
  if [[ $status -ne 0 && -n "$(ls -A out)" ]]; then fail "$name: a failed run left $(ls -A out)"; fi
  rm -rf out
}

tri=$'v 0 0 0\nv 1 0 0\nv 0 1 0\n'
camera=$'newcamera C\ncameraposition 0.3 0.3 3\ncameratarget 0.3 0.3 0\ncameraup 0 1 0\ncamerafov 45\n'
printf '%s' "$camera" > camera.mtl
render() { echo render "$1" -spp 2 --res 16x16 -q -o "out/$2.exr"; }

# Files that cannot be a scene.
check missing 1 "missing.obj: cannot open: No such file or directory" $(render missing.obj missing)
: > empty.obj
check empty 1 "empty.obj: the file is empty" $(render empty.obj empty)
mkdir folder.obj
check folder 1 "folder.obj: is a directory" $(render folder.obj folder)
mkfifo fifo.obj
check fifo 1 "fifo.obj: is not a regular file" $(render fifo.obj fifo)
head -c 4096 /dev/urandom > garbage.obj
printf '\0' >> garbage.obj
check binary_garbage 1 "contains a NUL byte; expected a text file" $(render garbage.obj garbage)
{ for i in $(seq 1 2000); do echo "kw$RANDOM $RANDOM.x zz"; done; } > text_garbage.obj
check text_garbage 0 "further warnings not shown" render text_garbage.obj -spp 2 --res 16x16 -o out/a.exr

# Truncated, malformed and out-of-range content.
printf '%sv 1 1' "$tri" > truncated.obj
check truncated 1 "truncated.obj:4: v: expected a number, found end of line" $(render truncated.obj truncated)
printf '%sf 1 2' "$tri" > short_face.obj
check short_face 1 "short_face.obj:4: f: expected at least 3 vertices, found 2" $(render short_face.obj short_face)
printf '%sf 1 2 4\n' "$tri" > index_range.obj
check index_out_of_range 1 "index_range.obj:4: f: vertex index 4 is out of range (3 defined so far" $(render index_range.obj r)
printf '%sf 0 1 2\n' "$tri" > index_zero.obj
check index_zero 1 "index_zero.obj:4: f: vertex index 0 is out of range" $(render index_zero.obj z)
printf '%sf 1/7 2/7 3/7\n' "$tri" > uv_range.obj
check uv_out_of_range 1 "uv_range.obj:4: f: texture coordinate index 7 is out of range" $(render uv_range.obj uv)
printf 'v 0 nan 0\n' > nan.obj
check nan_coordinate 1 'nan.obj:1: v: "nan" is not a finite number' $(render nan.obj nan)
printf 'v 0 0 -inf\n' > inf.obj
check inf_coordinate 1 'inf.obj:1: v: "-inf" is not a finite number' $(render inf.obj inf)
printf 'v 0 0 1e39\n' > overflow.obj
check overflow_coordinate 1 'overflow.obj:1: v: "1e39" is beyond float'"'"'s range' $(render overflow.obj overflow)
printf 'v 0 0 3e20\n' > huge.obj
check huge_coordinate 1 "huge.obj:1: v: coordinate beyond +-1e12" $(render huge.obj huge)
printf 'v 0 zero 0\n' > word.obj
check non_numeric 1 'word.obj:1: v: expected a number, found "zero"' $(render word.obj word)
printf '%sf 1 2 3\n' "$tri" > m.obj
printf 'newmtl A\nKd 0.5 red 0.5\n' > bad.mtl
printf 'mtllib bad.mtl\n%sf 1 2 3\n' "$tri" > bad_mtl.obj
check non_numeric_mtl 1 'bad.mtl:2: Kd: expected a number, found "red"' $(render bad_mtl.obj bad_mtl)
printf 'newmtl A\nNi -1\n' > neg.mtl
printf 'mtllib neg.mtl\n%sf 1 2 3\n' "$tri" > neg_mtl.obj
check negative_ior 1 "neg.mtl:2: Ni: expected an index of refraction > 0" $(render neg_mtl.obj neg)
printf 'newcamera C\ncameraposition 0 0 1\ncameratarget 0 0 1\n' > cam.mtl
printf 'mtllib cam.mtl\n%sf 1 2 3\n' "$tri" > bad_camera.obj
check degenerate_camera 1 "cam.mtl:3: camera \"C\": cameraposition equals cameratarget" $(render bad_camera.obj cam)
printf 'mtllib camera.mtl\n%susemtl Nowhere\nf 1 2 3\n' "$tri" > unknown_material.obj
check unknown_material 1 'unknown_material.obj:5: usemtl: no material named "Nowhere"' $(render unknown_material.obj um)

# Recoverable: a warning, a documented fallback, and an image.
printf 'mtllib camera.mtl\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n' > crlf.obj
check windows_line_endings 0 "16x16, 2 spp" render crlf.obj -spp 2 --res 16x16 -o out/crlf.exr
printf 'mtllib nothere.mtl\n%susemtl Red\nf 1 2 3\n' "$tri" > missing_mtl.obj
check missing_mtllib 0 'missing_mtl.obj:1: mtllib "nothere.mtl" not found' render missing_mtl.obj -spp 2 --res 16x16 -o out/a.exr
check missing_mtllib_material 0 'missing_mtl.obj:5: usemtl: material "Red" not found (its mtllib is missing)' \
  render missing_mtl.obj -spp 2 --res 16x16 -o out/a.exr
printf 'mtllib %s\n%sf 1 2 3\n' "$(head -c 300 /dev/zero | tr '\0' m).mtl" "$tri" > long_mtllib.obj
check mtllib_name_too_long 0 'long_mtllib.obj:1: mtllib "mmmm' render long_mtllib.obj -spp 2 --res 16x16 -o out/a.exr
printf 'newmtl Red\nKd 1 0 0\nmap_Kd nothere.png\n' > tex.mtl
printf 'mtllib tex.mtl\n%susemtl Red\nf 1 2 3\n' "$tri" > missing_tex.obj
check missing_texture 0 'tex.mtl:3: map_Kd: texture "nothere.png" not found; using the plain colour' \
  render missing_tex.obj -spp 2 --res 16x16 -o out/a.exr
printf '%sf 1 2 3\n' "$tri" > no_camera.obj
check no_camera 0 "no camera defined; framing the whole scene" render no_camera.obj -spp 2 --res 16x16 -o out/a.exr
check no_lights 0 "16x16, 2 spp" render no_camera.obj -spp 2 --res 16x16 -o no_lights.exr
# Environment light only: the triangle and the sky must still show.
[[ $(oiiotool --stats no_lights.exr 2>/dev/null | grep -m1 "Stats Max") == *" 0.000000 0.000000 0.000000"* ]] &&
  fail "no_lights: the image is black"
/usr/bin/python3 -c "
import math
n = 10000
print('mtllib camera.mtl')
print('\n'.join('v %f %f 0' % (math.cos(2 * math.pi * i / n), math.sin(2 * math.pi * i / n)) for i in range(n)))
print('f ' + ' '.join(str(i + 1) for i in range(n)))" > big_face.obj
check face_with_10000_vertices 0 "16x16, 2 spp" render big_face.obj -spp 2 --res 16x16 -o out/a.exr
{ printf 'mtllib camera.mtl\n%s# ' "$tri"; head -c 10000000 /dev/zero | tr '\0' x; printf '\nf 1 2 3\n'; } > long_line.obj
check line_of_10MB 0 "16x16, 2 spp" render long_line.obj -spp 2 --res 16x16 -o out/a.exr
{ printf 'v 0 0 '; head -c 10000000 /dev/zero | tr '\0' 3; echo; } > long_number.obj
check number_of_10MB 1 'long_number.obj:1: v: "33333333333333333333' $(render long_number.obj n)
printf 'mtllib camera.mtl\n%sv 2 0 0\nf 1 2 3\nf 1 2 3\nf 1 2 4\n' "$tri" > degenerate.obj
check degenerate_triangles 0 "1 of 3 triangles have zero area" render degenerate.obj -spp 2 --res 16x16 -o out/a.exr

# Bad usage: refused before any work, nothing written.
check spp_zero 2 "option -spp: 0 is out of range" render m.obj -spp 0 -o out/a.exr
check spp_negative 2 "option -spp: -4 is out of range" render m.obj -spp -4 -o out/a.exr
check spp_not_a_number 2 'option -spp: expected an integer, got "lots"' render m.obj -spp lots -o out/a.exr
check resolution_too_large 2 "more than this machine's memory" render m.obj --res 60000x60000 -o out/a.exr
check resolution_malformed 2 "option --res: expected WIDTHxHEIGHT" render m.obj --res 0x10 -o out/a.exr
check unknown_extension 2 'unknown extension ".jpg"; expected .exr or .png' render m.obj -o out/a.jpg
check missing_folder 2 'folder "out/no/such" does not exist' render m.obj -o out/no/such/a.exr
check clamp_negative 2 "option --clamp: -1 is out of range" render m.obj --clamp -1 -o out/a.exr
mkdir locked && chmod 555 locked
if [[ $(id -u) -eq 0 ]]; then # root writes anywhere: run this one case as nobody
  chmod 755 "$tmp"
  chmod o+r m.obj
  as_nobody=(setpriv --reuid=65534 --regid=65534 --clear-groups)
else
  as_nobody=()
fi
got=$("${as_nobody[@]}" "$pt" render m.obj -spp 1 --res 8x8 -o locked/a.exr 2>&1)
status=$?
[[ $status -eq 2 && "$got" == *'folder "locked" is not writable'* ]] || fail "unwritable_folder: exit $status: $got"
[[ -z "$(ls -A locked)" ]] || fail "unwritable_folder: wrote $(ls -A locked)"

# A good image is never replaced by a failed render.
"$pt" render m.obj -spp 1 --res 8x8 -q -o good.exr >/dev/null || fail "could not render good.exr"
before=$(md5sum good.exr)
check keeps_good_output 1 "cannot open" render missing.obj -spp 1 -o good.exr
[[ "$(md5sum good.exr)" == "$before" ]] || fail "keeps_good_output: good.exr changed"

if [[ $failures -gt 0 ]]; then
  echo "$failures bad-input checks failed"
  exit 1
fi
echo "all bad-input checks passed"
