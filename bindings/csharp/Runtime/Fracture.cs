// Fracture from C#: the options (a preset, a break radius as a fraction of the object's size or in
// model units, a thickness so that every shard is a solid with mass), the shards with what a
// rigid body needs, and HalfEdgeMesh.Fracture / SimulateBreaking. FractureOptions and the shard
// record carry fixed-size arrays (ByValArray), copied by the marshaller once per call.
using System;
using System.Runtime.InteropServices;

// The private fields of these structs are written by the native library only.
#pragma warning disable 0169, 0649

namespace Hedge
{
    /// <summary>The fracture presets (hedge_fracture_preset).</summary>
    public enum FracturePreset
    {
        /// <summary>Many small shards (40 break points).</summary>
        Glass = 0,
        /// <summary>Few large chunks (7 break points).</summary>
        Stone = 1,
        /// <summary>Splinters along the grain, x by default (18 break points).</summary>
        Wood = 2,
        /// <summary>26 break points.</summary>
        Ice = 3,
    }

    /// <summary>The units of <see cref="FractureOptions.Radius"/> (hedge_fracture_units).</summary>
    public enum FractureUnits
    {
        /// <summary>Mean edge lengths of the impact face: the same number of shards of the same number of faces on
        /// any mesh, a share of the object that shrinks as the mesh is refined.</summary>
        EdgeLengths = 0,
        /// <summary>Model units (metres in a game).</summary>
        Model = 1,
        /// <summary>A fraction of the diagonal of the mesh's bounding box (the presets): the same share of an object
        /// breaks whatever its size and resolution.</summary>
        DiagonalFraction = 2,
    }

    /// <summary>One ring of break points (24 bytes, hedge_fracture_ring).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FractureRing
    {
        /// <summary>Distance from the previous ring (the first: from the impact), greater than 0, in proportion:
        /// the spacings are scaled so that the outer ring lies at <see cref="FractureOptions.Radius"/>.</summary>
        public double Spacing;
        /// <summary>In [0, 1]: how far points stray from even angles and from the ring's radius.</summary>
        public double Jitter;
        /// <summary>Break points on the ring: 0 to 100000, and at most 10000 in all rings.</summary>
        public int Points;
        uint reserved;
    }

