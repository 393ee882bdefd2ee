// More of the UnityEngine stand-in: NativeArray and the unsafe utilities the zero-copy uploader uses,
// the NativeArray overloads of Mesh.SetVertexBufferData / SetIndexBufferData, Mesh.bounds, and just
// enough of Physics, Camera, Input and Transform for the click-to-split sample. Signatures follow
// Unity's scripting reference; behaviour is only what the tests need. Physics.Raycast intersects the
// ray with every triangle of each MeshCollider's mesh as the stand-in Mesh holds it (identity
// transforms), reporting the triangle's index in that mesh's index buffer as Unity documents for
// RaycastHit.triangleIndex. This is not Unity.
using System;
using System.Collections.Generic;
using System.Runtime.InteropServices;

namespace Unity.Collections
{
    public enum Allocator { Invalid = 0, None = 1, Temp = 2, TempJob = 3, Persistent = 4 }

    public enum NativeArrayOptions { UninitializedMemory = 0, ClearMemory = 1 }

    public struct NativeArray<T> : IDisposable where T : struct
    {
        internal IntPtr Buffer;
        internal int length;
        internal Allocator Owner;

        public NativeArray(int length, Allocator allocator, NativeArrayOptions options = NativeArrayOptions.ClearMemory)
        {
            if (allocator <= Allocator.None) throw new ArgumentException("allocator");
            int bytes = length * Marshal.SizeOf(typeof(T));
            Buffer = Marshal.AllocHGlobal(Math.Max(1, bytes));
            for (int i = 0; i < bytes; ++i) Marshal.WriteByte(Buffer, i, 0);
            this.length = length;
            Owner = allocator;
            ++LiveAllocations;
        }

        // Persistent allocations not yet disposed, to catch leaks in tests.
        public static int LiveAllocations;

        public int Length { get { return length; } }
        public bool IsCreated { get { return Buffer != IntPtr.Zero; } }

        public void Dispose()
        {
            if (Owner <= Allocator.None) throw new InvalidOperationException("this NativeArray does not own its memory");
            Marshal.FreeHGlobal(Buffer);
            Buffer = IntPtr.Zero;
            --LiveAllocations;
        }
    }
}

namespace Unity.Collections.LowLevel.Unsafe
{
    public struct AtomicSafetyHandle
    {
        public static AtomicSafetyHandle Create() { return new AtomicSafetyHandle(); }
        public static void Release(AtomicSafetyHandle handle) { }
    }

    public static class NativeArrayUnsafeUtility
    {
        public static unsafe NativeArray<T> ConvertExistingDataToNativeArray<T>(void* dataPointer, int length,
                                                                               Allocator allocator) where T : struct
        {
            var array = new NativeArray<T>();
            array.Buffer = (IntPtr)dataPointer;
            array.length = length;
            array.Owner = allocator;
            ++WrappedArrays;
            return array;
        }

        public static void SetAtomicSafetyHandle<T>(ref NativeArray<T> array, AtomicSafetyHandle safety) where T : struct { }

        public static unsafe void* GetUnsafePtr<T>(this NativeArray<T> nativeArray) where T : struct
        {
            return (void*)nativeArray.Buffer;
        }

        // NativeArrays made over existing memory: the zero-copy path was taken.
        public static int WrappedArrays;
    }
}

namespace UnityEngine
{
    using Unity.Collections;

    public partial struct Vector3
    {
        public static Vector3 zero { get { return new Vector3(0, 0, 0); } }
        public static Vector3 forward { get { return new Vector3(0, 0, 1); } }
        public static Vector3 operator +(Vector3 a, Vector3 b) { return new Vector3(a.x + b.x, a.y + b.y, a.z + b.z); }
        public static Vector3 operator -(Vector3 a, Vector3 b) { return new Vector3(a.x - b.x, a.y - b.y, a.z - b.z); }
        public static Vector3 operator *(Vector3 a, float s) { return new Vector3(a.x * s, a.y * s, a.z * s); }
        public static Vector3 operator *(float s, Vector3 a) { return new Vector3(a.x * s, a.y * s, a.z * s); }
        public static float Dot(Vector3 a, Vector3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
        public static Vector3 Cross(Vector3 a, Vector3 b)
        {
            return new Vector3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
        }
        public static float Distance(Vector3 a, Vector3 b) { return (a - b).magnitude; }
        public float sqrMagnitude { get { return x * x + y * y + z * z; } }
        public float magnitude { get { return (float)Math.Sqrt(sqrMagnitude); } }
        public override string ToString() { return "(" + x + ", " + y + ", " + z + ")"; }
    }

    public static class Mathf
    {
        public static float Clamp(float value, float min, float max) { return value < min ? min : value > max ? max : value; }
    }

    public static class Debug
    {
        public static readonly List<string> Messages = new List<string>();
        public static void Log(object message) { Messages.Add(message.ToString()); }
        public static void LogWarning(object message) { Messages.Add(message.ToString()); }
    }

    public partial class Component
    {
        static readonly Transform identity = new Transform();
        public Transform transform { get { return identity; } }
    }

    public partial class Transform
    {
        // Identity transforms only.
        public Vector3 InverseTransformPoint(Vector3 p) { return p; }
        public Vector3 TransformPoint(Vector3 p) { return p; }
    }

    public struct Ray
    {
        public Vector3 origin { get; set; }
        public Vector3 direction { get; set; }
        public Ray(Vector3 origin, Vector3 direction) : this() { this.origin = origin; this.direction = direction; }
    }

