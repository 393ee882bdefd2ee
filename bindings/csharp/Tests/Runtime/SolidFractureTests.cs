// Solid fracture from C# (Runtime/SolidFracture.cs): spot struck breaks into closed pieces whose
// volumes add up, their caps in the inner submesh, with the bond graph; the same strike gives the
// same pieces; an open mesh and a NaN impact are refused with the mesh unchanged, with their codes; "auto"
// falls back to surface fracture for an open mesh only.
using System;

namespace Hedge.Tests
{
    public static class SolidFractureTests
    {
        static HalfEdgeMesh Spot() { return HalfEdgeMesh.Read(Context.Data("spot_triangulated.obj")); }

        static SolidFractureOptions Stone(ulong seed)
        {
            SolidFractureOptions o = SolidFractureOptions.Preset(FracturePreset.Stone).WithRadius(0.3);
            o.Seed = seed;
            o.Tolerance = 10;
            o.InnerSubmesh = 5;
            return o;
        }

        [Test]
        static void SpotBreaksIntoClosedPiecesWithBonds()
        {
            using (HalfEdgeMesh spot = Spot())
            {
                double before = spot.Geometry.Volume;
                Check.Equal("", spot.SolidFractureRefusal(new Vec3(0, 0, 0), Stone(7)));
                using (SolidFracture r = spot.FractureSolid(new Vec3(0, 0, 0), Stone(7)))
                {
                    Check.True(r.Pieces.Length >= 2, "pieces: " + r.Pieces.Length);
                    Check.Equal(0.3, r.Radius);
                    Check.True(spot.Geometry.Closed, "the remaining object is closed");
                    Check.Valid(spot);
                    double total = spot.Geometry.Volume;
                    var bonded = new double[r.Pieces.Length];
                    for (int k = 0; k < r.Bonds.Length; ++k)
                    {
                        SolidBond b = r.Bonds[k];
                        Check.True(b.A < r.Pieces.Length && b.Area > 0, "bond " + k);
                        Check.True(b.ToRemaining || (b.A < b.B && b.B < r.Pieces.Length), "bond " + k + "'s ends");
                        bonded[b.A] += b.Area;
                        if (!b.ToRemaining) bonded[b.B] += b.Area;
                    }
                    for (int i = 0; i < r.Pieces.Length; ++i)
                    {
                        SolidPiece p = r.Pieces[i];
                        MeshGeometry g = p.Mesh.Geometry;
                        Check.True(g.Closed, "piece " + i + " is closed");
                        Check.Valid(p.Mesh);
                        Check.Near(g.Volume, p.Volume, 1e-9 * p.Volume, "piece " + i + "'s volume");
                        Check.Near(p.Volume, p.Mass, 1e-12, "density 1");
                        Check.True(p.CapArea > 0 && p.Hull != null && p.HullDimension == 4, "piece " + i);
                        Check.Near(p.CapArea, bonded[i], 1e-3 * p.CapArea, "piece " + i + "'s bonds cover its caps");
                        double[] q = p.PrincipalRotation();
                        Check.Near(1, q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1e-9, "a unit quaternion");
                        var submeshes = new int[p.Mesh.CopyFaceSubmeshes(null)];
                        p.Mesh.CopyFaceSubmeshes(submeshes);
                        Check.True(Array.IndexOf(submeshes, 5) >= 0, "piece " + i + " has caps in submesh 5");
                        total += p.Volume;
                    }
                    Check.Near(before, total, 1e-6 * before, "the volumes add up");
                }
            }
        }

        [Test]
        static void TheSameStrikeGivesTheSamePieces()
        {
            SolidFractureOptions o = SolidFractureOptions.Preset(FracturePreset.Glass).WithRadius(0.3);
            o.Seed = 11;
            o.Tolerance = 10;
            using (HalfEdgeMesh a = Spot())
            using (HalfEdgeMesh b = Spot())
            using (SolidFracture ra = a.FractureSolid(new Vec3(0, 0, 0), o))
            using (SolidFracture rb = b.FractureSolid(new Vec3(0, 0, 0), o))
            {
                Check.True(ra.Pieces.Length >= 10, "glass pieces: " + ra.Pieces.Length);
                Check.Equal(ra.Pieces.Length, rb.Pieces.Length);
                Check.Equal(ra.Bonds.Length, rb.Bonds.Length);
                for (int i = 0; i < ra.Pieces.Length; ++i) Check.Equal(ra.Pieces[i].Volume, rb.Pieces[i].Volume);
                for (int k = 0; k < ra.Bonds.Length; ++k) Check.Equal(ra.Bonds[k].Area, rb.Bonds[k].Area);
                // The short form, at a point of the surface (the default tolerance is small).
                double[] p = ra.ImpactPoint;
                using (HalfEdgeMesh c = Spot())
                using (SolidFracture rc = c.FractureSolid(new Vec3((float)p[0], (float)p[1], (float)p[2]),
                                                          FracturePreset.Stone, 0.2, 3))
                {
                    Check.True(rc.Pieces.Length >= 1 && rc.Radius == 0.2, "stone pieces: " + rc.Pieces.Length);
                    Check.Valid(c);
                }
            }
        }

