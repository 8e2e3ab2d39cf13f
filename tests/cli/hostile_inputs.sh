#!/usr/bin/env bash
# Hostile input (issue #7, point 4): huge counts, NaN/Inf, missing and unreadable files, paths
# escaping the scene's directory, zero-area reflectors, degenerate cameras, wrong CLI types.
# Every case must end with exit code 2, exactly one line on stderr ("ssrlab: <one sentence>.")
# naming the problem, and nothing (no output, no temporary file) in the output directory.
# Inputs are generated here; cases that tests/cli/cli_contract.sh already runs are not repeated.
#
# "A camera inside geometry": what input validation refuses is a camera that cannot form a view
# (position == target, up parallel to the view direction, fov outside (1,179) degrees,
# near <= 0, near >= far, non-finite fields). A camera inside a closed mesh is a legitimate hard
# case (the built-in hard-mirror-box): it must render with exit 0, finite pixels (render exits 1
# on a non-finite value) and a PNG.
set -u
tmp=$(mktemp -d)
trap 'chmod -R u+rwx "$tmp"; rm -rf "$tmp"' EXIT
in="$tmp/in"      # generated scenes, meshes, materials, textures
out="$tmp/out"    # every bad run writes here; it must stay empty
outside="$tmp/outside"  # files outside the scenes' directory, for the escape cases
mkdir -p "$in" "$out" "$outside"
fails=0; passes=0; n=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# bad WANT ARGS...: ssrlab ARGS must exit 2 with one sentence on stderr that mentions WANT
# (case-insensitive) and leave the output directory empty.
bad() {
  local want=$1; shift
  n=$((n + 1))
  timeout 300 "$SSRLAB" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local got=$? why=""
  if [ "$got" != 2 ]; then why="exit $got (want 2)"
  elif [ "$(wc -l <"$tmp/stderr")" != 1 ]; then why="stderr has $(wc -l <"$tmp/stderr") lines (want 1)"
  elif ! grep -qE '^ssrlab: [^ ].*[^ ]\.$' "$tmp/stderr"; then why="stderr is not 'ssrlab: <sentence>.'"
  elif grep -qE '[.!?] +[A-Z]' "$tmp/stderr"; then why="stderr has more than one sentence"
  elif ! grep -qiF -- "$want" "$tmp/stderr"; then why="stderr does not mention '$want'"
  elif [ -n "$(ls -A "$out")" ]; then why="left behind: $(ls -A "$out" | tr '\n' ' ')"
  fi
  if [ -n "$why" ]; then fail "$why: ssrlab $*"; sed 's/^/  | /' "$tmp/stderr" | head -5
  else passes=$((passes + 1)); fi
  rm -rf "${out:?}"/* "$out"/.[!.]* 2>/dev/null
}
# render_bad WANT SCENE: the scene must be refused by render (and by compare/bench, see below).
render_bad() { bad "$1" render --scene "$2" --technique none --size 32x18 --out "$out/x.png"; }

# ---- inputs ------------------------------------------------------------------------------------
cp "$TESTDATA/obj/textures/tex.png" "$in/tex.png"
cp "$TESTDATA/obj/textures/tex.png" "$outside/secret.png"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$outside/outside.obj"
tri='v 0 0 0\nv 1 0 0\nv 0 1 0\n'
obj() { printf "$2" >"$in/$1.obj"; }  # obj NAME CONTENT (printf format)
mtl() { printf "$2" >"$in/$1.mtl"; }
json() { printf '%s\n' "$2" >"$in/$1.json"; }
# A JSON scene: one floor plane plus EXTRA (JSON members after "primitives").
scene() { json "$1" "{\"primitives\": [{\"type\": \"plane\", \"size\": [4, 4]}]${2:+, $2}}"; }
cam() { scene "$1" "\"cameras\": [{\"position\": [0, 1, 4], \"target\": [0, 0, 0]$2}]"; }
refl() { json "$1" "{\"primitives\": [{\"type\": \"plane\", \"size\": [4, 4], \"reflector\": {$2}}]}"; }
obj good "mtllib good.mtl\nusemtl m\n${tri}f 1 2 3\n"
mtl good 'newmtl m\nKd 0.5 0.5 0.5\nmap_Kd tex.png\n'

# ---- huge counts -------------------------------------------------------------------------------
obj huge_index "${tri}f 1 2 4000000000\n";           render_bad 4000000000 "$in/huge_index.obj"
obj max_index "${tri}f 1 2 2147483647\n";            render_bad 2147483647 "$in/max_index.obj"
obj huge_relative "${tri}f -1 -2 -2147483647\n";     render_bad -2147483647 "$in/huge_relative.obj"
obj huge_face "${tri}f$(printf ' 1 2 3%.0s' $(seq 100))\n"; render_bad "300 vertices" "$in/huge_face.obj"
p=""; for i in $(seq 17); do p+="{\"type\": \"plane\", \"size\": [1, 1], \"translate\": [$i, 0, 0], \"reflector\": true},"; done
json reflectors17 "{\"primitives\": [${p%,}]}";      render_bad "16 supported" "$in/reflectors17.json"
l=""; for i in $(seq 33); do l+="{\"type\": \"point\", \"position\": [$i, 1, 0]},"; done
scene lights33 "\"lights\": [${l%,}]";               render_bad "33 lights" "$in/lights33.json"
json segments '{"primitives": [{"type": "sphere", "segments": 100000000, "rings": 3}]}'
render_bad "segments' must be in [3, 1024]" "$in/segments.json"
json rings '{"primitives": [{"type": "sphere", "rings": 100000000}]}'; render_bad "rings' must be in [2, 1024]" "$in/rings.json"
p=$(printf '{"type": "box"},%.0s' $(seq 70000))
json boxes "{\"primitives\": [${p%,}]}";             render_bad "65536 supported" "$in/boxes.json"
# 70000 one-triangle groups: refused from the pre-scan, before tinyobjloader makes 70000 shapes
# (a 1 GiB file of them used to become 50M meshes and draws).
{ printf "$tri"; printf 'g a\nf 1 2 3\n%.0s' $(seq 70000); } >"$in/groups.obj"
render_bad "65536 meshes" "$in/groups.obj"
# A PNG header claiming 10000x20000 pixels (stb_image reads no further to say so; CRCs unchecked).
printf '\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\0\x27\x10\0\0\x4e\x20\x08\x06\0\0\0\0\0\0\0' >"$in/huge.png"
obj tex_huge "mtllib tex_huge.mtl\nusemtl m\n${tri}f 1 2 3\n"; mtl tex_huge 'newmtl m\nmap_Kd huge.png\n'
render_bad 10000x20000 "$in/tex_huge.obj"
# Five flat 8192x8192 PNGs (270 KB each) would decode to 1.3 GiB and upload to several more; the
# scene's textures stop at 2^28 pixels, before the fifth is decoded (this case takes ~2 s, 1.3 GB).
python3 - "$in/flat0.png" <<'PY'
import struct, sys, zlib
def chunk(t, d): return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d))
raw = (b'\0' + b'\x80' * 8192 * 4) * 8192
open(sys.argv[1], 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', 8192, 8192, 8, 6, 0, 0, 0))
                             + chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))
PY
m=""; f=""; for i in 0 1 2 3 4; do [ $i = 0 ] || ln "$in/flat0.png" "$in/flat$i.png"; m+="newmtl m$i\nmap_Kd flat$i.png\n"; f+="usemtl m$i\nf 1 2 3\n"; done
mtl flat "$m"; obj flat "mtllib flat.mtl\n$tri$f";      render_bad "268435456 pixels" "$in/flat.obj"
render_bad reflectors "gallery:reflectors=100000"
render_bad reflectors "gallery:reflectors=99999999999999999999"
bad 16384x16384 render --size 16384x16384 --out "$out/x.png"
bad 100000x100000 compare --size 100000x100000 --out "$out/x.png" --json "$out/r.json"
bad 100000x100000 bench --sizes 64x36,100000x100000 --json "$out/b.json" --csv "$out/b.csv"
bad 40000x8 bench --sizes 40000x8 --techniques none --json "$out/b.json"
bad --frames compare --frames 1e12 --out "$out/x.png"
bad --frames bench --frames 1000000000000 --json "$out/b.json"
bad --warmup bench --warmup 99999999999 --json "$out/b.json"
bad reference.samples render --technique reference --set reference.samples=1000000000 --size 32x18 --out "$out/x.png"
bad reference.samples compare --set reference.samples=1000000000 --size 32x18 --out "$out/x.png"
bad linear.max_steps render --set linear.max_steps=4294967297 --size 32x18 --out "$out/x.png"
v=$(seq -s, 1 1000)
bad variants bench --techniques linear --sweep linear.max_steps=$v --sweep linear.thickness=$v \
  --sweep linear.max_distance=$v --json "$out/b.json"
bad scenes bench --scenes "$(printf 's%d,' $(seq 1000))gallery" --json "$out/b.json"
bad sizes bench --sizes "$(printf "%dx36," $(seq 64 1064))32x18" --json "$out/b.json"
# passfloor: unknown modes and kinds, chains and frames out of range, sizes the GL cannot hold.
bad "pass mode" passfloor --sizes 16x16 --modes cs8x8,cs7x7 --json "$out/p.json"
bad "pass kind" passfloor --sizes 16x16 --kinds taps9x9 --json "$out/p.json"
bad "chain length" passfloor --sizes 16x16 --chains 1,0 --json "$out/p.json"
bad "chain length" passfloor --sizes 16x16 --chains 2.5 --json "$out/p.json"
bad --frames passfloor --sizes 16x16 --frames 0 --json "$out/p.json"
bad 40000x8 passfloor --sizes 40000x8 --json "$out/p.json"
bad "at most 16" passfloor --chains "$(printf '%d,' $(seq 20))21" --json "$out/p.json"
bad "chain length" passfloor --sizes 16x16 --chains +3 --json "$out/p.json"

# ---- the verdict's options ---------------------------------------------------------------------
bad "unknown region 'floor'" compare --regions planar,floor --size 32x18 --out "$out/x.png" --json "$out/r.json"
bad "reflector:3" compare --regions reflector:3 --size 32x18 --out "$out/x.png"
bad "reference.bounces" compare --set reference.bounces=9 --size 32x18 --out "$out/x.png"
bad "reference.bounces" render --technique reference --set reference.bounces=0 --size 32x18 --out "$out/x.png"
obj matte 'v -1 0 -3\nv 1 0 -3\nv 0 1 -3\nf 1 2 3\n'
bad "reflective pixels" compare --scene "$in/matte.obj" --breakdown --size 32x18 --out "$out/x.png" --json "$out/r.json"
bad "hit-classes" render --technique reference --view hit-classes --size 32x18 --out "$out/x.png"

# ---- NaN / Inf / overflow ----------------------------------------------------------------------
obj v_nan 'v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n';       render_bad nan "$in/v_nan.obj"
obj v_inf 'v 0 -inf 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n';      render_bad inf "$in/v_inf.obj"
obj v_1e39 'v 1e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n';     render_bad 1e39 "$in/v_1e39.obj"
obj v_far 'v 1e30 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n';      render_bad 1e7 "$in/v_far.obj"
obj vn_nan "${tri}vn 0 nan 1\nf 1//1 2//1 3//1\n";         render_bad nan "$in/vn_nan.obj"
obj vt_inf "${tri}vt inf 0\nf 1/1 2/1 3/1\n";              render_bad inf "$in/vt_inf.obj"
obj mtl_nan "mtllib nan.mtl\nusemtl m\n${tri}f 1 2 3\n"; mtl nan 'newmtl m\nNs -nan\n'
render_bad nan "$in/mtl_nan.obj"
json t_inf '{"meshes": [{"obj": "good.obj", "translate": [1e999, 0, 0]}]}'; render_bad 1e999 "$in/t_inf.json"
json t_nan '{"meshes": [{"obj": "good.obj", "translate": [NaN, 0, 0]}]}';   render_bad 'JSON syntax error' "$in/t_nan.json"
json rot_big '{"meshes": [{"obj": "good.obj", "rotate_deg": [1e30, 0, 0]}]}'; render_bad rotate_deg "$in/rot_big.json"
json far '{"meshes": [{"obj": "good.obj", "translate": [9.5e6, 0, 0], "scale": 1e6}]}'; render_bad 1e7 "$in/far.json"
scene l_pos '"lights": [{"type": "point", "position": [0, 1e39, 0]}]';    render_bad "lights[0].position" "$in/l_pos.json"
scene l_int '"lights": [{"type": "point", "position": [0, 1, 0], "intensity": -1e999}]'
render_bad -1e999 "$in/l_int.json"
scene l_dir '"lights": [{"type": "directional", "direction": [0, 0, 0]}]'; render_bad "lights[0].direction" "$in/l_dir.json"
cam c_pos ', "position": [0, 1e400, 4]';                 render_bad 1e400 "$in/c_pos.json"
cam c_fov_str ', "fov_y": "NaN"';                       render_bad "cameras[0].fov_y" "$in/c_fov_str.json"
refl r_center '"center": [0, Infinity, 0], "tangent": [1, 0, 0], "bitangent": [0, 0, 1], "half_extents": [1, 1]'
render_bad 'JSON syntax error' "$in/r_center.json"
scene env '"environment": {"type": "constant", "color": [1, 1, 1], "intensity": 1e39}'; render_bad intensity "$in/env.json"
# Animation: a huge key time, a moving planar reflector (they are fixed rectangles), a path
# option naming no path.
scene a_time '"animation": {"paths": [{"name": "p", "keys": [{"time": 1e39, "position": [0, 1, 4], "target": [0, 0, 0]}]}]}'
render_bad "animation.paths[0].keys[0].time" "$in/a_time.json"
json a_refl '{"primitives": [{"type": "plane", "name": "floor", "size": [4, 4], "reflector": true}], "animation": {"objects": [{"meshes": ["floor"], "spin": {"period": 1}}]}}'
render_bad "planar reflector" "$in/a_refl.json"
render_bad "'nope'" "gallery:path=nope"

# ---- missing, unreadable and non-regular files -------------------------------------------------
render_bad nothere.obj "$in/nothere.obj"
json no_obj '{"meshes": [{"obj": "nothere.obj"}]}';        render_bad nothere.obj "$in/no_obj.json"
# A missing MTL is an error (as it has always been), like every missing texture.
obj no_mtl "mtllib nothere.mtl\n${tri}f 1 2 3\n";          render_bad nothere.mtl "$in/no_mtl.obj"
obj no_tex "mtllib no_tex.mtl\nusemtl m\n${tri}f 1 2 3\n"; mtl no_tex 'newmtl m\nmap_Kd nothere.png\n'
render_bad nothere.png "$in/no_tex.obj"
obj no_norm "mtllib no_norm.mtl\nusemtl m\n${tri}f 1 2 3\n"; mtl no_norm 'newmtl m\nbump -bm 0.5 nothere.png\n'
render_bad nothere.png "$in/no_norm.obj"
scene no_jtex '"materials": {"m": {"albedo_texture": "nothere.png"}}'; render_bad nothere.png "$in/no_jtex.json"
mkdir -p "$in/dir.json" "$in/dir.obj" "$in/dir.mtl" "$in/dir.png"
render_bad "not a regular file" "$in/dir.json"
render_bad "not a regular file" "$in/dir.obj"
json obj_dir '{"meshes": [{"obj": "dir.obj"}]}';           render_bad "not a regular file" "$in/obj_dir.json"
obj mtl_dir "mtllib dir.mtl\n${tri}f 1 2 3\n";             render_bad "not a regular file" "$in/mtl_dir.obj"
obj tex_dir "mtllib tex_dir.mtl\nusemtl m\n${tri}f 1 2 3\n"; mtl tex_dir 'newmtl m\nmap_Kd dir.png\n'
render_bad "not a regular file" "$in/tex_dir.obj"
ln -s /dev/zero "$in/zero.json";                           render_bad "not a regular file" "$in/zero.json"
mkfifo "$in/fifo.obj";                                     render_bad "not a regular file" "$in/fifo.obj"
ln -s nothere.json "$in/dangling.json";                    render_bad "dangling.json' does not exist" "$in/dangling.json"
printf '\x89PNG\r\n\x1a\n garbage' >"$in/bad.png"
obj tex_bad "mtllib tex_bad.mtl\nusemtl m\n${tri}f 1 2 3\n"; mtl tex_bad 'newmtl m\nmap_Kd bad.png\n'
render_bad bad.png "$in/tex_bad.obj"
: >"$in/empty.json";                                       render_bad "empty.json' is empty" "$in/empty.json"
head -c 4096 /dev/urandom >"$in/random.obj";               render_bad 'NUL byte' "$in/random.obj"
cp "$in/good.obj" "$in/locked.obj"; chmod 000 "$in/locked.obj"
if [ ! -r "$in/locked.obj" ]; then render_bad locked.obj "$in/locked.obj"; fi  # root reads anyway
bad "--scene needs a value" render --scene "" --size 32x18 --out "$out/x.png"
bad "does not exist" render --scene "$in/two
lines.json" --size 32x18 --out "$out/x.png"  # a line break in a name stays on one line

# ---- paths that escape the scene's directory ---------------------------------------------------
esc() {  # esc NAME MTL_LINE: an OBJ whose MTL names a texture by MTL_LINE must be refused.
  obj "$1" "mtllib $1.mtl\nusemtl m\n${tri}f 1 2 3\n"; mtl "$1" "newmtl m\n$2\n"
  render_bad "$3" "$in/$1.obj"
}
esc up 'map_Kd ../../../../../../etc/passwd' escapes
esc up_outside "map_Kd ../outside/secret.png" escapes
esc up_inner 'map_Kd tex/../../outside/secret.png' escapes
esc backslash 'map_Kd ..\\outside\\secret.png' escapes
esc absolute 'map_Kd /etc/passwd' absolute
esc absolute_opts 'map_Kd -bm 1 -s 1 1 1 /etc/passwd' absolute
esc bump_up 'bump -bm 2 ../outside/secret.png' escapes
ln -s "$outside/secret.png" "$in/link.png";                esc link 'map_Kd link.png' escapes
ln -s "$outside" "$in/linkdir";                            esc linkdir 'map_Kd linkdir/secret.png' escapes
obj mtl_up "mtllib ../outside/x.mtl\n${tri}f 1 2 3\n";     render_bad escapes "$in/mtl_up.obj"
obj mtl_abs "mtllib /etc/passwd\n${tri}f 1 2 3\n";        render_bad absolute "$in/mtl_abs.obj"
json obj_up '{"meshes": [{"obj": "../outside/outside.obj"}]}'; render_bad escapes "$in/obj_up.json"
json obj_abs "{\"meshes\": [{\"obj\": \"$outside/outside.obj\"}]}"; render_bad absolute "$in/obj_abs.json"
ln -s "$outside/outside.obj" "$in/outlink.obj"
json obj_link '{"meshes": [{"obj": "outlink.obj"}]}';         render_bad escapes "$in/obj_link.json"
scene jtex_abs '"materials": {"m": {"albedo_texture": "/etc/passwd"}}'; render_bad absolute "$in/jtex_abs.json"
scene jtex_up '"materials": {"m": {"normal_texture": "../outside/secret.png"}}'; render_bad escapes "$in/jtex_up.json"
# An OBJ placed by a JSON scene may use the JSON file's directory, not above it.
mkdir -p "$in/sub"; printf "mtllib ../../outside/x.mtl\n${tri}f 1 2 3\n" >"$in/sub/m.obj"
json sub_up '{"meshes": [{"obj": "sub/m.obj"}]}';          render_bad escapes "$in/sub_up.json"

# ---- zero-area and degenerate reflectors -------------------------------------------------------
frame='"center": [0, 0, 0], "tangent": [1, 0, 0], "bitangent": [0, 0, 1]'
refl r_zero "$frame, \"half_extents\": [0, 1]";             render_bad half_extents "$in/r_zero.json"
refl r_neg "$frame, \"half_extents\": [1, -1]";             render_bad half_extents "$in/r_neg.json"
refl r_tzero '"center": [0, 0, 0], "tangent": [0, 0, 0], "bitangent": [0, 0, 1], "half_extents": [1, 1]'
render_bad tangent "$in/r_tzero.json"
refl r_tiny '"center": [0, 0, 0], "tangent": [1e-30, 0, 0], "bitangent": [0, 0, 1], "half_extents": [1, 1]'
render_bad tangent "$in/r_tiny.json"
refl r_same '"center": [0, 0, 0], "tangent": [1, 0, 0], "bitangent": [1, 0, 0], "half_extents": [1, 1]'
render_bad orthogonal "$in/r_same.json"
refl r_par '"center": [0, 0, 0], "tangent": [1, 0, 0], "bitangent": [-1, 1e-9, 0], "half_extents": [1, 1]'
render_bad orthogonal "$in/r_par.json"
json r_flat '{"primitives": [{"type": "plane", "size": [0, 4], "reflector": true}]}'; render_bad size "$in/r_flat.json"
json r_scale '{"primitives": [{"type": "plane", "size": [4, 4], "scale": [1, 1, 0], "reflector": true}]}'
render_bad scale "$in/r_scale.json"

# ---- degenerate cameras ------------------------------------------------------------------------
scene c_same '"cameras": [{"position": [0, 1, 4], "target": [0, 1, 4]}]'; render_bad target "$in/c_same.json"
cam c_up ', "up": [0, -0.25, -1]';                        render_bad up "$in/c_up.json"
cam c_up0 ', "up": [0, 0, 0]';                            render_bad up "$in/c_up0.json"
for f in 0 1 180 -30; do cam c_fov ", \"fov_y\": $f";     render_bad fov_y "$in/c_fov.json"; done
cam c_near0 ', "near": 0';                                render_bad near "$in/c_near0.json"
cam c_nearneg ', "near": -1';                             render_bad near "$in/c_nearneg.json"
cam c_neareq ', "near": 5, "far": 5';                     render_bad far "$in/c_neareq.json"
cam c_nearfar ', "near": 10, "far": 1';                   render_bad far "$in/c_nearfar.json"

# ---- wrong command-line types and values -------------------------------------------------------
S="--size 32x18"
for s in 0x10 10x 64x-36 1e3x10 64x36x2 " 64x36" 64X36 0x0000001; do
  bad size render --size "$s" --out "$out/x.png"
done
bad size compare --size abc --out "$out/x.png"
bad --frames compare --frames -3 $S --out "$out/x.png"
bad --frames compare --frames x $S --out "$out/x.png"
bad --frames bench --frames 2.5 --json "$out/b.json"
bad --warmup bench --warmup -1 --json "$out/b.json"
bad linear.max_steps render --set linear.max_steps=abc $S --out "$out/x.png"
bad linear.max_steps render --set linear.max_steps=1.5 $S --out "$out/x.png"
bad linear.max_steps render --set linear.max_steps= $S --out "$out/x.png"
for v in inf -inf 1e400 0x10 " 1"; do bad linear.thickness render --set "linear.thickness=$v" $S --out "$out/x.png"; done
bad linear.depth_interp render --set linear.depth_interp=maybe $S --out "$out/x.png"
bad "--exposure must be in" render --exposure inf $S --out "$out/x.png"
bad "unknown subcommand 'nosuch'" nosuch
bad "--nosuch" render --nosuch $S --out "$out/x.png"
bad "--scene" render $S --out "$out/x.png" --scene
bad "nosuch" render --technique nosuch $S --out "$out/x.png"
bad "nosuch" compare --techniques linear,nosuch $S --out "$out/x.png"
bad "nosuch" render --view nosuch $S --out "$out/x.png"
bad "nosuch" render --preset nosuch $S --out "$out/x.png"
bad "classes" render --view classes --technique reference $S --out "$out/x.exr"
bad ".png" render $S --out "$out/x"
bad ".png" render $S --out "$out/x.PNG.txt"
bad ".png" compare $S --out "$out/x.exr"
bad "svg" bench --plot "$out/x.png" --json "$out/b.json"
bad "--json" bench --techniques none
bad "does not exist" compare $S --out "$out/x.png" --json "$out/no/such/r.json"
bad "does not exist" bench --json "$out/b.json" --csv "$out/no/b.csv"
bad "directory" render $S --out "$in/dir.png"
bad "directory" compare $S --out "$out/x.png" --json "$in/dir.json"
mkdir -p "$in/dir.svg"; bad "directory" bench --json "$out/b.json" --plot "$in/dir.svg"
bad "same file" compare $S --out "$out/x.png" --json "$out/x.png"
bad "same file" bench --json "$out/b.json" --csv "$out/./b.json"
bad "shader directory" bench --shaders "$in/no-such-dir" --json "$out/b.json"
bad "shader directory" sequence --frames 2 --shaders "$in/no-such-dir" --json "$out/s.json"
# Outputs are checked before any work: a directory that takes no new file (/proc refuses even
# root), a name longer than the file system allows, an output that is an input.
bad "cannot create --out" render $S --out /proc/ssrlab-x.png
bad "cannot create --json" compare $S --out "$out/x.png" --json /proc/ssrlab-r.json
bad "cannot create --csv" bench --sizes 32x18 --techniques none --json "$out/b.json" --csv /proc/b.csv
bad "cannot create --out" sequence $S --frames 2 --techniques none --json "$out/s.json" --out /proc/frames
bad "cannot create --json" passfloor --sizes 16x16 --json /proc/p.json
bad "longer than" render $S --out "$out/$(printf 'a%.0s' $(seq 252)).png"
scene as_input
cp "$in/as_input.json" "$tmp/as_input.kept"
bad "overwrite the input" compare --scene "$in/as_input.json" $S --out "$out/x.png" --json "$in/as_input.json"
bad "overwrite the input" bench --scenes "gallery,$in/as_input.json" --sizes 32x18 --json "$out/b.json" --csv "$in/as_input.json"
bad "overwrite the input" sequence --scene "$in/as_input.json" $S --frames 2 --json "$in/as_input.json"
cmp -s "$in/as_input.json" "$tmp/as_input.kept" || fail "the input scene was changed"
# An empty value is an error, not "not given" (CLI11 would read --warmup "" as 0).
bad "empty string" bench --warmup "" --json "$out/b.json"
bad "empty string" sequence $S --frames 2 --json ""
bad "empty string" render --exposure "" $S --out "$out/x.png"
# Sweeps that would run fewer or the same variants than they read as.
bad twice bench --techniques linear --sweep linear.max_steps=8,16 --sweep linear.max_steps=32 --json "$out/b.json"
bad twice bench --techniques linear --sweep linear.max_steps=8,8 --json "$out/b.json"
# A technique, preset, scene, size or region given twice would print two rows a reader takes
# for two different runs.
bad "names 'hiz' twice" compare --techniques hiz,hiz $S --out "$out/x.png"
bad "'stochastic-low' is given twice" sequence --techniques none --preset stochastic-low --preset stochastic-low $S --frames 2 --json "$out/s.json"
bad "names 1920x1080 twice" bench --sizes 1080p,1920x1080 --techniques none --json "$out/b.json"
bad "'gallery' is given twice" bench --scenes gallery --scene gallery --sizes 32x18 --techniques none --json "$out/b.json"
bad "names 'planar' twice" compare --scene gallery --regions planar,planar $S --out "$out/x.png"
bad "gives one value twice ('0.1' and '0.10')" bench --techniques linear --sweep linear.thickness=0.1,0.10 --json "$out/b.json"
bad "is given twice" bench --scenes "$in/as_input.json,$in/../in/as_input.json" --sizes 32x18 --techniques none --json "$out/b.json"
# The frame settings are options named after their table's rows, checked against its ranges.
bad "give it as --reflective-f0" compare --set frame.reflective_f0=0.5 $S --out "$out/x.png"
bad "--reflective-f0 must be in [0.001, 1], got 2" compare --reflective-f0 2 $S --out "$out/x.png"
bad "--exposure must be in [-20, 20], got 30" bench --exposure 30 --sizes 32x18 --techniques none --json "$out/b.json"
bad "both set" bench --techniques linear --set linear.max_steps=8 --sweep linear.max_steps=16,32 --json "$out/b.json"
# The number that stands for auto inside the table is not a value to write (only "auto" is).
bad "write auto" render --technique hiz --set hiz.max_iterations=0 $S --out "$out/x.png"
bad "write auto" render --set linear.roughness=-1 $S --out "$out/x.png"
# A rejected value is quoted to the digit, not rounded into the range.
bad "0.00099999999999" render --technique hiz --set hiz.thickness=0.00099999999999 $S --out "$out/x.png"
# A NUL inside a JSON string would cut a file name short.
json nul '{"meshes": [{"obj": "good.obj\u0000.png"}]}'
render_bad "NUL character" "$in/nul.json"
# Valid input a review found refused: an empty description is free text; "reflector": false asks
# nothing of a box. Both render (exit 0).
json empty_description '{"description": "", "primitives": [{"type": "box", "reflector": false}]}'
if "$SSRLAB" render --scene "$in/empty_description.json" --technique none --size 32x18 --out "$tmp/ok.png" >/dev/null 2>"$tmp/stderr"; then
  passes=$((passes + 1)); rm -f "$tmp/ok.png"
else fail "a valid scene was refused: $(grep -v 'GL via' "$tmp/stderr")"; fi
n=$((n + 1))
# Outputs are checked where they are written: "nodir/.." needs nodir (it rendered, then exit 1),
# a link to a missing directory is refused, and a link is written through, not replaced.
bad "does not exist" render $S --out "$out/nodir/../x.png"
ln -s /nonexistent/x.png "$tmp/dangling.png"
bad "a link to a file in a directory that does not exist" render $S --out "$tmp/dangling.png"
echo old > "$tmp/real.png"; ln -s real.png "$tmp/link.png"
n=$((n + 1))
if "$SSRLAB" render $S --out "$tmp/link.png" >/dev/null 2>&1 && [ -L "$tmp/link.png" ] && [ "$(head -c 4 "$tmp/real.png" | tail -c 3)" = PNG ]; then
  passes=$((passes + 1))
else fail "render --out LINK replaced the link or left its target"; fi
# render draws one frame: views of change over frames would be black and read as a result.
bad "shows change over frames" render --view motion $S --out "$out/x.png"
bad "shows change over frames" render --technique stochastic --view history $S --out "$out/x.png"
bad "shows change over frames" render --technique stochastic --view temporal $S --out "$out/x.png"  # = spatial at frame 0

# compare and bench refuse bad scenes the same way, before writing anything.
bad 4000000000 compare --scene "$in/huge_index.obj" $S --out "$out/x.png" --json "$out/r.json"
bad escapes bench --scene "$in/up.obj" --sizes 32x18 --json "$out/b.json" --csv "$out/b.csv" --plot "$out/p.svg"
bad fov_y bench --scenes "gallery,$in/c_fov.json" --sizes 32x18 --json "$out/b.json"

# ---- legitimate hard cases still render --------------------------------------------------------
good() {  # good FILE ARGS...: exit 0 and a non-empty FILE.
  local file=$1; shift
  n=$((n + 1))
  timeout 300 "$SSRLAB" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local got=$?
  if [ "$got" = 0 ] && [ -s "$file" ]; then passes=$((passes + 1))
  else fail "exit $got or no $file: ssrlab $*"; sed 's/^/  | /' "$tmp/stderr" | head -5; fi
}
# The camera inside a closed box (its faces seen from the back) with a light inside too.
json inside '{"primitives": [{"type": "box", "extents": [4, 3, 4], "translate": [0, 1.5, 0]},
  {"type": "plane", "size": [3.9, 3.9], "translate": [0, 0.01, 0], "reflector": true}],
  "materials": {"default": {"metallic": 1, "roughness": 0}},
  "lights": [{"type": "point", "position": [0, 2.5, 0]}],
  "cameras": [{"position": [0, 1.5, 1], "target": [0, 1, -1], "near": 0.01, "far": 20}]}'
mkdir -p "$tmp/good"
for t in linear ppr planar; do
  good "$tmp/good/inside-$t.png" render --scene "$in/inside.json" --technique $t $S --out "$tmp/good/inside-$t.png"
done
# Underflow is not overflow: 1e-50 reads as 0 (it used to be refused as non-finite).
obj tiny 'v 0 0 1e-50\nv 1 0 0\nv 0 1 0\nf 1 2 3\n'
good "$tmp/good/tiny.png" render --scene "$in/tiny.obj" --technique none $S --out "$tmp/good/tiny.png"
# A texture path that goes down and up again but stays inside is fine.
esc_ok() { obj ok "mtllib ok.mtl\nusemtl m\n${tri}f 1 2 3\n"; mtl ok 'newmtl m\nmap_Kd sub/../tex.png\n'; }
esc_ok; good "$tmp/good/ok.png" render --scene "$in/ok.obj" --technique none $S --out "$tmp/good/ok.png"

echo "$n cases: $passes passed, $fails failed"
[ "$fails" = 0 ]
