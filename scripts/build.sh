#!/usr/bin/env bash
# Configures and builds rtview into build/ (Release). Extra arguments go to CMake.
# CMake's own findings are shown (whether Embree was found, the SIMD level); its
# bookkeeping lines are not, nor Debian's harmless note that Imath's Python module
# (which OpenImageIO's CMake files mention and rtview never uses) is not installed.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" |
    awk '/^-- The imported target "Imath::PyImath/ { skip = 1 }
         skip && /not all the files it references/ { skip = 0; blank = 1; next }
         skip { next }
         blank && /^$/ { blank = 0; next }
         { blank = 0 }
         /^-- (Configuring done|Generating done|Build files have)/ { next }
         { print }'
cmake --build build
