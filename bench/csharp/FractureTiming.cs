// Times HalfEdgeMesh.SimulateBreaking from C# (Mono) as a game calls it: one strike at a time on a
// flat plate of n x n quads (2 n^2 triangles), glass preset with its defaults (each shard a solid
// GameRelativeThickness of the break radius thick, with mass properties and hull) but the break
// radius of BM_fracture, 7 edge lengths of the impact face (the preset's own, 0.13 of the plate's
// diagonal, breaks about 110k faces of the 1M plate a strike), at the centroid
// of a random remaining triangle, through the mesh's picking tree. The tree is built once before the
// strikes (UpdatePickingTree, timed apart); a few warm-up strikes are not counted; when a fifth of
// the faces has broken off, the plate is made again, not timed. Prints the median and the 99th
// percentile of the strikes, and a last line "csharp_median_ms X" for bench/fracture_csharp_ratio.
//
//   mono FractureTiming.exe [n (708: 1,002,528 triangles)] [strikes (200)]
//
// Built and run by the fracture_timing_csharp target (bench/csharp/CMakeLists.txt); the plate is
// Meshes.Plate of the binding's tests (bindings/csharp/Tests/Runtime/Meshes.cs).
using System;
using System.Collections.Generic;
using System.Diagnostics;
using Hedge;
using Hedge.Tests;

static class FractureTiming
{
    // The centroid of a random triangle of the plate that is still there.
    static Vec3 Impact(HalfEdgeMesh mesh, int n, Random random)
    {
        while (true)
        {
            int i = random.Next(n), j = random.Next(n);
            bool upper = random.Next(2) == 1;
            // Triangles (i, j), (i + 1, j), (i + 1, j + 1) and (i, j), (i + 1, j + 1), (i, j + 1).
            var p = upper ? new Vec3(i + 1f / 3, j + 2f / 3, 0) : new Vec3(i + 2f / 3, j + 1f / 3, 0);
            Face face;
            if (mesh.TryGetFaceContainingPoint(p, out face)) return p;
        }
    }

    static double Percentile(List<double> sorted, int percent)
    {
        return sorted[Math.Min(sorted.Count - 1, sorted.Count * percent / 100)];
    }

    static int Main(string[] args)
    {
        int n = args.Length > 0 ? int.Parse(args[0]) : 708;
        int strikes = args.Length > 1 ? int.Parse(args[1]) : 200;
        const int warmup = 5;
        var random = new Random(1);
        var clock = new Stopwatch();
        var times = new List<double>();
        double shards = 0, build = 0;
        HalfEdgeMesh mesh = null;
        int triangles = 2 * n * n;
        for (int s = 0; s < warmup + strikes; ++s)
        {
            if (mesh == null || mesh.FaceCount < triangles * 4 / 5)
            {
                if (mesh != null) mesh.Dispose();
                mesh = Meshes.Plate(n);
                clock.Restart();
                mesh.UpdatePickingTree();
                build = clock.Elapsed.TotalMilliseconds;
            }
            Vec3 impact = Impact(mesh, n, random);
            ulong seed = (ulong)random.Next();
            clock.Restart();
            // SimulateBreaking's options at BM_fracture's break radius, 7 edge lengths of the impact face.
            FractureOptions options = FractureOptions.Preset(FracturePreset.Glass);
            options.Units = FractureUnits.EdgeLengths;
            options.Radius = 7;
            options.Seed = seed;
            FractureShard[] result = mesh.Fracture(impact, options);
            double ms = clock.Elapsed.TotalMilliseconds;
            if (s >= warmup)
            {
                times.Add(ms);
                shards += result.Length;
            }
            foreach (FractureShard shard in result) shard.Dispose();
        }
        mesh.Dispose();
        times.Sort();
        Console.WriteLine("C# SimulateBreaking, plate of {0:N0} triangles, glass, {1} strikes (after {2} warm-up): median {3:F3} ms, " +
                          "p99 {4:F3} ms, {5:F1} shards per strike; picking tree built in {6:F0} ms before the strikes",
                          triangles, strikes, warmup, Percentile(times, 50), Percentile(times, 99), shards / strikes, build);
        Console.WriteLine("csharp_median_ms {0:R}", Percentile(times, 50));
        return 0;
    }
}
