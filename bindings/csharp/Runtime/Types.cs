// Enums and plain structs of the C ABI. Every struct is [StructLayout(LayoutKind.Sequential)] with
// the field types and order of its C counterpart (int32 booleans stay int fields behind bool
// properties), so it is blittable and passed by pointer without conversion; FractureOptions and the
// shard record (Fracture.cs) are the exceptions, their fixed-size arrays (ByValArray) copied by the
// marshaller once per fracture. The byte sizes are checked against the header's layouts by the tests. Counts and
// slot indices, uint32_t in the C ABI, are int here, the type Unity's APIs take: the same bits for
// every value up to int.MaxValue, and the binding's Counts properties refuse a mesh beyond that.
using System;
using System.Runtime.InteropServices;

// The private fields of these structs are written by the native library only.
#pragma warning disable 0169, 0649

namespace Hedge
{
    /// <summary>What to do with input a half-edge mesh cannot hold.</summary>
    public enum TopologyPolicy
    {
        /// <summary>Refuse it: <see cref="HedgeException"/> with <see cref="HedgeStatus.Topology"/>.</summary>
        Strict = 0,
        /// <summary>Split non-manifold edges and vertices, re-orient faces, drop degenerate faces;
        /// every repair is counted in the <see cref="BuildReport"/>.</summary>
        Repair = 1,
    }

    /// <summary>Vertex welding while building.</summary>
    public enum Weld
    {
        /// <summary>Keep the input's vertices.</summary>
        None = 0,
        /// <summary>Merge bit-identical positions (+0 equals -0).</summary>
        Exact = 1,
        /// <summary>Merge positions closer than WeldEpsilon times the bounding-box diagonal.</summary>
        Epsilon = 2,
    }

    /// <summary>Triangle winding. Unity and Direct3D are clockwise.</summary>
    public enum Winding
    {
        CounterClockwise = 0,
        Clockwise = 1,
    }

    /// <summary>Where the render buffers' normals come from.</summary>
    public enum NormalSource
    {
        /// <summary>No normal stream.</summary>
        None = 0,
        /// <summary>The mesh's corner or vertex normals as they are: imported normals are kept, a moved
        /// vertex keeps its normal. None if the mesh has none.</summary>
        Attribute = 1,
        /// <summary>Area-weighted smooth vertex normals.</summary>
        Computed = 2,
        /// <summary>The default. The mesh's normals if it has some, following the geometry: each sync
        /// recomputes the normals about what the edits touched (into the mesh's normals; creases stay).
        /// Computed normals if the mesh has none.</summary>
        Automatic = 3,
    }

    /// <summary>A vertex stream of a <see cref="RenderBuffers"/>.</summary>
    public enum VertexStream
    {
        /// <summary>Interleaved layout: whole vertices (Layout.Stride floats each). Separate layout:
        /// the positions (3 floats a vertex).</summary>
        Vertices = 0,
        /// <summary>Separate layout only: 3 floats a vertex (empty when interleaved).</summary>
        Normals = 1,
        /// <summary>Separate layout only: 2 floats a vertex (empty when interleaved).</summary>
        Texcoords = 2,
        /// <summary>Separate layout only: 4 floats (r, g, b, a) a vertex (empty when interleaved).</summary>
        Colors = 3,
        /// <summary>Separate layout only: 4 floats a vertex, the tangent xyz and its handedness w (+1
        /// or -1), as Unity's <c>Mesh.tangents</c> (empty when interleaved or the mesh has none).</summary>
        Tangents = 4,
        /// <summary>Separate layout only: 2 floats a vertex, the second texcoord channel (lightmap
        /// UVs, Unity's <c>uv2</c>; empty when interleaved or the mesh has none).</summary>
        Texcoords1 = 5,
    }

    /// <summary>Options for building a mesh from index buffers or a file (16 bytes).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct BuildOptions
    {
        public TopologyPolicy Policy;
        public Weld Weld;
        /// <summary>Relative to the bounding-box diagonal; used with <see cref="Hedge.Weld.Epsilon"/>.</summary>
        public double WeldEpsilon;

        /// <summary>The C ABI's defaults: repair, no welding, epsilon 1e-6.</summary>
        public static BuildOptions Default
        {
            get { return Status.Checked(Native.hedge_build_options_default(out BuildOptions options), options); }
        }
    }

