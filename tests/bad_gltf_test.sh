#!/usr/bin/env bash
# Bad glTF input: each malformed file meets a clear message naming the file and the glTF object
# at fault (exit 1), or a warning where the specification says what to do (exit 0); never a
# crash, a hang, a silent default or an output file left behind.
# usage: bad_gltf_test.sh PT
source "$(dirname "$0")/bad_input_lib.sh" "$1"

# glTF files (issue 13): each fault names the file and the object at fault; exit 1, nothing written.
# mutate.py IN OUT EXPRESSION: loads a .gltf (JSON, buffer 0 a data URI) as `d` and its buffer as
# `b` (a bytearray), runs EXPRESSION, writes the result.
cat > mutate.py <<'PY'
import base64, json, math, struct, sys
d = json.load(open(sys.argv[1]))
head, data = d["buffers"][0]["uri"].split(",", 1)
b = bytearray(base64.b64decode(data))
exec(sys.argv[3])
d["buffers"][0]["uri"] = head + "," + base64.b64encode(bytes(b)).decode()
json.dump(d, open(sys.argv[2], "w"))
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
mutate plane_point.gltf used_only.gltf 'd["extensionsUsed"] = ["KHR_materials_sheen"]'
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
check gltf_used_only 0 'uses the extension KHR_materials_sheen, which pt ignores' render used_only.gltf -spp 1 --res 8x8 -o out/a.exr
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
check gltf_thin_walled 0 'without KHR_materials_volume the surface is thin-walled' render thin_walled.gltf -spp 1 --res 8x8 -o out/a.exr
check gltf_lines 0 '1 point or line primitives skipped' render lines.gltf -spp 1 --res 8x8 -o out/a.exr
check gltf_missing_bin 1 'bin_and_image.bin' render lonely/bin_and_image.gltf -o out/a.exr
check gltf_missing_image 1 'material 0 "Checker" baseColorTexture: image 0: texture "no_image/checker.png" not found' render no_image/bin_and_image.gltf -o out/a.exr
check gltf_truncated 1 'truncated.glb' render truncated.glb -o out/a.exr
check gltf_bad_chunk 1 'bad_chunk.glb' render bad_chunk.glb -o out/a.exr
check gltf_not_json 1 'not_json.gltf' render not_json.gltf -o out/a.exr
check gltf_tiny 1 'tiny.glb' render tiny.glb -o out/a.exr
mkdir -p folder.gltf
check gltf_folder 1 'folder.gltf: not a regular file' render folder.gltf -o out/a.exr
check gltf_missing 1 'nowhere.glb: cannot open: No such file or directory' render nowhere.glb -o out/a.exr

finish
