"""The strikes bench/wasm_fracture_solid.mjs timed in WebAssembly, replayed natively through the
Python binding (the same library, compiled natively; the binding's own cost is a few microseconds
against milliseconds), twice, on fresh copies whose picking tree is built untimed:

    PYTHONPATH=build/release/bindings/python/package /usr/bin/python3 \\
        bench/python/fracture_solid_native.py [build/output/solid_strikes.json]

Prints the native median and the ratio of the wasm median given with --wasm-ms.
"""

import json
import os
import statistics
import sys
import time

import hedge

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    path = args[0] if args else os.path.join(ROOT, "build", "output", "solid_strikes.json")
    wasm_ms = next((float(a.split("=", 1)[1]) for a in sys.argv[1:] if a.startswith("--wasm-ms=")), None)
    with open(path, encoding="utf-8") as f:
        run = json.load(f)
    if run["mesh"] == "ico6":
        base = hedge.read(os.path.join(ROOT, "data", "icosahedron_binary.stl"))
        base.subdivide("loop", 6)
    else:
        base = hedge.read(os.path.join(ROOT, "data", "spot_triangulated.obj"))
    times, pieces = [], []
    for _ in range(2):
        for s in run["strikes"]:
            mesh = base.clone()
            mesh.ray_cast([[0, 0, 0]], [[0, 0, 1]])  # builds the picking tree
            t0 = time.perf_counter()
            broken, _ = mesh.fracture_solid(s["point"], run["material"], seed=s["seed"], radius=run["radius"])
            times.append(1000 * (time.perf_counter() - t0))
            pieces.append(len(broken))
    median = statistics.median(times)
    line = f"{run['mesh']}, {run['material']}: {len(times)} strikes, {sum(pieces) / len(pieces):.1f} pieces; native median {median:.1f} ms"
    if wasm_ms is not None:
        line += f"; wasm / native {wasm_ms / median:.2f}"
    print(line)


if __name__ == "__main__":
    main()
