// The fracture glue against the UnityEngine stand-in: ShardBody's values reproduce each shard's
// inertia tensor, and the BreakOnClick sample (Samples~/BreakOnClick) turns a click into shard
// GameObjects whose Rigidbody gets exactly the fracture's mass properties and whose convex
// MeshCollider gets the shard's hull, while the object itself uploads the hole.
using System;
using System.Collections.Generic;
using System.Reflection;
using Hedge.Unity;
using UnityEngine;

namespace Hedge.Tests
{
    public static class BreakOnClickTests
    {
        // An n x n plate of unit quads in Unity's winding (front faces toward -z, where the camera is).
        static UnityEngine.Mesh Plate(int n) { return StandinMeshes.Grid(n, "plate"); }

        // R diag(m) R^T from a float quaternion and moments, row-major.
        static double[] Tensor(Quaternion q, Vector3 m)
        {
            double x = q.x, y = q.y, z = q.z, w = q.w;
            var r = new double[]
            {
                1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
                2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y),
            };
            double[] d = { m.x, m.y, m.z };
            var t = new double[9];
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    for (int k = 0; k < 3; ++k) t[3 * i + j] += r[3 * i + k] * d[k] * r[3 * j + k];
            return t;
        }

        static double Largest(double[] a)
        {
            double m = 0;
            foreach (double x in a) m = Math.Max(m, Math.Abs(x));
            return m;
        }

        // ShardBody in Unity's float types: the moments and rotation give back the tensor to float precision,
        // and the rotation is a unit quaternion; an open shard has the body of a thin shell.
        [Test]
        static void ShardBodyReproducesTheInertiaTensor()
        {
            using (HalfEdgeMesh plate = UnityMeshes.FromUnityMesh(Plate(12).vertices, Plate(12).triangles))
            {
                FractureOptions o = FractureOptions.Preset(FracturePreset.Stone).WithBreakRadius(4);
                o.Seed = 3;
                o.Density = 2;
                FractureShard[] shards = plate.Fracture(new Vec3(6.2f, 5.9f, 0), o);
                Check.True(shards.Length >= 3, "stone shards: " + shards.Length);
                foreach (FractureShard s in shards)
                {
                    ShardBody b = ShardBody.Of(s);
                    Check.Equal((float)s.Mass, b.mass);
                    Check.True(b.mass > 0, "a solid has mass");
                    Check.Equal((float)s.CentreOfMass[2], b.centerOfMass.z);
                    double[] t = Tensor(b.inertiaTensorRotation, b.inertiaTensor);
                    double scale = Largest(s.Inertia);
                    for (int i = 0; i < 9; ++i) Check.Near(s.Inertia[i], t[i], 1e-5 * scale, "tensor element " + i);
                    Quaternion q = b.inertiaTensorRotation;
                    Check.Near(1, q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w, 1e-6, "a unit quaternion");
                    s.Dispose();
                }
                o = FractureOptions.Preset(FracturePreset.Stone);
                o.RelativeThickness = 0;
                FractureShard[] open = plate.Fracture(new Vec3(2.2f, 9.9f, 0), o);
                Check.True(open.Length > 0 && !open[0].Closed, "no thickness: open shards");
                ShardBody shell = ShardBody.Of(open[0]);
                Check.True(shell.mass > 0 && shell.inertiaTensor.x > 0, "an open shard weighs as a thin shell");
                foreach (FractureShard s in open) s.Dispose();
                Check.Valid(plate);
            }
        }

