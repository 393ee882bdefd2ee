// The process-wide thread setting (Hedge.Threads).
using System;

namespace Hedge.Tests
{
    public static class ThreadTests
    {
        [Test]
        static void MaxThreadsRoundTrips()
        {
            try
            {
                int cores = Threads.MaxThreads;
                Check.True(cores >= 1, "the default is at least one thread");
                Threads.MaxThreads = 1;
                Check.Equal(1, Threads.MaxThreads);
                Threads.MaxThreads = 3;
                Check.Equal(3, Threads.MaxThreads);
                Threads.MaxThreads = 0;
                Check.Equal(cores, Threads.MaxThreads, "0 restores the default");
            }
            finally
            {
                Threads.MaxThreads = 0;
            }
        }

        [Test]
        static void NegativeIsRefused()
        {
            Threads.MaxThreads = 2;
            try
            {
                var e = Check.ThrowsType<ArgumentOutOfRangeException>(() => Threads.MaxThreads = -1);
                Check.Contains(e.Message, "MaxThreads");
                Check.Equal(2, Threads.MaxThreads, "a refused value changes nothing");
            }
            finally
            {
                Threads.MaxThreads = 0;
            }
        }

        // A wavy 200 x 200 grid of quads: each subdivision pass is long enough to split between two threads.
        static float[] Subdivided(int threads)
        {
            const int side = 200, n = side + 1;
            var positions = new float[3 * n * n];
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x)
                {
                    positions[3 * (y * n + x)] = x;
                    positions[3 * (y * n + x) + 1] = y;
                    positions[3 * (y * n + x) + 2] = ((x * 7 + y * 13) % 5) * 0.25f;
                }
            var triangles = new int[6 * side * side];
            for (int y = 0, t = 0; y < side; ++y)
                for (int x = 0; x < side; ++x)
                {
                    int a = y * n + x, b = a + 1, c = a + n + 1, d = a + n;
                    triangles[t++] = a; triangles[t++] = b; triangles[t++] = c;
                    triangles[t++] = a; triangles[t++] = c; triangles[t++] = d;
                }
            Threads.MaxThreads = threads;
            using (HalfEdgeMesh mesh = HalfEdgeMesh.FromTriangles(positions, triangles))
            {
                mesh.Subdivide(Subdivision.Loop, 1);
                Check.Valid(mesh);
                var result = new float[mesh.CopyPositions(null)];
                mesh.CopyPositions(result);
                return result;
            }
        }

        [Test]
        static void SubdivisionIsTheSameOnOneThreadAsOnTwo()
        {
            try
            {
                float[] one = Subdivided(1), two = Subdivided(2);
                Check.Equal(one.Length, two.Length);
                Check.Same(one, two, one.Length, "positions");
            }
            finally
            {
                Threads.MaxThreads = 0;
            }
        }
    }
}
