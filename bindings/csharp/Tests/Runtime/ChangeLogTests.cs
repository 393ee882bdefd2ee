// RenderChangeLog: the union of the ranges of every sync since the log was cleared, whoever synced.
using System;
using System.Collections.Generic;

namespace Hedge.Tests
{
    public static class ChangeLogTests
    {
        // The slots covered by ranges, as a set.
        static SortedSet<int> Slots(SlotRange[] ranges, int count)
        {
            var s = new SortedSet<int>();
            for (int i = 0; i < count; ++i)
                for (int j = 0; j < ranges[i].Count; ++j) s.Add(ranges[i].First + j);
            return s;
        }

        static SortedSet<int> LogSlots(RenderChangeLog log, bool vertices)
        {
            int n = vertices ? log.VertexRangeCount : log.IndexRangeCount;
            var r = new SlotRange[n];
            for (int i = 0; i < n; ++i)
            {
                r[i] = vertices ? log.VertexRange(i) : log.IndexRange(i);
                // Sorted, disjoint, not touching: merged.
                if (i > 0) Check.True(r[i].First > r[i - 1].First + r[i - 1].Count, "merged ranges " + r[i - 1] + " " + r[i]);
            }
            return Slots(r, n);
        }

        [Test]
        static void GathersEverySync()
        {
            using (HalfEdgeMesh mesh = Meshes.Grid())
            using (RenderBuffers buffers = mesh.CreateRenderBuffers(RenderOptions.Unity))
            using (RenderChangeLog log = buffers.CreateChangeLog())
            {
                Check.True(log.IsEmpty, "empty at first");
                var expectedVertices = new SortedSet<int>();
                var expectedIndices = new SortedSet<int>();
                var ranges = new SlotRange[64];
                for (int step = 0; step < 4; ++step)
                {
                    if (step == 1) mesh.SplitFace(new Face(3), 1.5f, 1.5f, 0);
                    else mesh.SetPosition(new Vertex(step == 0 ? 0 : step == 2 ? 8 : 4), 0.1f * step, 0, 1);
                    if (step == 2) buffers.BeginTransaction();
                    SyncResult r = step == 2 ? buffers.CommitTransaction() : buffers.Sync();
                    Check.False(r.IsEmpty || r.Full || r.Resized, "a partial sync");
                    expectedVertices.UnionWith(Slots(ranges, buffers.GetDirtyVertexRanges(ranges)));
                    expectedIndices.UnionWith(Slots(ranges, buffers.GetDirtyIndexRanges(ranges)));
                }
                Check.False(log.IsEmpty || log.Everything);
                Check.True(expectedVertices.SetEquals(LogSlots(log, true)), "the union of the vertex ranges");
                Check.True(expectedIndices.SetEquals(LogSlots(log, false)), "the union of the index ranges");
                Check.True(expectedIndices.Count > 0 && expectedVertices.Count > 1);

                log.Clear();
                Check.True(log.IsEmpty, "cleared");
                buffers.Sync();
                Check.True(log.IsEmpty, "a sync without edits adds nothing");
                buffers.Rebuild();
                Check.True(log.Everything && log.VertexRangeCount == 0, "a rebuild: everything");
                log.Clear();
                buffers.Compact();
                Check.True(log.Everything, "a compaction: everything");
                log.Clear();
                Check.ThrowsType<ArgumentOutOfRangeException>(() => log.VertexRange(0));

                log.Dispose();
                mesh.SetPosition(new Vertex(0), 0, 0, 2);
                buffers.Sync();
                Check.True(log.IsEmpty, "a disposed log records nothing");
                Check.Valid(mesh);
            }
        }
    }
}
