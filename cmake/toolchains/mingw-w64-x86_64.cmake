# Cross build for Windows x64 from Debian with MinGW-w64 (packages g++-mingw-w64-x86-64-posix and
# gcc-mingw-w64-x86-64-posix; `source scripts/deps.sh && hedge_install_deps windows`). The posix
# flavour of the compilers is the one with std::thread (over winpthreads). Used by the `windows`
# preset (CMakePresets.json), which builds hedge_c.dll and the C ABI tests as .exe files and runs
# them under wine64.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR AMD64)

set(HEDGE_MINGW_TRIPLET x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${HEDGE_MINGW_TRIPLET}-gcc-posix)
set(CMAKE_CXX_COMPILER ${HEDGE_MINGW_TRIPLET}-g++-posix)
set(CMAKE_RC_COMPILER ${HEDGE_MINGW_TRIPLET}-windres)

# Libraries and headers of the target come from the MinGW-w64 sysroot only; programs run during the
# build come from the host. Header-only dependencies of the host (Eigen, tinygltf, nlohmann-json)
# are reached through their own folders (src/CMakeLists.txt), never through /usr/include, whose C
# library headers are glibc's.
set(CMAKE_FIND_ROOT_PATH /usr/${HEDGE_MINGW_TRIPLET})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# The Windows programs (the C ABI tests) run under wine64 (package wine64, which installs its loader
# outside PATH), through a wrapper that keeps wine's prefix inside the build tree.
find_program(HEDGE_WINE64 wine64 PATHS /usr/lib/wine NO_CMAKE_FIND_ROOT_PATH)
if(HEDGE_WINE64)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${CMAKE_CURRENT_LIST_DIR}/wine-run)
endif()
