// HalfEdgeMesh: a native hedge mesh (SurfaceMesh) behind the C ABI.
//
// Errors. Every call that the library answers with a status other than OK throws a
// HedgeException carrying that status and the library's message, with one exception: an edit
// that its predicate refuses (HEDGE_ERROR_REFUSED) is not an error, as in the C++ library. It
// returns false, an invalid handle or a count of 0, and leaves the mesh exactly as it was. An
// element index that is out of range or deleted is HedgeStatus.BadHandle; any call on a disposed
// mesh throws ObjectDisposedException.
// Arguments the binding can check itself before calling (a null array that is required, an array
// whose length does not fit the counts) throw ArgumentException, so that the library never reads
// or writes past the end of a managed array.
//
// Caller arrays. The query methods that return several elements fill an array the caller owns and
// return the count: pass the same array again and again, and nothing is allocated. Passing null
// asks for the count only. An array that is too small throws HedgeException(BufferTooSmall) and
// nothing is written. Queries and edits allocate no managed memory.
//
// Threads. Different meshes may be used from different threads at once; one mesh (with its
// RenderBuffers) must be used by one thread at a time.
using System;
using System.Runtime.InteropServices;

namespace Hedge
{
    /// <summary>A half-edge mesh: adjacency queries, local edits checked by predicates, building from
    /// index buffers and engine arrays, files, validation, and engine-ready render buffers.</summary>
    public sealed partial class HalfEdgeMesh : IDisposable
    {
        const int Refused = (int)HedgeStatus.Refused;
        static readonly string[] NoProblems = new string[0];

        readonly MeshHandle handle;
        readonly IntPtr liveId;
        // Render objects the finalizer released, destroyed on this mesh's thread (see RenderHandle).
        readonly PendingRenders pendingRenders = new PendingRenders();
        // Scratch for the three-corner AddFace overloads.
        readonly Vertex[] corners3 = new Vertex[3];

        HalfEdgeMesh(IntPtr id)
        {
            liveId = id;
            handle = new MeshHandle(id);
        }

        // The native id for a call: every call goes through here, so a disposed mesh throws
        // ObjectDisposedException (naming the type) before it reaches the library. One field read.
        IntPtr id { get { return handle.IsClosed ? throw new ObjectDisposedException("HalfEdgeMesh") : liveId; } }

        static HalfEdgeMesh Created(int status, IntPtr id)
        {
            Status.Check(status);
            return new HalfEdgeMesh(id);
        }

        internal IntPtr Id { get { return id; } }
        internal PendingRenders PendingRenders { get { return pendingRenders; } }

        /// <summary>The SafeHandle that owns the native mesh.</summary>
        public SafeHandle Handle { get { return handle; } }

        /// <summary>True after <see cref="Dispose"/>; every later call (but Dispose, IsDisposed, Handle and
        /// ToString) throws ObjectDisposedException.</summary>
        public bool IsDisposed { get { return handle.IsClosed; } }

        /// <summary>Destroys the native mesh and every RenderBuffers made for it.</summary>
        public void Dispose() { handle.Dispose(); }

        /// <summary>The native library's version.</summary>
        public static Version LibraryVersion
        {
            get
            {
                int status = Native.hedge_version(out int major, out int minor, out int patch);
                return Status.Checked(status, new Version(major, minor, patch));
            }
        }

        // =========================================================================================
        // Building
        // =========================================================================================

        /// <summary>Builds a mesh from triangles with the default options (repair, no welding).</summary>
        /// <param name="positions">x, y, z per vertex.</param>
        /// <param name="triangles">Three vertex indices per triangle, counter-clockwise.</param>
        public static HalfEdgeMesh FromTriangles(float[] positions, int[] triangles)
        {
            CheckNotNegative(triangles, "triangles", "a vertex index");
            BuildReport report;
            return Build(positions, triangles, null, BuildOptions.Default, out report, null, null);
        }

        /// <summary>Builds a mesh from triangles, welding and repairing as the options say.</summary>
        public static HalfEdgeMesh FromTriangles(float[] positions, int[] triangles, BuildOptions options,
                                                 out BuildReport report)
        {
            CheckNotNegative(triangles, "triangles", "a vertex index");
            return Build(positions, triangles, null, options, out report, null, null);
        }

