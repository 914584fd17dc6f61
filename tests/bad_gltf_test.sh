#!/usr/bin/env bash
# Bad glTF input: each malformed file meets a clear message naming the file and the glTF object
# at fault (exit 1), or a warning where the specification says what to do (exit 0); never a
# crash, a hang, a silent default or an output file left behind.
# usage: bad_gltf_test.sh PT
source "$(dirname "$0")/bad_input_lib.sh" "$1"

# glTF files (issue 13): each fault names the file and the object at fault; exit 1, nothing written.
# mutate.py IN OUT EXPRESSION: loads a .gltf as `d` and its buffer 0, where a data URI, as `b` (a
# bytearray; empty otherwise), runs EXPRESSION, writes the result. Shorthands: prim, mat and light
# (the first primitive, material and KHR_lights_punctual light), f32(...) (packed floats),
# view(bytes, ...) (appends a bufferView over new bytes of buffer 0 and gives its index); the
# strings "DEEP" and "DEEPOBJ" become 200000 nested arrays and objects.
cat > mutate.py <<'PY'
import base64, json, math, os, struct, sys
d = json.load(open(sys.argv[1]))
uri = d["buffers"][0].get("uri", "")
head, data = uri.split(",", 1) if uri.startswith("data:") else ("", "")
b = bytearray(base64.b64decode(data))
length = len(b)
f32 = lambda *v: struct.pack("<%df" % len(v), *v)
def view(data, **extra):
    while len(b) % 4: b.append(0)
    d["bufferViews"].append(dict(buffer=0, byteOffset=len(b), byteLength=len(data), **extra))
    b.extend(data)
    return len(d["bufferViews"]) - 1
prim = d["meshes"][0]["primitives"][0]
mat = (d.get("materials") or [{}])[0]
light = d.get("extensions", {}).get("KHR_lights_punctual", {}).get("lights", [{}])[0]
exec(sys.argv[3])
if head and d["buffers"][0].get("uri") == uri:
    d["buffers"][0]["uri"] = head + "," + base64.b64encode(bytes(b)).decode()
    if len(b) != length: d["buffers"][0]["byteLength"] = len(b)
