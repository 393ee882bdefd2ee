// The seam round trip: spot_triangulated.obj as an engine would hold it (one vertex per distinct
// position/texcoord pair, so UV seams are duplicated vertices), built with FromEngineMesh (positions
// welded), exported by RenderBuffers: the same triangles with the same attribute values, bit for
// bit, in hedge's conventions and in Unity's (clockwise, x flipped).
using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace Hedge.Tests
{
    public static class SeamTests
    {
        /// <summary>Engine arrays: one entry per engine vertex.</summary>
        sealed class EngineMesh
        {
            public float[] Positions, Normals, Texcoords, Colors;
            public int[] Triangles;
            public int VertexCount { get { return Positions.Length / 3; } }
        }

        /// <summary>Reads an OBJ with v, vt and triangular f lines into engine arrays: a vertex per distinct
        /// (v, vt) pair. Normals (the unit position vector) and colours (from the texcoords) are made up so
        /// that every attribute stream takes part.</summary>
        static EngineMesh ReadEngineObj(string path)
        {
            var v = new List<float>();
            var vt = new List<float>();
            var slot = new Dictionary<long, int>();
            var p = new List<float>();
            var uv = new List<float>();
            var tris = new List<int>();
            foreach (string raw in File.ReadAllLines(path))
            {
                string[] w = raw.Split(new[] { ' ', '\t' }, StringSplitOptions.RemoveEmptyEntries);
                if (w.Length == 0) continue;
                if (w[0] == "v")
                    for (int i = 1; i <= 3; ++i) v.Add(float.Parse(w[i], CultureInfo.InvariantCulture));
                else if (w[0] == "vt")
                    for (int i = 1; i <= 2; ++i) vt.Add(float.Parse(w[i], CultureInfo.InvariantCulture));
                else if (w[0] == "f")
                {
                    if (w.Length != 4) throw new InvalidDataException("not a triangle: " + raw);
                    for (int i = 1; i <= 3; ++i)
                    {
                        string[] parts = w[i].Split('/');
                        long a = long.Parse(parts[0], CultureInfo.InvariantCulture) - 1;
                        long b = long.Parse(parts[1], CultureInfo.InvariantCulture) - 1;
                        int index;
                        if (!slot.TryGetValue((a << 32) | b, out index))
                        {
                            index = (int)(p.Count / 3);
                            slot.Add((a << 32) | b, index);
                            p.Add(v[(int)(3 * a)]);
                            p.Add(v[(int)(3 * a + 1)]);
                            p.Add(v[(int)(3 * a + 2)]);
                            uv.Add(vt[(int)(2 * b)]);
                            uv.Add(vt[(int)(2 * b + 1)]);
                        }
                        tris.Add(index);
                    }
                }
            }
            var mesh = new EngineMesh
            {
                Positions = p.ToArray(), Texcoords = uv.ToArray(), Triangles = tris.ToArray()
            };
            int n = mesh.VertexCount;
            mesh.Normals = new float[3 * n];
            mesh.Colors = new float[4 * n];
            for (int i = 0; i < n; ++i)
            {
                float x = mesh.Positions[3 * i], y = mesh.Positions[3 * i + 1], z = mesh.Positions[3 * i + 2];
                float len = (float)Math.Sqrt(x * x + y * y + z * z);
                mesh.Normals[3 * i] = x / len;
                mesh.Normals[3 * i + 1] = y / len;
                mesh.Normals[3 * i + 2] = z / len;
                mesh.Colors[4 * i] = mesh.Texcoords[2 * i];
                mesh.Colors[4 * i + 1] = mesh.Texcoords[2 * i + 1];
                mesh.Colors[4 * i + 2] = 0.25f;
                mesh.Colors[4 * i + 3] = 1;
            }
            return mesh;
        }

        /// <summary>The same mesh in Unity's conventions: x negated (positions, normals), clockwise.</summary>
        static EngineMesh ToUnity(EngineMesh m)
        {
            var u = new EngineMesh
            {
                Positions = (float[])m.Positions.Clone(), Normals = (float[])m.Normals.Clone(),
                Texcoords = m.Texcoords, Colors = m.Colors, Triangles = (int[])m.Triangles.Clone()
            };
            for (int i = 0; i < u.VertexCount; ++i)
            {
                u.Positions[3 * i] = -u.Positions[3 * i];
                u.Normals[3 * i] = -u.Normals[3 * i];
            }
            for (int t = 0; t < u.Triangles.Length; t += 3)
            {
                int k = u.Triangles[t + 1];
                u.Triangles[t + 1] = u.Triangles[t + 2];
                u.Triangles[t + 2] = k;
            }
            return u;
        }

        // A corner's 12 floats as hex bits: position, normal, texcoord, colour.
        static string CornerKey(float[] p, float[] n, float[] uv, float[] c, int i)
        {
            var s = new StringBuilder(12 * 9);
            for (int k = 0; k < 3; ++k) s.Append(Bits(p[3 * i + k]));
            for (int k = 0; k < 3; ++k) s.Append(Bits(n[3 * i + k]));
            for (int k = 0; k < 2; ++k) s.Append(Bits(uv[2 * i + k]));
            for (int k = 0; k < 4; ++k) s.Append(Bits(c[4 * i + k]));
            return s.ToString();
        }

        static string Bits(float f)
        {
            return BitConverter.ToInt32(BitConverter.GetBytes(f), 0).ToString("x8") + " ";
        }

        // Triangles as sorted keys, each rotated to start at its smallest corner (winding kept).
        static List<string> TriangleKeys(float[] p, float[] n, float[] uv, float[] c, int[] indices, int count)
        {
            var keys = new List<string>();
            var corner = new string[3];
            for (int t = 0; t < count; t += 3)
            {
                if (indices[t] == indices[t + 1] && indices[t + 1] == indices[t + 2]) continue; // a free slot
                for (int k = 0; k < 3; ++k) corner[k] = CornerKey(p, n, uv, c, indices[t + k]);
                int s = 0;
                for (int k = 1; k < 3; ++k)
                    if (string.CompareOrdinal(corner[k], corner[s]) < 0) s = k;
                keys.Add(corner[s] + "|" + corner[(s + 1) % 3] + "|" + corner[(s + 2) % 3]);
            }
            keys.Sort(string.CompareOrdinal);
            return keys;
        }

        static int Distinct(EngineMesh m, bool positionsOnly)
        {
            var seen = new HashSet<string>();
            for (int i = 0; i < m.VertexCount; ++i)
            {
                string key = CornerKey(m.Positions, m.Normals, m.Texcoords, m.Colors, i);
                seen.Add(positionsOnly ? key.Substring(0, 27) : key);
            }
            return seen.Count;
        }

        static RenderOptions Separate(Winding winding, bool flipX)
        {
            RenderOptions o = RenderOptions.Default;
            o.Normals = NormalSource.Attribute;
            o.Interleaved = false;
            o.Winding = winding;
            o.FlipX = flipX;
            return o;
        }

        /// <summary>Copies the four separate streams and the indices of a render object.</summary>
        static void Export(RenderBuffers buffers, out float[] p, out float[] n, out float[] uv, out float[] c,
                           out int[] indices)
        {
            p = new float[buffers.CopyStream(VertexStream.Vertices, null)];
            n = new float[buffers.CopyStream(VertexStream.Normals, null)];
            uv = new float[buffers.CopyStream(VertexStream.Texcoords, null)];
            c = new float[buffers.CopyStream(VertexStream.Colors, null)];
            buffers.CopyStream(VertexStream.Vertices, p);
            buffers.CopyStream(VertexStream.Normals, n);
            buffers.CopyStream(VertexStream.Texcoords, uv);
            buffers.CopyStream(VertexStream.Colors, c);
            indices = new int[buffers.CopyIndices((int[])null)];
            buffers.CopyIndices(indices);
        }

        static void RoundTrip(EngineMesh engine, EngineImportOptions import, RenderOptions render)
        {
            BuildReport report;
            using (HalfEdgeMesh mesh = HalfEdgeMesh.FromEngineMesh(engine.Positions, engine.Triangles, engine.Normals,
                                                                   engine.Texcoords, engine.Colors, import, out report))
            using (RenderBuffers buffers = mesh.CreateRenderBuffers(render))
            {
                int meshVertices = Distinct(engine, true);
                int renderVertices = Distinct(engine, false);
                Check.Equal(meshVertices, mesh.VertexCount, "positions welded into topological vertices");
                Check.Equal((int)(engine.VertexCount - meshVertices), report.WeldedVertices);
                Check.Equal(0, report.Repairs);
                Check.Equal(engine.Triangles.Length / 3, mesh.FaceCount);
                MeshCounts c = mesh.Counts;
                Check.Equal(2L, (long)c.Vertices - c.Edges + c.Faces, "spot is a closed sphere once welded");

                BufferCounts counts = buffers.Counts;
                Check.Equal((int)renderVertices, counts.Vertices, "one render vertex per distinct corner");
                Check.Equal((int)(renderVertices - meshVertices), counts.SeamSplits);
                Check.True(counts.SeamSplits > 100, "spot has UV seams: " + counts.SeamSplits);
                Check.Equal((int)mesh.FaceCount, counts.Triangles);
                VertexLayout layout = buffers.Layout;
                Check.True(layout.HasNormals && layout.HasTexcoords && layout.HasColors);
                Check.Equal(12, layout.Stride);

                float[] p, n, uv, col;
                int[] indices;
                Export(buffers, out p, out n, out uv, out col, out indices);
                List<string> expected = TriangleKeys(engine.Positions, engine.Normals, engine.Texcoords, engine.Colors,
                                                     engine.Triangles, engine.Triangles.Length);
                List<string> exported = TriangleKeys(p, n, uv, col, indices, indices.Length);
                Check.Equal(expected.Count, exported.Count, "triangle count");
                for (int i = 0; i < expected.Count; ++i)
                    if (expected[i] != exported[i])
                        Check.Equal(expected[i], exported[i], "triangle " + i + " of the sorted lists");
                Check.Valid(mesh);
            }
        }

        [Test]
        static void SpotRoundTrip()
        {
            EngineMesh spot = ReadEngineObj(Context.Data("spot_triangulated.obj"));
            Check.Equal(5856 * 3, spot.Triangles.Length);
            Check.True(spot.VertexCount > 2930, "engine vertices duplicate the seams: " + spot.VertexCount);
            RoundTrip(spot, EngineImportOptions.Default, Separate(Winding.CounterClockwise, false));
        }

        // Spot as Unity's importer would hold it (x mirrored, winding reversed): Unity's data are taken as they
        // are, and come back as they were.
        [Test]
        static void SpotRoundTripUnityConventions()
        {
            EngineMesh spot = ToUnity(ReadEngineObj(Context.Data("spot_triangulated.obj")));
            RoundTrip(spot, EngineImportOptions.Unity, Separate(Winding.CounterClockwise, false));
        }

        // The conversion options for data in another convention: mirrored on the way in and back out.
        [Test]
        static void SpotRoundTripMirrored()
        {
            EngineMesh spot = ToUnity(ReadEngineObj(Context.Data("spot_triangulated.obj")));
            EngineImportOptions mirrored = EngineImportOptions.Default;
            mirrored.Winding = Winding.Clockwise;
            mirrored.FlipX = true;
            RoundTrip(spot, mirrored, Separate(Winding.Clockwise, true));
        }

        /// <summary>A UV-mapped n x n grid of unit squares as engine arrays: uv = (x, y) / n, normal +z. Squares
        /// right of column seamColumn (if 0 &lt; seamColumn &lt; n) map to uv + (10, 0), so the line x = seamColumn is
        /// a UV seam: its vertices are duplicated, as an engine holds seams.</summary>
        public static HalfEdgeMesh UvGrid(int n, int seamColumn = -1)
        {
            int side = n + 1;
            bool seam = seamColumn > 0 && seamColumn < n;
            int count = side * side + (seam ? side : 0);
            var p = new float[3 * count];
            var uv = new float[2 * count];
            var normals = new float[3 * count];
            for (int v = 0; v < count; ++v)
            {
                int i = v < side * side ? v % side : seamColumn, j = v < side * side ? v / side : v - side * side;
                bool right = v >= side * side || (seam && i > seamColumn);
                p[3 * v] = i;
                p[3 * v + 1] = j;
                uv[2 * v] = (float)i / n + (right ? 10 : 0);
                uv[2 * v + 1] = (float)j / n;
                normals[3 * v + 2] = 1;
            }
            var tris = new List<int>();
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i)
                {
                    int a = j * side + i, b = a + 1, c = a + side + 1, d = a + side;
                    if (seam && i == seamColumn)  // the right side's copies of the seam vertices
                    {
                        a = side * side + j;
                        d = side * side + j + 1;
                    }
                    tris.AddRange(new[] { a, b, c, a, c, d });
                }
            BuildReport report;
            return HalfEdgeMesh.FromEngineMesh(p, tris.ToArray(), normals, uv, null, EngineImportOptions.Unity,
                                               out report);
        }

        // The reported case: on a seamless grid, split the edge from uv (0.5, 0.5) to (0.75, 0.5) at a quarter and
        // merge the new vertex back into the first end: the survivor must keep one render vertex.
        [Test]
        static void SplitThenCollapseLeavesOneRenderVertex()
        {
            using (HalfEdgeMesh mesh = UvGrid(4))
            using (RenderBuffers buffers = mesh.GenerateUnityMesh())
            {
                Check.Equal(0, buffers.Counts.SeamSplits, "seamless");
                Vertex a = new Vertex(12), b = new Vertex(13);
                Check.Equal(new Vec3(2, 2, 0), mesh.GetPosition(a));
                Vertex v = mesh.SplitHalfEdge(mesh.FindHalfEdge(a, b), 2.25f, 2, 0);
                Check.True(v.IsValid, "split");
                buffers.Sync();
                Check.Equal(0, buffers.Counts.SeamSplits, "after the split");
                Check.Equal(a, mesh.Collapse(mesh.FindHalfEdge(v, a)), "the first end survives");
                buffers.Sync();
                Check.Equal(0, buffers.Counts.SeamSplits, "after the collapse");
                BufferCounts counts = buffers.Counts;
                var source = new Vertex[counts.VertexSlots];
                buffers.CopyVertexSource(source);
                var uv = new float[buffers.CopyStream(VertexStream.Texcoords, null)];
                buffers.CopyStream(VertexStream.Texcoords, uv);
                int survivors = 0;
                for (int r = 0; r < source.Length; ++r)
                {
                    if (source[r] != a) continue;
                    ++survivors;
                    Check.Equal(0.5f, uv[2 * r], "u of the survivor");
                    Check.Equal(0.5f, uv[2 * r + 1], "v of the survivor");
                }
                Check.Equal(1, survivors, "one render vertex for the survivor");
                RenderBuffersTests.CheckBuffersMatchMesh(mesh, buffers);
                Check.Valid(mesh);
            }
        }

        [Test]
        static void SpotEditsKeepMirrorsInStep()
        {
            EngineMesh spot = ReadEngineObj(Context.Data("spot_triangulated.obj"));
            BuildReport report;
            using (HalfEdgeMesh mesh = HalfEdgeMesh.FromEngineMesh(spot.Positions, spot.Triangles, spot.Normals,
                                                                   spot.Texcoords, spot.Colors,
                                                                   EngineImportOptions.Default, out report))
            using (RenderBuffers buffers = mesh.CreateRenderBuffers(Separate(Winding.CounterClockwise, false)))
            {
                // Mirrors of the four streams and the index buffer, kept by the caller.
                float[] p = null, n = null, uv = null, c = null;
                int[] indices = null;
                Check.False(UpdateMirrors(buffers, ref p, ref n, ref uv, ref c, ref indices), "the first copy is whole");
                int facesBefore = mesh.FaceCount;

                Check.True(p.Length >= 3 * buffers.Counts.VertexCapacity, "made at the library's capacity");
                Check.True(buffers.Counts.VertexCapacity > buffers.Counts.VertexSlots, "with room to grow");

                // Round 1, in a transaction: a face split adds a render vertex, within the capacity.
                buffers.BeginTransaction();
                var corners = new Vertex[3];
                mesh.GetFaceVertices(new Face(10), corners);
                Vec3 a = mesh.GetPosition(corners[0]), b = mesh.GetPosition(corners[1]), d = mesh.GetPosition(corners[2]);
                Vertex split = mesh.SplitFace(new Face(10), (a.X + b.X + d.X) / 3, (a.Y + b.Y + d.Y) / 3,
                                              (a.Z + b.Z + d.Z) / 3);
                Check.True(split.IsValid);
                SyncResult first = buffers.CommitTransaction();
                Check.False(first.Full);
                Check.Equal(3, first.FacesSynced);
                Check.True(UpdateMirrors(buffers, ref p, ref n, ref uv, ref c, ref indices), "only the dirty ranges");
                CheckMirrors(buffers, p, n, uv, c, indices);

                // Round 2: collapses and flips, within the mirrors' size: only the dirty ranges are copied.
                int collapsed = 0;
                for (int h = 0; h < 400 && collapsed < 5; h += 7)
                    if (!mesh.IsDeleted(new HalfEdge(h)) && mesh.CanCollapse(new HalfEdge(h)) &&
                        mesh.Collapse(new HalfEdge(h)).IsValid)
                        ++collapsed;
                Check.Equal(5, collapsed);
                int flipped = 0;
                for (int e = 500; e < 900 && flipped < 5; e += 11)
                    if (!mesh.IsDeleted(new Edge(e)) && mesh.Flip(new Edge(e))) ++flipped;
                Check.Equal(5, flipped);
                SyncResult second = buffers.Sync();
                Check.False(second.Full || second.Resized);
                Check.Equal(facesBefore + 2 - 2 * collapsed, mesh.FaceCount);
                Check.True(second.IndexBytes > 0);
                long total = (long)(p.Length + n.Length + uv.Length + c.Length) * 4;
                Check.True((long)second.VertexBytes < total / 10,
                           "a few edits rewrite a small part of the buffers: " + second.VertexBytes + " of " + total);
                Check.True(UpdateMirrors(buffers, ref p, ref n, ref uv, ref c, ref indices), "only the dirty ranges");
                CheckMirrors(buffers, p, n, uv, c, indices);
                RenderBuffersTests.CheckBuffersMatchMesh(mesh, buffers);
                Check.Valid(mesh);

                // Round 3: a face split everywhere outgrows the mirrors: they grow and take everything.
                int oldLength = p.Length;
                Check.Equal(mesh.FaceCount, mesh.SplitAllFaces());
                buffers.Sync();
                Check.False(UpdateMirrors(buffers, ref p, ref n, ref uv, ref c, ref indices), "copied whole");
                Check.True(p.Length > oldLength, "grown");
                CheckMirrors(buffers, p, n, uv, c, indices);
                RenderBuffersTests.CheckBuffersMatchMesh(mesh, buffers);
                Check.Valid(mesh);
            }
        }

        // Updates the five mirrors; true if they all took the dirty ranges only.
        static bool UpdateMirrors(RenderBuffers buffers, ref float[] p, ref float[] n, ref float[] uv, ref float[] c,
                                  ref int[] indices)
        {
            bool partial = buffers.UpdateVertexMirror(VertexStream.Vertices, ref p);
            Check.Equal(partial, buffers.UpdateVertexMirror(VertexStream.Normals, ref n));
            Check.Equal(partial, buffers.UpdateVertexMirror(VertexStream.Texcoords, ref uv));
            Check.Equal(partial, buffers.UpdateVertexMirror(VertexStream.Colors, ref c));
            Check.Equal(partial, buffers.UpdateIndexMirror(ref indices));
            return partial;
        }

        // The mirrors hold the buffers (their first Counts entries).
        static void CheckMirrors(RenderBuffers buffers, float[] p, float[] n, float[] uv, float[] c, int[] indices)
        {
            float[] p2, n2, uv2, c2;
            int[] indices2;
            Export(buffers, out p2, out n2, out uv2, out c2, out indices2);
            Check.Same(p2, p, p2.Length, "positions");
            Check.Same(n2, n, n2.Length, "normals");
            Check.Same(uv2, uv, uv2.Length, "texcoords");
            Check.Same(c2, c, c2.Length, "colours");
            for (int i = 0; i < indices2.Length; ++i)
                if ((int)indices2[i] != indices[i]) Check.Equal((int)indices2[i], indices[i], "index " + i);
        }
    }
}