        /// <summary>Builds a mesh from polygons: faceSizes[i] corners per face, taken in order from indices.</summary>
        public static HalfEdgeMesh FromPolygons(float[] positions, int[] indices, int[] faceSizes,
                                                BuildOptions options, out BuildReport report)
        {
            if (faceSizes == null) throw new ArgumentNullException("faceSizes");
            return Build(positions, indices, faceSizes, options, out report, null, null);
        }

        /// <summary>Builds a mesh from index buffers (every option of hedge_mesh_create).</summary>
        /// <param name="positions">x, y, z per vertex (finite).</param>
        /// <param name="indices">The corners of all faces, face after face.</param>
        /// <param name="faceSizes">Corners per face, or null for triangles.</param>
        /// <param name="options">Policy and welding.</param>
        /// <param name="report">What was welded and repaired.</param>
        /// <param name="vertexMap">Optional (null), one entry per input vertex: the mesh vertex it
        /// became (after welding; a split vertex maps to its first copy).</param>
        /// <param name="faceMap">Optional (null), one entry per input face: the mesh face, or
        /// <see cref="Face.Invalid"/> if it was dropped.</param>
        /// <exception cref="ArgumentException">A negative index or face size (ArgumentOutOfRangeException).</exception>
        public static HalfEdgeMesh Build(float[] positions, int[] indices, int[] faceSizes, BuildOptions options,
                                         out BuildReport report, Vertex[] vertexMap, Face[] faceMap)
        {
            uint vertexCount = VertexCountOf(positions, "positions");
            CheckNotNegative(indices, "indices", "a vertex index");
            if (faceSizes != null) CheckNotNegative(faceSizes, "faceSizes", "a face size");
            int faceCount = faceSizes != null ? faceSizes.Length : indices.Length / 3;
            if (vertexMap != null && vertexMap.Length < vertexCount)
                throw new ArgumentException("holds " + vertexMap.Length + " entries, " + vertexCount + " needed",
                                            "vertexMap");
            if (faceMap != null && faceMap.Length < faceCount)
                throw new ArgumentException("holds " + faceMap.Length + " entries, " + faceCount + " needed", "faceMap");
            IntPtr mesh;
            int status = Native.hedge_mesh_create_int(positions, vertexCount, indices, (uint)indices.Length, faceSizes,
                                                  faceSizes != null ? (uint)faceSizes.Length : 0u, ref options,
                                                  out report, vertexMap, faceMap, out mesh);
            return Created(status, mesh);
        }

        /// <summary>Builds a mesh from an engine's arrays (a Unity Mesh): positions welded for the topology,
        /// normals, texcoords and colours kept per corner, so that a <see cref="RenderBuffers"/> with the same
        /// winding and FlipX gives back the engine's triangles and attribute values, seams included.</summary>
        /// <param name="positions">x, y, z per engine vertex.</param>
        /// <param name="triangles">Three engine-vertex indices per triangle.</param>
        /// <param name="normals">Optional (null): x, y, z per engine vertex.</param>
        /// <param name="texcoords">Optional (null): u, v per engine vertex.</param>
        /// <param name="colors">Optional (null): r, g, b, a per engine vertex.</param>
        /// <param name="options">Welding, policy, winding and axes (see <see cref="EngineImportOptions.Unity"/>).</param>
        /// <param name="report">What was welded and repaired.</param>
        /// <exception cref="ArgumentException">A negative index (ArgumentOutOfRangeException).</exception>
        public static HalfEdgeMesh FromEngineMesh(float[] positions, int[] triangles, float[] normals,
                                                  float[] texcoords, float[] colors, EngineImportOptions options,
                                                  out BuildReport report)
        {
            uint n = CheckEngineArrays(positions, normals, texcoords, colors);
            CheckNotNegative(triangles, "triangles", "a vertex index");
            IntPtr mesh;
            int status = Native.hedge_mesh_from_engine_mesh_int(positions, n, triangles, (uint)triangles.Length,
                                                                normals, texcoords, colors, ref options, out report,
                                                                out mesh);
            return Created(status, mesh);
        }

