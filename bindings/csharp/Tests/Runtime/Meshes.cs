// Small meshes shared by the binding's tests, and by the C# fracture timing (bench/csharp/), which
// compiles this file in for its plate.
using System;

namespace Hedge.Tests
{
    /// <summary>Small meshes shared by the tests.</summary>
    public static class Meshes
    {
        // A tetrahedron, outward (counter-clockwise) faces.
        public static readonly float[] TetPositions = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
        public static readonly int[] TetTriangles = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 };

        // A square pyramid without its base: 5 vertices, 4 triangles, one boundary loop 0-1-2-3.
        public static readonly float[] PyramidPositions = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5f, 0.5f, 1 };
        public static readonly int[] PyramidTriangles = { 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4 };

        // A 2 x 2 grid of quads over 3 x 3 vertices.
        public static readonly float[] GridPositions =
            { 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0, 0, 2, 0, 1, 2, 0, 2, 2, 0 };
        public static readonly int[] GridQuads = { 0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7 };
        public static readonly int[] GridSizes = { 4, 4, 4, 4 };

        public static HalfEdgeMesh Tet() { return HalfEdgeMesh.FromTriangles(TetPositions, TetTriangles); }
        public static HalfEdgeMesh Pyramid() { return HalfEdgeMesh.FromTriangles(PyramidPositions, PyramidTriangles); }

        public static HalfEdgeMesh Grid()
        {
            BuildReport report;
            return HalfEdgeMesh.FromPolygons(GridPositions, GridQuads, GridSizes, BuildOptions.Default, out report);
        }

        /// <summary>Sorted indices of the first count vertices.</summary>
        public static int[] Sorted(Vertex[] vertices, int count)
        {
            var r = new int[count];
            for (int i = 0; i < count; ++i) r[i] = vertices[i].Index;
            Array.Sort(r);
            return r;
        }

        /// <summary>The corners of face f, rotated to start at its smallest vertex index.</summary>
        public static int[] Corners(HalfEdgeMesh mesh, Face f)
        {
            var buffer = new Vertex[16];
            int n = mesh.GetFaceVertices(f, buffer);
            return Rotated(buffer, n);
        }

        public static int[] Rotated(Vertex[] corners, int n)
        {
            int start = 0;
            for (int i = 1; i < n; ++i)
                if (corners[i].Index < corners[start].Index) start = i;
            var r = new int[n];
            for (int i = 0; i < n; ++i) r[i] = corners[(start + i) % n].Index;
            return r;
        }

        public static string Show(int[] a) { return "[" + string.Join(", ", a) + "]"; }

        /// <summary>A plate of n x n unit squares in z = 0, each cut into two triangles: (n + 1)^2 vertices,
        /// x and y in [0, n].</summary>
        public static HalfEdgeMesh Plate(int n)
        {
            var positions = new float[3 * (n + 1) * (n + 1)];
            for (int j = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i)
                {
                    int v = j * (n + 1) + i;
                    positions[3 * v] = i;
                    positions[3 * v + 1] = j;
                }
            var triangles = new int[6 * n * n];
            int k = 0;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i)
                {
                    int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
                    foreach (int v in new[] { a, b, c, a, c, d }) triangles[k++] = v;
                }
            return HalfEdgeMesh.FromTriangles(positions, triangles);
        }
    }
}
