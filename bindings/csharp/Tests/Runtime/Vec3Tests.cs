// Vec3's arithmetic: the operators and helpers a game needs without converting to its engine's type.
using System;

namespace Hedge.Tests
{
    public static class Vec3Tests
    {
        [Test]
        static void Operators()
        {
            var a = new Vec3(1, 2, 3);
            var b = new Vec3(4, -5, 6);
            Check.Equal(new Vec3(5, -3, 9), a + b);
            Check.Equal(new Vec3(-3, 7, -3), a - b);
            Check.Equal(new Vec3(-1, -2, -3), -a);
            Check.Equal(new Vec3(2, 4, 6), a * 2);
            Check.Equal(new Vec3(2, 4, 6), 2 * a, "scalar on either side");
            Check.Equal(new Vec3(0.5f, 1, 1.5f), a / 2);
            Check.True(a == new Vec3(1, 2, 3));
            Check.True(a != b);
            Check.False(a.Equals(b));
            Check.Equal(new Vec3(0, 0, 0), Vec3.Zero);
            Check.Equal(new Vec3(2.5f, -1.5f, 4.5f), Vec3.Lerp(a, b, 0.5f));
        }

        [Test]
        static void DotCrossLength()
        {
            var x = new Vec3(1, 0, 0);
            var y = new Vec3(0, 1, 0);
            Check.Equal(new Vec3(0, 0, 1), Vec3.Cross(x, y), "right-handed");
            Check.Equal(new Vec3(0, 0, -1), Vec3.Cross(y, x));
            Check.Equal(32f, Vec3.Dot(new Vec3(1, 2, 3), new Vec3(4, 5, 6)));
            Check.Equal(0f, Vec3.Dot(x, y));
            Check.Equal(5f, new Vec3(3, 4, 0).Length);
            Check.Equal(25f, new Vec3(3, 4, 0).SqrLength);
            Check.Equal(13f, Vec3.Distance(new Vec3(1, 1, 1), new Vec3(4, 5, 13)));
            Vec3 n = new Vec3(0, 3, 4).Normalized;
            Check.Equal(new Vec3(0, 0.6f, 0.8f), n);
            Check.Near(1, n.Length, 1e-6);
            Check.Equal(Vec3.Zero, Vec3.Zero.Normalized, "no direction: zero, not NaN");
            Check.Equal(Vec3.Zero, new Vec3(float.NaN, 0, 0).Normalized);
            var big = new Vec3(3e30f, 4e30f, 0);
            Check.Near(5e30, big.Length, 1e24, "no overflow");
            Check.Near(0.6, big.Normalized.X, 1e-6);
        }

        // The operators agree with the library: a triangle's normal is the normalized cross product of its edges.
        [Test]
        static void AgreesWithFaceNormals()
        {
            using (HalfEdgeMesh mesh = Meshes.Tet())
            {
                var corners = new Vertex[3];
                for (int f = 0; f < mesh.FaceCount; ++f)
                {
                    Check.Equal(3, mesh.GetFaceVertices(new Face(f), corners));
                    Vec3 p0 = mesh.GetPosition(corners[0]), p1 = mesh.GetPosition(corners[1]);
                    Vec3 p2 = mesh.GetPosition(corners[2]);
                    Vec3 n = Vec3.Cross(p1 - p0, p2 - p0).Normalized;
                    Check.Near(0, (n - mesh.FaceNormal(new Face(f))).Length, 1e-6, "face " + f);
                }
                Check.Valid(mesh);
            }
        }
    }
}