    /// <summary>What a reader may do for a file from a stranger (hedge_read_options, 16 bytes): read
    /// a glTF's external buffers or not, and how much memory it may take. See docs/security.md.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct ReadOptions
    {
        int externalBuffers;
        int reserved;
        /// <summary>The most bytes a glTF reader may allocate for what the file describes, checked
        /// before it allocates; 0 for the default, 64 times the input's size plus 64 MiB.</summary>
        public ulong MaxMemory;

        /// <summary>glTF buffers kept in separate files: read only from the .gltf's folder and below
        /// (true), or refused (false).</summary>
        public bool ExternalBuffers
        {
            get { return externalBuffers != 0; }
            set { externalBuffers = value ? 1 : 0; }
        }

        /// <summary>The defaults for reading a file by its path: external buffers beside it, the
        /// default memory budget.</summary>
        public static ReadOptions ForFiles
        {
            get { return Status.Checked(Native.hedge_read_options_default(out ReadOptions options), options); }
        }

        /// <summary>The defaults for bytes in memory: no external buffers, the default budget.</summary>
        public static ReadOptions ForBytes
        {
            get
            {
                ReadOptions options = ForFiles;
                options.ExternalBuffers = false;
                return options;
            }
        }
    }

    /// <summary>What building did; all zero for clean input (36 bytes).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct BuildReport
    {
        /// <summary>Input vertices merged into another by welding.</summary>
        public int WeldedVertices;
        /// <summary>Faces dropped: fewer than 3 distinct corners.</summary>
        public int DegenerateFaces;
        /// <summary>Consecutive repeated corners removed from kept faces.</summary>
        public int RepeatedCorners;
        /// <summary>Faces whose winding was reversed.</summary>
        public int ReorientedFaces;
        /// <summary>Input edges cut apart.</summary>
        public int NonManifoldEdges;
        /// <summary>Vertices whose faces formed several fans.</summary>
        public int NonManifoldVertices;
        /// <summary>Vertices added to split them.</summary>
        public int DuplicatedVertices;
        /// <summary>Vertices no face uses (kept; not a repair).</summary>
        public int IsolatedVertices;
        /// <summary>Total repairs (welding and isolated vertices excluded).</summary>
        public int Repairs;
    }

    /// <summary>Element counts (32 bytes). Live counts skip deleted elements; slot counts include
    /// them (element indices run up to the slot count - 1 until
    /// <see cref="HalfEdgeMesh.GarbageCollection"/>).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct MeshCounts
    {
        public int Vertices;
        public int HalfEdges;
        public int Edges;
        public int Faces;
        public int VertexSlots;
        public int HalfEdgeSlots;
        public int EdgeSlots;
        public int FaceSlots;

        public override string ToString()
        {
            return Vertices + " vertices, " + Edges + " edges, " + Faces + " faces (slots " + VertexSlots + "/" +
                   HalfEdgeSlots + "/" + EdgeSlots + "/" + FaceSlots + ")";
        }
    }

    /// <summary>How the faces around a vertex are weighted in its normal.</summary>
    public enum NormalWeighting
    {
        /// <summary>By face area.</summary>
        Area = 0,
        /// <summary>By the face's angle at the vertex: independent of how the surface is tessellated.</summary>
        Angle = 1,
        /// <summary>Every face alike.</summary>
        Uniform = 2,
    }

    /// <summary>The subdivision schemes of <see cref="HalfEdgeMesh.Subdivide"/>.</summary>
    public enum Subdivision
    {
        /// <summary>Loop's scheme: smooth.</summary>
        Loop = 0,
        /// <summary>New vertices at the edge midpoints: the shape is kept.</summary>
        Midpoint = 1,
        /// <summary>Catmull-Clark: any polygons; a face of n corners becomes n quads.</summary>
        CatmullClark = 2,
        /// <summary>Kobbelt's sqrt(3): triangles; each face gets a centre vertex and the old edges are flipped.</summary>
        Sqrt3 = 3,
        /// <summary>Each face of n corners becomes n triangles about its centroid: any polygons, the shape is kept.</summary>
        SplitFaces = 4,
    }

    /// <summary>How <see cref="HalfEdgeMesh.Smooth"/> weighs the neighbours.</summary>
    public enum SmoothMethod
    {
        /// <summary>The average of the neighbours.</summary>
        Uniform = 0,
        /// <summary>Taubin's lambda|mu steps: removes noise without shrinking.</summary>
        Taubin = 1,
        /// <summary>Cotangent weights: follows the geometry, not the tessellation (triangle meshes only).</summary>
        Cotangent = 2,
        /// <summary>Backward Euler steps of the cotangent flow (Lambda is the time step, any positive value).</summary>
        Implicit = 3,
    }

    /// <summary>The element orders of <see cref="HalfEdgeMesh.Reorder"/>.</summary>
    public enum Ordering
    {
        /// <summary>A Morton curve through the positions: traversals read memory in order.</summary>
        Spatial = 0,
        /// <summary>Faces for a GPU's vertex cache, vertices in the order the faces first use them.</summary>
        VertexCache = 1,
    }