        // A solid fracture piece's ShardBody: the same values in Unity's float types.
        [Test]
        static void ShardBodyOfASolidPiece()
        {
            // A closed box 4 x 4 x 2, struck at the centre of its top.
            float[] p = { 0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0, 0, 0, 2, 4, 0, 2, 4, 4, 2, 0, 4, 2 };
            int[] t = { 0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                        1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7 };
            using (HalfEdgeMesh box = HalfEdgeMesh.FromTriangles(p, t))
            using (SolidFracture r = box.FractureSolid(new Vec3(2.1f, 1.9f, 2), FracturePreset.Stone, 1, 5))
            {
                Check.True(r.Pieces.Length >= 2, "stone pieces: " + r.Pieces.Length);
                foreach (SolidPiece piece in r.Pieces)
                {
                    ShardBody b = ShardBody.Of(piece);
                    Check.Equal((float)piece.Mass, b.mass);
                    Check.True(b.mass > 0, "a piece has mass");
                    Check.Equal((float)piece.CentreOfMass[1], b.centerOfMass.y);
                    double[] tensor = Tensor(b.inertiaTensorRotation, b.inertiaTensor);
                    double scale = Largest(piece.Inertia);
                    for (int i = 0; i < 9; ++i) Check.Near(piece.Inertia[i], tensor[i], 1e-5 * scale, "tensor element " + i);
                }
                Check.Valid(box);
            }
            Check.ThrowsType<ArgumentNullException>(() => ShardBody.Of((SolidPiece)null), "no piece");
        }

