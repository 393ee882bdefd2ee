// A minimal stand-in for the few UnityEngine types the glue in Runtime/Unity/ uses, so that the glue
// is compiled (and smoke-run) without Unity. Signatures follow Unity's scripting reference for the
// members used; behaviour is only what the smoke test needs. Mesh keeps its buffers in managed
// arrays, with the start and count arguments of SetVertexBufferData / SetIndexBufferData in
// elements of the array type T, as Unity documents. This is not Unity: nothing here says the glue
// runs in the editor or a player.
using System;
using System.Collections.Generic;
using System.Reflection;

namespace UnityEngine
{
    public struct Vector2
    {
        public float x, y;
        public Vector2(float x, float y) { this.x = x; this.y = y; }
        public static implicit operator Vector3(Vector2 v) { return new Vector3(v.x, v.y, 0); }
    }

    public partial struct Vector3
    {
        public float x, y, z;
        public Vector3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }
    }

    public struct Color
    {
        public float r, g, b, a;
        public Color(float r, float g, float b, float a) { this.r = r; this.g = g; this.b = b; this.a = a; }
    }

    public struct Bounds
    {
        public Vector3 center { get; set; }
        public Vector3 extents { get; set; }
        public Vector3 size { get { return new Vector3(2 * extents.x, 2 * extents.y, 2 * extents.z); } }
        public Vector3 min { get { return new Vector3(center.x - extents.x, center.y - extents.y, center.z - extents.z); } }
        public Vector3 max { get { return new Vector3(center.x + extents.x, center.y + extents.y, center.z + extents.z); } }
        public Bounds(Vector3 center, Vector3 size)
        {
            this.center = center;
            extents = new Vector3(size.x / 2, size.y / 2, size.z / 2);
        }
        public void SetMinMax(Vector3 min, Vector3 max)
        {
            extents = new Vector3((max.x - min.x) / 2, (max.y - min.y) / 2, (max.z - min.z) / 2);
            center = new Vector3(min.x + extents.x, min.y + extents.y, min.z + extents.z);
        }
    }

    public enum MeshTopology { Triangles = 0, Quads = 2, Lines = 3, LineStrip = 4, Points = 5 }

    [AttributeUsage(AttributeTargets.Class, AllowMultiple = true)]
    public sealed class RequireComponent : Attribute
    {
        public Type m_Type0;
        public RequireComponent(Type requiredComponent) { m_Type0 = requiredComponent; }
    }

    public class Object
    {
        public string name { get; set; }
        public static readonly List<Object> Destroyed = new List<Object>();
        public static void Destroy(Object obj) { Destroyed.Add(obj); }
    }

    public partial class GameObject : Object
    {
        readonly List<Component> components = new List<Component>();

        // Unity runs Awake when a component is added; the stand-in does the same through reflection.
        public T AddComponent<T>() where T : Component, new()
        {
            var component = new T();
            component.gameObject = this;
            components.Add(component);
            MethodInfo awake = typeof(T).GetMethod("Awake", BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic);
            if (awake != null) awake.Invoke(component, null);
            return component;
        }

        public T GetComponent<T>() where T : Component
        {
            foreach (Component c in components)
                if (c is T) return (T)c;
            return null;
        }
    }

    public partial class Component : Object
    {
        public GameObject gameObject { get; internal set; }
        public T GetComponent<T>() where T : Component { return gameObject.GetComponent<T>(); }
    }

    public class Behaviour : Component { }

    public class MonoBehaviour : Behaviour { }

    public sealed class MeshFilter : Component
    {
        public Mesh sharedMesh { get; set; }
    }

    public sealed partial class Mesh : Object
    {
        // The simple API: per-vertex arrays.
        public Vector3[] vertices { get; set; }
        public Vector3[] normals { get; set; }
        public Vector2[] uv { get; set; }
        public Color[] colors { get; set; }
        public int[] triangles { get; set; }
        public int subMeshCount { get; set; }

        // The advanced API, as the stand-in keeps it.
        public Rendering.VertexAttributeDescriptor[] Attributes { get; private set; }
        public int VertexBufferCount { get; private set; }
        public Array[] Streams { get; private set; }
        public Array IndexBuffer { get; private set; }
        public Rendering.IndexFormat IndexFormatUsed { get; private set; }
        public Rendering.SubMeshDescriptor SubMesh { get; private set; }
        public int VertexUploads { get; set; }   // elements written by SetVertexBufferData since reset
        public int IndexUploads { get; set; }    // elements written by SetIndexBufferData since reset
        public bool Dynamic { get; private set; }
        public int BoundsRecalculations { get; private set; }
        Bounds meshBounds;
        public Bounds bounds { get { return meshBounds; } set { meshBounds = value; ++BoundsSets; } }
        public int BoundsSets { get; set; }      // assignments to bounds since reset

        public Mesh()
        {
            vertices = new Vector3[0];
            triangles = new int[0];
        }

        public void MarkDynamic() { Dynamic = true; }

        public void RecalculateBounds() { ++BoundsRecalculations; }

        public void SetVertexBufferParams(int vertexCount, params Rendering.VertexAttributeDescriptor[] attributes)
        {
            CheckDescriptors(attributes);
            Attributes = attributes;
            VertexBufferCount = vertexCount;
            var floatsPerStream = new int[4];
            foreach (var a in attributes)
            {
                if (a.format != Rendering.VertexAttributeFormat.Float32)
                    throw new NotSupportedException("the stand-in keeps Float32 attributes only");
                if (a.stream < 0 || a.stream > 3) throw new ArgumentException("stream out of range 0..3");
                floatsPerStream[a.stream] += a.dimension;
            }
            Streams = new Array[4];
            for (int s = 0; s < 4; ++s)
                if (floatsPerStream[s] > 0) Streams[s] = new float[vertexCount * floatsPerStream[s]];
        }

        public void SetVertexBufferData<T>(T[] data, int dataStart, int meshBufferStart, int count, int stream = 0,
                                           Rendering.MeshUpdateFlags flags = Rendering.MeshUpdateFlags.Default)
            where T : struct
        {
            if (Streams == null || stream < 0 || stream > 3 || Streams[stream] == null)
                throw new ArgumentException("no such vertex stream: " + stream);
            if (typeof(T) != typeof(float)) throw new NotSupportedException("the stand-in takes float data only");
            if (dataStart < 0 || meshBufferStart < 0 || count < 0 || dataStart + count > data.Length ||
                meshBufferStart + count > Streams[stream].Length)
                throw new ArgumentOutOfRangeException("Bad start/count arguments (dataStart:" + dataStart +
                                                      " meshBufferStart:" + meshBufferStart + " count:" + count + ")");
            Array.Copy(data, dataStart, Streams[stream], meshBufferStart, count);
            VertexUploads += count;
        }

        public void SetIndexBufferParams(int indexCount, Rendering.IndexFormat format)
        {
            IndexFormatUsed = format;
            IndexBuffer = format == Rendering.IndexFormat.UInt32 ? (Array)new int[indexCount] : new ushort[indexCount];
        }

        public void SetIndexBufferData<T>(T[] data, int dataStart, int meshBufferStart, int count,
                                          Rendering.MeshUpdateFlags flags = Rendering.MeshUpdateFlags.Default)
            where T : struct
        {
            if (IndexBuffer == null) throw new InvalidOperationException("SetIndexBufferParams first");
            if (IndexFormatUsed == Rendering.IndexFormat.UInt32 && typeof(T) != typeof(int) && typeof(T) != typeof(uint))
                throw new ArgumentException("32-bit indices need 4-byte data");
            if (dataStart < 0 || meshBufferStart < 0 || count < 0 || dataStart + count > data.Length ||
                meshBufferStart + count > IndexBuffer.Length)
                throw new ArgumentOutOfRangeException("Bad start/count arguments (dataStart:" + dataStart +
                                                      " meshBufferStart:" + meshBufferStart + " count:" + count + ")");
            var ints = data as int[];
            var target = IndexBuffer as int[];
            if (ints != null && target != null)  // without boxing, so that tests can measure the caller's allocations
                Array.Copy(ints, dataStart, target, meshBufferStart, count);
            else
                for (int i = 0; i < count; ++i)
                    IndexBuffer.SetValue(Convert.ToInt32(data[dataStart + i]), meshBufferStart + i);
            IndexUploads += count;
        }

        public void SetSubMesh(int index, Rendering.SubMeshDescriptor desc,
                               Rendering.MeshUpdateFlags flags = Rendering.MeshUpdateFlags.Default)
        {
            if (index < 0 || index >= subMeshCount)
                throw new IndexOutOfRangeException("Specified sub mesh is out of range. Must be greater or equal to 0 " +
                                                   "and less than subMeshCount " + subMeshCount);
            if (IndexBuffer == null || desc.indexStart + desc.indexCount > IndexBuffer.Length)
                throw new ArgumentException("submesh beyond the index buffer");
            RecordSubMesh(index, desc, flags);
            if (index == 0) SubMesh = desc;
        }
    }
}

