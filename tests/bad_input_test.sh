#!/usr/bin/env bash
# Bad input meets a clear message and nothing else: every case below is a file or a command line
# a user could really produce. Each must end with the expected exit status (1 bad input, 2 bad
# usage, 0 where a warning and a documented fallback are the right answer), print the expected
# text (naming the file and line for text formats), never crash, and never leave an output file
# behind when it fails.
# usage: bad_input_test.sh PT
source "$(dirname "$0")/bad_input_lib.sh" "$1"

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
# The data maps of issue 11: each way a map line can be wrong.
echo "not an image" > corrupt.png
oiiotool --create 4x4 1 -d uint8 -o grey.png >/dev/null 2>&1
oiiotool --create 4x4 3 -d uint8 -o rgb.png >/dev/null 2>&1
maps_case() { # NAME STATUS TEXT MAP-LINE
  printf 'newmtl M\nKd 0.5 0.5 0.5\n%s\n' "$4" > "maps_$1.mtl"
  printf 'mtllib maps_%s.mtl\n%svt 0 0\nvt 1 0\nvt 0 1\nusemtl M\nf 1/1 2/2 3/3\n' "$1" "$tri" > "maps_$1.obj"
  check "$1" "$2" "$3" render "maps_$1.obj" -spp 2 --res 16x16 -o out/a.exr
}
maps_case corrupt_normal_map 0 'maps_corrupt_normal_map.mtl:3: norm: cannot read texture "corrupt.png"' 'norm corrupt.png'
# A JPEG cut short or damaged in its data is unreadable as a PNG cut short is (OpenImageIO's reader
# says so only beside a read that succeeds, and the missing part came out flat grey).
damaged_jpegs
maps_case jpeg_cut_short 0 'maps_jpeg_cut_short.mtl:3: map_Kd: cannot read texture "cut.jpg": the file is damaged or cut short (JPEG error: Premature end of JPEG file' 'map_Kd cut.jpg'
maps_case jpeg_garbled 0 'maps_jpeg_garbled.mtl:3: map_Kd: cannot read texture "garbled.jpg": the file is damaged or cut short (JPEG error: Corrupt JPEG data' 'map_Kd garbled.jpg'
maps_case grey_normal_map 0 'maps_grey_normal_map.mtl:3: norm: normal map "grey.png" has 1 channel(s); expected RGB' 'norm grey.png'
maps_case cutout_without_alpha 0 'maps_cutout_without_alpha.mtl:3: map_d: texture "grey.png" has no alpha channel' 'map_d -imfchan m grey.png'
maps_case missing_roughness_map 0 'maps_missing_roughness_map.mtl:3: map_Pr: texture "nothere.png" not found; using the plain value' 'map_Pr nothere.png'
maps_case depth_channel 1 'maps_depth_channel.mtl:3: map_Pm -imfchan: expected r, g, b, m (alpha) or l (luminance), found "z"' 'map_Pm -imfchan z grey.png'
maps_case bump_scale_missing 1 'maps_bump_scale_missing.mtl:3: bump -bm: expected a number' 'bump -bm grey.png'
maps_case bump_and_normal 0 'has both a normal map (norm) and a bump map; the bump map is ignored' $'norm -bm 0.5 rgb.png\nbump grey.png'
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

# Byte-order marks and old Mac line endings: accepted in OBJ and MTL, with the right line numbers.
printf '\xEF\xBB\xBFmtllib camera.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > bom.obj
check utf8_bom 0 "16x16, 2 spp" render bom.obj -spp 2 --res 16x16 -o out/a.exr
printf '\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nf 1 2 3\n' > bom_bad.obj
check utf8_bom_line_numbers 1 "bom_bad.obj:3: f: vertex index 3 is out of range" $(render bom_bad.obj bom)
printf 'mtllib cr.mtl\rv 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r' > cr.obj
printf '\xEF\xBB\xBFnewcamera C\rcameraposition 0.3 0.3 3\rcameratarget 0.3 0.3 0\r' > cr.mtl
got=$("$pt" render cr.obj -spp 2 --res 16x16 -o cr.exr 2>&1)
[[ $? -eq 0 && "$got" != *warning* ]] || fail "cr_line_endings: $got"
tr '\r' '\n' < cr.obj > lf.obj && tr '\r' '\n' < cr.mtl | sed 's/cr.mtl/lf.mtl/' > lf.mtl && sed -i 's/cr.mtl/lf.mtl/' lf.obj
"$pt" render lf.obj -spp 2 --res 16x16 -q -o lf.exr > /dev/null
oiiotool --diff cr.exr lf.exr > /dev/null || fail "cr_line_endings: the image differs from the same scene with LF endings"
printf 'v 0 0 0\rv 1 0 0\rf 1 2 4\r' > cr_bad.obj
check cr_line_numbers 1 "cr_bad.obj:3: f: vertex index 4 is out of range" $(render cr_bad.obj crb)
printf 'mtllib camera.mtl\nv 1e-320 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > denormal.obj
check denormal_is_a_number 0 "16x16, 2 spp" render denormal.obj -spp 2 --res 16x16 -o out/a.exr

