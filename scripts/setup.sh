#!/usr/bin/env bash
# Installs what rtview needs from Debian 12's packages, and only what is missing.
# Idempotent: a second run installs nothing and does not touch the network.
set -euo pipefail

packages=(
  cmake g++ ninja-build git
  dpkg-dev file                       # cpack -G DEB: dpkg-shlibdeps finds the package's dependencies
  libglm-dev                          # vector maths
  libopenimageio-dev openimageio-tools  # image files and comparison (idiff)
  libpng-dev libjpeg-dev              # PNG files, JPEG textures (without loading OpenImageIO)
  nlohmann-json3-dev                  # scene files
  libtinyobjloader-dev                # OBJ + MTL meshes
  libtinygltf-dev                     # glTF 2.0 scenes
  libassimp-dev                       # PLY and STL meshes
  libcli11-dev                        # command lines
  libgtest-dev                        # tests
  python3-glad                        # generates the OpenGL loader at build time
  libegl-dev libegl-mesa0 libgl1-mesa-dri  # headless EGL on Mesa (llvmpipe)
  libosmesa6-dev                      # headless OSMesa
  libglfw3-dev libimgui-dev libglx-mesa0  # the viewer: window, panel, GLX on Mesa
  xvfb xdotool imagemagick            # the viewer's tests: X server, input, screen grabs
  libembree-dev gnuplot-nox           # rtbench: the reference BVH, and its plots
  clang libclang-rt-14-dev            # libFuzzer targets (scripts/fuzz.sh)
  povray                              # the oracle test: an independent tracer
  rsync                               # scripts/mutants.sh: copies the tree to plant bugs in
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo=sudo
fi
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
