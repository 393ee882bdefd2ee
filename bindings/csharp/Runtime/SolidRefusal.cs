// Why a strike cannot be a solid fracture, as a code (hedge_solid_fracture_refusal_code), and
// "auto": solid fracture where the mesh encloses a solid, surface fracture where its shape does not
// (open or non-manifold), the one rule of every binding and the CLI (hedge/algorithms/fracture_solid.h,
// solid_refusal_falls_back()).
using System;
using System.Runtime.InteropServices;

namespace Hedge
{
    /// <summary>Why a strike cannot be a solid fracture: the C ABI's HEDGE_SOLID_REFUSAL_* in PascalCase, value for
    /// value. Each keeps its value in every later release.</summary>
    public enum SolidRefusal
    {
        /// <summary>Not refused.</summary>
        None = 0,
        /// <summary>The mesh is open (anywhere, or near the impact): "auto" breaks it by surface fracture.</summary>
        Open = 1,
        /// <summary>A vertex near the impact joins several fans of faces: "auto" breaks it by surface fracture.</summary>
        NonManifold = 2,
        /// <summary>An illegal option or material.</summary>
        BadOption = 3,
        /// <summary>The impact is not finite.</summary>
        BadImpact = 4,
        /// <summary>No face lies within the tolerance of the impact.</summary>
        OffSurface = 5,
        /// <summary>The mesh has no face.</summary>
        NoFace = 6,
        /// <summary>The break radius is not positive (a mesh of zero size).</summary>
        BadRadius = 7,
        /// <summary>A picking tree of another mesh (the C++ library only).</summary>
        ForeignTree = 8,
    }

    /// <summary>The "auto" rule.</summary>
    public static class SolidRefusals
    {
        /// <summary>True for the refusals about the input's shape, <see cref="SolidRefusal.Open"/> and
        /// <see cref="SolidRefusal.NonManifold"/>, which "auto" breaks by surface fracture instead; any other
        /// refusal is an error with "auto" too.</summary>
        public static bool FallsBackToSurface(SolidRefusal code)
        {
            return code == SolidRefusal.Open || code == SolidRefusal.NonManifold;
        }
    }

    /// <summary>What <see cref="HalfEdgeMesh.FractureSolidOrSurface"/> returns: the solid fracture, or the shards of
    /// the surface fracture it fell back to and why. Disposing it disposes the pieces or the shards.</summary>
    public sealed class AutoFracture : IDisposable
    {
        /// <summary>The pieces and bonds of the solid fracture; null when it fell back.</summary>
        public SolidFracture Solid { get; internal set; }
        /// <summary>The shards of the surface fracture; null for a solid fracture.</summary>
        public FractureShard[] Shards { get; internal set; }
        /// <summary>Why solid fracture was refused: <see cref="SolidRefusal.Open"/> or
        /// <see cref="SolidRefusal.NonManifold"/> with shards, <see cref="SolidRefusal.None"/> with a solid.</summary>
        public SolidRefusal Refusal { get; internal set; }
        /// <summary>The refusal's text ("the mesh is open: edge ..."), "" for a solid fracture.</summary>
        public string Why { get; internal set; }

        public void Dispose()
        {
            if (Solid != null) Solid.Dispose();
            if (Shards != null)
                foreach (FractureShard s in Shards) s.Dispose();
        }
    }

    internal static partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_solid_fracture_refusal_code(IntPtr mesh, float x, float y, float z,
                                                                     ref SolidFractureOptions options, out int code);
    }

    public sealed partial class HalfEdgeMesh
    {
        /// <summary><see cref="SolidFractureRefusal"/>'s answer as a code: <see cref="SolidRefusal.None"/> when the
        /// strike can be made. Changes nothing; allocates nothing.</summary>
        public SolidRefusal SolidFractureRefusalCode(Vec3 impact, SolidFractureOptions options)
        {
            CheckRings(options);
            int code;
            Status.Check(Native.hedge_solid_fracture_refusal_code(id, impact.X, impact.Y, impact.Z, ref options,
                                                                  out code));
            return (SolidRefusal)code;
        }

        /// <summary>"auto": breaks this mesh as a solid (<see cref="FractureSolid(Vec3, SolidFractureOptions)"/>), or,
        /// where solid fracture is refused for the mesh's shape (<see cref="SolidRefusals.FallsBackToSurface"/>: open
        /// or non-manifold), by surface fracture with <paramref name="surface"/> (<see cref="Fracture"/>). Any other
        /// refusal (a bad option or impact) throws HedgeException (InvalidArgument), as
        /// <see cref="FractureSolid(Vec3, SolidFractureOptions)"/> does, and the mesh is unchanged.</summary>
        public AutoFracture FractureSolidOrSurface(Vec3 impact, SolidFractureOptions options, FractureOptions surface)
        {
            SolidRefusal code = SolidFractureRefusalCode(impact, options);
            if (!SolidRefusals.FallsBackToSurface(code))
                return new AutoFracture { Solid = FractureSolid(impact, options), Refusal = SolidRefusal.None, Why = "" };
            string why = SolidFractureRefusal(impact, options);
            return new AutoFracture { Shards = Fracture(impact, surface), Refusal = code, Why = why };
        }
    }
}
