#!/usr/bin/env bash
# The command-line contract (ARCHITECTURE §7): outputs, exit codes, one-sentence errors, and no file
# left behind on bad input. Runs the real binary ($SSRLAB) headless.
set -u
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0; passes=0
ok()   { passes=$((passes + 1)); }
bad()  { echo "FAIL: $*"; fails=$((fails + 1)); }

# expect_exit CODE ARGS...: runs ssrlab, checks the exit code; on code 2 also checks that stderr
# is exactly one line and that no output file appeared.
expect_exit() {
  local want=$1; shift
  rm -f "$tmp"/out.*
  "$SSRLAB" "$@" >"$tmp/stdout" 2>"$tmp/stderr"
  local got=$?
  if [ "$got" != "$want" ]; then bad "exit $got (want $want): ssrlab $*"; sed 's/^/  | /' "$tmp/stderr"; return; fi
  if [ "$want" = 2 ]; then
    # Exactly one line: the "GL via" log comes only once every input (sizes too) is checked.
    local lines; lines=$(wc -l <"$tmp/stderr")
    [ "$lines" = 1 ] || { bad "stderr is not one sentence ($lines lines): ssrlab $*"; sed 's/^/  | /' "$tmp/stderr"; return; }
    ls "$tmp"/out.* >/dev/null 2>&1 && { bad "output left behind: ssrlab $*"; return; }
  fi
  ok
}

# says WORDS: the refusal just checked holds WORDS (another refusal of the same input passed).
says() { grep -qF -- "$1" "$tmp/stderr" || bad "refused, but not for '$1': $(cat "$tmp/stderr")"; }

S="--size 64x36"
# --- good input -------------------------------------------------------------------------------
expect_exit 0 render --scene gallery --technique none $S --out "$tmp/out.png"
expect_exit 0 render --scene gallery --technique linear $S --view reflection --out "$tmp/none.png"
[ -s "$tmp/none.png" ] && ok || bad "render wrote no PNG"
expect_exit 0 render --scene cornell --technique linear $S --set linear.max_steps=32 --set linear.depth_interp=false --out "$tmp/c.exr"
[ "$(head -c 4 "$tmp/c.exr" | od -An -tx1 | tr -d ' ')" = "762f3101" ] && ok || bad "EXR magic missing"
expect_exit 0 render --scene corridor --camera default --gl osmesa $S --out "$tmp/o.png"
expect_exit 0 scenes
grep -q gallery "$tmp/stdout" && ok || bad "scenes does not list gallery"
expect_exit 0 techniques
for key in linear.max_steps linear.step_size linear.thickness linear.max_distance linear.depth_interp \
           stochastic.roughness_threshold hiz.denoise stochastic-low stochastic-medium stochastic-high stochastic-ultra; do
  grep -q "$key" "$tmp/stdout" && ok || bad "techniques does not list $key"