        [Test]
        static void AnOpenMeshOrANaNImpactIsRefusedAndNothingChanges()
        {
            using (HalfEdgeMesh plate = Meshes.Plate(4))
            {
                MeshCounts c = plate.Counts;
                SolidFractureOptions o = Stone(1).WithRadius(3);
                Check.Contains(plate.SolidFractureRefusal(new Vec3(2, 2, 0), o), "the mesh is open: edge");
                HedgeException e = Check.Throws(HedgeStatus.InvalidArgument, () => plate.FractureSolid(new Vec3(2, 2, 0), o));
                Check.Contains(e.Message, "the mesh is open: edge");
                Check.Equal(c.Faces, plate.Counts.Faces);
                Check.Valid(plate);
            }
            using (HalfEdgeMesh spot = Spot())
            {
                double before = spot.Geometry.Volume;
                Check.Contains(spot.SolidFractureRefusal(new Vec3(float.NaN, 0, 0), Stone(1)), "finite");
                Check.Throws(HedgeStatus.InvalidArgument, () => spot.FractureSolid(new Vec3(float.NaN, 0, 0), Stone(1)));
                SolidFractureOptions bad = Stone(1);
                bad.Density = -1;
                Check.Contains(spot.SolidFractureRefusal(new Vec3(0, 0, 0), bad), "density");
                Check.Equal(SolidRefusal.BadOption, spot.SolidFractureRefusalCode(new Vec3(0, 0, 0), bad));
                Check.Equal(SolidRefusal.BadImpact, spot.SolidFractureRefusalCode(new Vec3(float.NaN, 0, 0), Stone(1)));
                Check.Equal(before, spot.Geometry.Volume);
                Check.Valid(spot);
            }
        }

        // "auto" falls back to surface fracture for the mesh's shape only: the open plate breaks into shards, the
        // closed spot into pieces, and an impact off the plate's surface is the solid fracture's error.
        [Test]
        static void AutoFallsBackForAnOpenMeshOnly()
        {
            FractureOptions surface = FractureOptions.Preset(FracturePreset.Glass).WithBreakRadius(1.5);
            using (HalfEdgeMesh plate = Meshes.Plate(4))
            {
                SolidFractureOptions o = Stone(1).WithRadius(3);
                Check.Equal(SolidRefusal.Open, plate.SolidFractureRefusalCode(new Vec3(2, 2, 0), o));
                Check.True(SolidRefusals.FallsBackToSurface(SolidRefusal.Open), "open falls back");
                Check.True(SolidRefusals.FallsBackToSurface(SolidRefusal.NonManifold), "non-manifold falls back");
                Check.True(!SolidRefusals.FallsBackToSurface(SolidRefusal.OffSurface), "off the surface does not");
                Check.True(!SolidRefusals.FallsBackToSurface(SolidRefusal.None), "none does not");
                MeshCounts c = plate.Counts;
                Check.Equal(SolidRefusal.OffSurface, plate.SolidFractureRefusalCode(new Vec3(2, 2, 50), o));
                HedgeException e = Check.Throws(HedgeStatus.InvalidArgument,
                                                () => plate.FractureSolidOrSurface(new Vec3(2, 2, 50), o, surface));
                Check.Contains(e.Message, "fracture_solid: the impact");
                Check.Equal(c.Faces, plate.Counts.Faces);
                using (AutoFracture a = plate.FractureSolidOrSurface(new Vec3(2, 2, 0), o, surface))
                {
                    Check.Equal(SolidRefusal.Open, a.Refusal);
                    Check.Contains(a.Why, "the mesh is open: edge");
                    Check.True(a.Solid == null && a.Shards != null && a.Shards.Length > 0, "shards");
                }
                Check.Valid(plate);
            }
            using (HalfEdgeMesh spot = Spot())
            {
                Check.Equal(SolidRefusal.None, spot.SolidFractureRefusalCode(new Vec3(0, 0, 0), Stone(2)));
                using (AutoFracture a = spot.FractureSolidOrSurface(new Vec3(0, 0, 0), Stone(2), surface))
                {
                    Check.Equal(SolidRefusal.None, a.Refusal);
                    Check.Equal("", a.Why);
                    Check.True(a.Shards == null && a.Solid != null && a.Solid.Pieces.Length > 0, "pieces");
                }
                Check.Valid(spot);
            }
        }
    }
}
