// More of the UnityEngine stand-in: a Mesh's submeshes, as Unity's scripting reference describes
// them. SetTriangles(triangles, submesh) and GetIndices(submesh) for a source mesh of several
// materials (GetIndices applies no base vertex: the stand-in keeps none); SetSubMesh records every
// descriptor with its flags, GetSubMesh gives it back. This is not Unity.
using System;
using System.Collections.Generic;

namespace UnityEngine
{
    public sealed partial class Mesh
    {
        readonly List<int[]> submeshIndices = new List<int[]>();
        readonly List<Rendering.SubMeshDescriptor> submeshes = new List<Rendering.SubMeshDescriptor>();
        readonly List<Rendering.MeshUpdateFlags> submeshFlags = new List<Rendering.MeshUpdateFlags>();

        /// <summary>SetSubMesh calls since the last reset (the tests count them).</summary>
        public int SubMeshSets { get; set; }

        public void SetTriangles(int[] triangles, int submesh)
        {
            if (submesh < 0 || submesh >= subMeshCount) throw new IndexOutOfRangeException("submesh out of range");
            while (submeshIndices.Count < subMeshCount) submeshIndices.Add(new int[0]);
            submeshIndices[submesh] = (int[])triangles.Clone();
            var all = new List<int>();
            for (int i = 0; i < subMeshCount; ++i) all.AddRange(submeshIndices[i]);
            this.triangles = all.ToArray();
        }

        public int[] GetIndices(int submesh)
        {
            if (submesh < 0 || submesh >= Math.Max(1, subMeshCount)) throw new IndexOutOfRangeException("submesh out of range");
            if (submesh < submeshIndices.Count) return (int[])submeshIndices[submesh].Clone();
            return submesh == 0 ? (int[])triangles.Clone() : new int[0];
        }

        public MeshTopology GetTopology(int submesh)
        {
            if (submesh < 0 || submesh >= Math.Max(1, subMeshCount)) throw new IndexOutOfRangeException("submesh out of range");
            return MeshTopology.Triangles;
        }

        public Rendering.SubMeshDescriptor GetSubMesh(int index)
        {
            if (index < 0 || index >= subMeshCount || index >= submeshes.Count)
                throw new IndexOutOfRangeException("no submesh " + index);
            return submeshes[index];
        }

        /// <summary>The flags of the last SetSubMesh of submesh index.</summary>
        public Rendering.MeshUpdateFlags GetSubMeshFlags(int index) { return submeshFlags[index]; }

        /// <summary>The end of the last submesh's index range: what a MeshCollider bakes.</summary>
        public int SubmeshIndexEnd
        {
            get
            {
                int end = 0;
                for (int i = 0; i < Math.Min(subMeshCount, submeshes.Count); ++i)
                    end = Math.Max(end, submeshes[i].indexStart + submeshes[i].indexCount);
                return end;
            }
        }

        void RecordSubMesh(int index, Rendering.SubMeshDescriptor desc, Rendering.MeshUpdateFlags flags)
        {
            while (submeshes.Count <= index)
            {
                submeshes.Add(new Rendering.SubMeshDescriptor());
                submeshFlags.Add(Rendering.MeshUpdateFlags.Default);
            }
            submeshes[index] = desc;
            submeshFlags[index] = flags;
            ++SubMeshSets;
        }
    }
}
