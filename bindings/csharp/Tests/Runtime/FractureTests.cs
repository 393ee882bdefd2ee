// Fracture from C# as a game uses it (Runtime/Fracture.cs): a break radius in model units or as a
// fraction of the object's size, a thickness by default so that every shard has mass, the shards'
// inner faces in a submesh of their own, and the principal frame of each shard's inertia.
using System;

namespace Hedge.Tests
{
    public static class FractureTests
    {
        // A 10 x 10 plate of n x n unit-free squares (each cut into two triangles).
        static HalfEdgeMesh Pane(int n)
        {
            var positions = new float[3 * (n + 1) * (n + 1)];
            for (int j = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i)
                {
                    int v = j * (n + 1) + i;
                    positions[3 * v] = 10f * i / n;
                    positions[3 * v + 1] = 10f * j / n;
                }
            var triangles = new int[6 * n * n];
            int k = 0;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i)
                {
                    int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
                    foreach (int v in new[] { a, b, c, a, c, d }) triangles[k++] = v;
                }
            return HalfEdgeMesh.FromTriangles(positions, triangles);
        }

        // The share of the pane's area that one strike breaks off.
        static double BrokenShare(int n, Func<HalfEdgeMesh, FractureOptions> options)
        {
            using (HalfEdgeMesh pane = Pane(n))
            {
                double before = pane.Geometry.Area, broken = 0;
                FractureShard[] shards = pane.Fracture(new Vec3(5.03f, 4.98f, 0), options(pane));
                foreach (FractureShard s in shards)
                {
                    broken += s.Area;
                    s.Dispose();
                }
                Check.Valid(pane);
                return broken / before;
            }
        }

        // A break radius in edge lengths breaks a quarter of the share each time the resolution doubles (7.4%,
        // 1.6%, 0.4% at Loop x0, x1, x2); a preset as it is (a fraction of the object's size) or a break radius in
        // model units breaks the same share at every resolution.
        [Test]
        static void ABreakRadiusBreaksTheSameShareAtEveryResolution()
        {
            Func<HalfEdgeMesh, FractureOptions> edges = m =>
            {
                FractureOptions o = FractureOptions.Preset(FracturePreset.Glass);
                o.Units = FractureUnits.EdgeLengths;
                o.Radius = 7;
                return o;
            };
            Check.True(BrokenShare(80, edges) < BrokenShare(20, edges) / 8, "a share in edge lengths shrinks with the edges");
            Func<HalfEdgeMesh, FractureOptions> preset = m => FractureOptions.Preset(FracturePreset.Glass);
            double coarse = BrokenShare(20, preset), fine = BrokenShare(80, preset);
            Check.True(Math.Abs(fine - coarse) < 0.1 * coarse, "a preset breaks the same share: " + coarse + ", " + fine);
            Func<HalfEdgeMesh, FractureOptions> metres = m => FractureOptions.Preset(FracturePreset.Glass).WithBreakRadius(2);
            Func<HalfEdgeMesh, FractureOptions> fraction =
                m => FractureOptions.Preset(FracturePreset.Glass).WithBreakRadiusFraction(2 / Math.Sqrt(200));
            foreach (int n in new[] { 10, 20, 80 })
                foreach (Func<HalfEdgeMesh, FractureOptions> o in new[] { metres, fraction })
                {
                    double share = BrokenShare(n, o);
                    // The broken area reaches the outer ring plus half its spacing: about pi (2.34)^2 of 100.
                    Check.True(share > 0.12 && share < 0.24, "share at " + n + ": " + share);
                }
        }

