#!/usr/bin/env bash
# Install test: installs a hedge build tree into a fresh prefix, then configures, builds and runs
# a consumer project that finds it with find_package(hedge) and CMAKE_PREFIX_PATH only.
# Usage: run.sh BUILD_DIR CONSUMER_SOURCE_DIR [GENERATOR] [CXX_COMPILER] [EXTRA_CXX_FLAGS] [BUILD_TYPE]
set -euo pipefail

build_dir=$1
consumer_src=$2
generator=${3:-}
compiler=${4:-}
extra_flags=${5:-}
build_type=${6:-Release}

work=$(mktemp -d -t hedge-install-test.XXXXXX)
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"

echo "-- installing $build_dir into $prefix"
cmake --install "$build_dir" --prefix "$prefix"
test -f "$prefix/include/hedge/core/surface_mesh.h"
test -f "$prefix/include/hedge/c_api.h"
ls "$prefix"/lib*/cmake/hedge/hedgeConfig.cmake >/dev/null

configure=(cmake -S "$consumer_src" -B "$work/build" -DCMAKE_PREFIX_PATH="$prefix"
  -DCMAKE_BUILD_TYPE="$build_type")
[ -n "$generator" ] && configure+=(-G "$generator")
[ -n "$compiler" ] && configure+=(-DCMAKE_CXX_COMPILER="$compiler")
[ -n "$extra_flags" ] && configure+=(-DCMAKE_CXX_FLAGS="$extra_flags" -DCMAKE_EXE_LINKER_FLAGS="$extra_flags")

echo "-- configuring the consumer"
"${configure[@]}"
echo "-- building the consumer"
cmake --build "$work/build"
echo "-- running the consumer"
"$work/build/hedge_consumer"
echo "-- running the C consumer"
"$work/build/hedge_c_consumer"