        [Test]
        static void BreakOnClickSample()
        {
            MeshCollider.All.Clear();
            GameObject.Created.Clear();
            var go = new GameObject("pane");
            MeshFilter filter = go.AddComponent<MeshFilter>();
            UnityEngine.Mesh source = Plate(20);
            filter.sharedMesh = source;
            MeshCollider collider = go.AddComponent<MeshCollider>();
            go.AddComponent<MeshRenderer>().sharedMaterials = new[] { new Material() };
            BreakOnClick sample = go.AddComponent<BreakOnClick>();
            sample.innerMaterial = new Material();
            Camera.main = new Camera();
            Invoke(sample, "Start");
            HalfEdgeMesh mesh = sample.HalfEdgeMesh;
            // The break radius: a fifth of the plate's diagonal.
            FractureOptions options = sample.Options;
            Check.True(options.Units == FractureUnits.DiagonalFraction, "a break radius as a fraction of the size");
            Check.Near(0.2, options.Radius, 1e-7, "a fifth (a float)");
            Check.Equal(1, options.InnerSubmesh, "the cut faces after the object's one submesh");
            int facesBefore = mesh.FaceCount;

            // A twin of the object, struck with the same options and seed: the shards the sample must have made.
            using (HalfEdgeMesh twin = UnityMeshes.FromUnityMesh(source.vertices, source.triangles))
            {
                options.Seed = 1;
                FractureShard[] expected = twin.Fracture(new Vec3(10.2f, 9.7f, 0), options);
                Click(sample, 10.2f, 9.7f);
                IList<GameObject> shards = sample.Shards;
                Check.Equal(expected.Length, shards.Count, "one GameObject per shard");
                Check.True(shards.Count >= 20, "glass shards: " + shards.Count);
                for (int i = 0; i < shards.Count; ++i)
                {
                    FractureShard e = expected[i];
                    Rigidbody body = shards[i].GetComponent<Rigidbody>();
                    Check.True(body != null, "a Rigidbody");
                    Check.Equal(4, body.Assigned.Count, "mass, centre, tensor and rotation set once each");
                    ShardBody b = ShardBody.Of(e);
                    Check.Equal((float)e.Mass, body.mass, "mass");
                    Check.True(body.mass > 0, "a usable mass");
                    Check.Near(2500 * e.Volume, body.mass, 1e-6 * body.mass, "the sample's density");
                    Check.Equal(b.centerOfMass.x, body.centerOfMass.x);
                    Check.Equal(b.centerOfMass.y, body.centerOfMass.y);
                    Check.Equal(b.centerOfMass.z, body.centerOfMass.z);
                    Check.Equal(b.inertiaTensor.x, body.inertiaTensor.x);
                    Check.Equal(b.inertiaTensor.y, body.inertiaTensor.y);
                    Check.Equal(b.inertiaTensor.z, body.inertiaTensor.z);
                    Check.Equal(b.inertiaTensorRotation.x, body.inertiaTensorRotation.x);
                    Check.Equal(b.inertiaTensorRotation.w, body.inertiaTensorRotation.w);
                    double[] t = Tensor(body.inertiaTensorRotation, body.inertiaTensor);
                    for (int k = 0; k < 9; ++k) Check.Near(e.Inertia[k], t[k], 1e-5 * Largest(e.Inertia));
                    // The collider: convex, its mesh the shard's hull.
                    MeshCollider c = shards[i].GetComponent<MeshCollider>();
                    Check.True(c != null && c.convex, "a convex collider");
                    using (RenderBuffers hb = e.Hull.CreateRenderBuffers(RenderOptions.Unity))
                    {
                        var positions = new float[hb.CopyStream(VertexStream.Vertices, null)];
                        hb.CopyStream(VertexStream.Vertices, positions);
                        Check.Same(positions, (float[])c.sharedMesh.Streams[0], positions.Length, "the hull's positions");
                        Check.Equal((int)hb.Counts.IndexCount, c.sharedMesh.SubMesh.indexCount, "the hull's triangles");
                    }
                    UnityEngine.Mesh rendered = shards[i].GetComponent<MeshFilter>().sharedMesh;
                    Check.True(rendered.SubMesh.indexCount > c.sharedMesh.SubMesh.indexCount / 2,
                               "the shard renders its own mesh");
                    // Two submeshes, outer and cut faces, drawn with the object's and the inner material.
                    Check.Equal(2, rendered.subMeshCount, "outer and inner submeshes");
                    Check.True(rendered.GetSubMesh(1).indexCount > 0, "the cut faces are the inner submesh");
                    Material[] materials = shards[i].GetComponent<MeshRenderer>().sharedMaterials;
                    Check.Equal(2, materials.Length, "one material per submesh");
                    Check.True(materials[0] == go.GetComponent<MeshRenderer>().sharedMaterials[0], "the object's material outside");
                    Check.True(materials[1] == sample.innerMaterial, "the inner material on the cut faces");
                    e.Dispose();
                }
            }
            // The object lost the broken faces, and its uploaded mesh follows.
            Check.True(mesh.FaceCount < facesBefore, "faces broke off");
            // Triangle slots of deleted faces stay in the index buffer, degenerate.
            Array indices = sample.RenderedMesh.IndexBuffer; // 16-bit while the vertices fit
            int drawn = 0;
            for (int t = 0; 3 * t + 2 < sample.RenderedMesh.SubMesh.indexCount; ++t)
            {
                int a = Convert.ToInt32(indices.GetValue(3 * t)), b = Convert.ToInt32(indices.GetValue(3 * t + 1));
                if (a != b || a != Convert.ToInt32(indices.GetValue(3 * t + 2))) ++drawn;
            }
            Check.Equal(mesh.FaceCount, drawn, "the hole is uploaded");
            Check.True(collider.Cookings >= 2, "the collider was given the mesh with the hole");
            Check.Valid(mesh);
            // A click into the hole hits nothing of the object: no new shards.
            int count = sample.Shards.Count;
            Click(sample, 10.2f, 9.7f);
            Check.Equal(count, sample.Shards.Count, "a click into the hole breaks nothing");
            // Elsewhere it breaks again.
            Click(sample, 3.3f, 16.6f);
            Check.True(sample.Shards.Count > count, "a second strike");
            Check.Valid(mesh);
            Invoke(sample, "OnDestroy");
            Check.True(mesh.IsDisposed);
        }

        static void Click(BreakOnClick sample, float x, float y) { NativeUploadTests.Click(sample, 0, x, y); }

        static void Invoke(object target, string method)
        {
            target.GetType().GetMethod(method, BindingFlags.Instance | BindingFlags.NonPublic).Invoke(target, null);
        }
    }
}