        [Test]
        static void WithBreakRadiusScalesACopy()
        {
            FractureOptions preset = FractureOptions.Preset(FracturePreset.Ice);
            Check.True(preset.Units == FractureUnits.DiagonalFraction && preset.Radius == 0.11, "a fraction of the size");
            double refine = preset.RefineEdge, spacings = 0, first = preset.Rings[0].Spacing;
            for (int i = 0; i < preset.RingCount; ++i) spacings += preset.Rings[i].Spacing;
            FractureOptions o = preset.WithBreakRadius(0.75);
            Check.True(o.Units == FractureUnits.Model && preset.Units == FractureUnits.DiagonalFraction,
                       "model units, the original kept");
            Check.Near(0.75, o.BreakRadius, 1e-12, "the outer ring at the radius");
            Check.Near(refine * 0.75 / spacings, o.RefineEdge, 1e-12, "the refinement scaled alike");
            Check.Equal(first, preset.Rings[0].Spacing, "the original's rings are not shared");
            Check.Equal(preset.TotalPoints, o.TotalPoints);
            Check.Throws(HedgeStatus.InvalidArgument, () => preset.WithBreakRadius(0));
            Check.Throws(HedgeStatus.InvalidArgument, () => preset.WithBreakRadius(double.NaN));
            Check.ThrowsType<ArgumentOutOfRangeException>(() => preset.WithBreakRadiusFraction(-1));
            Check.ThrowsType<ArgumentOutOfRangeException>(() => preset.WithBreakRadiusFraction(double.PositiveInfinity));
            FractureOptions tenth = o.WithBreakRadiusFraction(0.1);
            Check.True(tenth.Units == FractureUnits.DiagonalFraction && tenth.Radius == 0.1 && o.Radius == 0.75,
                       "a tenth of the diagonal, the original kept");
#pragma warning disable 618 // the former overload, with the mesh it no longer needs
            using (HalfEdgeMesh pane = Pane(4))
            {
                Check.ThrowsType<ArgumentNullException>(() => preset.WithBreakRadiusFraction(null, 0.1));
                Check.Equal(0.1, preset.WithBreakRadiusFraction(pane, 0.1).Radius, "the mesh is not needed");
            }
#pragma warning restore 618
        }

        // Open shards (no thickness) weigh as thin shells: every shard of a strike has a mass and a positive-definite
        // inertia, a twentieth of the break radius thick by default or ShellThickness thick.
        [Test]
        static void OpenShardsWeighAsThinShells()
        {
            foreach (double shell in new[] { 0.0, 0.05 })
                using (HalfEdgeMesh pane = Pane(20))
                {
                    FractureOptions o = FractureOptions.Preset(FracturePreset.Glass);
                    o.RelativeThickness = 0;
                    o.ShellThickness = shell;
                    double thickness = shell > 0 ? shell : 0.05 * 0.13 * Math.Sqrt(200);
                    FractureShard[] shards = pane.Fracture(new Vec3(5.03f, 4.98f, 0), o);
                    Check.True(shards.Length >= 20, "glass shards: " + shards.Length);
                    foreach (FractureShard s in shards)
                    {
                        Check.True(!s.Closed && s.Mass > 0 && s.PrincipalMoments[0] > 0, "a shell with mass");
                        Check.Near(s.Area * thickness, s.Volume, 1e-6 * s.Volume, "the shell's volume");
                        s.Dispose();
                    }
                    Check.Valid(pane);
                }
        }

        // The library's FractureMaterial.TheDefaultStrikeOnSpotThatEveryBindingChecks gives these numbers: the
        // binding's defaults are the library's (open shards: no thickness).
        [Test]
        static void TheDefaultStrikeOnSpotGivesTheLibrarysShards()
        {
            using (HalfEdgeMesh spot = HalfEdgeMesh.Read(Context.Data("spot_triangulated.obj")))
            {
                FractureOptions o = FractureOptions.Preset(FracturePreset.Glass);
                o.RelativeThickness = 0;
                FractureShard[] shards = spot.Fracture(new Vec3(0.380073f, -0.0641595f, 0.195141f), o);
                Check.Equal(40, shards.Length, "glass shards");
                double area = 0, mass = 0;
                foreach (FractureShard s in shards)
                {
                    area += s.Area;
                    mass += s.Mass;
                    s.Dispose();
                }
                Check.Near(0.498213, area, 1e-6, "the broken area");
                Check.Near(0.00838123, mass, 1e-8, "the shells' mass");
            }
        }

