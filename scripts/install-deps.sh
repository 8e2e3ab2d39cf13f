#!/usr/bin/env bash
# Installs the Debian 12 packages ssrlab needs, only those missing. Uses sudo when not root.
set -euo pipefail
pkgs=(
  build-essential cmake ninja-build pkg-config git
  python3-glad                      # glad generator (run with --reproducible at build time)
  libegl-dev libegl-mesa0 libgl1-mesa-dri libosmesa6   # headless GL: EGL, llvmpipe, OSMesa
  libglfw3-dev libimgui-dev         # viewer
  libglm-dev libembree-dev libtinyobjloader-dev libstb-dev libtinyexr-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev                      # tests
  clang-14 libclang-rt-14-dev       # fuzz targets (tests/fuzz): libclang_rt.fuzzer, asan, ubsan
  xvfb xauth                        # viewer test in a real X window
  ffmpeg                            # ssrlab sequence --video (H.264 through libx264); tests/unit/test_video.cpp
)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "install-deps: installing ${missing[*]}"
sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