    /// <summary>Options of <see cref="HalfEdgeMesh.Smooth"/> (32 bytes, hedge_smooth_options). Start from
    /// <see cref="Default"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SmoothOptions
    {
        public SmoothMethod Method;
        /// <summary>0..100000; a Taubin iteration is its two steps.</summary>
        public int Iterations;
        /// <summary>The step toward the average, in (0, 1].</summary>
        public double Lambda;
        /// <summary>Taubin's inflating step, in [-1, -Lambda).</summary>
        public double Mu;
        int fixBoundary;
        int reserved;

        /// <summary>Boundary vertices stay where they are (else they move along the boundary).</summary>
        public bool FixBoundary { get { return fixBoundary != 0; } set { fixBoundary = value ? 1 : 0; } }

        /// <summary>Uniform, 10 iterations, lambda 0.5, mu -0.53, boundary fixed.</summary>
        public static SmoothOptions Default
        {
            get { return Status.Checked(Native.hedge_smooth_options_default(out SmoothOptions o), o); }
        }
    }

    /// <summary>Options of <see cref="HalfEdgeMesh.Decimate"/> (80 bytes, hedge_decimate_options). Start from
    /// <see cref="Default"/> and set a target.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct DecimateOptions
    {
        /// <summary>Stop at this many vertices (0: no vertex target).</summary>
        public ulong TargetVertices;
        /// <summary>Stop at this many faces (0: no face target).</summary>
        public ulong TargetFaces;
        /// <summary>Stop before a collapse that moves the surface farther than this (model units); infinity: no limit.</summary>
        public double MaxError;
        /// <summary>Weight of the planes that keep open boundaries in place (0: none).</summary>
        public double BoundaryWeight;
        /// <summary>Edges whose faces meet at a larger dihedral angle (degrees) are kept like boundaries.</summary>
        public double FeatureAngleDegrees;
        /// <summary>Weight of the planes that keep feature edges (0: none).</summary>
        public double FeatureWeight;
        /// <summary>Greater than 0: texture distortion enters the error with this weight.</summary>
        public double AttributeWeight;
        /// <summary>Refuse collapses that turn a face by more than this, in (0, 180].</summary>
        public double MaxNormalChangeDegrees;
        int keepBoundary;
        int keepSeams;
        int relaxNormalChange;
        int reserved;

        /// <summary>Boundary vertices never move and are never removed.</summary>
        public bool KeepBoundary { get { return keepBoundary != 0; } set { keepBoundary = value ? 1 : 0; } }
        /// <summary>UV seams are not collapsed across or broken.</summary>
        public bool KeepSeams { get { return keepSeams != 0; } set { keepSeams = value ? 1 : 0; } }
        /// <summary>Should <see cref="MaxNormalChangeDegrees"/> (below 90) alone stop the run short of its target, it is
        /// raised to 90 for the rest (the default); false: it holds to the end, and the result says so
        /// (<see cref="DecimateStop.NoLegalCollapse"/>, refusals counted).</summary>
        public bool RelaxNormalChange
        {
            get { return relaxNormalChange != 0; }
            set { relaxNormalChange = value ? 1 : 0; }
        }

        /// <summary>No target, no error limit, boundary weight 1, feature angle 60 and weight 1, normal change 60
        /// degrees relaxed to 90 when it alone stops the run, boundary free, seams kept.</summary>
        public static DecimateOptions Default
        {
            get { return Status.Checked(Native.hedge_decimate_options_default(out DecimateOptions o), o); }
        }
    }

    /// <summary>Why <see cref="HalfEdgeMesh.Decimate"/> stopped (hedge_decimate_stop).</summary>
    public enum DecimateStop
    {
        /// <summary>The vertex and face targets are met.</summary>
        TargetReached = 0,
        /// <summary>Every collapse left would exceed the error limit.</summary>
        ErrorBound = 1,
        /// <summary>Each collapse left is refused by a check (counted in the result), or none is left.</summary>
        NoLegalCollapse = 2,
    }

