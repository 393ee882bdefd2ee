# Build dependencies of hedge, in one place. Source this file, then call
#   hedge_install_deps GROUP...
# Groups:
#   core   compiler, CMake, Ninja, Eigen and tinygltf with nlohmann-json (used from their headers):
#          enough to build the library
#   cli    what the hedge command-line tool needs
#   test   the unit tests
#   bench  the benchmarks
#   peers  other mesh libraries the benchmarks compare against (large)
#   fuzz   the libFuzzer targets
#   format clang-format 14, for scripts/format (prettier, its JavaScript half, comes from web/'s npm)
#   csharp Mono's C# compiler and runtime, for the C# binding's tests (bindings/csharp/)
#   python Debian's Python 3 with pybind11, numpy, pytest, venv, setuptools and wheel, and stb (for
#          hedge.render), for the Python binding (bindings/python/; its CMake build wants
#          -DPython_EXECUTABLE=/usr/bin/python3)
#   wasm   emscripten (with its node and clang) for the WebAssembly module (bindings/wasm/)
#   windows MinGW-w64 (posix threads) to cross-build hedge_c.dll and the C ABI tests for Windows
#          x64, and wine64 to run them (the windows preset, cmake/toolchains/mingw-w64-x86_64.cmake)
#   web    Debian's chromium (and its driver), for the playground's browser tests (web/); node 18
#          or newer (Debian 12's nodejs) and npm must be present already (hedge_web_npm checks)
# Only missing packages are installed; when everything is present nothing is run, so the check is
# fast on a machine that is already set up. Debian 12 (apt-get) is assumed.

hedge_deps_packages() {
  local group
  for group in "$@"; do
    case "$group" in
      core) echo cmake g++ ninja-build libeigen3-dev libtinygltf-dev nlohmann-json3-dev ;;
      cli) echo libcli11-dev nlohmann-json3-dev libstb-dev fonts-dejavu-core pkg-config ;;
      test) echo libgtest-dev nlohmann-json3-dev ;;
      bench) echo libbenchmark-dev ;;
      peers) echo libopenmesh-dev libcgal-dev libeigen3-dev libmeshoptimizer-dev ;;
      fuzz) echo clang libclang-rt-14-dev ;;
      format) echo clang-format-14 ;;
      csharp) echo mono-mcs mono-runtime ;;
      python) echo python3 python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest python3-venv \
        python3-setuptools python3-wheel libstb-dev pkg-config ;;
      wasm) echo emscripten nodejs ;;
      web) echo chromium chromium-driver ;;
      windows) echo g++-mingw-w64-x86-64-posix gcc-mingw-w64-x86-64-posix wine64 ;;
      *)
        echo "deps.sh: unknown dependency group '$group'" >&2
        return 1
        ;;
    esac
  done
}

hedge_package_installed() {
  dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q 'install ok installed'
}

hedge_install_deps() {
  local packages pkg
  local -a missing=()
  packages=$(hedge_deps_packages "$@") || return 1
  # shellcheck disable=SC2086  # the package list is split on whitespace on purpose
  for pkg in $(printf '%s\n' $packages | sort -u); do
    hedge_package_installed "$pkg" || missing+=("$pkg")
  done
  if [ "${#missing[@]}" -eq 0 ]; then
    return 0
  fi

  local -a sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
      sudo=(sudo)
    else
      echo "deps.sh: missing packages (${missing[*]}) and not root; install them with apt-get" >&2
      return 1
    fi
  fi
  echo "==> Installing: ${missing[*]}"
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q || return 1
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y -q --no-install-recommends "${missing[@]}" </dev/null || return 1
}

# Installs the playground's npm packages (web/node_modules) from web/package-lock.json with
# `npm ci`, unless they are installed already and the lock file has not changed since.
hedge_web_npm() {
  local root web
  root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  web=$root/web
  if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
    echo "deps.sh: node (18 or newer) and npm are needed for web/; install them first" \
      "(Debian 12: apt-get install nodejs npm)" >&2
    return 1
  fi
  local major
  major=$(node -p 'process.versions.node.split(".")[0]')
  # 18: Debian 12's nodejs. bindings/wasm/test/engines.test.mjs checks that every npm package of
  # web/package-lock.json (and of the package's tests) admits it.
  if [ "$major" -lt 18 ]; then
    echo "deps.sh: web/ needs node 18 or newer, found $(node --version)" >&2
    return 1
  fi
  if [ -f "$web/node_modules/.package-lock.json" ] &&
    [ ! "$web/package-lock.json" -nt "$web/node_modules/.package-lock.json" ]; then
    return 0
  fi
  echo "==> npm ci in web/"
  (cd "$web" && npm ci --no-audit --no-fund) || return 1
}
