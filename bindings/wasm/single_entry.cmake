# Writes hedge.single.js (OUT): hedge.js (IN) with its one import of the module, './hedge.mjs',
# turned into './hedge.single.mjs', so the single-file entry shares every line of the API and never
# refers to hedge.wasm (a bundler would emit it otherwise).
file(READ "${IN}" text)
set(from "import createHedge from './hedge.mjs';")
string(FIND "${text}" "${from}" first)
string(FIND "${text}" "${from}" last REVERSE)
if(first EQUAL -1 OR NOT first EQUAL last)
  message(FATAL_ERROR "${IN} must contain the line \"${from}\" exactly once")
endif()
string(REPLACE "${from}" "import createHedge from './hedge.single.mjs';" text "${text}")
file(WRITE "${OUT}" "// Generated from hedge.js by single_entry.cmake: the API over hedge.single.mjs.\n${text}")
