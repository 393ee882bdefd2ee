// Files read in Unity's space: UnityMeshes.Read gives what Unity's model importer gives (x negated
// in positions and normals, triangles reversed, texcoords kept), and UnityMeshes.Write gives the
// file back. The reference is built here by hand from the file's own arrays with that rule.
using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;
using Hedge.Unity;
using UnityEngine;

namespace Hedge.Tests
{
    public static class UnitySpaceTests
    {
        static string TestFile(string name)
        {
            string dir = Environment.GetEnvironmentVariable("HEDGE_CSHARP_TESTS_DIR");
            if (string.IsNullOrEmpty(dir)) throw new InvalidOperationException("HEDGE_CSHARP_TESTS_DIR is not set");
            return Path.Combine(dir, name);
        }

        static RenderOptions FileAttributes()
        {
            RenderOptions o = RenderOptions.Unity;
            o.Normals = NormalSource.Attribute;  // the file's normals, not recomputed ones
            return o;
        }

        // The mesh's render arrays in Unity's layout (a fresh RenderBuffers has no free slots).
        static void Arrays(HalfEdgeMesh mesh, out Vector3[] p, out Vector3[] n, out Vector2[] uv, out int[] t)
        {
            using (RenderBuffers b = mesh.CreateRenderBuffers(FileAttributes()))
            {
                var fp = new float[b.CopyStream(VertexStream.Vertices, null)];
                var fn = new float[b.CopyStream(VertexStream.Normals, null)];
                var fuv = new float[b.CopyStream(VertexStream.Texcoords, null)];
                b.CopyStream(VertexStream.Vertices, fp);
                b.CopyStream(VertexStream.Normals, fn);
                b.CopyStream(VertexStream.Texcoords, fuv);
                t = new int[b.CopyIndices(null)];
                b.CopyIndices(t);
                p = new Vector3[fp.Length / 3];
                n = new Vector3[fn.Length / 3];
                uv = new Vector2[fuv.Length / 2];
                for (int i = 0; i < p.Length; ++i) p[i] = new Vector3(fp[3 * i], fp[3 * i + 1], fp[3 * i + 2]);
                for (int i = 0; i < n.Length; ++i) n[i] = new Vector3(fn[3 * i], fn[3 * i + 1], fn[3 * i + 2]);
                for (int i = 0; i < uv.Length; ++i) uv[i] = new Vector2(fuv[2 * i], fuv[2 * i + 1]);
            }
        }

        static string Corner(Vector3[] p, Vector3[] n, Vector2[] uv, int i)
        {
            Func<float, string> f = x => x.ToString("R", CultureInfo.InvariantCulture);
            return "(" + f(p[i].x) + " " + f(p[i].y) + " " + f(p[i].z) + " | " + f(n[i].x) + " " + f(n[i].y) + " " +
                   f(n[i].z) + " | " + f(uv[i].x) + " " + f(uv[i].y) + ")";
        }

        // Every triangle as its corners (position, normal, texcoord) in winding order, starting at the
        // smallest corner; sorted. Equal lists: the same triangles, facing the same way, same attributes.
        static List<string> Triangles(HalfEdgeMesh mesh)
        {
            Vector3[] p, n;
            Vector2[] uv;
            int[] t;
            Arrays(mesh, out p, out n, out uv, out t);
            var list = new List<string>();
            for (int k = 0; k + 2 < t.Length; k += 3)
            {
                var c = new[] { Corner(p, n, uv, t[k]), Corner(p, n, uv, t[k + 1]), Corner(p, n, uv, t[k + 2]) };
                int s = 0;
                for (int i = 1; i < 3; ++i)
                    if (string.CompareOrdinal(c[i], c[s]) < 0) s = i;
                list.Add(c[s] + " " + c[(s + 1) % 3] + " " + c[(s + 2) % 3]);
            }
            list.Sort(string.CompareOrdinal);
            return list;
        }

        static void CheckSameTriangles(List<string> expected, List<string> actual, string what)
        {
            Check.Equal(expected.Count, actual.Count, "triangles " + what);
            for (int i = 0; i < expected.Count; ++i) Check.Equal(expected[i], actual[i], what);
        }