        // Throws for a null array or a negative entry, which the C ABI would read as a huge uint32_t.
        static void CheckNotNegative(int[] values, string name, string what)
        {
            if (values == null) throw new ArgumentNullException(name);
            for (int i = 0; i < values.Length; ++i)
                if (values[i] < 0)
                    throw new ArgumentOutOfRangeException(name, values[i],
                                                          name + "[" + i + "] is " + values[i] + ": " + what + " is 0 or more");
        }

        static uint VertexCountOf(float[] positions, string name)
        {
            if (positions == null) throw new ArgumentNullException(name);
            if (positions.Length % 3 != 0)
                throw new ArgumentException("length " + positions.Length + " is not a multiple of 3 (x, y, z)", name);
            return (uint)(positions.Length / 3);
        }

        static uint CheckEngineArrays(float[] positions, float[] normals, float[] texcoords, float[] colors)
        {
            uint n = VertexCountOf(positions, "positions");
            if (normals != null && normals.Length != 3L * n)
                throw new ArgumentException("length " + normals.Length + ", " + 3L * n + " expected (3 per vertex)",
                                            "normals");
            if (texcoords != null && texcoords.Length != 2L * n)
                throw new ArgumentException("length " + texcoords.Length + ", " + 2L * n + " expected (2 per vertex)",
                                            "texcoords");
            if (colors != null && colors.Length != 4L * n)
                throw new ArgumentException("length " + colors.Length + ", " + 4L * n + " expected (4 per vertex)",
                                            "colors");
            return n;
        }

        // =========================================================================================
        // Files: OBJ, OFF, PLY, STL, chosen by the extension
        // =========================================================================================

        /// <summary>Reads a mesh with the format's default options (repair; exact welding for STL).</summary>
        /// <exception cref="HedgeException">HedgeStatus.Io for an unreadable or malformed file or an
        /// unknown extension; the message is "path:line: ..." (text) or "path (byte N): ..." (binary).</exception>
        public static HalfEdgeMesh Read(string path)
        {
            BuildReport report;
            return Read(path, out report);
        }

        /// <summary>Reads a mesh with the format's default options, and reports the repairs.</summary>
        public static HalfEdgeMesh Read(string path, out BuildReport report)
        {
            IntPtr mesh;
            int status = Native.hedge_mesh_read_defaults(Status.ToUtf8(path, "path"), IntPtr.Zero, out report,
                                                         out mesh);
            return Created(status, mesh);
        }

        /// <summary>Reads a mesh with the given options.</summary>
        public static HalfEdgeMesh Read(string path, BuildOptions options, out BuildReport report)
        {
            IntPtr mesh;
            int status = Native.hedge_mesh_read(Status.ToUtf8(path, "path"), ref options, out report, out mesh);
            return Created(status, mesh);
        }

        /// <summary>Reads a mesh with the format's default build options and the given read options
        /// (a glTF's external buffers, the memory budget).</summary>
        public static HalfEdgeMesh Read(string path, ReadOptions readOptions, out BuildReport report)
        {
            IntPtr mesh;
            int status = Native.hedge_mesh_read_with_defaults(Status.ToUtf8(path, "path"), IntPtr.Zero, ref readOptions,
                                                              out report, out mesh);
            return Created(status, mesh);
        }

        /// <summary>Reads a mesh from a file's bytes (a download, an upload, an asset bundle's
        /// TextAsset.bytes). A glTF's external buffers are refused: the bytes have no folder.</summary>
        /// <param name="name">The file's name: its extension (.obj, .off, .ply, .stl, .gltf, .glb)
        /// chooses the format, and messages start with it.</param>
        public static HalfEdgeMesh FromBytes(byte[] bytes, string name)
        {
            BuildReport report;
            return FromBytes(bytes, name, ReadOptions.ForBytes, out report);
        }

        /// <summary>Reads a mesh from a file's bytes with the given read options; with external
        /// buffers on, they are looked up in the folder of <paramref name="name"/>.</summary>
        public static HalfEdgeMesh FromBytes(byte[] bytes, string name, ReadOptions readOptions, out BuildReport report)
        {
            if (bytes == null) throw new ArgumentNullException("bytes");
            IntPtr mesh;
            int status = Native.hedge_mesh_read_memory_defaults(bytes, (ulong)bytes.Length, Status.ToUtf8(name, "name"),
                                                                IntPtr.Zero, ref readOptions, out report, out mesh);
            return Created(status, mesh);
        }