# Input far larger than a scene: refused at once, from the first block or the header.
truncate -s 2G sparse.mtl
printf 'mtllib sparse.mtl\n%sf 1 2 3\n' "$tri" > sparse.obj
start=$(date +%s%N)
check sparse_2GB_mtl 1 "sparse.mtl:1: contains a NUL byte" $(render sparse.obj sparse)
(( ($(date +%s%N) - start) / 1000000 < 10000 )) || fail "sparse_2GB_mtl: took more than 10 s to refuse (18 s when it read the whole file)"
truncate -s 8G sparse.mtl
check sparse_8GB_mtl 1 "sparse.mtl:1: contains a NUL byte" $(render sparse.obj sparse8)
rm -f sparse.mtl
# A PNG whose header declares 1000000 x 1000000 (4 TB as 8-bit texels with their mip levels: beyond a
# quarter of any machine's memory) and holds no pixels.
/usr/bin/python3 -c "
import struct, zlib
def chunk(t, d): return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d))
open('huge.png', 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', 1000000, 1000000, 8, 2, 0, 0, 0))
                             + chunk(b'IDAT', zlib.compress(b'')) + chunk(b'IEND', b''))"
printf 'newmtl T\nmap_Kd huge.png\n' > huge_tex.mtl
printf 'mtllib huge_tex.mtl\n%susemtl T\nf 1 2 3\n' "$tri" > huge_tex.obj
check texture_beyond_budget 1 'huge_tex.mtl:2: map_Kd: texture "huge.png" is too large: 1000000x1000000' $(render huge_tex.obj ht)

# Values that would overflow float somewhere in the renderer: refused at their line.
light() { printf 'newlight L\nlightposition 0.3 0.3 1\n%s\n' "$1" > light.mtl; printf 'mtllib camera.mtl\nmtllib light.mtl\n%sf 1 2 3\n' "$tri" > light.obj; }
light 'lightintensity 1e38'
check point_light_1e38 1 'light.mtl:3: light "L": lightintensity 1e+38 of a point light' $(render light.obj l1)
light 'lightintensity 5e20'
check point_light_5e20 1 'light.mtl:3: light "L": lightintensity 5e+20 of a point light' $(render light.obj l2)
light $'lightradius 1e20\nlightintensity 1'
check light_radius_1e20 1 'light.mtl:3: lightradius: beyond 1e12' $(render light.obj l3)
light $'lightradius 1e-20\nlightintensity 1'
check light_radius_1e-20 1 'light.mtl:4: light "L": lightintensity 1 on a sphere of radius 1e-20 emits radiance inf' $(render light.obj l4)
light $'lightradius 1e-14\nlightintensity 1e-20'
check light_radius_below_scene_fraction 1 'light.mtl:3: light "L": lightradius 1e-14 is below 1e-12 of the scene' $(render light.obj l5)
light $'lightradius 0.1\nlightintensity 1e3'
check legal_light_renders 0 "16x16, 2 spp" render light.obj -spp 2 --res 16x16 -o out/a.exr
printf 'newmtl Hot\nKe 1e19 1 1\n' > hot.mtl
printf 'mtllib hot.mtl\n%susemtl Hot\nf 1 2 3\n' "$tri" > hot.obj
check emission_beyond_1e18 1 'hot.mtl:2: Ke: radiance 1e+19 is beyond the 1e18' $(render hot.obj hot)
printf 'newmtl Bright\nKd 1.5 0.5 0.5\nKd 1.2 0.5 0.5\n' > bright.mtl
printf 'mtllib camera.mtl\nmtllib bright.mtl\n%susemtl Bright\nf 1 2 3\n' "$tri" > bright.obj
check kd_above_one_warns 0 'bright.mtl:2: Kd above 1 in material "Bright" creates energy' render bright.obj -spp 2 --res 16x16 -o out/a.exr
[[ $("$pt" render bright.obj -spp 1 --res 8x8 -o bright.exr 2>&1 | grep -c "creates energy") -eq 1 ]] || fail "kd_above_one_warns: not once"
printf 'newmtl Gain\nKd 20 1 1\n' > gain.mtl
printf 'mtllib gain.mtl\n%susemtl Gain\nf 1 2 3\n' "$tri" > gain.obj
check kd_beyond_10 1 'gain.mtl:2: Kd: 20 is beyond 10' $(render gain.obj gain)
# Light that grows 10x per bounce inside a closed box overflows float after ~40 bounces: the
# dropped samples are said in a warning, not only counted.
printf 'newmtl Gain\nKd 10\nnewcamera C\ncameraposition 0 0 0.5\ncameratarget 0 0 0\nnewlight L\nlightposition 0 0 0\nlightintensity 1\n' > box.mtl
{ echo 'mtllib box.mtl'; for z in -1 1; do for y in -1 1; do for x in -1 1; do echo "v $x $y $z"; done; done; done
  echo 'usemtl Gain'; printf 'f 1 2 4 3\nf 5 7 8 6\nf 1 5 6 2\nf 3 4 8 7\nf 1 3 7 5\nf 2 6 8 4\n'; } > box.obj
check dropped_samples_warn 0 "samples came out NaN, infinite or negative and were dropped" render box.obj -spp 2 --res 8x8 --max-depth 200 -o out/a.exr
printf 'mtllib camera.mtl\n%sv -1e17 -1e17 -5\nv 1e17 -1e17 -5\nv 0 1e17 -5\nf 1 2 3\nf 4 5 6\n' "$tri" > backdrop.obj
check backdrop_at_1e17 1 "backdrop.obj:5: v: coordinate beyond +-1e12" $(render backdrop.obj bd)
printf 'mtllib camera.mtl\nv 0 0 0\nv 1e-7 0 0\nv 0 1e-7 0\nf 1 2 3\n' > tiny.obj
check scene_below_1e-6 1 "tiny.obj: the scene's triangles span only 1.41421e-07 across" $(render tiny.obj tiny)
printf 'newcamera OnlyFov\ncamerafov 30\n' > fov.mtl
printf 'mtllib fov.mtl\n%sf 1 2 3\n' "$tri" > fov.obj
check camera_without_position_warns 0 'fov.mtl:1: camera "OnlyFov" has neither cameraposition nor cameratarget' render fov.obj -spp 1 --res 8x8 -o out/a.exr
printf 'newcamera C\ncameraposition 0 0 1\ncameraup 0 0 0\ncamerafov 45\n' > up.mtl
printf 'mtllib up.mtl\n%sf 1 2 3\n' "$tri" > up.obj
check camera_error_names_its_keyword 1 'up.mtl:3: camera "C": cameraup is zero' $(render up.obj up)