    /// <summary>What <see cref="HalfEdgeMesh.Decimate"/> achieved (64 bytes, hedge_decimate_result).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct DecimateResult
    {
        /// <summary>Live vertices left.</summary>
        public ulong Vertices;
        /// <summary>Live faces left.</summary>
        public ulong Faces;
        /// <summary>Edge collapses done.</summary>
        public ulong Collapses;
        /// <summary>The largest error (a distance) of a collapse done, 0 if none.</summary>
        public double MaxError;
        /// <summary>Why it stopped.</summary>
        public DecimateStop Stop;
        int reserved;
        /// <summary>Collapse attempts refused by the link condition (an edge retried in a later pass counts again).</summary>
        public ulong RefusedTopology;
        /// <summary>Attempts refused because a face would turn too far, turn over or lose its area.</summary>
        public ulong RefusedNormal;
        /// <summary>Attempts refused because a new face would be a sliver.</summary>
        public ulong RefusedShape;
    }

    /// <summary>Measures of a whole mesh (48 bytes, hedge_geometry).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct MeshGeometry
    {
        /// <summary>The sum of the live faces' areas.</summary>
        public double Area;
        /// <summary>The signed enclosed volume (positive for outward faces); NaN when the mesh is not closed.</summary>
        public double Volume;
        int closed;
        int empty;
        /// <summary>The axis-aligned bounding box of the live vertices (zero when there are none).</summary>
        public Vec3 BoxMin;
        public Vec3 BoxMax;

        /// <summary>True if the mesh has no boundary, so that <see cref="Volume"/> is defined.</summary>
        public bool Closed { get { return closed != 0; } }
        /// <summary>True if the mesh has no vertex.</summary>
        public bool Empty { get { return empty != 0; } }
    }

    /// <summary>Options of a <see cref="RenderBuffers"/> (24 bytes).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct RenderOptions
    {
        public NormalSource Normals;
        int texcoords;
        int colors;
        int interleaved;
        public Winding Winding;
        int flipX;

        /// <summary>Texcoords from the mesh's corner or vertex texcoords when present.</summary>
        public bool Texcoords { get { return texcoords != 0; } set { texcoords = value ? 1 : 0; } }
        /// <summary>Colours from the mesh's corner or vertex colours when present.</summary>
        public bool Colors { get { return colors != 0; } set { colors = value ? 1 : 0; } }
        /// <summary>One buffer of whole vertices (true) or one buffer per stream (false).</summary>
        public bool Interleaved { get { return interleaved != 0; } set { interleaved = value ? 1 : 0; } }
        /// <summary>Negate x of positions and normals, for mirrored data (Unity needs none: see <see cref="Unity"/>).</summary>
        public bool FlipX { get { return flipX != 0; } set { flipX = value ? 1 : 0; } }

        /// <summary>The defaults: automatic normals, texcoords, colours, interleaved, counter-clockwise,
        /// x not flipped.</summary>
        public static RenderOptions Default
        {
            get { return Status.Checked(Native.hedge_render_buffers_options_default(out RenderOptions options), options); }
        }

        /// <summary>For a Unity Mesh: one stream per attribute (position, normal, texcoord, colour:
        /// Mesh.SetVertexBufferData streams 0-3), automatic normals, and Unity's own coordinates and
        /// triangles as they are (no winding change, no mirroring: Unity's clockwise front faces in its
        /// left-handed axes have the same cross-product normals as counter-clockwise faces in right-handed
        /// axes, so none is needed). Use with a mesh imported with <see cref="EngineImportOptions.Unity"/>.</summary>
        public static RenderOptions Unity
        {
            get
            {
                RenderOptions options = Default;
                options.Interleaved = false;
                return options;
            }
        }
    }

    /// <summary>Where each attribute sits in a vertex, in floats; an absent attribute has offset -1
    /// (32 bytes). Interleaved: all in the <see cref="VertexStream.Vertices"/> buffer, Stride floats
    /// a vertex, in the order position, normal, texcoord, colour, tangent, texcoord1. Separate: each
    /// in its own stream, tightly packed, at offset 0; Stride still counts the floats of a whole
    /// vertex over all streams. Tangents and the second texcoord channel are present when the mesh
    /// has them (<see cref="HalfEdgeMesh.FromEngineMesh(EngineStreams, EngineImportOptions)"/>).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct VertexLayout
    {
        public int Stride;
        public int Position;
        public int Normal;
        public int Texcoord;
        public int Color;
        int interleaved;
        /// <summary>The tangent (4 floats: xyz, handedness w), -1 when absent.</summary>
        public int Tangent;
        /// <summary>The second texcoord channel (2 floats: lightmap UVs), -1 when absent.</summary>
        public int Texcoord1;

        public bool Interleaved { get { return interleaved != 0; } }
        public bool HasNormals { get { return Normal >= 0; } }
        public bool HasTexcoords { get { return Texcoord >= 0; } }
        public bool HasColors { get { return Color >= 0; } }
        public bool HasTangents { get { return Tangent >= 0; } }
        public bool HasTexcoords1 { get { return Texcoord1 >= 0; } }
    }