        /// <summary>Writes the live faces atomically (a failed write leaves the target as it was).</summary>
        /// <param name="path">The file; the extension chooses the format.</param>
        /// <param name="binary">PLY and STL: binary (little endian) or ASCII; ignored for OBJ and OFF.</param>
        /// <param name="precision">Significant digits of ASCII coordinates, 1 to 17; 0 for the default
        /// (9, an exact round trip of every float).</param>
        public void Write(string path, bool binary = false, int precision = 0)
        {
            Status.Check(Native.hedge_mesh_write(id, Status.ToUtf8(path, "path"), binary ? 1 : 0, precision));
        }

        // =========================================================================================
        // Counts and positions
        // =========================================================================================

        /// <summary>Live and slot counts of every element kind (one native call).</summary>
        public MeshCounts Counts
        {
            get
            {
                MeshCounts counts = Status.Checked(Native.hedge_mesh_counts(id, out MeshCounts c), c);
                if (counts.HalfEdgeSlots < 0) throw Status.TooLarge("half-edge slots");
                return counts;
            }
        }

        /// <summary>Live vertices.</summary>
        public int VertexCount { get { return (int)Counts.Vertices; } }
        /// <summary>Live half-edges.</summary>
        public int HalfEdgeCount { get { return (int)Counts.HalfEdges; } }
        /// <summary>Live edges.</summary>
        public int EdgeCount { get { return (int)Counts.Edges; } }
        /// <summary>Live faces.</summary>
        public int FaceCount { get { return (int)Counts.Faces; } }

        public Vec3 GetPosition(Vertex v) { return Status.Checked(Native.hedge_vertex_position(id, v.Raw, out Vec3 p), p); }

        /// <summary>Moves a vertex; render buffers see it at their next sync. Coordinates must be finite.</summary>
        public void SetPosition(Vertex v, float x, float y, float z)
        {
            Status.Check(Native.hedge_set_vertex_position(id, v.Raw, x, y, z));
        }

        public void SetPosition(Vertex v, Vec3 p) { SetPosition(v, p.X, p.Y, p.Z); }

        /// <summary>Copies the positions of every vertex slot (deleted ones with stale data), 3 floats a slot.</summary>
        /// <returns>The floats needed (3 x vertex slots); with a null buffer, only that.</returns>
        public int CopyPositions(float[] buffer)
        {
            return Filled(Native.hedge_mesh_copy_positions(id, buffer, Status.Capacity(buffer), out ulong n), buffer, n);
        }


        // =========================================================================================
        // Geometry and normals
        // =========================================================================================

        /// <summary>Subdivides steps times (0..12): Loop and Midpoint refine triangles 1-to-4, CatmullClark turns a face of
        /// n corners into n quads, Sqrt3 (triangles) and SplitFaces turn it into n triangles about its centroid. Every index changes, as after
        /// <see cref="GarbageCollection"/>: old vertex v keeps index v, the vertex of edge e is VertexSlots + e. Render
        /// buffers rebuild at their next sync. A face that is not a triangle (Loop, Midpoint, Sqrt3): HedgeException (InvalidArgument), and the
        /// mesh is unchanged.</summary>
        public void Subdivide(Subdivision scheme, int steps = 1)
        {
            pendingRenders.Drain();
            Status.Check(Native.hedge_mesh_subdivide(id, (int)scheme, steps));
        }

        /// <summary>Renumbers the elements in the given order: <see cref="Ordering.Spatial"/> (a Morton curve, so that
        /// traversals read memory in order) or <see cref="Ordering.VertexCache"/> (faces for a GPU vertex cache of
        /// <paramref name="cacheSize"/> entries, vertices by first use). Garbage is collected at the same time. The optional
        /// maps receive old-to-new indices, as with <see cref="GarbageCollection"/>. Render buffers rebuild at their next
        /// sync.</summary>
        public void Reorder(Ordering ordering = Ordering.Spatial, int cacheSize = 16, Vertex[] vertexMap = null,
                            HalfEdge[] halfEdgeMap = null, Edge[] edgeMap = null, Face[] faceMap = null)
        {
            if (cacheSize < 0) throw new ArgumentOutOfRangeException(nameof(cacheSize), "the cache size is 0 or more");
            pendingRenders.Drain();
            Status.Check(Native.hedge_mesh_reorder(id, (int)ordering, (uint)cacheSize, vertexMap, Status.Capacity(vertexMap),
                                                   halfEdgeMap, Status.Capacity(halfEdgeMap), edgeMap,
                                                   Status.Capacity(edgeMap), faceMap, Status.Capacity(faceMap)));
        }

