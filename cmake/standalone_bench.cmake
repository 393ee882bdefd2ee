# What a benchmark folder that is configured on its own (cmake -S bench/<name>) needs after its
# project() call: C++20, a Release build unless told otherwise, and hedge itself (the library only,
# without its tests and tool) built beside it. Included by bench/io and bench/locate.
set(CMAKE_CXX_STANDARD 20)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
if(NOT CMAKE_BUILD_TYPE)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "" FORCE)
endif()
set(HEDGE_BUILD_TESTS OFF CACHE BOOL "" FORCE)
set(HEDGE_BUILD_TOOLS OFF CACHE BOOL "" FORCE)
add_subdirectory(${CMAKE_CURRENT_LIST_DIR}/.. hedge EXCLUDE_FROM_ALL)
