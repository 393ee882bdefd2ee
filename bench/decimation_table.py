#!/usr/bin/env python3
"""The README's decimation table from two runs of bench/peers, one per share.

Run both shares side by side, each pinned to its own core, then print the table:

    M=../shared/meshes
    MESHES="$M/anchor.off $M/spot_triangulated.obj $M/fandisk.off $M/turbine.off $M/bunny.off \
      $M/armadillo.obj $M/horse.ply $M/igea.ply $M/stanford-bunny.obj $M/mannequin-devil.off \
      $M/three_peaks.off $M/bob_small.ply $M/elephant-with-holes.off $M/blobby-shuffled.off"
    taskset -c 1 bench/peers --only decimate --reps 1 --decimate-ratio 0.1 $MESHES > ten.txt &
    taskset -c 0 bench/peers --only decimate --reps 1 --decimate-ratio 0.01 $MESHES > one.txt
    wait
    bench/decimation_table.py ten.txt:10% one.txt:1%

A share may name further runs for the times, `ten.txt,t1.txt,t2.txt,t3.txt:10%`, e.g. of
`--only hedge:decimate,meshopt:decimate --reps 5` (OpenMesh and CGAL left out, so more rounds fit
in the same minutes); the distances then come from the first file, and each time is the median of
that mesh's times over the further runs.

Meshes that only meshoptimizer takes (no Hausdorff row for the other peers) are left out. The
summary line after the table gives, per bar, how many cases pass and the worst case.
"""

import re
import sys

HEAD = re.compile(r"^(\S+): \d+ vertices, \d+ triangles")
TIME = re.compile(r"^\s+QEM decimation \(--decimate-ratio\)\s+(.*?)\s{2,}\S+x \(")
DIST = re.compile(r"^\s+Hausdorff distance to input\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)")
UNITS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def millis(text):
    value, unit = text.split()
    return float(value) * UNITS[unit]


def cases(path):
    """(mesh, [hedge, OpenMesh, CGAL, meshopt] times as printed, [distances]) per mesh."""
    out, mesh, times = [], None, None
    with open(path, encoding="utf-8") as f:
        for line in f:
            if m := HEAD.match(line):
                mesh, times = m.group(1).rsplit(".", 1)[0], None
            elif m := TIME.match(line):
                times = re.split(r"\s{2,}", m.group(1).strip())  # a peer left out: n/a
            elif (m := DIST.match(line)) and mesh and times and len(times) == 4:
                out.append((mesh, times, list(m.groups())))
    return out


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    print("| mesh | share | hedge | meshopt | hedge / meshopt | Hausdorff: hedge | OpenMesh | CGAL "
          "| meshopt | hedge / best |")
    print("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    time_ratios, dist_ratios = [], []
    for arg in argv[1:]:
        paths, share = arg.rsplit(":", 1)
        path, *time_paths = paths.split(",")
        # Several timing runs: per mesh, the median of their hedge and meshoptimizer times.
        runs = {}
        for time_path in time_paths:
            for mesh, times, _ in cases(time_path):
                runs.setdefault(mesh, []).append(times)
        def median(texts):
            return sorted(texts, key=millis)[(len(texts) - 1) // 2]

        timed = {mesh: [median([r[i] for r in rs]) if i in (0, 3) else rs[0][i] for i in range(4)]
                 for mesh, rs in runs.items()}
        for mesh, times, dist in cases(path):
            times = timed.get(mesh, times)
            d = [float(x) for x in dist]
            if d[1] <= 0 or d[2] <= 0:
                continue
            t = millis(times[0]) / millis(times[3])
            r = d[0] / min(d[1], d[2])
            time_ratios.append((t, f"{mesh} {share}"))
            dist_ratios.append((r, f"{mesh} {share}"))
            print(f"| {mesh} | {share} | {times[0]} | {times[3]} | {t:.2f}x | {dist[0]} | {dist[1]} "
                  f"| {dist[2]} | {dist[3]} | {r:.2f}x |")
    passed = sum(1 for r, _ in dist_ratios if r <= 1.0 + 5e-3)
    worst_t, worst_d = max(time_ratios), max(dist_ratios)
    print(f"\nHausdorff bar (1.0x): {passed} of {len(dist_ratios)} pass; worst {worst_d[1]} "
          f"{worst_d[0]:.2f}x. Time: {min(time_ratios)[0]:.2f}-{worst_t[0]:.2f}x meshoptimizer's, "
          f"worst {worst_t[1]}; {sum(1 for t, _ in time_ratios if t <= 2)} within 2x.")


if __name__ == "__main__":
    main(sys.argv)