        /// <summary>Vertex loads per triangle when the faces are drawn in index order through a first-in first-out
        /// vertex cache of <paramref name="cacheSize"/> entries: 0.5 (best) to 3 (worst).</summary>
        public double CacheMissRatio(int cacheSize = 16)
        {
            if (cacheSize < 0) throw new ArgumentOutOfRangeException(nameof(cacheSize), "the cache size is 0 or more");
            return Status.Checked(Native.hedge_mesh_cache_miss_ratio(id, (uint)cacheSize, out double ratio), ratio);
        }

        /// <summary>Decimates a triangle mesh by quadric-ranked edge collapses until the targets of the options are met, the
        /// next collapse's error would exceed MaxError, or no legal collapse is left. Garbage is collected at the end, so
        /// every index may change, as after <see cref="GarbageCollection"/>; render buffers rebuild at their next sync.
        /// A face that is not a triangle, a position that is not finite or options out of range: HedgeException
        /// (InvalidArgument), and the mesh is unchanged.</summary>
        /// <param name="options">Targets and weights; see <see cref="DecimateOptions.Default"/>.</param>
        public DecimateResult Decimate(DecimateOptions options)
        {
            pendingRenders.Drain();
            return Status.Checked(Native.hedge_mesh_decimate(id, ref options, out DecimateResult result), result);
        }

        /// <summary>Smooths the positions of the live vertices; render buffers see the moves at their next sync.</summary>
        /// <param name="options">Method, iterations and steps; see <see cref="SmoothOptions.Default"/>.</param>
        /// <param name="mask">Optional (null): one byte per vertex slot; only vertices with a nonzero byte move.</param>
        public void Smooth(SmoothOptions options, byte[] mask = null)
        {
            Status.Check(Native.hedge_mesh_smooth(id, ref options, mask, mask != null ? (uint)mask.Length : 0));
        }

        /// <summary>Area, volume (NaN unless closed) and bounding box of the mesh (one native call, O(n)).</summary>
        public MeshGeometry Geometry
        {
            get { return Status.Checked(Native.hedge_mesh_geometry(id, out MeshGeometry g), g); }
        }

        /// <summary>The unit normal of a live face, by its winding (zero for a degenerate face).</summary>
        public Vec3 FaceNormal(Face f) { return Status.Checked(Native.hedge_face_normal(id, f.Raw, out Vec3 n), n); }

        /// <summary>The area of a live face.</summary>
        public double FaceArea(Face f) { return Status.Checked(Native.hedge_face_area(id, f.Raw, out double a), a); }

        /// <summary>Computes unit vertex normals into the mesh. <see cref="RenderBuffers"/> made afterwards with
        /// <see cref="NormalSource.Attribute"/> (or Automatic) use them.</summary>
        public void ComputeVertexNormals(NormalWeighting weighting = NormalWeighting.Area)
        {
            Status.Check(Native.hedge_mesh_compute_vertex_normals(id, (int)weighting));
        }

        /// <summary>Computes corner normals into the mesh: around each vertex, the faces between boundary gaps and
        /// edges sharper than creaseDegrees (0..180) share one normal; 0 is flat shading, 180 smooth. Render buffers
        /// made afterwards with <see cref="NormalSource.Attribute"/> split their vertices along the creases: hard
        /// edges on a smooth surface.</summary>
        public void ComputeCornerNormals(double creaseDegrees, NormalWeighting weighting = NormalWeighting.Angle)
        {
            Status.Check(Native.hedge_mesh_compute_corner_normals(id, creaseDegrees, (int)weighting));
        }