done
ls "$tmp"/*.tmp* >/dev/null 2>&1 && bad "temporary files left behind" || ok
expect_exit 0 render --technique stochastic $S --view spatial --out "$tmp/s.png"
expect_exit 0 render --preset stochastic-low $S --out "$tmp/s.png"
expect_exit 0 render --technique hiz --set hiz.denoise=true $S --view variance --out "$tmp/s.png"
# Half resolution on an image 1 pixel high: the half grid rounds up (1 row), documented.
expect_exit 0 render --technique stochastic --size 3x1 --set stochastic.half_resolution=true --out "$tmp/s.exr"

expect_exit 0 render --technique linear --view difference $S --out "$tmp/d.png"
grep -q "view difference" "$tmp/stdout" && [ -s "$tmp/d.png" ] && ok || bad "render --view difference wrote no PNG"

# --- bad input: one sentence, exit 2, nothing written -----------------------------------------
expect_exit 2 render --technique reference --view difference $S --out "$tmp/out.png"; says "scores a technique against the reference"
expect_exit 2 render --technique linear --view difference $S --out "$tmp/out.exr"; says "writes a .png"
expect_exit 2 render --scene nope $S --out "$tmp/out.png"; says "unknown scene 'nope'"
expect_exit 2 render --scene "$tmp/missing.json" $S --out "$tmp/out.png"; says "missing.json' does not exist"
expect_exit 2 render --technique nope $S --out "$tmp/out.png"; says "unknown technique 'nope'"
expect_exit 2 render --set linear.nope=1 $S --out "$tmp/out.png"; says "unknown parameter 'linear.nope'"
expect_exit 2 render --set dda.thickness=1 $S --out "$tmp/out.png"; says "does not belong to technique 'linear'"
expect_exit 2 render --set linear.max_steps=0 $S --out "$tmp/out.png"; says "must be in [1, 8192], got 0"
expect_exit 2 render --set linear.thickness=nan $S --out "$tmp/out.png"; says "got nan"
expect_exit 2 render --set linear.max_steps $S --out "$tmp/out.png"; says "not of the form key=value"
expect_exit 2 render --size 0x0 --out "$tmp/out.png"; says "must be at least 1x1"
expect_exit 2 render --size 1x0 --out "$tmp/out.png"; says "must be at least 1x1"
expect_exit 2 render --size 100000x100000 --out "$tmp/out.png"; says "more than the 67108864"
expect_exit 2 render --size 40000x8 --out "$tmp/out.png"; says "more than this GL supports"
expect_exit 2 render --size big --out "$tmp/out.png"; says "not of the form WIDTHxHEIGHT"
expect_exit 2 render --camera nope $S --out "$tmp/out.png"; says "no camera 'nope'"
expect_exit 2 render --view nope $S --out "$tmp/out.png"; says "unknown view 'nope'"
expect_exit 2 render --technique linear --view spatial $S --out "$tmp/out.png"; says "does not fill the view 'spatial'"
expect_exit 2 render --technique none --view steps $S --out "$tmp/out.png"; says "does not fill the view 'steps'"
expect_exit 2 render --preset stochastic-mega $S --out "$tmp/out.png"; says "unknown preset 'stochastic-mega'"
expect_exit 2 render --technique stochastic --set stochastic.roughness_threshold=1.5 $S --out "$tmp/out.png"; says "must be in [0, 1], got 1.5"
expect_exit 2 render --technique stochastic --set stochastic.rays_per_quad=3 $S --out "$tmp/out.png"; says "takes one of 1|2|4, got '3'"
expect_exit 2 render $S --out "$tmp/out.jpg"; says "must end in .png or .exr"
expect_exit 2 render $S --out "$tmp/no/such/dir/out.png"; says "does not exist"
expect_exit 2 render $S --exposure abc --out "$tmp/out.png"; says "--exposure cannot take the value 'abc'"
expect_exit 2 render $S --gl vulkan --out "$tmp/out.png"; says "unknown GL path 'vulkan'"
expect_exit 2 render $S; says "--out is required"
expect_exit 2 nosuchcommand; says "unknown subcommand 'nosuchcommand'"
# Found by a review: a preset beside --technique (one was silently ignored), --shaders naming a
# file or a folder without shaders, an empty --techniques list (it ran every technique), the
# extra plots beside --plot colliding with --json (found only after every run).
expect_exit 2 render --technique dda --preset thesis-hq $S --out "$tmp/out.png"; says "--technique excludes --preset"
expect_exit 2 render --shaders "$TESTDATA/json/minimal.json" $S --out "$tmp/out.png"; says "is not a directory"
mkdir -p "$tmp/empty_shaders"
expect_exit 2 render --shaders "$tmp/empty_shaders" $S --out "$tmp/out.png"; says "holds no render/gbuffer.vert"
# A shader that does not compile is named where it is: in the directory given (it said shaders/...).
cp -r "$(dirname "$0")/../../shaders" "$tmp/broken_shaders"
echo 'syntax error here' >>"$tmp/broken_shaders/techniques/linear.comp"
expect_exit 1 render --shaders "$tmp/broken_shaders" --technique linear $S --out "$tmp/out.png"
grep -q "^$tmp/broken_shaders/techniques/linear.comp:[0-9]*:" "$tmp/stderr" || bad "a compile error does not name the --shaders file"
# sequence loads them too (--shaders there once parsed and went unused would pass sequence.sh).
expect_exit 1 sequence --shaders "$tmp/broken_shaders" --techniques linear --frames 1 $S --json "$tmp/seq.json"
grep -q "^$tmp/broken_shaders/techniques/linear.comp:[0-9]*:" "$tmp/stderr" || bad "sequence does not load --shaders"
expect_exit 2 compare --techniques "" $S --out "$tmp/out.png"
expect_exit 2 bench --techniques linear --sizes 32x18 --sweep linear.max_steps=8,16 --frames 1 --warmup 0 \
  --json "$tmp/out.b-sweep-gallery-32x18.svg" --plot "$tmp/out.b.svg"
# Two scenes whose plots would be one file: two files of one name in two folders.
for d in one two; do mkdir -p "$tmp/$d"; cp "$TESTDATA/json/minimal.json" "$tmp/$d/s.json"; cp -r "$TESTDATA/json/meshes" "$tmp/$d/"; done
expect_exit 2 bench --scenes "$tmp/one/s.json,$tmp/two/s.json" --techniques linear --sizes 32x18,64x36 --frames 1 --warmup 0 \
  --plot "$tmp/out.b.svg"
grep -q "same plot" "$tmp/stderr" || bad "two scenes of one plot name: not the plots' sentence: $(cat "$tmp/stderr")"
# Each bad file and words its refusal must hold: a file refused for another reason passed (without
# the absolute-path check, bad_absolute.json was refused as escaping the directory).
declare -A why=(
  [bad_absolute.json]="is absolute" [bad_camera_up.json]="must not be parallel"
  [bad_duplicate_key.json]="has the key 'name' twice" [bad_escape.json]="escapes the directory"
  [bad_light_key.json]="unknown key 'lights[0].direction'" [bad_missing_mesh.json]="missing.obj' does not exist"
  [bad_no_meshes.json]="has no meshes or primitives" [bad_not_object.json]="must hold a JSON object"
  [bad_number_overflow.json]="number overflow" [bad_obj_inside.json]="broken.obj' line 3"
  [bad_out_of_range.json]="roughness' must be in [0, 1]" [bad_primitive_type.json]="not 'torus'"
  [bad_skew_reflector.json]="orthogonal tangent" [bad_syntax.json]="JSON syntax error at line 3"
  [bad_unclosed.json]="unexpected end of input" [bad_unknown_key.json]="unknown key 'materials.floor.rougness'"
  [bad_unknown_material.json]="unknown material 'nope'" [bad_unknown_top_key.json]="unknown key 'colour'"
  [bad_wrong_type.json]="roughness' must be a number" [bad_wrong_vec.json]="must be an array of 3 numbers"
  [bad_zero_reflector.json]="half_extents' must be positive" [bad_zero_scale.json]="scale' must be in"
  [bad_absolute_texture.obj]="'/etc/hostname' is absolute" [bad_corrupt_texture.obj]="not a readable image"
  [bad_escape_texture.obj]="escapes the directory" [bad_exponent_overflow.obj]="'0e2147483648'"
  [bad_face_two_vertices.obj]="at least 3 vertices" [bad_garbage_index.obj]="vertex index '2x'"
  [bad_garbage_number.obj]="number 'abc'" [bad_huge_vertex.obj]="number '1e39'"
  [bad_index_past_end.obj]="vertex index 4 is past the end" [bad_missing_mtl.obj]="nowhere.mtl' does not exist"
  [bad_missing_texture.obj]="gone.png' does not exist" [bad_mtl_garbage.obj]="'Ns' has a malformed"
  [bad_mtl_nan.obj]="'Kd' has a malformed or non-finite number 'nan'" [bad_nan_vertex.obj]="vertex has a malformed or non-finite number 'nan'"
  [bad_negative_index.obj]="relative vertex index -9" [bad_no_faces.obj]="has no faces"
  [bad_normal_index.obj]="normal index 2 is past the end" [bad_texcoord_index.obj]="texture coordinate index -2"
  [bad_zero_index.obj]="vertex index 0"
)
for f in "$TESTDATA"/json/bad_* "$TESTDATA"/obj/bad_*; do
  [ -e "$f" ] || continue
  name=$(basename "$f")
  [ -n "${why[$name]:-}" ] || { bad "$name: no row in this test's table of reasons"; continue; }
  expect_exit 2 render --scene "$f" $S --out "$tmp/out.png"
  grep -qF -- "${why[$name]}" "$tmp/stderr" || bad "$name: refused, but not for '${why[$name]}': $(cat "$tmp/stderr")"
done

echo "$passes passed, $fails failed"
[ "$fails" = 0 ]