s = json.dumps(d).replace('"DEEP"', "[" * 200000 + "]" * 200000)
open(sys.argv[2], "w").write(s.replace('"DEEPOBJ"', '{"a":' * 200000 + "1" + "}" * 200000))
PY
mutate() { /usr/bin/python3 mutate.py "$gltf/$1" "$2" "$3"; }
mutate plane_point.gltf past_buffer.gltf 'd["accessors"][0]["count"] = 100000'
mutate plane_point.gltf past_view.gltf 'd["accessors"][0]["byteOffset"] = 40'
mutate plane_point.gltf bad_index.gltf 'i = d["meshes"][0]["primitives"][0]["indices"]; v = d["bufferViews"][d["accessors"][i]["bufferView"]]; struct.pack_into("<I", b, v["byteOffset"] + 4, 999)'
mutate plane_point.gltf nan_position.gltf 'v = d["bufferViews"][d["accessors"][0]["bufferView"]]; struct.pack_into("<f", b, v["byteOffset"] + 8, math.nan)'
mutate plane_point.gltf bad_material.gltf 'd["meshes"][0]["primitives"][0]["material"] = 7'
mutate plane_point.gltf cycle.gltf 'd["nodes"][0]["children"] = [0]'
mutate plane_point.gltf bad_node.gltf 'd["scenes"][0]["nodes"].append(42)'
mutate plane_point.gltf draco.gltf 'd["extensionsRequired"] = ["KHR_draco_mesh_compression"]; d["extensionsUsed"] = ["KHR_draco_mesh_compression"]'
mutate plane_point.gltf meshopt.gltf 'd["extensionsRequired"] = ["EXT_meshopt_compression"]; d["extensionsUsed"] = ["EXT_meshopt_compression"]'
mutate plane_point.gltf used_only.gltf 'd["extensionsUsed"] = ["KHR_materials_iridescence"]'
mutate plane_point.gltf bad_stride.gltf 'd["bufferViews"][0]["byteStride"] = 4'
mutate plane_point.gltf view_past_buffer.gltf 'd["bufferViews"][0]["byteLength"] = 1 << 20'
mutate plane_point.gltf bad_alpha_mode.gltf 'd["materials"][0]["alphaMode"] = "CUTOUT"'
mutate plane_point.gltf bad_roughness.gltf 'd["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = 2.0'
mutate plane_point.gltf bad_spot.gltf 'd["extensions"]["KHR_lights_punctual"]["lights"][0] = {"type": "spot", "spot": {"innerConeAngle": 0.6, "outerConeAngle": 0.5}}'
mutate plane_point.gltf bad_light_type.gltf 'd["extensions"]["KHR_lights_punctual"]["lights"][0]["type"] = "area"'
mutate plane_point.gltf bad_camera.gltf 'd["cameras"][0]["type"] = "fisheye"'
mutate plane_point.gltf bad_transmission.gltf 'd["materials"][0]["extensions"] = {"KHR_materials_transmission": {"transmissionFactor": 2}}'
mutate plane_point.gltf bad_specular_color.gltf 'd["materials"][0]["extensions"] = {"KHR_materials_specular": {"specularColorFactor": [1, -1, 0]}}'
mutate plane_point.gltf bad_specular.gltf 'd["materials"][0]["extensions"] = {"KHR_materials_specular": {"specularFactor": "high"}}'
mutate plane_point.gltf bad_clearcoat.gltf 'd["materials"][0]["extensions"] = {"KHR_materials_clearcoat": {"clearcoatFactor": 1.5}}'
mutate plane_point.gltf nan_clearcoat.gltf 'd["materials"][0]["extensions"] = {"KHR_materials_clearcoat": {"clearcoatRoughnessFactor": "NaN"}}'
mutate plane_point.gltf clearcoat_texture.gltf 'd["materials"][0]["extensions"] = {"KHR_materials_clearcoat": {"clearcoatFactor": 1, "clearcoatTexture": {"index": 7}}}'
mutate clearcoat.gltf clearcoat_normal_scale.gltf '[m for m in d["materials"] if m["name"] == "TexturedCoat"][0]["extensions"]["KHR_materials_clearcoat"]["clearcoatNormalTexture"]["scale"] = 1e9'
mutate plane_point.gltf volume_thickness.gltf 'd["materials"][0]["extensions"] = {"KHR_materials_transmission": {"transmissionFactor": 1}, "KHR_materials_volume": {"thicknessFactor": -1}}'
mutate plane_point.gltf volume_distance.gltf 'd["materials"][0]["extensions"] = {"KHR_materials_transmission": {"transmissionFactor": 1}, "KHR_materials_volume": {"thicknessFactor": 1, "attenuationDistance": 0}}'
mutate plane_point.gltf volume_color.gltf 'd["materials"][0]["extensions"] = {"KHR_materials_transmission": {"transmissionFactor": 1}, "KHR_materials_volume": {"thicknessFactor": 1, "attenuationColor": [1, "NaN", 0]}}'
mutate plane_point.gltf transmission_texture.gltf 'd["materials"][0]["extensions"] = {"KHR_materials_transmission": {"transmissionFactor": 1, "transmissionTexture": {"index": 9}}}'
mutate plane_point.gltf specular_texture.gltf 'd["materials"][0]["extensions"] = {"KHR_materials_specular": {"specularColorTexture": {"index": -1}}}'
mutate plane_point.gltf sheen_color.gltf 'd["materials"][0]["extensions"] = {"KHR_materials_sheen": {"sheenColorFactor": [1, 2, 0]}}'
mutate plane_point.gltf sheen_roughness.gltf 'd["materials"][0]["extensions"] = {"KHR_materials_sheen": {"sheenColorFactor": [1, 1, 1], "sheenRoughnessFactor": "NaN"}}'
mutate plane_point.gltf sheen_texture.gltf 'd["materials"][0]["extensions"] = {"KHR_materials_sheen": {"sheenColorFactor": [1, 1, 1], "sheenRoughnessTexture": {"index": 3}}}'
mutate plane_point.gltf unlit_value.gltf 'd["materials"][0]["extensions"] = {"KHR_materials_unlit": True}'
mutate plane_point.gltf thin_walled.gltf 'd["materials"][0]["extensions"] = {"KHR_materials_transmission": {"transmissionFactor": 0.5}}'
mutate plane_point.gltf lines.gltf 'd["meshes"][0]["primitives"][0]["mode"] = 1'
mkdir -p lonely && cp "$gltf/bin_and_image.gltf" lonely/
mkdir -p no_image && cp "$gltf/bin_and_image.gltf" "$gltf/bin_and_image.bin" no_image/
head -c 700 "$gltf/transforms.glb" > truncated.glb
/usr/bin/python3 -c "import struct,sys; b=bytearray(open(sys.argv[1],'rb').read()); struct.pack_into('<I', b, 12, 1 << 30); open('bad_chunk.glb','wb').write(b)" "$gltf/transforms.glb"
printf '{"asset": {"version": "2.0"}, "nodes": [' > not_json.gltf
printf 'glTF\x02\x00\x00\x00' > tiny.glb
check gltf_past_buffer 1 'past_buffer.gltf: mesh 0 primitive 0 POSITION, accessor 0: 100000 elements from byte 0 pass the end of bufferView 0 (48 bytes)' render past_buffer.gltf -o out/a.exr
check gltf_past_view 1 'past_view.gltf: mesh 0 primitive 0 POSITION, accessor 0: 4 elements from byte 40 pass the end' render past_view.gltf -o out/a.exr
check gltf_bad_index 1 'bad_index.gltf: mesh 0 primitive 0 indices, accessor 2: index 1 is 999, past the primitive'"'"'s 4 vertices' render bad_index.gltf -o out/a.exr
check gltf_nan_position 1 'nan_position.gltf: mesh 0 primitive 0 POSITION, accessor 0: element 0 component 2 is not a finite number' render nan_position.gltf -o out/a.exr
check gltf_bad_material 1 'mesh 0 primitive 0: material 7 does not exist' render bad_material.gltf -o out/a.exr
check gltf_cycle 1 'node 0 is reached twice in the node hierarchy' render cycle.gltf -o out/a.exr
check gltf_bad_node 1 'node 42 does not exist' render bad_node.gltf -o out/a.exr
check gltf_draco 1 'requires the extension KHR_draco_mesh_compression, which pt does not support' render draco.gltf -o out/a.exr
check gltf_meshopt 1 'requires the extension EXT_meshopt_compression' render meshopt.gltf -o out/a.exr
check gltf_used_only 0 'uses the extension KHR_materials_iridescence, which pt ignores' render used_only.gltf -spp 1 --res 8x8 -o out/a.exr
check gltf_bad_stride 1 'byteStride 4 is below the element size 12' render bad_stride.gltf -o out/a.exr
check gltf_view_past_buffer 1 'pass the end of buffer 0' render view_past_buffer.gltf -o out/a.exr
check gltf_bad_alpha_mode 1 'alphaMode "CUTOUT"; expected OPAQUE, MASK or BLEND' render bad_alpha_mode.gltf -o out/a.exr
check gltf_bad_roughness 1 'material 0 "White": pbrMetallicRoughness.roughnessFactor 2.0 must be a number in [0, 1]' render bad_roughness.gltf -o out/a.exr
check gltf_bad_spot 1 'spot cone angles must satisfy 0 <= inner < outer <= pi/2' render bad_spot.gltf -o out/a.exr
check gltf_bad_light_type 1 'type "area"; expected point, spot or directional' render bad_light_type.gltf -o out/a.exr
check gltf_bad_camera 1 'bad_camera.gltf: camera 0 "Down": type "fisheye"; expected perspective or orthographic' render bad_camera.gltf -o out/a.exr
check gltf_bad_transmission 1 'material 0 "White": extensions.KHR_materials_transmission.transmissionFactor 2 must be a number in [0, 1]' render bad_transmission.gltf -o out/a.exr
check gltf_bad_specular_color 1 'extensions.KHR_materials_specular.specularColorFactor must be an array of 3 numbers of at least 0, found -1 in it' render bad_specular_color.gltf -o out/a.exr
check gltf_bad_specular 1 'extensions.KHR_materials_specular.specularFactor must be a number, found "high"' render bad_specular.gltf -o out/a.exr
check gltf_bad_clearcoat 1 'extensions.KHR_materials_clearcoat.clearcoatFactor 1.5 must be a number in [0, 1]' render bad_clearcoat.gltf -o out/a.exr
check gltf_nan_clearcoat 1 'extensions.KHR_materials_clearcoat.clearcoatRoughnessFactor must be a number, found "NaN"' render nan_clearcoat.gltf -o out/a.exr
check gltf_clearcoat_texture 1 'extensions.KHR_materials_clearcoat.clearcoatTexture.index: texture 7 does not exist' render clearcoat_texture.gltf -o out/a.exr
check gltf_clearcoat_normal_scale 1 'KHR_materials_clearcoat clearcoatNormalTexture: scale 1e+09 is beyond +-1e6' render clearcoat_normal_scale.gltf -o out/a.exr
check gltf_volume_thickness 1 'extensions.KHR_materials_volume.thicknessFactor -1 must be a number' render volume_thickness.gltf -o out/a.exr
check gltf_volume_distance 1 'extensions.KHR_materials_volume.attenuationDistance 0 must be a number' render volume_distance.gltf -o out/a.exr
check gltf_volume_color 1 'extensions.KHR_materials_volume.attenuationColor must be an array of 3 numbers' render volume_color.gltf -o out/a.exr
check gltf_transmission_texture 1 'extensions.KHR_materials_transmission.transmissionTexture.index: texture 9 does not exist' render transmission_texture.gltf -o out/a.exr
check gltf_specular_texture 1 'extensions.KHR_materials_specular.specularColorTexture.index' render specular_texture.gltf -o out/a.exr
check gltf_sheen_color 1 'extensions.KHR_materials_sheen.sheenColorFactor must be an array of 3 numbers' render sheen_color.gltf -o out/a.exr
check gltf_sheen_roughness 1 'extensions.KHR_materials_sheen.sheenRoughnessFactor must be a number, found "NaN"' render sheen_roughness.gltf -o out/a.exr
check gltf_sheen_texture 1 'extensions.KHR_materials_sheen.sheenRoughnessTexture.index: texture 3 does not exist' render sheen_texture.gltf -o out/a.exr
check gltf_unlit_value 1 'extensions.KHR_materials_unlit must be an object' render unlit_value.gltf -o out/a.exr
check gltf_thin_walled 0 'without KHR_materials_volume (or with thicknessFactor 0) the surface is thin-walled' render thin_walled.gltf -spp 1 --res 8x8 -o out/a.exr
check gltf_lines 0 '1 point or line primitives skipped' render lines.gltf -spp 1 --res 8x8 -o out/a.exr
check gltf_missing_bin 1 'lonely/bin_and_image.gltf: buffer 0: "lonely/bin_and_image.bin" cannot be opened: No such file or directory' render lonely/bin_and_image.gltf -o out/a.exr
check gltf_missing_image 1 'material 0 "Checker" baseColorTexture: image 0: texture "no_image/checker.png" not found' render no_image/bin_and_image.gltf -o out/a.exr
check gltf_truncated 1 'truncated.glb' render truncated.glb -o out/a.exr
check gltf_bad_chunk 1 'bad_chunk.glb' render bad_chunk.glb -o out/a.exr
check gltf_not_json 1 'not_json.gltf' render not_json.gltf -o out/a.exr
check gltf_tiny 1 'tiny.glb' render tiny.glb -o out/a.exr
mkdir -p folder.gltf
check gltf_folder 1 'folder.gltf: not a regular file' render folder.gltf -o out/a.exr
check gltf_missing 1 'nowhere.glb: cannot open: No such file or directory' render nowhere.glb -o out/a.exr