        /// <summary>Copies the vertex normals, 3 floats per vertex slot. Pass null to ask for the size.</summary>
        /// <returns>The number of floats needed (3 x VertexSlots).</returns>
        public int CopyVertexNormals(float[] buffer)
        {
            return Filled(Native.hedge_mesh_copy_vertex_normals(id, buffer, Status.Capacity(buffer), out ulong n), buffer, n);
        }

        /// <summary>Copies the corner normals, 3 floats per half-edge slot (the corner of the half-edge's face at its
        /// target vertex; zero on boundary half-edges). Pass null to ask for the size.</summary>
        /// <returns>The number of floats needed (3 x HalfEdgeSlots).</returns>
        public int CopyCornerNormals(float[] buffer)
        {
            return Filled(Native.hedge_mesh_copy_corner_normals(id, buffer, Status.Capacity(buffer), out ulong n), buffer, n);
        }

        /// <summary>The sampled symmetric Hausdorff distance between this surface and other's: each surface's vertices
        /// plus samples seeded, area-proportional points on its faces, measured exactly against the other surface;
        /// O((V + samples) log F). meanDistance: the mean over all those points. A mesh without faces throws
        /// (InvalidArgument).</summary>
        public double HausdorffDistance(HalfEdgeMesh other, out double meanDistance, ulong samples = 100000, ulong seed = 1)
        {
            if (other == null) throw new ArgumentNullException("other");
            int status = Native.hedge_mesh_hausdorff(id, other.id, samples, seed, out double distance, out meanDistance);
            return Status.Checked(status, distance);
        }

        // Throws unless array holds at least count entries (count 0 or more).
        static void CheckSpan(Array array, int count, string name)
        {
            if (array == null) throw new ArgumentNullException(name);
            if (count < 0 || count > array.Length)
                throw new ArgumentOutOfRangeException("count", count, name + " holds " + array.Length + " entries");
        }

        // The length of the corners array, which must not be null.
        static int LengthOf(Vertex[] corners)
        {
            if (corners == null) throw new ArgumentNullException("corners");
            return corners.Length;
        }

        // The three corners in the mesh's scratch array (for the three-corner overloads).
        Vertex[] Triangle(Vertex a, Vertex b, Vertex c)
        {
            corners3[0] = a;
            corners3[1] = b;
            corners3[2] = c;
            return corners3;
        }

        // =========================================================================================
        // Edits. A refused edit returns false / an invalid handle / 0 and changes nothing;
        // LastRefusalCode and LastRefusal then say why (Refusals.cs). Render buffers of the mesh see
        // every edit at their next sync.
        // =========================================================================================

        /// <summary>Inserts a vertex at point p on the edge. Triangles on either side are split in two;
        /// half-edge 2 x e then runs from the edge's first vertex to the new vertex.</summary>
        /// <returns>The new vertex, or <see cref="Vertex.Invalid"/> if refused.</returns>
        public Vertex SplitEdge(Edge e, Vec3 p)
        {
            uint v;
            return WasRefused(Native.hedge_split_edge(id, e.Raw, p.X, p.Y, p.Z, out v)) ? Vertex.Invalid : new Vertex(v);
        }

        public Vertex SplitEdge(Edge e, float x, float y, float z) { return SplitEdge(e, new Vec3(x, y, z)); }

        /// <summary>Merges the from-vertex of h into its to-vertex; the to-vertex survives and keeps its
        /// position.</summary>
        /// <returns>The surviving vertex, or <see cref="Vertex.Invalid"/> if <see cref="CanCollapse"/> refuses
        /// (the mesh is then unchanged).</returns>
        public Vertex Collapse(HalfEdge h)
        {
            uint v;
            return WasRefused(Native.hedge_collapse(id, h.Raw, out v)) ? Vertex.Invalid : new Vertex(v);
        }

        /// <summary>Turns the edge to join the opposite corners of its two triangles; the edge keeps its index.</summary>
        /// <returns>False if <see cref="CanFlip(Edge)"/> refuses.</returns>
        public bool Flip(Edge e) { return !WasRefused(Native.hedge_flip(id, e.Raw)); }

        public bool Flip(HalfEdge h) { return Flip(h.Edge); }