namespace UnityEngine.Rendering
{
    [Flags]
    public enum MeshUpdateFlags
    {
        Default = 0,
        DontValidateIndices = 1,
        DontResetBoneBounds = 2,
        DontNotifyMeshUsers = 4,
        DontRecalculateBounds = 8,
    }

    public enum IndexFormat { UInt16 = 0, UInt32 = 1 }

    public enum VertexAttribute
    {
        Position = 0, Normal, Tangent, Color, TexCoord0, TexCoord1, TexCoord2, TexCoord3,
        TexCoord4, TexCoord5, TexCoord6, TexCoord7, BlendWeight, BlendIndices,
    }

    public enum VertexAttributeFormat
    {
        Float32 = 0, Float16, UNorm8, SNorm8, UNorm16, SNorm16, UInt8, SInt8, UInt16, SInt16, UInt32, SInt32,
    }

    public struct VertexAttributeDescriptor
    {
        public VertexAttribute attribute { get; set; }
        public VertexAttributeFormat format { get; set; }
        public int dimension { get; set; }
        public int stream { get; set; }

        public VertexAttributeDescriptor(VertexAttribute attribute = VertexAttribute.Position,
                                         VertexAttributeFormat format = VertexAttributeFormat.Float32,
                                         int dimension = 3, int stream = 0)
            : this()
        {
            this.attribute = attribute;
            this.format = format;
            this.dimension = dimension;
            this.stream = stream;
        }
    }

    public struct SubMeshDescriptor
    {
        public int indexStart { get; set; }
        public int indexCount { get; set; }
        public MeshTopology topology { get; set; }

        // Submeshes (materials): the fields SetSubMesh takes as they are with DontRecalculateBounds.
        public int baseVertex { get; set; }
        public int firstVertex { get; set; }
        public int vertexCount { get; set; }
        public Bounds bounds { get; set; }

        public SubMeshDescriptor(int indexStart, int indexCount, MeshTopology topology = MeshTopology.Triangles)
            : this()
        {
            this.indexStart = indexStart;
            this.indexCount = indexCount;
            this.topology = topology;
        }
    }
}