# Hostile glTF files: one case for each defect a hostile test found, by class.
cp "$gltf/bin_and_image.bin" "$gltf/checker.png" .
# quick NAME STATUS TEXT pt-arguments...: check(), and fail where pt took 10 s or more to answer
# (it waited on a pipe, or read a whole file it should have refused at once). check()'s timeout
# only sends TERM, which pt blocked in open() on a FIFO never acts on: here pt is also killed at 12 s.
printf '#!/bin/sh\nexec timeout -k 2 10 "%s" "$@"\n' "$pt" > pt_killed_at_12s && chmod +x pt_killed_at_12s
quick() {
  local start pt=$PWD/pt_killed_at_12s
  start=$(date +%s%N)
  check "$@"
  (( ($(date +%s%N) - start) / 1000000 < 10000 )) || fail "$1: took more than 10 s to refuse"
}
# pfm NAME VALUE: a 2x2 float texture (PFM) of VALUE in every channel.
pfm() { /usr/bin/python3 -c "import struct, sys; open(sys.argv[1], 'wb').write(b'PF\n2 2\n-1.0\n' + struct.pack('<12f', *[float(sys.argv[2])] * 12))" "$@"; }

# Crashes (stack overflow, Embree's ray assertion, reads past the end of a buffer or file).
mutate plane_point.gltf deep_extras.gltf 'd["nodes"][0]["extras"] = "DEEP"'
mutate plane_point.gltf deep_extension.gltf 'mat["extensions"] = {"FOO": "DEEPOBJ"}'
mutate plane_point.gltf deep_light.gltf 'light["name"] = "DEEP"'
mutate bin_and_image.gltf image_view_2p40.gltf 'd["bufferViews"].append({"buffer": 0, "byteOffset": 2**40, "byteLength": 81}); d["images"][0] = {"bufferView": 4, "mimeType": "image/png"}'
mutate bin_and_image.gltf image_view_1e8.gltf 'd["bufferViews"].append({"buffer": 0, "byteLength": 100000000}); d["images"][0] = {"bufferView": 4, "mimeType": "image/png"}'
# transforms.glb's BIN chunk header is at byte 1136 and declares 216 bytes; 224 reach 8 bytes past the file.
/usr/bin/python3 -c "import struct,sys; b=bytearray(open(sys.argv[1],'rb').read()); struct.pack_into('<I', b, 1136, 224); open('bin_lies.glb','wb').write(b)" "$gltf/transforms.glb"
mutate plane_point.gltf camera_far.gltf 'd["nodes"][2]["translation"] = [0, 1e20, 0]'
mutate plane_point.gltf ortho_2e18.gltf 'd["cameras"][0]["orthographic"].update(xmag=2e18, ymag=2e18)'
mutate plane_point.gltf up_parallel.gltf 'd["nodes"][2] = {"camera": 0, "matrix": [1, 0, 0, 0, 0, -1, 1e-45, 0, 0, 1, 0, 0, 0, 10, 0, 1]}'
check gltf_deep_extras 1 'deep_extras.gltf:1: arrays and objects nest deeper than 128 levels; pt reads at most that' render deep_extras.gltf -o out/a.exr
check gltf_deep_extension 1 'deep_extension.gltf:1: arrays and objects nest deeper than 128 levels' render deep_extension.gltf -o out/a.exr
check gltf_deep_light 1 'deep_light.gltf:1: arrays and objects nest deeper than 128 levels' render deep_light.gltf -o out/a.exr
check gltf_image_view_2p40 1 'image_view_2p40.gltf: bufferView 4: bytes 1099511627776 to 1099511627857 pass the end of buffer 0 (152 bytes)' render image_view_2p40.gltf -o out/a.exr
check gltf_image_view_1e8 1 'image_view_1e8.gltf: bufferView 4: bytes 0 to 100000000 pass the end of buffer 0 (152 bytes)' render image_view_1e8.gltf -o out/a.exr
check gltf_bin_lies 1 'bin_lies.glb: the chunk at byte 1136 declares 224 bytes, past the end of the file' render bin_lies.glb -o out/a.exr
check gltf_camera_far 1 'camera_far.gltf: camera "Down": its position or target lies beyond 1e12' render camera_far.gltf -o out/a.exr
check gltf_ortho_2e18 1 'ortho_2e18.gltf: camera "Down": its orthographic half-height 2e+18 is outside [0.001, 1e12]' render ortho_2e18.gltf -o out/a.exr
check gltf_up_parallel 1 'up_parallel.gltf: camera "Down": its up direction is zero or parallel to its view direction' render up_parallel.gltf -o out/a.exr