        /// <summary>Inserts a vertex at p into the face and joins it to every corner (an n-gon becomes n
        /// triangles).</summary>
        /// <returns>The new vertex, or <see cref="Vertex.Invalid"/> if refused.</returns>
        public Vertex SplitFace(Face f, Vec3 p)
        {
            uint v;
            return WasRefused(Native.hedge_split_face(id, f.Raw, p.X, p.Y, p.Z, out v)) ? Vertex.Invalid : new Vertex(v);
        }

        public Vertex SplitFace(Face f, float x, float y, float z) { return SplitFace(f, new Vec3(x, y, z)); }

        /// <summary>Cuts the face of h0 and h1 in two along a new edge (a diagonal) from the target of h0 to
        /// the target of h1; no vertex is added.</summary>
        /// <returns>The new half-edge from the target of h0 to the target of h1, or <see cref="HalfEdge.Invalid"/>
        /// if <see cref="CanCutFace"/> refuses.</returns>
        public HalfEdge CutFace(HalfEdge h0, HalfEdge h1)
        {
            uint h;
            return WasRefused(Native.hedge_cut_face(id, h0.Raw, h1.Raw, out h)) ? HalfEdge.Invalid : new HalfEdge(h);
        }

        /// <summary>Splits every live face at its centroid. Never refused.</summary>
        /// <param name="newVertices">Optional (null): receives the new vertices, one per face, in face order; it
        /// must hold at least <see cref="FaceCount"/> entries.</param>
        /// <returns>The number of new vertices.</returns>
        public int SplitAllFaces(Vertex[] newVertices = null)
        {
            return (int)Status.Checked(Native.hedge_mesh_split_all_faces(id, newVertices, Status.Capacity(newVertices),
                                                                     out uint count), count);
        }

        /// <summary>Adds a face with the first count corners (counter-clockwise).</summary>
        /// <returns>The new face, or <see cref="Face.Invalid"/> if <see cref="CanAddFace(Vertex[], int)"/> refuses.</returns>
        public Face AddFace(Vertex[] corners, int count)
        {
            CheckSpan(corners, count, "corners");
            uint f;
            return WasRefused(Native.hedge_add_face(id, corners, (uint)count, out f)) ? Face.Invalid : new Face(f);
        }

        public Face AddFace(Vertex[] corners) { return AddFace(corners, LengthOf(corners)); }

        public Face AddFace(Vertex a, Vertex b, Vertex c) { return AddFace(Triangle(a, b, c), 3); }

        /// <summary>Removes the face; edges and vertices it leaves unused go too.</summary>
        /// <returns>False if <see cref="CanRemoveFace"/> refuses.</returns>
        public bool RemoveFace(Face f) { return !WasRefused(Native.hedge_remove_face(id, f.Raw)); }

        /// <summary>Removes the vertex, its faces and whatever they leave unused.</summary>
        /// <returns>False if <see cref="CanRemoveVertex"/> refuses.</returns>
        public bool RemoveVertex(Vertex v) { return !WasRefused(Native.hedge_remove_vertex(id, v.Raw)); }

        /// <summary>Fills the boundary loop of h with triangles (shortest diagonals first).</summary>
        /// <param name="h">A boundary half-edge.</param>
        /// <param name="newFaces">Optional (null): receives the new faces; it must hold at least the loop length
        /// - 2 entries.</param>
        /// <returns>The number of new faces; 0 if <see cref="CanFillHole"/> refuses.</returns>
        public int FillHole(HalfEdge h, Face[] newFaces = null)
        {
            uint count;
            return WasRefused(Native.hedge_fill_hole(id, h.Raw, newFaces, Status.Capacity(newFaces), out count)) ? 0 : (int)count;
        }

        /// <summary>Moves the faces out of this mesh into a new mesh, with all their properties. Vertices the
        /// removal leaves pinched are split so both meshes stay manifold; repeated faces are ignored.</summary>
        /// <param name="faces">Live faces; the first count are used.</param>
        /// <param name="count">How many of faces.</param>
        /// <param name="vertexOrigin">Optional (null): receives new-mesh vertex -> vertex of this mesh. It must
        /// hold at least the total number of corners of the faces.</param>
        public HalfEdgeMesh DetachFaces(Face[] faces, int count, Vertex[] vertexOrigin = null)
        {
            CheckSpan(faces, count, "faces");
            uint originCount;
            IntPtr mesh;
            int status = Native.hedge_detach_faces(id, faces, (uint)count, vertexOrigin, Status.Capacity(vertexOrigin),
                                                   out originCount, out mesh);
            return Created(status, mesh);
        }

