// Element handles: one int index each, blittable, so arrays of them go to the C ABI as its
// uint32_t* (the same bits: the C ABI's "none", 0xFFFFFFFF, is -1 here).
//
// A handle is only an index; the mesh it belongs to is not part of it. Index InvalidIndex (-1)
// means "none": the face of a boundary half-edge, a refused edit's result. A handle is made from an
// index of 0 or more; a negative one throws ArgumentOutOfRangeException (use Invalid for "none").
using System;
using System.Runtime.InteropServices;

namespace Hedge
{
    /// <summary>A vertex of a <see cref="HalfEdgeMesh"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public readonly struct Vertex : IEquatable<Vertex>
    {
        /// <summary>The "none" index.</summary>
        public const int InvalidIndex = -1;

        /// <summary>The vertex index (a slot: 0 .. vertex slot count - 1), or -1 for none.</summary>
        public readonly int Index;

        /// <summary>The vertex of index 0 or more.</summary>
        public Vertex(int index) { Index = Handle.Checked(index); }
        internal Vertex(uint raw) { Index = unchecked((int)raw); }
        /// <summary>The index as the C ABI takes it (0xFFFFFFFF for none).</summary>
        internal uint Raw { get { return unchecked((uint)Index); } }

        /// <summary>The handle that names no vertex.</summary>
        public static Vertex Invalid { get { return new Vertex(uint.MaxValue); } }
        public bool IsValid { get { return Index != InvalidIndex; } }

        public bool Equals(Vertex other) { return Index == other.Index; }
        public override bool Equals(object obj) { return obj is Vertex && Equals((Vertex)obj); }
        public override int GetHashCode() { return Index; }
        public static bool operator ==(Vertex a, Vertex b) { return a.Index == b.Index; }
        public static bool operator !=(Vertex a, Vertex b) { return a.Index != b.Index; }
        public override string ToString() { return IsValid ? "v" + Index : "v(invalid)"; }
    }

    /// <summary>A half-edge. Half-edges come in pairs: half-edge h belongs to edge h / 2, and its twin
    /// is h ^ 1; <see cref="Twin"/> and <see cref="Edge"/> use that arithmetic without a mesh.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public readonly struct HalfEdge : IEquatable<HalfEdge>
    {
        /// <summary>The index, or -1 for none.</summary>
        public readonly int Index;

        /// <summary>The half-edge of index 0 or more.</summary>
        public HalfEdge(int index) { Index = Handle.Checked(index); }
        internal HalfEdge(uint raw) { Index = unchecked((int)raw); }
        internal uint Raw { get { return unchecked((uint)Index); } }

        public static HalfEdge Invalid { get { return new HalfEdge(uint.MaxValue); } }
        public bool IsValid { get { return Index != Vertex.InvalidIndex; } }

        /// <summary>The opposite half-edge of the same edge (index arithmetic, not checked against a
        /// mesh; <see cref="HalfEdgeMesh.Twin"/> checks). Invalid stays invalid.</summary>
        public HalfEdge Twin { get { return IsValid ? new HalfEdge(Index ^ 1) : Invalid; } }
        /// <summary>The edge of this half-edge (index arithmetic). Invalid stays invalid.</summary>
        public Edge Edge { get { return IsValid ? new Edge(Index >> 1) : Hedge.Edge.Invalid; } }

        public bool Equals(HalfEdge other) { return Index == other.Index; }
        public override bool Equals(object obj) { return obj is HalfEdge && Equals((HalfEdge)obj); }
        public override int GetHashCode() { return Index; }
        public static bool operator ==(HalfEdge a, HalfEdge b) { return a.Index == b.Index; }
        public static bool operator !=(HalfEdge a, HalfEdge b) { return a.Index != b.Index; }
        public override string ToString() { return IsValid ? "h" + Index : "h(invalid)"; }
    }

    /// <summary>An edge: the pair of half-edges 2 x Index and 2 x Index + 1.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public readonly struct Edge : IEquatable<Edge>
    {
        /// <summary>The index, or -1 for none.</summary>
        public readonly int Index;

        /// <summary>The edge of index 0 or more.</summary>
        public Edge(int index) { Index = Handle.Checked(index); }
        internal Edge(uint raw) { Index = unchecked((int)raw); }
        internal uint Raw { get { return unchecked((uint)Index); } }

        public static Edge Invalid { get { return new Edge(uint.MaxValue); } }
        public bool IsValid { get { return Index != Vertex.InvalidIndex; } }

        /// <summary>Half-edge i (0 or 1) of the edge (index arithmetic, not checked against a mesh).</summary>
        public HalfEdge GetHalfEdge(int i)
        {
            if (i != 0 && i != 1) throw new ArgumentOutOfRangeException("i", i, "a half-edge of an edge is 0 or 1");
            return IsValid ? new HalfEdge(Index * 2 + i) : HalfEdge.Invalid;
        }

        public bool Equals(Edge other) { return Index == other.Index; }
        public override bool Equals(object obj) { return obj is Edge && Equals((Edge)obj); }
        public override int GetHashCode() { return Index; }
        public static bool operator ==(Edge a, Edge b) { return a.Index == b.Index; }
        public static bool operator !=(Edge a, Edge b) { return a.Index != b.Index; }
        public override string ToString() { return IsValid ? "e" + Index : "e(invalid)"; }
    }