# Hangs: a buffer or image file that is a pipe, a device, a folder or a sparse 8 GB file is
# refused at once.
mkfifo fifo && ln -s /dev/zero zero.bin && mkdir -p folder.bin && truncate -s 8G sparse.bin
for f in fifo zero.bin folder.bin sparse.bin; do mutate bin_and_image.gltf "buffer_$f.gltf" "d['buffers'][0]['uri'] = '$f'"; done
for f in fifo sparse.bin; do mutate bin_and_image.gltf "image_$f.gltf" "d['images'][0]['uri'] = '$f'"; done
quick gltf_buffer_fifo 1 'buffer_fifo.gltf: buffer 0: "fifo" is not a regular file (a folder, device or pipe)' render buffer_fifo.gltf -o out/a.exr
quick gltf_buffer_dev_zero 1 'buffer_zero.bin.gltf: buffer 0: "zero.bin" is not a regular file' render buffer_zero.bin.gltf -o out/a.exr
quick gltf_buffer_folder 1 'buffer_folder.bin.gltf: buffer 0: "folder.bin" is not a regular file' render buffer_folder.bin.gltf -o out/a.exr
quick gltf_buffer_sparse 1 "buffer_sparse.bin.gltf: buffer 0: \"sparse.bin\" has 8589934592 bytes; its byteLength says 152" render buffer_sparse.bin.gltf -o out/a.exr
quick gltf_image_fifo 1 'image_fifo.gltf: material 0 "Checker" baseColorTexture: image 0: texture "fifo" is not a regular file' render image_fifo.gltf -o out/a.exr
quick gltf_image_sparse 1 'image_sparse.bin.gltf: material 0 "Checker" baseColorTexture: image 0: cannot read texture "sparse.bin": not an image file pt reads' render image_sparse.bin.gltf -o out/a.exr
rm -f sparse.bin