# Bad usage: refused before any work, nothing written.
check spp_zero 2 "option -spp: 0 is out of range" render m.obj -spp 0 -o out/a.exr
check spp_negative 2 "option -spp: -4 is out of range" render m.obj -spp -4 -o out/a.exr
check spp_not_a_number 2 'option -spp: expected an integer, got "lots"' render m.obj -spp lots -o out/a.exr
check resolution_too_large 2 "more than this machine's memory" render m.obj --res 60000x60000 -o out/a.exr
check resolution_malformed 2 "option --res: expected WIDTHxHEIGHT" render m.obj --res 0x10 -o out/a.exr
check unknown_extension 2 'unknown extension ".jpg"; expected .exr or .png' render m.obj -o out/a.jpg
check missing_folder 2 'folder "out/no/such" does not exist' render m.obj -o out/no/such/a.exr
check clamp_negative 2 "option --clamp: -1 is out of range" render m.obj --clamp -1 -o out/a.exr
check res_negative 2 'option --res: expected WIDTHxHEIGHT with two positive sizes such as 512x512, got "-64x64"' render m.obj --res -64x64 -o out/a.exr
check clamp_range_is_short 2 "option --clamp: 1e40 is out of range [0, 1e+30]" render m.obj --clamp 1e40 -o out/a.exr
check seed_range 2 "option --seed: 4294967296 is out of range [0, 2147483647]" render m.obj --seed 4294967296 -o out/a.exr
check value_missing_names_the_option 2 "option -o needs a value" render m.obj -o
check double_dash_ends_options 0 "8x8, 1 spp" render -spp 1 --res 8x8 -o out/a.exr -- m.obj
cp m.obj ./-dash.obj
check dash_named_scene 0 "8x8, 1 spp" render -spp 1 --res 8x8 -o out/a.exr -- -dash.obj
check threads_beyond_cores 0 "this machine runs $(nproc) threads at once; using $(nproc)" render m.obj --threads 4096 -spp 1 --res 8x8 -o out/a.exr

# Environment maps (--env): each fault is an error naming the file, exit 1, nothing written.
oiiotool --pattern constant:color=1,nan,1 8x4 3 -d float -o nan_env.exr
oiiotool --pattern constant:color=1,1,-1 8x4 3 -d float -o negative_env.exr
oiiotool --pattern constant:color=1,1,1 8x4 3 -d uint8 -o ldr_env.png
oiiotool --pattern constant:color=1,1,1 8x8 3 -d half -o square_env.exr
head -c 2000 /dev/urandom > corrupt_env.exr
check env_missing 1 'environment map "no_such.exr" not found' render m.obj --env no_such.exr -spp 1 --res 8x8 -o out/a.exr
check env_nan 1 'environment map "nan_env.exr": pixel (0, 0) channel 1 is nan' render m.obj --env nan_env.exr -spp 1 --res 8x8 -o out/a.exr
check env_negative 1 'pixel (0, 0) channel 2 is -1; radiance must be finite and not negative' render m.obj --env negative_env.exr -spp 1 --res 8x8 -o out/a.exr
check env_not_float 1 'environment map "ldr_env.png" holds uint8 values; expected float or half' render m.obj --env ldr_env.png -spp 1 --res 8x8 -o out/a.exr
check env_corrupt 1 'cannot read environment map "corrupt_env.exr"' render m.obj --env corrupt_env.exr -spp 1 --res 8x8 -o out/a.exr
check env_folder 1 'environment map "out" is not a regular file' render m.obj --env out -spp 1 --res 8x8 -o out/a.exr
check env_not_2_to_1 0 'is 8x8, not twice as wide as high' render m.obj --env square_env.exr -spp 1 --res 8x8 -o out/a.exr
check env_rotate_alone 2 '--env-rotate needs --env PATH' render m.obj --env-rotate 30 -o out/a.exr
check env_scale_negative 2 'option --env-scale: -1 is out of range' render m.obj --env square_env.exr --env-scale -1 -o out/a.exr
check env_is_output 2 'square_env.exr' render m.obj --env square_env.exr -spp 1 -o square_env.exr