        // What Unity's importer makes of the file: its arrays with x negated in positions and normals
        // and each triangle reversed, taken as the component takes a Unity mesh.
        static HalfEdgeMesh AsUnityImports(string path)
        {
            Vector3[] p, n;
            Vector2[] uv;
            int[] t;
            using (HalfEdgeMesh file = HalfEdgeMesh.Read(path)) Arrays(file, out p, out n, out uv, out t);
            for (int i = 0; i < p.Length; ++i) p[i].x = -p[i].x;
            for (int i = 0; i < n.Length; ++i) n[i].x = -n[i].x;
            for (int k = 0; k + 2 < t.Length; k += 3)
            {
                int b = t[k + 1];
                t[k + 1] = t[k + 2];
                t[k + 2] = b;
            }
            return UnityMeshes.FromUnityMesh(p, t, n, uv, null);
        }

        static bool HasVertexAt(HalfEdgeMesh mesh, Vec3 p)
        {
            for (int v = 0; v < mesh.Counts.VertexSlots; ++v)
                if (!mesh.IsDeleted(new Vertex(v)) && mesh.GetPosition(new Vertex(v)) == p) return true;
            return false;
        }

        [Test]
        static void ReadGivesWhatUnitysImporterGives()
        {
            string path = TestFile("asymmetric_arm.obj");
            using (HalfEdgeMesh expected = AsUnityImports(path))
            using (HalfEdgeMesh read = UnityMeshes.Read(path))
            using (HalfEdgeMesh fromBytes = UnityMeshes.FromBytes(File.ReadAllBytes(path), "asymmetric_arm.obj"))
            using (HalfEdgeMesh plain = HalfEdgeMesh.Read(path))
            {
                Check.True(HasVertexAt(plain, new Vec3(3, 0, 0.6f)), "the file's arm is at x = +3");
                Check.True(HasVertexAt(read, new Vec3(-3, 0, 0.6f)), "Unity's arm is at x = -3");
                Check.False(HasVertexAt(read, new Vec3(3, 0, 0.6f)), "not mirrored twice");
                CheckSameTriangles(Triangles(expected), Triangles(read), "UnityMeshes.Read");
                CheckSameTriangles(Triangles(expected), Triangles(fromBytes), "UnityMeshes.FromBytes");
                // Faces face where their normals point: the imported normal of each corner agrees with the face.
                for (int f = 0; f < read.Counts.FaceSlots; ++f)
                {
                    Vec3 fn = read.FaceNormal(new Face(f));
                    Check.True(fn.X > 0.1f && fn.Z > 0.9f, "face " + f + " faces +z, tilted to +x: " + fn);
                }
                Check.Valid(read);
            }
        }

        [Test]
        static void WriteGivesTheFileBack()
        {
            string path = TestFile("asymmetric_arm.obj");
            string dir = Path.Combine(Path.GetTempPath(), "hedge-unity-space-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            try
            {
                string plainOut = Path.Combine(dir, "plain.obj"), unityOut = Path.Combine(dir, "unity.obj");
                using (HalfEdgeMesh plain = HalfEdgeMesh.Read(path)) plain.Write(plainOut);
                using (HalfEdgeMesh read = UnityMeshes.Read(path))
                {
                    List<string> before = Triangles(read);
                    UnityMeshes.Write(read, unityOut);
                    CheckSameTriangles(before, Triangles(read), "the mesh after writing it");
                    Check.True(HasVertexAt(read, new Vec3(-3, 0, 0.6f)), "still in Unity's space");
                    Check.Valid(read);
                }
                Check.Equal(Encoding.UTF8.GetString(File.ReadAllBytes(plainOut)),
                            Encoding.UTF8.GetString(File.ReadAllBytes(unityOut)), "the file back, byte for byte");
                using (HalfEdgeMesh again = HalfEdgeMesh.Read(unityOut))
                using (HalfEdgeMesh original = HalfEdgeMesh.Read(path))
                    CheckSameTriangles(Triangles(original), Triangles(again), "the written file read back");
            }
            finally
            {
                Directory.Delete(dir, true);
            }
        }
    }
}