# Memory: counts a small file cannot back. (Not here, as each needs half this machine's memory
# read or built before it is refused: many nodes instancing a mesh past the triangle memory bound,
# many buffers naming one file past half the memory.)
mutate plane_point.gltf count_2p40.gltf 'd["accessors"][0]["count"] = 2**40'
mutate plane_point.gltf count_max.gltf 'd["accessors"][0]["count"] = 2**32 - 1'
mutate plane_point.gltf sparse_only.gltf 'd["accessors"][0] = dict(componentType=5126, count=3 * 2**26, type="VEC3", sparse=dict(count=1, indices=dict(bufferView=view(struct.pack("<I", 0)), componentType=5125), values=dict(bufferView=view(f32(0, 5, 0))))); del prim["indices"]'
check gltf_count_2p40 1 'count_2p40.gltf: accessor 0: count 1099511627776 is outside [1, 4294967295]' render count_2p40.gltf -o out/a.exr
check gltf_count_max 1 'count_max.gltf: mesh 0 primitive 0 POSITION, accessor 0: 4294967295 elements from byte 0 pass the end of bufferView 0 (48 bytes)' render count_max.gltf -o out/a.exr
check gltf_sparse_only 1 'sparse_only.gltf: mesh 0 primitive 0 POSITION, accessor 0: a count of 201326592 with no buffer behind it (at most 2^24)' render sparse_only.gltf -o out/a.exr