# The sky (--sky): each bad value is a usage error naming the option, nothing written.
check light_choice 2 'option --light-choice: expected auto, power or tree, got "bvh"' render m.obj --light-choice bvh -o out/a.exr
check sky_option_alone 2 '--turbidity needs --sky' render m.obj --turbidity 4 -o out/a.exr
check sky_and_env 2 '--sky and --env both set the environment' render m.obj --sky --env square_env.exr -o out/a.exr
check sky_sun_twice 2 '--sun-dir and --sun-elevation/--sun-azimuth both place the sun' render m.obj --sky --sun-dir 0,1,0 --sun-elevation 30 -o out/a.exr
check sky_turbidity_low 2 'option --turbidity: 1.2 is out of range [1.7, 10]' render m.obj --sky --turbidity 1.2 -o out/a.exr
check sky_turbidity_nan 2 'option --turbidity' render m.obj --sky --turbidity nan -o out/a.exr
check sky_elevation_range 2 'option --sun-elevation: 95 is out of range [-90, 90]' render m.obj --sky --sun-elevation 95 -o out/a.exr
check sky_sun_dir_zero 2 'option --sun-dir: 0,0,0 has no direction' render m.obj --sky --sun-dir 0,0,0 -o out/a.exr
check sky_sun_dir_form 2 'option --sun-dir: expected three numbers X,Y,Z' render m.obj --sky --sun-dir 1,2 -o out/a.exr
check sky_sun_dir_huge 2 'option --sun-dir: 1,1e40,0 has a component that is not a number of magnitude below 1e30' render m.obj --sky --sun-dir 1,1e40,0
check sky_sun_dir_inf 2 'option --sun-dir: expected three numbers' render m.obj --sky --sun-dir 1,inf,0 -o out/a.exr
check sky_scale_negative 2 'option --sky-scale: -1 is out of range' render m.obj --sky --sky-scale -1 -o out/a.exr
check sky_sun_below 0 'the sun is below the horizon' render m.obj --sky --sun-elevation -10 -spp 1 --res 8x8 -o out/a.exr
printf 'mtllib sky.mtl\n%s' "$tri" > skyblock.obj
printf 'newenvironment Day\nenvsky\nturbidity 12\n' > sky.mtl
check sky_mtl_turbidity 1 'sky.mtl:3: turbidity: expected a value in [1.7, 10]' render skyblock.obj -spp 1 --res 8x8 -o out/a.exr
"$pt" render m.obj --threads 4096 -spp 1 --res 8x8 -o threads.exr > /dev/null 2>&1
oiiotool --info -v threads.exr | grep -q "pt:threads: $(nproc)$" || fail "threads_beyond_cores: pt:threads is not $(nproc)"
oiiotool --info -v threads.exr | grep -q "pt:threadsRequested: 4096" || fail "threads_beyond_cores: pt:threadsRequested is not recorded"
mkdir -p out
got=$(TBB_VERSION=1 "$pt" render fov.obj -q -spp 1 --res 8x8 -o out/a.exr 2>&1 >/dev/null)
[[ -z "$got" ]] || fail "quiet: libraries or warnings still print: $(echo "$got" | head -2)"
got=$("$pt" render missing.obj -q -o out/a.exr 2>&1)
[[ "$got" == *"missing.obj: cannot open"* ]] || fail "quiet: errors must still print: $got"
rm -rf out
check alpha_range_is_short 2 "option --alpha: 0.9 is out of range [1e-12, 0.5]" diff a.exr b.exr --alpha 0.9
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

# Split renders and pt merge (issue 14): each fault is a clear message, exit 1 (2 for usage),
# nothing written, an existing output untouched.
split=(-spp 8 --res 16x16 -q)
"$pt" render m.obj "${split[@]}" --samples 0:4 -o part_a.exr >/dev/null || fail "could not render part_a.exr"
"$pt" render m.obj "${split[@]}" --samples 2:8 -o part_b.exr >/dev/null || fail "could not render part_b.exr"
"$pt" render m.obj "${split[@]}" --samples 4:8 --seed 7 -o part_seed.exr >/dev/null || fail "could not render part_seed.exr"
"$pt" render m.obj "${split[@]}" -o whole.exr >/dev/null || fail "could not render whole.exr"
head -c 600 part_a.exr > truncated_part.exr
check merge_missing 1 'nowhere.exr' merge part_a.exr nowhere.exr -o out/m.exr
check merge_truncated 1 'truncated_part.exr' merge part_a.exr truncated_part.exr -o out/m.exr
check merge_foreign 1 'whole.exr: it is not a part of a split render' merge part_a.exr whole.exr -o out/m.exr
check merge_png 1 'checker' merge part_a.exr "$gltf/checker.png" -o out/m.exr
check merge_other_job 1 'part_seed.exr is a part of another job than part_a.exr: its pt:seed is "7", not "0"' merge part_a.exr part_seed.exr -o out/m.exr
check merge_overlap 1 'part_a.exr and part_b.exr both hold samples 2:4 of pixels [0, 16) x [0, 16)' merge part_a.exr part_b.exr -o out/m.exr
check merge_no_parts 2 'expected one or more PART.exr files' merge -o out/m.exr
check merge_aov_png 2 '--aov needs an .exr output' merge part_a.exr --aov variance -o out/m.png
check merge_aov_missing 1 'part_a.exr has no first-hit sums' merge part_a.exr --aov albedo -o out/m.exr
check merge_into_part 2 'is also an input' merge part_a.exr -o part_a.exr
cp part_a.exr keep.exr
before=$(md5sum keep.exr)
check merge_keeps_output 1 'both hold samples' merge part_a.exr part_b.exr -o keep.exr
[[ "$(md5sum keep.exr)" == "$before" ]] || fail "merge_keeps_output: keep.exr changed"
check samples_form 2 'option --samples: expected A:B with 0 <= A < B, got "4"' render m.obj "${split[@]}" --samples 4 -o out/a.exr
check samples_empty 2 'option --samples: expected A:B with 0 <= A < B, got "4:4"' render m.obj "${split[@]}" --samples 4:4 -o out/a.exr
check samples_past_spp 1 '--samples 0:9: the job has -spp 8, so its sample indices run from 0 to 8' render m.obj "${split[@]}" --samples 0:9 -o out/a.exr
check samples_past_seed 1 'a pixel has 16777216 (2^24) sample indices per seed' render m.obj "${split[@]}" --samples 0:20000000 -o out/a.exr
check samples_png 2 '--samples writes a part for pt merge, which needs an .exr output' render m.obj "${split[@]}" --samples 0:4 -o out/a.png
check crop_outside 1 '--crop 0,0,17,16 passes the 16x16 image' render m.obj "${split[@]}" --crop 0,0,17,16 -o out/a.exr
check crop_form 2 'option --crop: expected X0,Y0,X1,Y1 with 0 <= X0 < X1 and 0 <= Y0 < Y1, got "4,4,2,8"' render m.obj "${split[@]}" --crop 4,4,2,8 -o out/a.exr
check resume_other_job 1 'it is a part of another job: its pt:seed is "7", this command'"'"'s is "0"' render m.obj "${split[@]}" --samples 4:8 --resume part_seed.exr -o out/a.exr
check resume_other_range 1 'it holds samples 0:4, this command renders 4:8' render m.obj "${split[@]}" --samples 4:8 --resume part_a.exr -o out/a.exr
check resume_not_part 1 'whole.exr: it is not a part' render m.obj "${split[@]}" --resume whole.exr -o out/a.exr
check resume_no_layers 1 'it has no first-hit sums, so --aov albedo, normal and depth and --denoise cannot go on from it' render m.obj "${split[@]}" --samples 0:4 --aov albedo --resume part_a.exr -o out/a.exr
check resume_missing 1 '--resume: cannot read "nowhere.exr"' render m.obj "${split[@]}" --resume nowhere.exr -o out/a.exr