    /// <summary>A face (a polygon of three or more corners).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public readonly struct Face : IEquatable<Face>
    {
        /// <summary>The index, or -1 for none.</summary>
        public readonly int Index;

        /// <summary>The face of index 0 or more.</summary>
        public Face(int index) { Index = Handle.Checked(index); }
        internal Face(uint raw) { Index = unchecked((int)raw); }
        internal uint Raw { get { return unchecked((uint)Index); } }

        public static Face Invalid { get { return new Face(uint.MaxValue); } }
        public bool IsValid { get { return Index != Vertex.InvalidIndex; } }

        public bool Equals(Face other) { return Index == other.Index; }
        public override bool Equals(object obj) { return obj is Face && Equals((Face)obj); }
        public override int GetHashCode() { return Index; }
        public static bool operator ==(Face a, Face b) { return a.Index == b.Index; }
        public static bool operator !=(Face a, Face b) { return a.Index != b.Index; }
        public override string ToString() { return IsValid ? "f" + Index : "f(invalid)"; }
    }

    static class Handle
    {
        // An index given to a handle's public constructor: 0 or more.
        internal static int Checked(int index)
        {
            if (index < 0)
                throw new ArgumentOutOfRangeException("index", index,
                                                      "an element index is 0 or more (Invalid names no element)");
            return index;
        }
    }

    /// <summary>A point or direction of three floats (x, y, z), laid out as the C ABI's float[3].</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Vec3 : IEquatable<Vec3>
    {
        public float X;
        public float Y;
        public float Z;

        public Vec3(float x, float y, float z) { X = x; Y = y; Z = z; }

        public bool Equals(Vec3 other) { return X == other.X && Y == other.Y && Z == other.Z; }
        public override bool Equals(object obj) { return obj is Vec3 && Equals((Vec3)obj); }
        public override int GetHashCode() { return X.GetHashCode() ^ (Y.GetHashCode() * 397) ^ (Z.GetHashCode() * 7919); }
        public static bool operator ==(Vec3 a, Vec3 b) { return a.Equals(b); }
        public static bool operator !=(Vec3 a, Vec3 b) { return !a.Equals(b); }

        // Arithmetic, componentwise in float, as Unity's Vector3 does it. Equality above is exact (bit for
        // bit but for 0 == -0 and NaN != NaN); compare with a tolerance through (a - b).Length.
        public static Vec3 operator +(Vec3 a, Vec3 b) { return new Vec3(a.X + b.X, a.Y + b.Y, a.Z + b.Z); }
        public static Vec3 operator -(Vec3 a, Vec3 b) { return new Vec3(a.X - b.X, a.Y - b.Y, a.Z - b.Z); }
        public static Vec3 operator -(Vec3 a) { return new Vec3(-a.X, -a.Y, -a.Z); }
        public static Vec3 operator *(Vec3 a, float s) { return new Vec3(a.X * s, a.Y * s, a.Z * s); }
        public static Vec3 operator *(float s, Vec3 a) { return new Vec3(a.X * s, a.Y * s, a.Z * s); }
        public static Vec3 operator /(Vec3 a, float s) { return new Vec3(a.X / s, a.Y / s, a.Z / s); }

        public static readonly Vec3 Zero = new Vec3(0, 0, 0);

        public static float Dot(Vec3 a, Vec3 b) { return a.X * b.X + a.Y * b.Y + a.Z * b.Z; }

        /// <summary>The right-handed cross product: Cross((1, 0, 0), (0, 1, 0)) is (0, 0, 1).</summary>
        public static Vec3 Cross(Vec3 a, Vec3 b)
        {
            return new Vec3(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);
        }

        /// <summary>The Euclidean length, computed in double (no overflow for large floats).</summary>
        public float Length { get { return (float)Math.Sqrt((double)X * X + (double)Y * Y + (double)Z * Z); } }

        public float SqrLength { get { return X * X + Y * Y + Z * Z; } }

        /// <summary>This direction with length 1, or <see cref="Zero"/> for a zero (or not finite) vector.</summary>
        public Vec3 Normalized
        {
            get
            {
                double l = Math.Sqrt((double)X * X + (double)Y * Y + (double)Z * Z);
                if (!(l > 0) || double.IsInfinity(l)) return Zero;
                return new Vec3((float)(X / l), (float)(Y / l), (float)(Z / l));
            }
        }

        public static float Distance(Vec3 a, Vec3 b) { return (a - b).Length; }

        /// <summary>a + (b - a) t, t not clamped.</summary>
        public static Vec3 Lerp(Vec3 a, Vec3 b, float t) { return new Vec3(a.X + (b.X - a.X) * t, a.Y + (b.Y - a.Y) * t, a.Z + (b.Z - a.Z) * t); }
        public override string ToString()
        {
            return "(" + X.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + ", " +
                   Y.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + ", " +
                   Z.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + ")";
        }
    }
}