# Silent defaults, now refused: a value of the wrong type, size or range, or a missing one.
g() { mutate "$1" "$2.gltf" "$3"; } # g SEED NAME EXPRESSION: mutate into NAME.gltf
g plane_point.gltf required_string 'd["extensionsRequired"] = "EXT_foo"'
g plane_point.gltf index_2p32 'd["nodes"][0]["mesh"] = 2**32'
g plane_point.gltf index_string 'prim["indices"] = "2"'
g plane_point.gltf index_negative 'prim["material"] = -7'
g plane_point.gltf index_float 'prim["indices"] = 2.0'
g plane_point.gltf light_index_string 'd["nodes"][1]["extensions"]["KHR_lights_punctual"]["light"] = "0"'
g plane_point.gltf emissive2 'mat["emissiveFactor"] = [1, 1]'
g plane_point.gltf light_color2 'light["color"] = [1, 0]'
g textured.gltf base_color3 'mat["pbrMetallicRoughness"]["baseColorFactor"] = [1, 1, 1]'
g textured.gltf offset_strings 'mat["pbrMetallicRoughness"]["baseColorTexture"]["extensions"] = {"KHR_texture_transform": {"offset": ["0.5", "0.5"]}}'
g plane_point.gltf range_tiny 'light["range"] = 1e-300'
g plane_point.gltf ortho_tiny 'd["cameras"][0]["orthographic"].update(xmag=1e-30, ymag=1e-30)'
g cameras.gltf yfov_tiny 'd["cameras"][0]["perspective"]["yfov"] = 1e-300'
g cameras.gltf aspect_huge 'd["cameras"][0]["perspective"]["aspectRatio"] = 1e39'
g textured.gltf texcoord1_missing 'mat["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 1'
g textured.gltf no_attributes 'del d["meshes"][1]["primitives"][0]["attributes"]'
g vertex_colors.gltf wrap_float 'd["samplers"][0]["wrapS"] = 33071.0'
g vertex_colors.gltf wrap_unknown 'd["samplers"][0]["wrapS"] = 1234'
g plane_point.gltf sparse_unsorted 'd["accessors"][0]["sparse"] = dict(count=3, indices=dict(bufferView=view(struct.pack("<3I", 2, 2, 0)), componentType=5125), values=dict(bufferView=view(f32(*[5] * 9))))'
g plane_point.gltf index_stride 'd["accessors"][2].update(bufferView=view(struct.pack("<6I", 0, 0, 1, 0, 2, 0), byteStride=8), count=3)'
g plane_point.gltf matrix_and_trs 'd["nodes"][2]["matrix"] = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 10, 0, 1]'
g plane_point.gltf not_affine 'd["nodes"][0]["matrix"] = [1, 0, 0, 0, 0, 1, 0, 0.5, 0, 0, 1, 0, 0, 0, 0, 3]'
g plane_point.gltf zfar_below 'd["cameras"][0]["orthographic"].update(znear=100, zfar=1)'
g plane_point.gltf no_uri 'del d["buffers"][0]["uri"]'
g plane_point.gltf uri_length 'd["buffers"][0]["byteLength"] = 121'
g bin_and_image.gltf image_no_mime 'd["bufferViews"].append({"buffer": 0, "byteLength": 81}); d["images"][0] = {"bufferView": 4}'
g plane_point.gltf unaligned 'd["accessors"][0]["byteOffset"] = 1; d["accessors"][0]["count"] = 3'
g plane_point.gltf version3 'd["asset"]["version"] = "3.0"'
g vertex_colors.gltf color_negative 'd["accessors"][0] = dict(bufferView=view(f32(*[-5] * 12)), componentType=5126, count=4, type="VEC3")'
g vertex_colors.gltf color_huge 'd["accessors"][0] = dict(bufferView=view(f32(*[3e38] * 12)), componentType=5126, count=4, type="VEC3")'
g plane_point.gltf light_far 'd["nodes"][1]["translation"] = [0, 1e30, 0]'
g tangents.gltf normal_scale_huge 'mat["normalTexture"]["scale"] = 1e308'
g plane_spot.gltf spot_equal 'light["spot"] = {"innerConeAngle": 0.5, "outerConeAngle": 0.5 + 1e-12}'
g bin_and_image.gltf uri_nul 'd["images"][0]["uri"] = "checker.png%00.jpg"'
g bin_and_image.gltf uri_absolute 'd["buffers"][0]["uri"] = os.getcwd() + "/bin_and_image.bin"'
g textured.gltf ktt_scale_1e30 'mat["pbrMetallicRoughness"]["baseColorTexture"]["extensions"] = {"KHR_texture_transform": {"scale": [1e30, 1e30]}}'
g plane_point.gltf nodes_string 'd["nodes"] = "x"'
g plane_point.gltf scene_without_scenes 'del d["scenes"]; d["scene"] = 5'
g plane_point.gltf image_data_corrupt 'd["images"] = [{"uri": "data:image/png;base64,iVBORw0KGgoAAAAA"}]; d["textures"] = [{"source": 0}]; mat["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}'
cp "$gltf/transforms.glb" glb_bytes.gltf
check gltf_required_string 1 'required_string.gltf: extensionsRequired must be an array, found "EXT_foo"' render required_string.gltf -o out/a.exr
check gltf_index_2p32 1 'index_2p32.gltf: node 0 "Plane": mesh 4294967296 is outside [0, 2147483647]' render index_2p32.gltf -o out/a.exr
check gltf_index_string 1 'index_string.gltf: mesh 0 primitive 0: indices must be an integer, found "2"' render index_string.gltf -o out/a.exr
check gltf_index_negative 1 'index_negative.gltf: mesh 0 primitive 0: material -7 is outside [0, 2147483647]' render index_negative.gltf -o out/a.exr
check gltf_index_float 1 'index_float.gltf: mesh 0 primitive 0: indices must be an integer, found 2.0' render index_float.gltf -o out/a.exr
check gltf_light_index_string 1 'light_index_string.gltf: node 1: extensions.KHR_lights_punctual.light must be an integer, found "0"' render light_index_string.gltf -o out/a.exr
check gltf_emissive2 1 'emissive2.gltf: material 0 "White": emissiveFactor must be an array of 3 numbers in [0, 1], found an array of 2' render emissive2.gltf -o out/a.exr
check gltf_light_color2 1 'light_color2.gltf: KHR_lights_punctual light 0: color must be an array of 3 numbers in [0, 1], found an array of 2' render light_color2.gltf -o out/a.exr
check gltf_base_color3 1 'base_color3.gltf: material 0 "Tile": pbrMetallicRoughness.baseColorFactor must be an array of 4 numbers in [0, 1], found an array of 3' render base_color3.gltf -o out/a.exr
check gltf_offset_strings 1 'offset_strings.gltf: material 0 "Tile": pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform.offset must be an array of 2 numbers, found "0.5" in it' render offset_strings.gltf -o out/a.exr
check gltf_range_tiny 1 "range_tiny.gltf: light 0: range 1e-300 underflows float (0 would mean no range)" render range_tiny.gltf -o out/a.exr
check gltf_ortho_tiny 1 'ortho_tiny.gltf: camera "Down": its orthographic half-height 1e-30 is outside [0.001, 1e12]' render ortho_tiny.gltf -o out/a.exr
check gltf_yfov_tiny 1 'yfov_tiny.gltf: camera "Wide": its field of view 0 degrees is outside [0.01, 180)' render yfov_tiny.gltf -o out/a.exr
check gltf_aspect_huge 1 'aspect_huge.gltf: camera "Wide": its aspect ratio 1e+39 is outside [1/65536, 65536]' render aspect_huge.gltf -o out/a.exr
check gltf_texcoord1_missing 1 'texcoord1_missing.gltf: mesh 0 primitive 0: its material 0 reads textures through TEXCOORD_1, which the primitive does not have' render texcoord1_missing.gltf -o out/a.exr
check gltf_no_attributes 1 'no_attributes.gltf: mesh 1 primitive 0: attributes is missing' render no_attributes.gltf -o out/a.exr
check gltf_wrap_float 1 'wrap_float.gltf: sampler 0: wrapS must be an integer, found 33071.0' render wrap_float.gltf -o out/a.exr
check gltf_wrap_unknown 1 'wrap_unknown.gltf: sampler 0: wrapS 1234; expected 33071, 33648 or 10497' render wrap_unknown.gltf -o out/a.exr
check gltf_sparse_unsorted 1 'sparse_unsorted.gltf: mesh 0 primitive 0 POSITION, accessor 0: sparse index 1 is 2, not above the one before it (they must strictly increase)' render sparse_unsorted.gltf -o out/a.exr
check gltf_index_stride 1 'index_stride.gltf: mesh 0 primitive 0 indices, accessor 2: bufferView 3 of indices has a byteStride; index views are packed' render index_stride.gltf -o out/a.exr
check gltf_matrix_and_trs 1 'matrix_and_trs.gltf: node 2 "Down": matrix and translation are both given; a node has one or the other' render matrix_and_trs.gltf -o out/a.exr
check gltf_not_affine 1 'not_affine.gltf: node 0 "Plane": matrix is not affine: its last row must be 0, 0, 0, 1' render not_affine.gltf -o out/a.exr
check gltf_zfar_below 1 'zfar_below.gltf: camera 0 "Down": orthographic.zfar 1 is not beyond znear 100' render zfar_below.gltf -o out/a.exr
check gltf_no_uri 1 'no_uri.gltf: buffer 0: uri is missing' render no_uri.gltf -o out/a.exr
check gltf_uri_length 1 'uri_length.gltf: buffer 0: uri holds 120 bytes of base64 data; byteLength says 121' render uri_length.gltf -o out/a.exr
check gltf_image_no_mime 1 'image_no_mime.gltf: image 0: mimeType is missing; an image in a bufferView needs it' render image_no_mime.gltf -o out/a.exr
check gltf_unaligned 1 'unaligned.gltf: accessor 0: byteOffset 1 is not a multiple of the component size 4' render unaligned.gltf -o out/a.exr
check gltf_version3 1 'version3.gltf: asset.version "3.0"; pt reads glTF 2.0' render version3.gltf -o out/a.exr
check gltf_color_negative 1 'color_negative.gltf: mesh 0 primitive 0 COLOR_0: a component is -5; vertex colours multiply the base colour and must lie in [0, 10]' render color_negative.gltf -o out/a.exr
check gltf_color_huge 1 'color_huge.gltf: mesh 0 primitive 0 COLOR_0: a component is 3e+38' render color_huge.gltf -o out/a.exr
check gltf_light_far 1 'light_far.gltf: light "light 0": it lies beyond 1e12, the largest coordinate pt renders correctly' render light_far.gltf -o out/a.exr
check gltf_normal_scale_huge 1 'normal_scale_huge.gltf: material 0 "Mapped": normalTexture.scale 1e+308 is beyond +-1e6' render normal_scale_huge.gltf -o out/a.exr
check gltf_spot_equal 1 'spot_equal.gltf: light 0: spot cone angles 0.5 and 0.5 have the same cosine in float; make the outer cone wider' render spot_equal.gltf -o out/a.exr
check gltf_uri_nul 1 'uri_nul.gltf: image 0: uri "checker.png%00.jpg" holds an encoded NUL (%00)' render uri_nul.gltf -o out/a.exr
check gltf_uri_absolute 1 "uri_absolute.gltf: buffer 0: uri \"$PWD/bin_and_image.bin\" is not a relative path" render uri_absolute.gltf -o out/a.exr
check gltf_ktt_scale_1e30 1 'ktt_scale_1e30.gltf: material "Tile": its diffuse or base colour texture'"'"'s coordinate transform has 1e+30, beyond +-1e4' render ktt_scale_1e30.gltf -o out/a.exr
check gltf_nodes_string 1 'nodes_string.gltf: nodes must be an array, found "x"' render nodes_string.gltf -o out/a.exr
check gltf_scene_without_scenes 1 'scene_without_scenes.gltf: scene 5 does not exist (the file has 0)' render scene_without_scenes.gltf -o out/a.exr
check gltf_image_data_corrupt 1 'image_data_corrupt.gltf: material 0 "White" baseColorTexture: image 0: cannot decode image_data_corrupt.gltf image 0' render image_data_corrupt.gltf -o out/a.exr
check gltf_glb_bytes 0 '-> out/a.exr' render glb_bytes.gltf -spp 1 --res 8x8 -o out/a.exr