# Issue 24: the newer options and inputs within the range pt renders correctly. Each is refused
# with its limit named, or warned about and counted; never an infinity or NaN written silently.
check exposure_64 2 'option --exposure: 64 is out of range [-32, 32]' render m.obj --exposure 64 -o out/a.exr
check exposure_nan 2 'option --exposure' render m.obj --exposure nan -o out/a.exr
printf 'newmtl Hot\nKe 1e18 1e18 1e18\n' > hot18.mtl
printf 'mtllib camera.mtl\nmtllib hot18.mtl\n%susemtl Hot\nf 1 2 3\n' "$tri" > hot18.obj
check exposure_overflow_warns 0 "values of the image and its layers pass float's range (at --exposure 20)" \
  render hot18.obj --exposure 20 --aov variance -spp 2 --res 8x8 -o hot18.exr
[[ $(oiiotool --stats hot18.exr | grep -c "InfCount: 0 0 0 0 0 0") -eq 1 ]] || fail "exposure_overflow_warns: infinities written"
"$pt" render hot18.obj --exposure 20 -spp 2 --res 8x8 -q -o hot18.png > /dev/null
[[ $(oiiotool --stats hot18.png | grep "Stats Max") == *"255 255 255"* ]] || fail "png_overflow: the emitter is not white"
oiiotool --pattern constant:color=3e38,1,1 8x4 3 -d float -o huge_env.exr
check env_scale_1e30 1 'its brightest texel, times its scale 1e+30, is a radiance of 1e+30, beyond the 1e18' \
  render m.obj --env square_env.exr --env-scale 1e30 -spp 1 --res 8x8 -o out/a.exr
check env_texel_3e38 1 'environment map "huge_env.exr": its brightest texel, times its scale 1, is a radiance of 3e+38' \
  render m.obj --env huge_env.exr -spp 1 --res 8x8 -o out/a.exr
check sky_scale_1e30 2 "option --sky-scale: 1e+30 makes the sky's peak radiance (the sun's disk where it is up)" \
  render m.obj --sky --sky-scale 1e30 -spp 1 --res 8x8 -o out/a.exr
check sky_scale_sun_down 2 "option --sky-scale: 1e+25 makes the sky's peak radiance" \
  render m.obj --sky --sun-elevation -20 --sky-scale 1e25 -spp 1 --res 8x8 -o out/a.exr