        public HalfEdgeMesh DetachFaces(Face[] faces)
        {
            if (faces == null) throw new ArgumentNullException("faces");
            return DetachFaces(faces, faces.Length);
        }

        // =========================================================================================
        // The original Unity project's names ("Half-Edge Mesh für Unity3D"), kept so that its users find
        // their way. Each forwards to the method named in its summary; docs/names.md maps every name.
        // SplitFace and SplitAllFaces keep the original's names as they are.
        // =========================================================================================

        /// <summary>The original's SplitHalfEdge: <see cref="SplitEdge(Edge, Vec3)"/> on the edge of h.</summary>
        public Vertex SplitHalfEdge(HalfEdge h, Vec3 p) { return SplitEdge(h.Edge, p); }

        /// <summary>The original's SplitHalfEdge: <see cref="SplitEdge(Edge, Vec3)"/> on the edge of h.</summary>
        public Vertex SplitHalfEdge(HalfEdge h, float x, float y, float z) { return SplitEdge(h.Edge, new Vec3(x, y, z)); }

        /// <summary>The original's EdgeCollapse: <see cref="Collapse"/>.</summary>
        public Vertex EdgeCollapse(HalfEdge h) { return Collapse(h); }

        /// <summary>The original's GenerateUnityMesh, made incremental: <see cref="CreateRenderBuffers(RenderOptions)"/>
        /// with <see cref="RenderOptions.Unity"/>. Sync the buffers after edits and upload the dirty ranges.</summary>
        public RenderBuffers GenerateUnityMesh() { return CreateRenderBuffers(RenderOptions.Unity); }

        /// <summary>Removes deleted elements and compacts storage; element indices change. Each map is optional
        /// (null) and receives old index -> new element (invalid for a removed one); it must hold at least the
        /// slot count of its kind before the call (<see cref="Counts"/>). Render buffers rebuild at their next
        /// sync.</summary>
        public void GarbageCollection(Vertex[] vertexMap = null, HalfEdge[] halfEdgeMap = null, Edge[] edgeMap = null,
                                      Face[] faceMap = null)
        {
            pendingRenders.Drain();
            Status.Check(Native.hedge_mesh_garbage_collection(id, vertexMap, Status.Capacity(vertexMap), halfEdgeMap,
                                                              Status.Capacity(halfEdgeMap), edgeMap, Status.Capacity(edgeMap),
                                                              faceMap, Status.Capacity(faceMap)));
        }

        // =========================================================================================
        // Validation
        // =========================================================================================

        /// <summary>Checks every invariant of the mesh. O(#elements).</summary>
        /// <returns>One line per broken invariant; empty when the mesh is valid.</returns>
        public string[] Validate()
        {
            uint count;
            Status.Check(Native.hedge_mesh_validate(id, out count));
            if (count == 0) return NoProblems;
            var problems = new string[count];
            for (uint i = 0; i < count; ++i)
            {
                uint size;
                int status = Native.hedge_mesh_validation_problem(id, i, null, 0, out size);
                if (status != Status.BufferTooSmall) Status.Check(status);
                var text = new byte[size];
                Status.Check(Native.hedge_mesh_validation_problem(id, i, text, size, out size));
                problems[i] = Status.FromUtf8(text);
            }
            GC.KeepAlive(this);
            return problems;
        }

        // =========================================================================================
        // Render buffers
        // =========================================================================================

        /// <summary>Makes engine-ready vertex and index buffers that follow this mesh's edits. Disposing the
        /// mesh disposes them too.</summary>
        public RenderBuffers CreateRenderBuffers(RenderOptions options)
        {
            pendingRenders.Drain();
            return new RenderBuffers(this, options);
        }

        /// <summary>Render buffers with the default options (interleaved, counter-clockwise).</summary>
        public RenderBuffers CreateRenderBuffers() { return CreateRenderBuffers(RenderOptions.Default); }


        public override string ToString()
        {
            return IsDisposed ? "HalfEdgeMesh (disposed)" : "HalfEdgeMesh: " + Counts;
        }
    }
}