# NaN: float textures that are not finite, negative, or overflow with their factor; texture
# coordinates of 3e38 render without a NaN.
pfm nan.pfm nan && pfm negative.pfm -5 && pfm huge.pfm 3e38
g textured.gltf texture_nan 'd["images"][0] = {"uri": "nan.pfm"}'
g textured.gltf texture_negative 'd["images"][0] = {"uri": "negative.pfm"}'
g textured.gltf texture_huge 'd["images"][3] = {"uri": "huge.pfm"}; mat["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = 1e6'
g textured.gltf uv_huge 'd["accessors"][2]["bufferView"] = view(f32(*[3e38, -3e38] * 4))'
check gltf_texture_nan 1 'texture_nan.gltf: material 0 "Tile" baseColorTexture: image 0: texture "nan.pfm": texel (0, 0) channel 0 is nan; a colour must be finite and not negative' render texture_nan.gltf -o out/a.exr
check gltf_texture_negative 1 'texture_negative.gltf: material 0 "Tile" baseColorTexture: image 0: texture "negative.pfm": texel (0, 0) channel 0 is -5' render texture_negative.gltf -o out/a.exr
check gltf_texture_huge 1 'texture_huge.gltf: material "Tile": its emission texture "huge.pfm" reaches 3e+38, which times its factor 1e+06 passes the radiance limit 1e18' render texture_huge.gltf -o out/a.exr
check gltf_uv_huge 0 '), 0 discarded samples,' render uv_huge.gltf -spp 4 --res 16x16 -o uv_huge.exr
counts=$(oiiotool --stats uv_huge.exr 2>&1 | grep -E 'NanCount|InfCount')
[[ $(grep -cE '(Nan|Inf)Count: (0 )+$' <<< "$counts") -eq 2 ]] || fail "gltf_uv_huge: the image holds NaN or Inf: $counts"