    /// <summary>Options of <see cref="HalfEdgeMesh.Fracture"/> (488 bytes, hedge_fracture_options): the material's rings
    /// and grain, its break radius, the seed, and what each shard gets. Start from <see cref="Preset"/> (a break
    /// radius as a fraction of the object's size); give it in model units with <see cref="WithBreakRadius"/>, or
    /// another fraction with <see cref="WithBreakRadiusFraction(double)"/>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct FractureOptions
    {
        /// <summary>Most rings (HEDGE_FRACTURE_MAX_RINGS).</summary>
        public const int MaxRings = 16;
        /// <summary>The thickness <see cref="Preset"/> gives, as a fraction of the break radius
        /// (<see cref="RelativeThickness"/>): 5%, so that every shard is a solid with mass, ready for a rigid
        /// body.</summary>
        public const double GameRelativeThickness = 0.05;
        /// <summary>The rings, innermost first; the first <see cref="RingCount"/> are used.</summary>
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = MaxRings)]
        public FractureRing[] Rings;
        /// <summary>Rings used, 0 to <see cref="MaxRings"/>.</summary>
        public int RingCount;
        /// <summary>The units of <see cref="Radius"/>; the presets: <see cref="FractureUnits.DiagonalFraction"/>.</summary>
        public FractureUnits Units;
        /// <summary>Grain direction, nonzero when <see cref="GrainStretch"/> is greater than 1.</summary>
        public Vec3 Grain;
        uint reserved;
        /// <summary>1 or more: cells this many times longer along the grain.</summary>
        public double GrainStretch;
        /// <summary>Longest edge left in the broken area (in the units of the spacings, so in proportion to the
        /// radius).</summary>
        public double RefineEdge;
        /// <summary>Seed of the break points: the same seed gives the same shards, bit for bit.</summary>
        public ulong Seed;
        double thickness;
        /// <summary>Mass per unit volume.</summary>
        public double Density;
        /// <summary>Largest distance from the impact to the surface; 0: 1e-3 of the nearest face's longest edge.</summary>
        public double Tolerance;
        int hulls;
        /// <summary>With a thickness, the submesh (face property "f:submesh") of the faces the solid adds: the back
        /// and the side walls, the shard's new cut faces, for an inner material. -1 (the presets): one more than the
        /// mesh's largest submesh, or 1 when the mesh has none. The broken faces keep theirs (0 when none).</summary>
        public int InnerSubmesh;
        double relativeThickness;
        /// <summary>The break radius (the outer ring's distance from the impact) in <see cref="Units"/>, greater than
        /// 0. The presets: 0.13 (glass), 0.14 (stone), 0.11 (wood, ice) of the diagonal.</summary>
        public double Radius;
        /// <summary>0 or more: an open shard (no thickness) gets the mass properties of a thin shell this thick (model
        /// units); 0: a twentieth of the break radius.</summary>
        public double ShellThickness;

        /// <summary>Greater than 0: each shard is extruded into a closed solid this thick (model units), at most 10
        /// times the diagonal of the mesh's bounding box. Setting it above 0 clears <see cref="RelativeThickness"/>;
        /// 0 and a relative thickness of 0: open shards, weighed as thin shells (<see cref="ShellThickness"/>).</summary>
        public double Thickness
        {
            get { return thickness; }
            set { thickness = value; if (value > 0) relativeThickness = 0; }
        }

        /// <summary>In [0, 1]; greater than 0: the thickness as this fraction of the strike's break radius in model
        /// units, so small and large breaks get solids of
        /// the same proportion, at a cost that does not grow with the mesh. <see cref="Preset"/> sets <see cref="GameRelativeThickness"/>. Setting it above 0 clears
        /// <see cref="Thickness"/>.</summary>
        public double RelativeThickness
        {
            get { return relativeThickness; }
            set { relativeThickness = value; if (value > 0) thickness = 0; }
        }

        /// <summary>Compute each shard's convex hull.</summary>
        public bool Hulls { get { return hulls != 0; } set { hulls = value ? 1 : 0; } }

        /// <summary>The break points of the rings used: the most shards an impact can give.</summary>
        public int TotalPoints
        {
            get
            {
                int n = 0;
                for (int i = 0; Rings != null && i < RingCount && i < Rings.Length; ++i) n += (int)Rings[i].Points;
                return n;
            }
        }

        /// <summary>The break radius in <see cref="Units"/>: <see cref="Radius"/>.</summary>
        public double BreakRadius { get { return Radius; } }

        /// <summary>A preset with seed 0, density 1, automatic tolerance, hulls on, the automatic inner submesh and a
        /// thickness of <see cref="GameRelativeThickness"/> of the break radius, so that every shard is a closed
        /// solid with mass. Its break radius is a fraction of the diagonal of the object's bounding box, so a strike
        /// breaks the same share of the object at any size and mesh resolution; give it in model units with
        /// <see cref="WithBreakRadius"/>.</summary>
        public static FractureOptions Preset(FracturePreset preset)
        {
            FractureOptions o;
            Status.Check(Native.hedge_fracture_options_default((int)preset, out o));
            o.relativeThickness = GameRelativeThickness;
            return o;
        }

        /// <summary>These options with the outer ring <paramref name="radius"/> model units (metres in a game) from
        /// the impact: <see cref="Units"/> <see cref="FractureUnits.Model"/>, <see cref="Radius"/> radius, each
        /// spacing and <see cref="RefineEdge"/> scaled to read in model units (hedge_fracture_options_at_radius).
        /// These options are not changed.</summary>
        /// <exception cref="HedgeException">InvalidArgument for a radius that is not finite and positive, or no
        /// ring.</exception>
        public FractureOptions WithBreakRadius(double radius)
        {
            FractureOptions o = this;
            o.Rings = Rings != null ? (FractureRing[])Rings.Clone() : null;
            if (o.Rings == null || o.Rings.Length != MaxRings)
                throw new ArgumentException("Rings must hold " + MaxRings + " rings (start from FractureOptions.Preset)");
            Status.Check(Native.hedge_fracture_options_at_radius(ref o, radius));
            return o;
        }

        /// <summary>These options with a break radius of <paramref name="fraction"/> times the diagonal of the
        /// struck mesh's bounding box (<see cref="FractureUnits.DiagonalFraction"/>): 0.1 breaks a tenth of the
        /// object's size around the impact, whatever its scale or resolution. The library takes the diagonal from
        /// the mesh's picking tree at each strike, without a pass over the mesh. These options are not
        /// changed.</summary>
        /// <exception cref="ArgumentOutOfRangeException">A fraction that is not finite and positive.</exception>
        public FractureOptions WithBreakRadiusFraction(double fraction)
        {
            if (!(fraction > 0) || double.IsInfinity(fraction))
                throw new ArgumentOutOfRangeException("fraction", fraction, "a fraction of the object's size must be finite and positive");
            FractureOptions o = this;
            o.Rings = Rings != null ? (FractureRing[])Rings.Clone() : null;
            o.Units = FractureUnits.DiagonalFraction;
            o.Radius = fraction;
            return o;
        }

        /// <summary><see cref="WithBreakRadiusFraction(double)"/>; the mesh is no longer needed (the library takes
        /// the diagonal of the struck mesh itself).</summary>
        [Obsolete("use WithBreakRadiusFraction(fraction): the library takes the diagonal of the struck mesh")]
        public FractureOptions WithBreakRadiusFraction(HalfEdgeMesh mesh, double fraction)
        {
            if (mesh == null) throw new ArgumentNullException("mesh");
            return WithBreakRadiusFraction(fraction);
        }
    }

    /// <summary>One shard of <see cref="HalfEdgeMesh.Fracture"/>: its mesh and hull (each disposed with the shard),
    /// and what a rigid body needs. Its mass properties are in the mesh's own coordinates.</summary>
    public sealed class FractureShard : IDisposable
    {
        /// <summary>The shard's faces with their properties (a closed solid with a thickness, its added faces in the
        /// options' <see cref="FractureOptions.InnerSubmesh"/>).</summary>
        public HalfEdgeMesh Mesh { get; internal set; }
        /// <summary>Its convex hull, or null (hulls off, or all its points on one line).</summary>
        public HalfEdgeMesh Hull { get; internal set; }
        /// <summary>Area-weighted centroid of the broken faces.</summary>
        public double[] Centroid { get; internal set; }
        /// <summary>Area of the broken faces.</summary>
        public double Area { get; internal set; }
        /// <summary>Volume of the solid when closed; when open, of the thin shell it is weighed as (area x the
        /// options' <see cref="FractureOptions.ShellThickness"/>, or its automatic value).</summary>
        public double Volume { get; internal set; }
        /// <summary>Mass at the density, of the solid or the shell; 0 only for a shard without area.</summary>
        public double Mass { get; internal set; }
        /// <summary>Centre of mass, of the solid or the shell.</summary>
        public double[] CentreOfMass { get; internal set; }
        /// <summary>Inertia tensor about the centre of mass, row-major 3 x 3, of the solid or the shell.</summary>
        public double[] Inertia { get; internal set; }
        /// <summary>The eigenvalues of <see cref="Inertia"/>, ascending (zero with no mass): a rigid body's principal
        /// moments.</summary>
        public double[] PrincipalMoments { get; internal set; }
        /// <summary>Row i (elements 3i..3i+2): the unit axis of PrincipalMoments[i], a right-handed frame; zero with
        /// no mass.</summary>
        public double[] PrincipalAxes { get; internal set; }
        /// <summary>The mesh has no boundary.</summary>
        public bool Closed { get; internal set; }
        /// <summary>0 empty, 1 point, 2 segment, 3 flat (a thin prism), 4 solid.</summary>
        public int HullDimension { get; internal set; }

        /// <summary>The rotation (x, y, z, w, a unit quaternion) that turns the coordinate axes into the principal
        /// axes: with R its matrix, Inertia = R diag(PrincipalMoments) R^T. What a physics engine takes as the
        /// inertia tensor's rotation. The identity with no mass.</summary>
        public double[] PrincipalRotation()
        {
            double[] a = PrincipalAxes;
            if (a == null || !(Mass > 0)) return new double[] { 0, 0, 0, 1 };
            // R's columns are the axes: R[r, c] = a[3c + r].
            double m00 = a[0], m11 = a[4], m22 = a[8];
            double m01 = a[3], m10 = a[1], m02 = a[6], m20 = a[2], m12 = a[7], m21 = a[5];
            double x, y, z, w, trace = m00 + m11 + m22;
            if (trace > 0)
            {
                double s = 2 * Math.Sqrt(trace + 1);
                w = s / 4; x = (m21 - m12) / s; y = (m02 - m20) / s; z = (m10 - m01) / s;
            }
            else if (m00 > m11 && m00 > m22)
            {
                double s = 2 * Math.Sqrt(1 + m00 - m11 - m22);
                w = (m21 - m12) / s; x = s / 4; y = (m01 + m10) / s; z = (m02 + m20) / s;
            }
            else if (m11 > m22)
            {
                double s = 2 * Math.Sqrt(1 + m11 - m00 - m22);
                w = (m02 - m20) / s; x = (m01 + m10) / s; y = s / 4; z = (m12 + m21) / s;
            }
            else
            {
                double s = 2 * Math.Sqrt(1 + m22 - m00 - m11);
                w = (m10 - m01) / s; x = (m02 + m20) / s; y = (m12 + m21) / s; z = s / 4;
            }
            double n = Math.Sqrt(x * x + y * y + z * z + w * w);
            return new[] { x / n, y / n, z / n, w / n };
        }

        public void Dispose()
        {
            if (Mesh != null) Mesh.Dispose();
            if (Hull != null) Hull.Dispose();
        }
    }

    /// <summary>hedge_fracture_shard as the C ABI lays it out (264 bytes).</summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct NativeFractureShard
    {
        public IntPtr Mesh;
        public IntPtr Hull;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)]
        public double[] Centroid;
        public double Area;
        public double Volume;
        public double Mass;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)]
        public double[] CentreOfMass;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 9)]
        public double[] Inertia;
        public int Closed;
        public int HullDimension;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 3)]
        public double[] PrincipalMoments;
        [MarshalAs(UnmanagedType.ByValArray, SizeConst = 9)]
        public double[] PrincipalAxes;
    }

    public sealed partial class HalfEdgeMesh
    {
        /// <summary>Breaks the mesh at the impact into shards (hedge/algorithms/fracture.h): break points in rings
        /// around the impact, Voronoi-like cells of faces around them on the surface, each cell a new mesh with its
        /// properties, its hull and mass properties. The broken faces leave this mesh; render buffers see it at their
        /// next sync. No face within the tolerance, a non-finite impact or options out of range: HedgeException
        /// (InvalidArgument), and the mesh is unchanged. Dispose the shards (their meshes) when done.</summary>
        public FractureShard[] Fracture(Vec3 impact, FractureOptions options)
        {
            if (options.Rings == null || options.Rings.Length != FractureOptions.MaxRings)
                throw new ArgumentException("Rings must hold " + FractureOptions.MaxRings + " rings (start from FractureOptions.Preset)",
                                            "options");
            pendingRenders.Drain();
            var native = new NativeFractureShard[Math.Max(1, options.TotalPoints)];
            uint count;
            Status.Check(Native.hedge_mesh_fracture(id, impact.X, impact.Y, impact.Z, ref options, native,
                                                    (uint)options.TotalPoints, out count));
            var shards = new FractureShard[count];
            for (int i = 0; i < shards.Length; ++i)
            {
                NativeFractureShard n = native[i];
                shards[i] = new FractureShard
                {
                    Mesh = new HalfEdgeMesh(n.Mesh),
                    Hull = n.Hull != IntPtr.Zero ? new HalfEdgeMesh(n.Hull) : null,
                    Centroid = n.Centroid,
                    Area = n.Area,
                    Volume = n.Volume,
                    Mass = n.Mass,
                    CentreOfMass = n.CentreOfMass,
                    Inertia = n.Inertia,
                    PrincipalMoments = n.PrincipalMoments,
                    PrincipalAxes = n.PrincipalAxes,
                    Closed = n.Closed != 0,
                    HullDimension = n.HullDimension,
                };
            }
            return shards;
        }

        /// <summary>The original's SimulateBreaking, on any surface and repeatable: <see cref="Fracture"/> with a
        /// preset material (<see cref="FractureOptions.Preset"/>: its break radius a fraction of the object's size,
        /// each shard a solid <see cref="FractureOptions.GameRelativeThickness"/> of the break radius thick) and a
        /// seed.
        /// Returns the shards, each a mesh ready for engine buffers (<see cref="CreateRenderBuffers(RenderOptions)"/>)
        /// with its convex hull and mass properties for a rigid body.</summary>
        public FractureShard[] SimulateBreaking(Vec3 impactPoint, FracturePreset material, ulong seed)
        {
            FractureOptions o = FractureOptions.Preset(material);
            o.Seed = seed;
            return Fracture(impactPoint, o);
        }

        /// <summary><see cref="SimulateBreaking(Vec3, FracturePreset, ulong)"/> with the outer ring
        /// <paramref name="breakRadius"/> model units (metres in a game) from the impact
        /// (<see cref="FractureOptions.WithBreakRadius"/>): the same share of the object breaks at any mesh
        /// resolution.</summary>
        public FractureShard[] SimulateBreaking(Vec3 impactPoint, FracturePreset material, double breakRadius, ulong seed)
        {
            FractureOptions o = FractureOptions.Preset(material).WithBreakRadius(breakRadius);
            o.Seed = seed;
            return Fracture(impactPoint, o);
        }

        /// <summary>Copies each face slot's submesh (the face property "f:submesh"; 0 for every slot of a mesh
        /// without one) into buffer. A shard with a thickness has one: its added faces in the options'
        /// <see cref="FractureOptions.InnerSubmesh"/>.</summary>
        /// <returns>The face slots (the length needed); with a null buffer, only that.</returns>
        /// <exception cref="HedgeException">BufferTooSmall if buffer holds fewer; nothing is written.</exception>
        public int CopyFaceSubmeshes(int[] buffer)
        {
            ulong count;
            int status = Native.hedge_mesh_copy_face_submeshes(id, buffer, buffer != null ? (ulong)buffer.Length : 0,
                                                               out count);
            return Filled(status, buffer, count);
        }
    }
}
