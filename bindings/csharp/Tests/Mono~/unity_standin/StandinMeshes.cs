// The flat grids the stand-in tests build their Unity meshes from: n x n unit squares at z = 0,
// two triangles each, in Unity's winding (clockwise seen from -z, where the tests' camera is).
using UnityEngine;

namespace Hedge.Tests
{
    public static class StandinMeshes
    {
        /// <summary>The (n + 1)^2 grid points, row by row: point (x, y) is at index y * (n + 1) + x.</summary>
        public static Vector3[] GridPositions(int n)
        {
            var v = new Vector3[(n + 1) * (n + 1)];
            for (int y = 0; y <= n; ++y)
                for (int x = 0; x <= n; ++x) v[y * (n + 1) + x] = new Vector3(x, y, 0);
            return v;
        }

        /// <summary>The six indices of square (x, y): two triangles in Unity's winding.</summary>
        public static int[] SquareTriangles(int n, int x, int y)
        {
            int a = y * (n + 1) + x, b = a + 1, c = a + n + 2, d = a + n + 1;
            return new[] { a, c, b, a, d, c };
        }

        /// <summary>Every square's two triangles, row by row.</summary>
        public static int[] GridTriangles(int n)
        {
            var t = new int[6 * n * n];
            int k = 0;
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x)
                    foreach (int i in SquareTriangles(n, x, y)) t[k++] = i;
            return t;
        }

        /// <summary>A Unity mesh of the grid: positions and triangles only.</summary>
        public static UnityEngine.Mesh Grid(int n, string name)
        {
            var m = new UnityEngine.Mesh();
            m.name = name;
            m.vertices = GridPositions(n);
            m.triangles = GridTriangles(n);
            return m;
        }
    }
}