printf 'newenvironment E\nenvmap square_env.exr\nenvscale 3e38\n' > envscale.mtl
printf 'mtllib envscale.mtl\n%sf 1 2 3\n' "$tri" > envscale.obj
check mtl_envscale_3e38 1 'envscale.mtl:2: environment map "square_env.exr": its brightest texel, times its scale 3e+38' $(render envscale.obj es)
printf 'newenvironment Day\nenvsky\nskyscale 3e38\n' > skyscale.mtl
printf 'mtllib skyscale.mtl\n%sf 1 2 3\n' "$tri" > skyscale.obj
check mtl_skyscale_3e38 1 "skyscale.mtl:3: skyscale 3e+38: the sky's peak radiance" $(render skyscale.obj ss)
# Float textures: a texel that is not finite is said (the MTL then falls back to its plain colour,
# as for any unreadable map); a map whose largest texel passes the factor's own limit is refused.
oiiotool --pattern constant:color=inf,1,1 4x4 3 -d float -o inf_tex.exr
oiiotool --pattern constant:color=1e5,1,1 4x4 3 -d float -o bright_tex.exr
maps_case inf_texel 0 'map_Kd: texture "inf_tex.exr": texel (0, 0) channel 0 is inf; a colour must be finite and not negative' 'map_Kd inf_tex.exr'
# An EXR found by the part fuzzer, whose chunk table pointed before the file (OpenImageIO's memory
# reader read the byte before its buffer; MemoryImageReader's unit test holds that) and whose
# channel list is longer than it declares, which the header check now refuses before OpenEXR.
cp "$gltf/../../tests/fuzz/corpus/part/regress_chunk_offset_before_file.exr" offset_before.exr
maps_case exr_offset_before_file 0 'map_Kd: cannot read texture "offset_before.exr": its OpenEXR attribute "channels" of type chlist declares 393 bytes' 'map_Kd offset_before.exr'
maps_case texture_scale_1e5 1 'material "M": its diffuse or base colour texture'"'"'s coordinate transform has 100000, beyond +-1e4' 'map_Kd -s 1e5 1e5 rgb.png'
maps_case bright_texel 1 'its diffuse or base colour texture "bright_tex.exr" reaches 100000, which times its factor 0.5 passes the reflectance limit 10' 'map_Kd bright_tex.exr'
truncate -s 8G sparse_tex.png
start=$(date +%s%N)
maps_case sparse_8GB_texture 0 'cannot read texture "sparse_tex.png": not an image file pt reads' 'map_Kd sparse_tex.png'
(( ($(date +%s%N) - start) / 1000000 < 10000 )) || fail "sparse_8GB_texture: took more than 10 s (OpenImageIO tried every reader on it)"
rm -f sparse_tex.png
# Turbidity: one rule for the command line and the MTL (1.7 was refused on one and taken by the other).
check turbidity_1.7 0 '8x8, 1 spp' render m.obj --sky --turbidity 1.7 -spp 1 --res 8x8 -o out/a.exr
check turbidity_below 2 "option --turbidity: 1.69 is out of range [1.7, 10], the range of Preetham et al.'s fit" render m.obj --sky --turbidity 1.69 -o out/a.exr
printf 'newenvironment Day\nenvsky\nturbidity 1.7\n' > sky17.mtl
printf 'mtllib camera.mtl\nmtllib sky17.mtl\n%sf 1 2 3\n' "$tri" > sky17.obj
check mtl_turbidity_1.7 0 '8x8, 1 spp' render sky17.obj -spp 1 --res 8x8 -o out/a.exr
printf 'newenvironment Day\nenvsky\nturbidity 1.69\n' > sky169.mtl
printf 'mtllib sky169.mtl\n%sf 1 2 3\n' "$tri" > sky169.obj
check mtl_turbidity_below 1 "sky169.mtl:3: turbidity: expected a value in [1.7, 10], the range of Preetham et al.'s fit" $(render sky169.obj t)
# Cameras: a name two cameras share, or a name that is another camera's index, is refused.
printf 'newcamera C\ncameraposition 0.3 0.3 3\ncameratarget 0.3 0.3 0\nnewcamera C\ncameraposition 0.3 0.3 2\ncameratarget 0.3 0.3 0\n' > twins.mtl
printf 'mtllib twins.mtl\n%sf 1 2 3\n' "$tri" > twins.obj
check camera_twins_warn 0 'cameras 0 and 1 are both named "C"; --camera picks them by index' render twins.obj -spp 1 --res 8x8 -o out/a.exr
check camera_twins_by_name 2 '--camera C: cameras 0 and 1 are both named "C"; give the index' render twins.obj --camera C -spp 1 --res 8x8 -o out/a.exr
check camera_twins_by_index 0 '8x8, 1 spp' render twins.obj --camera 1 -spp 1 --res 8x8 -o out/a.exr
printf 'newcamera 1\ncameraposition 0.3 0.3 3\ncameratarget 0.3 0.3 0\nnewcamera Other\ncameraposition 0.3 0.3 2\ncameratarget 0.3 0.3 0\n' > numbered.mtl
printf 'mtllib numbered.mtl\n%sf 1 2 3\n' "$tri" > numbered.obj
check camera_name_is_an_index 2 '--camera 1: camera 0 is named "1", and camera 1 is another' render numbered.obj --camera 1 -spp 1 --res 8x8 -o out/a.exr
"$pt" render numbered.obj -spp 1 --res 8x8 -q -o numbered.exr > /dev/null
oiiotool --info -v numbered.exr | grep -q 'pt:cameraIndex: 0' || fail "camera_default: no --camera is not camera 0"

# Parts that lie (issue 24): pt merge and --resume check every field against the others and
# against the memory a merge needs, and every pixel's sums against its count.
cat > editpart.py <<'PY'
# editpart.py IN OUT OP...: a copy of part IN with OPs applied: attr:NAME=int|float|str:VALUE,
# chan:CHANNEL=VALUE (every pixel), mul:CHANNEL=FACTOR, window:X,Y,FULLW,FULLH.
import sys, numpy as np, OpenImageIO as oiio
src, dst, ops = sys.argv[1], sys.argv[2], sys.argv[3:]
inp = oiio.ImageInput.open(src)
spec = inp.spec()
px = np.array(inp.read_image(oiio.FLOAT)).reshape(spec.height, spec.width, spec.nchannels)
inp.close()
names, out = list(spec.channelnames), oiio.ImageSpec(spec)
for op in ops:
    kind, arg = op.split(':', 1)
    if kind == 'attr':
        name, typed = arg.split('=', 1)
        t, v = typed.split(':', 1)
        out.erase_attribute(name)
        if t == 'int': out.attribute(name, oiio.TypeDesc('int'), int(v))
        elif t == 'float': out.attribute(name, oiio.TypeDesc('float'), float(v))
        else: out.attribute(name, v)
    elif kind in ('chan', 'mul'):
        name, v = arg.split('=')
        c = names.index(name)
        px[:, :, c] = float(v) if kind == 'chan' else px[:, :, c] * float(v)