    public struct RaycastHit
    {
        public Vector3 point { get; set; }
        public float distance { get; set; }
        public int triangleIndex { get; set; }
        public Collider collider { get; set; }
    }

    public class Collider : Component { }

    public sealed partial class MeshCollider : Collider
    {
        public static readonly List<MeshCollider> All = new List<MeshCollider>();
        Mesh mesh;
        public int Cookings { get; private set; }
        public MeshCollider() { All.Add(this); }
        public Mesh sharedMesh
        {
            get { return mesh; }
            set
            {
                mesh = value;
                if (value != null) ++Cookings;
            }
        }
    }

    public sealed class Camera : Behaviour
    {
        public static Camera main { get; set; }
        // An orthographic camera looking down +z from z = -10: screen (x, y) is world (x, y).
        public Ray ScreenPointToRay(Vector3 position) { return new Ray(new Vector3(position.x, position.y, -10), Vector3.forward); }
    }

    public static class Input
    {
        public static Vector3 mousePosition { get; set; }
        public static readonly bool[] ButtonsDown = new bool[3];
        public static bool GetMouseButtonDown(int button) { return ButtonsDown[button]; }
    }

    public static class Physics
    {
        public static bool Raycast(Ray ray, out RaycastHit hit)
        {
            hit = new RaycastHit();
            float best = float.PositiveInfinity;
            foreach (MeshCollider c in MeshCollider.All)
            {
                Mesh m = c.sharedMesh;
                if (m == null || m.Streams == null || m.IndexBuffer == null) continue;
                var p = (float[])m.Streams[0];
                int count = m.SubmeshIndexEnd;
                for (int t = 0; 3 * t + 2 < count; ++t)
                {
                    Vector3 a = At(p, m, 3 * t), b = At(p, m, 3 * t + 1), d = At(p, m, 3 * t + 2);
                    Vector3 e1 = b - a, e2 = d - a, q = Vector3.Cross(ray.direction, e2);
                    float det = Vector3.Dot(e1, q);
                    if (Math.Abs(det) < 1e-12f) continue;
                    Vector3 s = ray.origin - a, r = Vector3.Cross(s, e1);
                    float u = Vector3.Dot(s, q) / det, v = Vector3.Dot(ray.direction, r) / det, dist = Vector3.Dot(e2, r) / det;
                    if (u < 0 || v < 0 || u + v > 1 || dist < 0 || dist >= best) continue;
                    best = dist;
                    hit = new RaycastHit { point = ray.origin + dist * ray.direction, distance = dist, triangleIndex = t, collider = c };
                }
            }
            return best < float.PositiveInfinity;
        }

        static Vector3 At(float[] p, Mesh m, int i)
        {
            int v = Convert.ToInt32(m.IndexBuffer.GetValue(i));
            return new Vector3(p[3 * v], p[3 * v + 1], p[3 * v + 2]);
        }
    }

    public sealed partial class Mesh
    {
        public int NativeVertexUploads { get; set; } // elements written from NativeArrays since reset
        public int NativeIndexUploads { get; set; }

        public unsafe void SetVertexBufferData<T>(NativeArray<T> data, int dataStart, int meshBufferStart, int count,
                                                  int stream = 0,
                                                  Rendering.MeshUpdateFlags flags = Rendering.MeshUpdateFlags.Default)
            where T : struct
        {
            if (Streams == null || stream < 0 || stream > 3 || Streams[stream] == null)
                throw new ArgumentException("no such vertex stream: " + stream);
            if (typeof(T) != typeof(float)) throw new NotSupportedException("the stand-in takes float data only");
            var target = (float[])Streams[stream];
            if (dataStart < 0 || meshBufferStart < 0 || count < 0 || dataStart + count > data.Length ||
                meshBufferStart + count > target.Length)
                throw new ArgumentOutOfRangeException("Bad start/count arguments (dataStart:" + dataStart +
                                                      " meshBufferStart:" + meshBufferStart + " count:" + count + ")");
            if (count > 0) Marshal.Copy(data.Buffer + 4 * dataStart, target, meshBufferStart, count);
            VertexUploads += count;
            NativeVertexUploads += count;
        }

        public unsafe void SetIndexBufferData<T>(NativeArray<T> data, int dataStart, int meshBufferStart, int count,
                                                 Rendering.MeshUpdateFlags flags = Rendering.MeshUpdateFlags.Default)
            where T : struct
        {
            if (IndexBuffer == null) throw new InvalidOperationException("SetIndexBufferParams first");
            int size = Marshal.SizeOf(typeof(T));
            if (size != (IndexFormatUsed == Rendering.IndexFormat.UInt32 ? 4 : 2))
                throw new ArgumentException("index data of " + size + " bytes for " + IndexFormatUsed + " indices");
            if (dataStart < 0 || meshBufferStart < 0 || count < 0 || dataStart + count > data.Length ||
                meshBufferStart + count > IndexBuffer.Length)
                throw new ArgumentOutOfRangeException("Bad start/count arguments (dataStart:" + dataStart +
                                                      " meshBufferStart:" + meshBufferStart + " count:" + count + ")");
            for (int i = 0; i < count; ++i)
            {
                if (size == 4) ((int[])IndexBuffer)[meshBufferStart + i] = ((int*)data.Buffer)[dataStart + i];
                else ((ushort[])IndexBuffer)[meshBufferStart + i] = ((ushort*)data.Buffer)[dataStart + i];
            }
            IndexUploads += count;
            NativeIndexUploads += count;
        }
    }
}