        // A preset gives a thickness relative to the break radius; a thickness in model units replaces it, and the
        // other way round; both at once cannot be set from C#, and the library refuses both through the C ABI.
        [Test]
        static void ThicknessDefaultsToAShareOfTheBreakRadius()
        {
            FractureOptions o = FractureOptions.Preset(FracturePreset.Glass).WithBreakRadius(2);
            Check.Equal(FractureOptions.GameRelativeThickness, o.RelativeThickness);
            Check.Equal(-1, o.InnerSubmesh, "the automatic inner submesh");
            using (HalfEdgeMesh pane = Pane(20))
            {
                FractureShard[] shards = pane.Fracture(new Vec3(5.03f, 4.98f, 0), o);
                foreach (FractureShard s in shards)
                {
                    Check.True(s.Closed, "a solid");
                    Check.Near(s.Area * 0.05 * 2, s.Volume, 1e-4 * s.Area, "5% of the 2 m radius thick");
                    s.Dispose();
                }
            }
            o.Thickness = 0.3;
            Check.True(o.Thickness == 0.3 && o.RelativeThickness == 0, "a thickness replaces the relative one");
            o.RelativeThickness = 0.1;
            Check.True(o.Thickness == 0 && o.RelativeThickness == 0.1, "and the other way round");
            o.RelativeThickness = -1;
            using (HalfEdgeMesh pane = Pane(4))
                Check.Throws(HedgeStatus.InvalidArgument, () => pane.Fracture(new Vec3(5, 5, 0), o));
        }

        // The faces a solid adds (back and walls) are in the inner submesh, the broken faces keep theirs (0 here).
        [Test]
        static void InnerFacesGetASubmeshOfTheirOwn()
        {
            foreach (int inner in new[] { -1, 3 })
                using (HalfEdgeMesh pane = Pane(20))
                {
                    FractureOptions o = FractureOptions.Preset(FracturePreset.Stone).WithBreakRadius(3);
                    o.InnerSubmesh = inner;
                    FractureShard[] shards = pane.Fracture(new Vec3(5.03f, 4.98f, 0), o);
                    Check.True(shards.Length > 0, "shards");
                    int expected = inner < 0 ? 1 : inner;
                    foreach (FractureShard s in shards)
                    {
                        var submesh = new int[s.Mesh.CopyFaceSubmeshes(null)];
                        s.Mesh.CopyFaceSubmeshes(submesh);
                        int front = 0, added = 0;
                        foreach (int m in submesh)
                        {
                            Check.True(m == 0 || m == expected, "submesh " + m);
                            if (m == 0) ++front; else ++added;
                        }
                        Check.True(front > 0 && added > front, "front " + front + ", added " + added);
                        Check.Valid(s.Mesh);
                        s.Dispose();
                    }
                    var rest = new int[pane.CopyFaceSubmeshes(null)];
                    pane.CopyFaceSubmeshes(rest);
                    foreach (int m in rest) Check.Equal(0, m, "the pane has no submesh");
                    Check.Throws(HedgeStatus.BufferTooSmall, () => pane.CopyFaceSubmeshes(new int[1]));
                    Check.Valid(pane);
                }
        }

        // The principal moments and the rotation of the principal axes give back the full tensor: R diag(m) R^T
        // equals Inertia to 1e-9 relative, R a proper rotation (a unit quaternion).
        [Test]
        static void PrincipalFrameReproducesTheTensor()
        {
            using (HalfEdgeMesh pane = Pane(20))
            {
                FractureOptions o = FractureOptions.Preset(FracturePreset.Wood).WithBreakRadius(3);
                o.Density = 700;
                o.Seed = 11;
                FractureShard[] shards = pane.Fracture(new Vec3(5.03f, 4.98f, 0), o);
                Check.True(shards.Length >= 8, "wood shards: " + shards.Length);
                foreach (FractureShard s in shards)
                {
                    double[] q = s.PrincipalRotation(), m = s.PrincipalMoments;
                    double x = q[0], y = q[1], z = q[2], w = q[3];
                    Check.Near(1, x * x + y * y + z * z + w * w, 1e-12, "a unit quaternion");
                    var r = new double[]
                    {
                        1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
                        2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                        2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y),
                    };
                    double largest = 0;
                    foreach (double v in s.Inertia) largest = Math.Max(largest, Math.Abs(v));
                    for (int i = 0; i < 3; ++i)
                        for (int j = 0; j < 3; ++j)
                        {
                            double t = 0;
                            for (int k = 0; k < 3; ++k) t += r[3 * i + k] * m[k] * r[3 * j + k];
                            Check.Near(s.Inertia[3 * i + j], t, 1e-9 * largest, "tensor (" + i + ", " + j + ")");
                        }
                    Check.True(m[0] > 0 && m[0] <= m[1] && m[1] <= m[2], "ascending positive moments");
                    s.Dispose();
                }
            }
        }
    }
}
