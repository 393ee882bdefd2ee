// Refusal codes: the C# enum is the C ABI's table value for value, a refused edit sets the code
// without allocating, and the text comes on demand.
using System;

namespace Hedge.Tests
{
    public static class RefusalCodeTests
    {
        // "HEDGE_REFUSAL_FLIP_BOUNDARY_EDGE" -> "FlipBoundaryEdge".
        public static string PascalCase(string cName)
        {
            const string prefix = "HEDGE_REFUSAL_";
            Check.True(cName.StartsWith(prefix), cName);
            var words = cName.Substring(prefix.Length).ToLowerInvariant().Split('_');
            for (int i = 0; i < words.Length; ++i)
                words[i] = char.ToUpperInvariant(words[i][0]) + words[i].Substring(1);
            return string.Concat(words);
        }

        [Test]
        static void EnumIsTheLibrarysTable()
        {
            var values = (RefusalCode[])Enum.GetValues(typeof(RefusalCode));
            Check.Equal(Native.RefusalCount, values.Length, "one member per code");
            for (int i = 0; i < values.Length; ++i)
            {
                Check.Equal(i, (int)values[i], "codes 0, 1, 2, ... in order");
                string cName = Status.FromUtf8(Native.hedge_refusal_name(i));
                Check.Equal(PascalCase(cName), values[i].ToString(), "code " + i);
                Check.Equal(Status.FromUtf8(Native.hedge_refusal_text(i)), values[i].Text() ?? "");
            }
            Check.Equal("HEDGE_REFUSAL_UNKNOWN", Status.FromUtf8(Native.hedge_refusal_name(values.Length)),
                        "the library knows no more codes than the enum");
            Check.Equal(null, RefusalCode.None.Text());
            Check.Equal("the edge is on the boundary (a flip needs a triangle on both sides)",
                        RefusalCode.FlipBoundaryEdge.Text());
            Check.Equal("", ((RefusalCode)1000).Text(), "no such code");
        }

        [Test]
        static void CodeAfterRefusedAndDoneEdits()
        {
            using (HalfEdgeMesh mesh = Meshes.Pyramid())
            {
                Check.Equal(RefusalCode.None, mesh.LastRefusalCode);
                HalfEdge open = mesh.FindHalfEdge(new Vertex(0), new Vertex(1));
                Check.False(mesh.Flip(open), "a boundary edge");
                Check.Equal(RefusalCode.FlipBoundaryEdge, mesh.LastRefusalCode);
                Check.Equal(RefusalCode.FlipBoundaryEdge.Text(), mesh.LastRefusal);
                Check.True(object.ReferenceEquals(mesh.LastRefusal, mesh.LastRefusal), "one string per code");
                Check.Equal(0, mesh.FillHole(open), "a half-edge with a face");
                Check.Equal(RefusalCode.FillHoleNotBoundary, mesh.LastRefusalCode);
                Check.True(mesh.SplitEdge(open.Edge, 0.5f, 0, 0).IsValid);
                Check.Equal(RefusalCode.None, mesh.LastRefusalCode, "cleared by an edit that was done");
                Check.Equal(null, mesh.LastRefusal);
                Check.Valid(mesh);
            }
        }

        // A predicate sets the code too: after a refused edit, a predicate that answers false gives its own
        // edit's reason (not the earlier one), and one that answers true clears it. A disposed mesh has none.
        [Test]
        static void PredicatesSetTheCode()
        {
            HalfEdgeMesh mesh = Meshes.Pyramid();
            HalfEdge open = mesh.FindHalfEdge(new Vertex(0), new Vertex(1));
            Check.Equal(0, mesh.FillHole(open), "a half-edge with a face");
            Check.Equal(RefusalCode.FillHoleNotBoundary, mesh.LastRefusalCode);
            Check.False(mesh.CanFlip(open), "a boundary edge");
            Check.Equal(RefusalCode.FlipBoundaryEdge, mesh.LastRefusalCode, "the flip's reason, not the fill's");
            Check.Equal(RefusalCode.FlipBoundaryEdge.Text(), mesh.LastRefusal);
            Check.False(mesh.CanCutFace(open, open));
            Check.Equal(RefusalCode.CutSameHalfedge, mesh.LastRefusalCode);
            Check.True(mesh.CanSplitEdge(open.Edge));
            Check.Equal(RefusalCode.None, mesh.LastRefusalCode, "cleared by a predicate that allows its edit");
            Check.False(mesh.CanFillHole(open));
            Check.Equal(RefusalCode.FillHoleNotBoundary, mesh.LastRefusalCode);
            Check.Valid(mesh);
            mesh.Dispose();
            Check.ThrowsType<ObjectDisposedException>(() => { RefusalCode c = mesh.LastRefusalCode; }, "disposed");
            Check.ThrowsType<ObjectDisposedException>(() => { string t = mesh.LastRefusal; }, "disposed");
        }

        // A game checks refusals every frame: refusing and reading the code allocate nothing, and the text
        // allocates once per code, not per edit.
        [Test]
        static void RefusalsAllocateNothing()
        {
            using (HalfEdgeMesh mesh = Meshes.Pyramid())
            {
                HalfEdge open = mesh.FindHalfEdge(new Vertex(0), new Vertex(1));
                Check.False(mesh.Flip(open));  // warm up: JIT, the P/Invoke stubs, the text's string
                string first = mesh.LastRefusal;
                const int rounds = 1000;
                int refused = 0;
                long before = GC.GetAllocatedBytesForCurrentThread();
                for (int i = 0; i < rounds; ++i)
                {
                    if (!mesh.Flip(open) && mesh.LastRefusalCode == RefusalCode.FlipBoundaryEdge) ++refused;
                    if (!mesh.CutFace(open, open).IsValid && mesh.LastRefusalCode == RefusalCode.CutSameHalfedge) ++refused;
                }
                long codes = GC.GetAllocatedBytesForCurrentThread() - before;
                before = GC.GetAllocatedBytesForCurrentThread();
                int length = 0;
                for (int i = 0; i < rounds; ++i)
                {
                    mesh.Flip(open);
                    length += mesh.LastRefusal.Length;
                }
                long texts = GC.GetAllocatedBytesForCurrentThread() - before;
                Console.WriteLine("    " + rounds + " rounds of a refused flip and cut, codes checked: " + codes +
                                  " bytes; text read: " + texts + " bytes");
                Check.Equal(2 * rounds, refused);
                Check.Equal(0L, codes, "bytes allocated by refused edits and their codes");
                Check.Equal(0L, texts, "bytes allocated by reading the text of a code seen before");
                Check.Equal(rounds * first.Length, length);
                Check.Valid(mesh);
            }
        }
    }
}
