// Appended to hedge.single.mjs, the module built with hedge.wasm embedded (SINGLE_FILE): tells
// loadHedge (load.js) that there is no wasm file to read under node.
createHedge.wasmEmbedded = true;
