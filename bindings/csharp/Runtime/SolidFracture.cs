// Solid fracture from C#: a closed mesh struck at a point breaks into closed pieces, their cut faces
// capped in an inner submesh, with what a rigid body needs and the bond graph
// (hedge/algorithms/fracture_solid.h through hedge_mesh_fracture_solid). The options carry the
// rings inline (ByValArray), copied by the marshaller once per call.
using System;
using System.Runtime.InteropServices;

// The private fields of these structs are written by the native library only.
#pragma warning disable 0169, 0649

namespace Hedge
{
    /// <summary>Options of <see cref="HalfEdgeMesh.FractureSolid"/> (440 bytes, hedge_solid_fracture_options): the
    /// material's rings, the break radius in model units (or as a fraction of the object's size), the seed, and what
    /// each piece gets. Start from <see cref="Preset"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SolidFractureOptions
    {
        /// <summary>The rings, innermost first (the first <see cref="RingCount"/> are used), scaled so that the outer
        /// one lies at the break radius; each ring's points lie on a sphere about the impact.</summary>
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = FractureOptions.MaxRings)]
        public FractureRing[] Rings;
        /// <summary>Rings used, 1 to <see cref="FractureOptions.MaxRings"/>.</summary>
        public int RingCount;
        int hulls;
        /// <summary>The break radius in model units (metres in a game); 0: <see cref="RadiusFraction"/> of the
        /// diagonal of the mesh's bounding box.</summary>
        public double Radius;
        /// <summary>Used when <see cref="Radius"/> is 0: in (0, 10].</summary>
        public double RadiusFraction;
        /// <summary>Seed of the break points: the same seed gives the same pieces, bit for bit.</summary>
        public ulong Seed;
        /// <summary>Mass per unit volume.</summary>
        public double Density;
        /// <summary>Largest distance from the impact to the surface; 0: 1e-3 of the nearest face's longest edge.</summary>
        public double Tolerance;
        /// <summary>The submesh (face property "f:submesh") of the cap faces, for an inner material. -1 (the presets):
        /// one more than the mesh's largest submesh, or 1 when the mesh has none.</summary>
        public int InnerSubmesh;
        uint reserved;

        /// <summary>Compute each piece's convex hull.</summary>
        public bool Hulls { get { return hulls != 0; } set { hulls = value ? 1 : 0; } }

        /// <summary>A preset's rings with a break radius of a quarter of the bounding box's diagonal, seed 0, density
        /// 1, automatic tolerance, hulls on and the automatic inner submesh.</summary>
        public static SolidFractureOptions Preset(FracturePreset preset)
        {
            SolidFractureOptions o;
            Status.Check(Native.hedge_solid_fracture_options_default((int)preset, out o));
            return o;
        }

        /// <summary>These options with the break radius <paramref name="radius"/> model units.</summary>
        public SolidFractureOptions WithRadius(double radius)
        {
            SolidFractureOptions o = this;
            o.Radius = radius;
            return o;
        }
    }

    /// <summary>Two pieces that touch, or a piece and the remaining object (<see cref="B"/> is
    /// <see cref="Remaining"/>), sharing <see cref="Area"/> of cap: what a support structure (which pieces hold
    /// which) is built on. 16 bytes, hedge_solid_bond.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SolidBond
    {
        /// <summary>The value of <see cref="B"/> that names the remaining object (HEDGE_SOLID_REMAINING).</summary>
        public const uint Remaining = 0xFFFFFFFF;
        /// <summary>Index of a piece, less than <see cref="B"/>.</summary>
        public uint A;
        /// <summary>Index of a piece, or <see cref="Remaining"/>.</summary>
        public uint B;
        /// <summary>The shared cap area.</summary>
        public double Area;

        /// <summary>B is the remaining object.</summary>
        public bool ToRemaining { get { return B == Remaining; } }
    }

    /// <summary>One piece of <see cref="HalfEdgeMesh.FractureSolid"/>: its closed mesh and hull (each disposed with
    /// the piece), and what a rigid body needs, in the mesh's own coordinates.</summary>
    public sealed class SolidPiece : IDisposable
    {
        /// <summary>The closed piece: its outer faces keep their properties, its caps are in the options'
        /// <see cref="SolidFractureOptions.InnerSubmesh"/> (see <see cref="HalfEdgeMesh.CopyFaceSubmeshes"/>).</summary>
        public HalfEdgeMesh Mesh { get; internal set; }
        /// <summary>Its convex hull, or null (hulls off).</summary>
        public HalfEdgeMesh Hull { get; internal set; }
        /// <summary>Enclosed volume, positive.</summary>
        public double Volume { get; internal set; }
        /// <summary>Area of the cap (inner) faces.</summary>
        public double CapArea { get; internal set; }
        /// <summary>Mass at the options' density.</summary>
        public double Mass { get; internal set; }
        /// <summary>Centre of mass (uniform density).</summary>
        public double[] CentreOfMass { get; internal set; }
        /// <summary>Inertia tensor about the centre of mass, row-major 3 x 3.</summary>
        public double[] Inertia { get; internal set; }
        /// <summary>The eigenvalues of <see cref="Inertia"/>, ascending.</summary>
        public double[] PrincipalMoments { get; internal set; }
        /// <summary>Row i (elements 3i..3i+2): the unit axis of PrincipalMoments[i], a right-handed frame.</summary>
        public double[] PrincipalAxes { get; internal set; }
        /// <summary>0 empty, 1 point, 2 segment, 3 flat, 4 solid.</summary>
        public int HullDimension { get; internal set; }

        /// <summary>The rotation (x, y, z, w, a unit quaternion) that turns the coordinate axes into the principal
        /// axes, as <see cref="FractureShard.PrincipalRotation"/>.</summary>
        public double[] PrincipalRotation()
        {
            return new FractureShard { PrincipalAxes = PrincipalAxes, Closed = true, Mass = Mass }.PrincipalRotation();
        }

        public void Dispose()
        {
            if (Mesh != null) Mesh.Dispose();
            if (Hull != null) Hull.Dispose();
        }
    }

    /// <summary>What <see cref="HalfEdgeMesh.FractureSolid"/> returns: the pieces, in the order of their break
    /// points, and the bonds between them, sorted by (A, B). Disposing it disposes the pieces.</summary>
    public sealed class SolidFracture : IDisposable
    {
        public SolidPiece[] Pieces { get; internal set; }
        public SolidBond[] Bonds { get; internal set; }
        /// <summary>The impact moved onto the surface.</summary>
        public double[] ImpactPoint { get; internal set; }
        /// <summary>The break radius used, in model units.</summary>
        public double Radius { get; internal set; }

        public void Dispose()
        {
            if (Pieces == null) return;
            foreach (SolidPiece p in Pieces) p.Dispose();
        }
    }

    /// <summary>hedge_solid_piece as the C ABI lays it out (240 bytes).</summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct NativeSolidPiece
    {
        public IntPtr Mesh;
        public IntPtr Hull;
        public double Volume;
        public double CapArea;
        public double Mass;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)]
        public double[] CentreOfMass;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 9)]
        public double[] Inertia;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)]
        public double[] PrincipalMoments;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 9)]
        public double[] PrincipalAxes;
        public int HullDimension;
        uint reserved;
    }

    /// <summary>hedge_solid_fracture_summary (48 bytes).</summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct NativeSolidSummary
    {
        public uint PieceCount;
        public uint BondCount;
        public uint ImpactFace;
        uint reserved;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)]
        public double[] ImpactPoint;
        public double Radius;
    }

    internal static partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_solid_fracture_options_default(int preset, out SolidFractureOptions options);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_solid_fracture_refusal(IntPtr mesh, float x, float y, float z,
                                                                ref SolidFractureOptions options, byte[] buffer,
                                                                uint capacity, out uint size);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_fracture_solid(IntPtr mesh, float x, float y, float z,
                                                             ref SolidFractureOptions options, out IntPtr result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_solid_fracture_get_summary(IntPtr result, out NativeSolidSummary summary);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_solid_fracture_copy_pieces(IntPtr result, [Out] NativeSolidPiece[] pieces,
                                                                    uint capacity, out uint count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_solid_fracture_copy_bonds(IntPtr result, [Out] SolidBond[] bonds,
                                                                   uint capacity, out uint count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_solid_fracture_destroy(IntPtr result);
    }

    public sealed partial class HalfEdgeMesh
    {
        static void CheckRings(SolidFractureOptions options)
        {
            if (options.Rings == null || options.Rings.Length != FractureOptions.MaxRings)
                throw new ArgumentException("Rings must hold " + FractureOptions.MaxRings +
                                            " rings (start from SolidFractureOptions.Preset)", "options");
        }

        /// <summary>Why this mesh cannot be broken as a solid at the impact with these options, or "" when it can: a
        /// non-finite impact, no face within the tolerance, a mesh that is open (anywhere) or non-manifold near the impact, or an option
        /// out of range. Checks through the picking tree, which keeps whether the mesh is closed until it changes;
        /// changes nothing. <see cref="SolidFractureRefusalCode"/> gives it as a code, and
        /// <see cref="FractureSolidOrSurface"/> is "auto".</summary>
        public string SolidFractureRefusal(Vec3 impact, SolidFractureOptions options)
        {
            CheckRings(options);
            uint size;
            Native.hedge_solid_fracture_refusal(id, impact.X, impact.Y, impact.Z, ref options, null, 0, out size);
            var text = new byte[Math.Max(size, 1u)];
            Status.Check(Native.hedge_solid_fracture_refusal(id, impact.X, impact.Y, impact.Z, ref options, text,
                                                             (uint)text.Length, out size));
            return System.Text.Encoding.UTF8.GetString(text, 0, (int)Math.Max(size, 1u) - 1);
        }

        /// <summary>Breaks this closed mesh at the impact into closed pieces (hedge/algorithms/fracture_solid.h): Voronoi
        /// cells of break points within the break radius, each the part of the object inside it with its cut faces
        /// capped. This mesh becomes the remaining object, closed; render buffers see it at their next sync. What
        /// <see cref="SolidFractureRefusal"/> names: HedgeException (InvalidArgument), and the mesh is unchanged.
        /// Dispose the result (its pieces) when done.</summary>
        public SolidFracture FractureSolid(Vec3 impact, SolidFractureOptions options)
        {
            CheckRings(options);
            pendingRenders.Drain();
            IntPtr handle;
            Status.Check(Native.hedge_mesh_fracture_solid(id, impact.X, impact.Y, impact.Z, ref options, out handle));
            try
            {
                NativeSolidSummary s;
                Status.Check(Native.hedge_solid_fracture_get_summary(handle, out s));
                var native = new NativeSolidPiece[Math.Max(1u, s.PieceCount)];
                var bonds = new SolidBond[s.BondCount];
                uint n;
                Status.Check(Native.hedge_solid_fracture_copy_pieces(handle, native, s.PieceCount, out n));
                Status.Check(Native.hedge_solid_fracture_copy_bonds(handle, bonds, s.BondCount, out n));
                var pieces = new SolidPiece[s.PieceCount];
                for (int i = 0; i < pieces.Length; ++i)
                {
                    NativeSolidPiece p = native[i];
                    pieces[i] = new SolidPiece
                    {
                        Mesh = new HalfEdgeMesh(p.Mesh),
                        Hull = p.Hull != IntPtr.Zero ? new HalfEdgeMesh(p.Hull) : null,
                        Volume = p.Volume,
                        CapArea = p.CapArea,
                        Mass = p.Mass,
                        CentreOfMass = p.CentreOfMass,
                        Inertia = p.Inertia,
                        PrincipalMoments = p.PrincipalMoments,
                        PrincipalAxes = p.PrincipalAxes,
                        HullDimension = p.HullDimension,
                    };
                }
                return new SolidFracture { Pieces = pieces, Bonds = bonds, ImpactPoint = s.ImpactPoint, Radius = s.Radius };
            }
            finally
            {
                Native.hedge_solid_fracture_destroy(handle);
            }
        }

        /// <summary><see cref="FractureSolid"/> with a preset material, a break radius in model units and a seed.</summary>
        public SolidFracture FractureSolid(Vec3 impact, FracturePreset material, double radius, ulong seed)
        {
            SolidFractureOptions o = SolidFractureOptions.Preset(material).WithRadius(radius);
            o.Seed = seed;
            return FractureSolid(impact, o);
        }
    }
}