o = oiio.ImageOutput.create(dst)
o.open(dst, out) and o.write_image(np.ascontiguousarray(px, dtype=np.float32)) and o.close() or sys.exit(o.geterror())
PY
lie() { /usr/bin/python3 editpart.py part_a.exr "$1" "${@:2}" || fail "editpart $1"; }
lie lie_range.exr attr:pt:samplesFirst=int:5
check merge_first_past_last 1 'lie_range.exr: pt:samplesLast is 4; expected an integer in [6, 8]' merge lie_range.exr -o out/m.exr
lie lie_count.exr chan:ptCount.N=8
check merge_count_past_range 1 'lie_count.exr: pixel (0, 0) holds 8 samples; its range 0:4 has 4' merge lie_count.exr -o out/m.exr
lie lie_empty.exr chan:ptCount.N=0
check merge_sums_without_samples 1 'lie_empty.exr: pixel (0, 0): its sums' merge lie_empty.exr -o out/m.exr
lie lie_negative.exr mul:ptSum.R=-1
check merge_negative_sum 1 'cannot be those of 4 samples of radiance' merge lie_negative.exr -o out/m.exr
lie lie_squares.exr chan:ptSumSq.G=-5
check merge_negative_squares 1 'lie_squares.exr: pixel (0, 0): its sums' merge lie_squares.exr -o out/m.exr
lie lie_big_text.exr attr:pt:samplesLast=str:99999999999999999999
check merge_number_past_64_bits 1 'lie_big_text.exr: pt:samplesLast is "99999999999999999999"; expected an integer in [1, 8]' merge lie_big_text.exr -o out/m.exr
lie lie_wrap.exr attr:pt:sppRequested=str:4294967304
check merge_number_past_32_bits 1 'pt:sppRequested is "4294967304"; expected an integer in [1, 16777216]' merge lie_wrap.exr -o out/m.exr
lie lie_minus.exr attr:pt:samplesFirst=str:-5
check merge_negative_text 1 'pt:samplesFirst is "-5"; expected an integer in [0, 7]' merge lie_minus.exr -o out/m.exr
lie lie_word.exr attr:pt:fullWidth=str:abc
check merge_word_for_number 1 'pt:fullWidth is "abc"; expected an integer in [1, 65536]' merge lie_word.exr -o out/m.exr
lie lie_float.exr attr:pt:samplesLast=float:4.5
check merge_fraction_for_integer 1 'pt:samplesLast is 4.5; expected an integer' merge lie_float.exr -o out/m.exr
lie lie_wide.exr attr:pt:fullWidth=int:100000
check merge_side_past_65536 1 'pt:fullWidth is 100000; expected an integer in [1, 65536]' merge lie_wide.exr -o out/m.exr
lie lie_huge.exr attr:pt:fullWidth=int:65536 attr:pt:fullHeight=int:65536
check merge_beyond_memory 1 'lie_huge.exr: pt:fullWidth x pt:fullHeight, 65536x65536, would take' merge lie_huge.exr -o out/m.exr
lie lie_exposure.exr attr:pt:exposure=float:nan
check merge_exposure_nan 1 'lie_exposure.exr: pt:exposure is nan; expected a number in [-32, 32]' merge lie_exposure.exr -o out/m.exr
lie lie_seconds.exr attr:pt:renderSeconds=float:-1
check merge_negative_seconds 1 'pt:renderSeconds is -1; expected a number in [0, 1e+12]' merge lie_seconds.exr -o out/m.exr
"$pt" render m.obj "${split[@]}" --crop 0,0,8,16 -o part_crop.exr > /dev/null || fail "could not render part_crop.exr"
/usr/bin/python3 editpart.py part_crop.exr lie_window.exr attr:pt:fullWidth=int:8
check merge_window_disagrees 1 'its EXR display window is 16x16, not its pt:fullWidth x pt:fullHeight 8x16' merge lie_window.exr -o out/m.exr
lie lie_attribute.exr attr:pt:camera=str:$(head -c 70000 /dev/zero | tr '\0' c)
check merge_huge_attribute 1 'lie_attribute.exr: its attribute pt:camera holds 70000 bytes' merge lie_attribute.exr -o out/m.exr
# EXR headers that declare more than their file can hold: OpenEXR allocates the table of chunk
# offsets from the header before reading it (16 GB for 2^31 scanlines; a 200-byte file made pt
# merge take 2 GB), so a table longer than the file, or a side past 262144, is refused first.
/usr/bin/python3 -c "
import struct
def attr(name, kind, data): return name.encode() + b'\0' + kind.encode() + b'\0' + struct.pack('<i', len(data)) + data
channels = b'R\0' + struct.pack('<iB3xii', 2, 0, 1, 1) + b'\0'
header = (b'\x76\x2f\x31\x01' + struct.pack('<I', 2) + attr('channels', 'chlist', channels)
          + attr('compression', 'compression', b'\0') + attr('dataWindow', 'box2i', struct.pack('<4i', 0, 0, 3, 199999))
          + attr('displayWindow', 'box2i', struct.pack('<4i', 0, 0, 3, 3)) + attr('lineOrder', 'lineOrder', b'\0')
          + attr('pixelAspectRatio', 'float', struct.pack('<f', 1)) + attr('screenWindowCenter', 'v2f', struct.pack('<2f', 0, 0))
          + attr('screenWindowWidth', 'float', struct.pack('<f', 1)) + b'\0')