# Issue 35: values float rounds to 0 (which would mean "not orthographic", "no aspect ratio")
# meet the rule of any other value outside the range; a JPEG cut short or damaged is refused as a
# PNG is, from a file and from a data URI.
g plane_point.gltf ortho_1e300 'd["cameras"][0]["orthographic"].update(xmag=1e-300, ymag=1e-300)'
g plane_point.gltf ortho_1e40 'd["cameras"][0]["orthographic"].update(xmag=1e-40, ymag=1e-40)'
g plane_point.gltf ortho_xmag_1e300 'd["cameras"][0]["orthographic"].update(xmag=1e-300)'
g cameras.gltf aspect_1e300 'd["cameras"][0]["perspective"]["aspectRatio"] = 1e-300'
check gltf_ortho_1e300 1 'ortho_1e300.gltf: camera "Down": its orthographic half-height 1e-300 is outside [0.001, 1e12]' render ortho_1e300.gltf -o out/a.exr
check gltf_ortho_1e40 1 'ortho_1e40.gltf: camera "Down": its orthographic half-height 1e-40 is outside [0.001, 1e12]' render ortho_1e40.gltf -o out/a.exr
check gltf_ortho_xmag_1e300 1 'ortho_xmag_1e300.gltf: camera "Down": its aspect ratio 5e-301 is outside [1/65536, 65536]' render ortho_xmag_1e300.gltf -o out/a.exr
check gltf_aspect_1e300 1 'aspect_1e300.gltf: camera "Wide": its aspect ratio 1e-300 is outside [1/65536, 65536]' render aspect_1e300.gltf -o out/a.exr
damaged_jpegs
g textured.gltf jpeg_cut 'd["images"][0] = {"uri": "cut.jpg"}'
g textured.gltf jpeg_garbled 'd["images"][0] = {"uri": "garbled.jpg"}'
g textured.gltf jpeg_cut_data_uri 'import base64; d["images"][0] = {"uri": "data:image/jpeg;base64," + base64.b64encode(open("cut.jpg", "rb").read()).decode()}'
g textured.gltf jpeg_whole 'd["images"][0] = {"uri": "whole.jpg"}'
check gltf_jpeg_cut 1 'jpeg_cut.gltf: material 0 "Tile" baseColorTexture: image 0: cannot read texture "cut.jpg": the file is damaged or cut short (JPEG error: Premature end of JPEG file' render jpeg_cut.gltf -o out/a.exr
check gltf_jpeg_garbled 1 'jpeg_garbled.gltf: material 0 "Tile" baseColorTexture: image 0: cannot read texture "garbled.jpg": the file is damaged or cut short (JPEG error: Corrupt JPEG data' render jpeg_garbled.gltf -o out/a.exr
check gltf_jpeg_cut_data_uri 1 'jpeg_cut_data_uri.gltf: material 0 "Tile" baseColorTexture: image 0: cannot read texture "jpeg_cut_data_uri.gltf image 0": the file is damaged or cut short' render jpeg_cut_data_uri.gltf -o out/a.exr
check gltf_jpeg_whole 0 '-> out/a.exr' render jpeg_whole.gltf -spp 1 --res 8x8 -o out/a.exr
# A normal map of one or two channels (grey, grey and alpha) is dropped with a warning naming
# it, as the MTL's norm is; it was read as three channels, past the end of its texels.
oiiotool --create 4x4 1 -d uint8 -o grey.png >/dev/null 2>&1
oiiotool --create 4x4 2 -d uint8 -o grey_alpha.png >/dev/null 2>&1
g tangents.gltf normal_grey 'd["images"][0] = {"uri": "grey.png"}'
g tangents.gltf normal_grey_alpha 'd["images"][0] = {"uri": "grey_alpha.png"}'
g clearcoat.gltf coat_normal_grey '[m for m in d["materials"] if m["name"] == "TexturedCoat"][0]["extensions"]["KHR_materials_clearcoat"]["clearcoatNormalTexture"]["index"] = len(d["textures"]); d["textures"].append({"source": len(d["images"])}); d["images"].append({"uri": "grey.png"})'
check gltf_normal_grey 0 'normal_grey.gltf: material 0 "Mapped" normalTexture: image "grey.png" has 1 channel (grey); a normal map needs RGB, so it is ignored' render normal_grey.gltf -spp 1 --res 8x8 -o out/a.exr
check gltf_normal_grey_alpha 0 'normal_grey_alpha.gltf: material 0 "Mapped" normalTexture: image "grey_alpha.png" has 2 channels (grey and alpha); a normal map needs RGB' render normal_grey_alpha.gltf -spp 1 --res 8x8 -o out/a.exr
check gltf_coat_normal_grey 0 'KHR_materials_clearcoat clearcoatNormalTexture: image "grey.png" has 1 channel (grey)' render coat_normal_grey.gltf -spp 1 --res 8x8 -o out/a.exr

# Warnings: values the specification defines but that are likely mistakes.
g tangents.gltf tangent_w0 'd["accessors"][4]["bufferView"] = view(f32(*[1, 0, 0, 0] * 4))'
g vertex_colors.gltf color_above1 'd["accessors"][0] = dict(bufferView=view(f32(*[2] * 12)), componentType=5126, count=4, type="VEC3")'
check gltf_tangent_w0 0 'tangent_w0.gltf: mesh 0 primitive 0 TANGENT: w is 0 at vertex 0, not +1 or -1; taken by its sign (0 as +1)' render tangent_w0.gltf -spp 1 --res 8x8 -o out/a.exr
check gltf_color_above1 0 'color_above1.gltf: mesh 0 primitive 0 COLOR_0: components above 1 (up to 2) make the surface reflect more light than it receives' render color_above1.gltf -spp 1 --res 8x8 -o out/a.exr

finish