    /// <summary>A run of slots [First, First + Count) (8 bytes).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SlotRange
    {
        public int First;
        public int Count;

        public SlotRange(int first, int count)
        {
            if (first < 0) throw new ArgumentOutOfRangeException("first", first, "a slot index is 0 or more");
            if (count < 0) throw new ArgumentOutOfRangeException("count", count, "a slot count is 0 or more");
            First = first;
            Count = count;
        }
        public override string ToString() { return "[" + First + ", " + (First + Count) + ")"; }
    }

    /// <summary>What a sync, commit or rebuild rewrote (40 bytes). The ranges themselves:
    /// <see cref="RenderBuffers.GetDirtyVertexRanges"/> and <see cref="RenderBuffers.GetDirtyIndexRanges"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SyncResult
    {
        /// <summary>Bytes in the vertex ranges, all streams.</summary>
        public ulong VertexBytes;
        /// <summary>Bytes in the index ranges.</summary>
        public ulong IndexBytes;
        /// <summary>Rewritten render-vertex ranges.</summary>
        public int VertexRangeCount;
        /// <summary>Rewritten index-buffer ranges (in indices, not triangles).</summary>
        public int IndexRangeCount;
        public int FacesSynced;
        public int VerticesSynced;
        int resized;
        int full;

        /// <summary>The buffers grew or were rebuilt: reallocate GPU buffers and upload everything.</summary>
        public bool Resized { get { return resized != 0; } }
        /// <summary>Everything was rebuilt (first sync, garbage collection, rebuild).</summary>
        public bool Full { get { return full != 0; } }
        /// <summary>Nothing was rewritten.</summary>
        public bool IsEmpty { get { return VertexRangeCount == 0 && IndexRangeCount == 0; } }
    }

    /// <summary>Buffer sizes of a <see cref="RenderBuffers"/> (40 bytes). Slot counts include free slots;
    /// allocate GPU buffers at the capacities, inside which the counts grow without a Resized sync.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct BufferCounts
    {
        /// <summary>Render vertex slots, free ones included: the vertex buffer's length in vertices.</summary>
        public int VertexSlots;
        /// <summary>The index buffer's length in indices (3 per triangle slot).</summary>
        public int IndexCount;
        /// <summary>Render vertex slots in use.</summary>
        public int Vertices;
        /// <summary>Triangle slots in use.</summary>
        public int Triangles;
        /// <summary>Render vertices beyond one per used mesh vertex: what seams cost.</summary>
        public int SeamSplits;
        /// <summary>Degenerate triangle slots waiting for reuse or compaction.</summary>
        public int FreeTriangleSlots;
        /// <summary>Bytes of the whole vertex and index buffers (a full upload).</summary>
        public ulong BufferBytes;
        /// <summary>Render vertex slots to allocate (at least VertexSlots).</summary>
        public int VertexCapacity;
        /// <summary>Index-buffer entries to allocate (at least IndexCount).</summary>
        public int IndexCapacity;
    }

    /// <summary>Options for <c>HalfEdgeMesh.FromEngineMesh</c> (24 bytes).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct EngineImportOptions
    {
        /// <summary>How positions are welded into one topological vertex (attributes stay per corner,
        /// so seams survive any welding).</summary>
        public Weld Weld;
        public TopologyPolicy Policy;
        public double WeldEpsilon;
        /// <summary>The engine's triangle winding (Unity: clockwise).</summary>
        public Winding Winding;
        int flipX;

        /// <summary>Negate x of positions and normals, for mirrored data (Unity needs none: see <see cref="Unity"/>).</summary>
        public bool FlipX { get { return flipX != 0; } set { flipX = value ? 1 : 0; } }

        /// <summary>The defaults: exact welding, repair, epsilon 1e-6, counter-clockwise, x not flipped.</summary>
        public static EngineImportOptions Default
        {
            get { return Status.Checked(Native.hedge_engine_import_options_default(out EngineImportOptions o), o); }
        }

        /// <summary>For a Unity Mesh: positions welded exactly, and Unity's coordinates and triangles kept as
        /// they are, so that the half-edge mesh holds the user's own coordinates (a vertex at (1, 0, 0) in Unity
        /// is at (1, 0, 0) in the mesh) and computed normals agree with Unity's RecalculateNormals. No
        /// conversion is needed: Unity's clockwise front faces in its left-handed axes have the same
        /// cross-product normals as counter-clockwise faces in right-handed axes. <see cref="Winding"/> and
        /// <see cref="FlipX"/> are for data in another convention.</summary>
        public static EngineImportOptions Unity
        {
            get { return Default; }
        }
    }
}