open('tall.exr', 'wb').write(header + bytes(64))
open('taller.exr', 'wb').write(header.replace(struct.pack('<4i', 0, 0, 3, 199999), struct.pack('<4i', 0, 0, 3, 2**31 - 2)) + bytes(64))
small = header.replace(struct.pack('<4i', 0, 0, 3, 199999), struct.pack('<4i', 0, 0, 3, 3))
extra = lambda a: small[:8] + a + small[8:]
# A string vector whose one string claims 2 GB (OpenEXR allocates it), a channel list that runs
# past its declared size and a preview larger than its value (OpenEXR reads both by content).
open('strings.exr', 'wb').write(extra(attr('notes', 'stringvector', struct.pack('<i', 2**31 - 1) + b'abc')) + bytes(64))
open('chlist.exr', 'wb').write(extra(attr('channels', 'chlist', channels)[:-len(channels) - 4] + struct.pack('<i', 4) + channels) + bytes(64))
open('preview.exr', 'wb').write(extra(attr('preview', 'preview', struct.pack('<II', 65535, 65535) + bytes(16))) + bytes(64))
# A multipart file (flag 0x10) whose second header is the one that lies.
part = lambda h: h[8:-1] + attr('name', 'string', b'p') + attr('type', 'string', b'scanlineimage')
tall2 = header[:-1] + attr('chunkCount', 'int', struct.pack('<i', 200000)) + b'\0'
open('multipart.exr', 'wb').write(b'\x76\x2f\x31\x01' + struct.pack('<I', 2 | 0x1000) + part(small + b'') + attr('chunkCount', 'int', struct.pack('<i', 1)) + b'\0'
                                  + part(tall2) + b'\0' + b'\0' + bytes(64))"
check merge_exr_taller_than_its_file 1 'tall.exr": its OpenEXR header declares a 4x200000 data window in 200000 chunks, whose table of offsets alone needs 1600000 bytes' merge tall.exr -o out/m.exr
check merge_exr_side_past_262144 1 'taller.exr": its OpenEXR data window is 4x2147483647; pt reads images of at most 262144 pixels a side' merge taller.exr -o out/m.exr
check merge_exr_string_past_its_attribute 1 'strings.exr": its OpenEXR attribute "notes" of type stringvector declares 7 bytes, which its value does not fill' merge strings.exr -o out/m.exr
check merge_exr_channels_past_their_size 1 'chlist.exr": its OpenEXR attribute "channels" of type chlist declares 4 bytes' merge chlist.exr -o out/m.exr
check merge_exr_preview_past_its_size 1 'preview.exr": its OpenEXR attribute "preview" of type preview declares 24 bytes' merge preview.exr -o out/m.exr
check merge_exr_second_part_lies 1 'multipart.exr": its OpenEXR header declares a 4x200000 data window in 200001 chunks' merge multipart.exr -o out/m.exr
check merge_quiet_still_errs 1 'nowhere.exr' merge -q part_a.exr nowhere.exr -o out/m.exr
check resume_count_past_range 1 '--resume: lie_count.exr: pixel (0, 0) holds 8 samples' render m.obj "${split[@]}" --samples 0:4 --resume lie_count.exr -o out/a.exr

# A good image is never replaced by a failed render.
"$pt" render m.obj -spp 1 --res 8x8 -q -o good.exr >/dev/null || fail "could not render good.exr"
# Loops of symbolic links are named as loops, not as missing files or folders (issue 35).
ln -s loop.obj loop.obj && ln -s loop.mtl loop.mtl && ln -s loop.png loop.png && ln -s loop.hdr loop.hdr && ln -s loopdir loopdir
ln -s nothere.hdr dangling.hdr
printf 'mtllib loop.mtl\n%sf 1 2 3\n' "$tri" > mtllib_loop.obj
printf 'newmtl M\nmap_Kd loop.png\n' > map_loop.mtl
printf 'mtllib map_loop.mtl\n%svt 0 0\nvt 1 0\nvt 0 1\nusemtl M\nf 1/1 2/2 3/3\n' "$tri" > map_loop.obj
check scene_symlink_loop 1 'loop.obj: cannot open: Too many levels of symbolic links' render loop.obj -o out/a.exr
check mtllib_symlink_loop 0 'mtllib_loop.obj:1: mtllib "loop.mtl" is a loop of symbolic links; faces using its materials get the default material' \
  render mtllib_loop.obj -spp 1 --res 8x8 -o out/a.exr
check texture_symlink_loop 0 'map_loop.mtl:2: map_Kd: texture "loop.png" is a loop of symbolic links; using the plain colour' \
  render map_loop.obj -spp 1 --res 8x8 -o out/a.exr
check env_symlink_loop 1 'environment map "loop.hdr" is a loop of symbolic links' render map_loop.obj --env loop.hdr -o out/a.exr
check env_dangling_link 1 'environment map "dangling.hdr" is a symbolic link to a missing file' render map_loop.obj --env dangling.hdr -o out/a.exr
ln -s loop.hdr.exr loop.hdr.exr 2>/dev/null
check output_symlink_loop 2 'output "loop.hdr.exr" is a loop of symbolic links' render map_loop.obj -o loop.hdr.exr
check output_folder_symlink_loop 2 'output "loopdir/a.exr": folder "loopdir" is a loop of symbolic links' render map_loop.obj -o loopdir/a.exr

before=$(md5sum good.exr)
check keeps_good_output 1 "cannot open" render missing.obj -spp 1 -o good.exr
[[ "$(md5sum good.exr)" == "$before" ]] || fail "keeps_good_output: good.exr changed"

finish
