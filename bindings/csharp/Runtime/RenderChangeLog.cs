// RenderChangeLog: what the render buffers rewrote since a consumer last took it, whoever synced.
//
// A RenderBuffers reports the ranges of its last sync only, so a consumer that uploads what its
// own Sync() returned misses every sync, commit or rebuild another script made in between, and the
// GPU copy goes stale. Instead each consumer (NativeMeshUploader, HalfEdgeMeshBehaviour) keeps a
// change log of its own: every sync, commit, rebuild and compaction of the buffers merges its dirty
// ranges into every open log, or marks the log "everything" when the result was full or resized
// (or when the ranges became too many to be worth uploading one by one). The consumer uploads the
// log's ranges from the buffers' current data, then clears it. The ranges are kept sorted, merged
// and disjoint in arrays that grow and are reused: recording and reading allocate nothing once
// the arrays have grown.
using System;

namespace Hedge
{
    /// <summary>The render-vertex and index ranges a <see cref="RenderBuffers"/> rewrote since the last
    /// <see cref="Clear"/>, gathered from every sync, commit, rebuild and compaction, whoever made it. Made by
    /// <see cref="RenderBuffers.CreateChangeLog"/>; dispose it to stop recording.</summary>
    public sealed class RenderChangeLog : IDisposable
    {
        /// <summary>Past this many ranges in either list the log marks everything: one whole upload is then
        /// cheaper than many small ones.</summary>
        public const int MaxRanges = 1024;

        readonly RenderBuffers buffers;
        SlotRange[] vertexRanges = new SlotRange[16], indexRanges = new SlotRange[16], scratch = new SlotRange[32];
        int vertexCount, indexCount;
        bool everything, disposed;

        internal RenderChangeLog(RenderBuffers buffers) { this.buffers = buffers; }

        /// <summary>The buffers this log follows.</summary>
        public RenderBuffers Buffers { get { return buffers; } }
        /// <summary>Everything must be uploaded again: a full or resized result (a rebuild, a compaction,
        /// garbage collection, growth beyond the capacity), or more than <see cref="MaxRanges"/> ranges.</summary>
        public bool Everything { get { return everything; } }
        /// <summary>Nothing was rewritten since the last <see cref="Clear"/>.</summary>
        public bool IsEmpty { get { return !everything && vertexCount == 0 && indexCount == 0; } }
        /// <summary>Rewritten render-vertex ranges (sorted, merged, disjoint); 0 when <see cref="Everything"/>.</summary>
        public int VertexRangeCount { get { return everything ? 0 : vertexCount; } }
        /// <summary>Rewritten index-buffer ranges, in indices; 0 when <see cref="Everything"/>.</summary>
        public int IndexRangeCount { get { return everything ? 0 : indexCount; } }
        /// <summary>Render-vertex range i, 0 &lt;= i &lt; <see cref="VertexRangeCount"/>.</summary>
        public SlotRange VertexRange(int i) { return Item(vertexRanges, VertexRangeCount, i); }
        /// <summary>Index-buffer range i, 0 &lt;= i &lt; <see cref="IndexRangeCount"/>.</summary>
        public SlotRange IndexRange(int i) { return Item(indexRanges, IndexRangeCount, i); }

        /// <summary>Forgets what was recorded: call it after uploading it.</summary>
        public void Clear()
        {
            vertexCount = indexCount = 0;
            everything = false;
        }

        /// <summary>Marks everything as rewritten (the next upload sends whole buffers).</summary>
        public void MarkEverything() { everything = true; }

        /// <summary>Stops recording (the buffers stay).</summary>
        public void Dispose()
        {
            if (disposed) return;
            disposed = true;
            buffers.RemoveChangeLog(this);
        }

        static SlotRange Item(SlotRange[] ranges, int count, int i)
        {
            if (i < 0 || i >= count) throw new ArgumentOutOfRangeException("i", i, "a range index below " + count);
            return ranges[i];
        }

        // Merges sorted, disjoint ranges into the vertex (or index) list.
        internal void Record(bool vertices, SlotRange[] added, int addedCount)
        {
            if (everything || addedCount == 0) return;
            if (vertices) vertexCount = Merge(ref vertexRanges, vertexCount, added, addedCount);
            else indexCount = Merge(ref indexRanges, indexCount, added, addedCount);
            if (vertexCount > MaxRanges || indexCount > MaxRanges) everything = true;
        }

        // Merges two sorted lists of disjoint ranges into one, joining overlapping and touching ranges;
        // the result replaces `kept` (the arrays swap with the scratch, so nothing is allocated once grown).
        int Merge(ref SlotRange[] kept, int keptCount, SlotRange[] added, int addedCount)
        {
            if (scratch.Length < keptCount + addedCount) scratch = new SlotRange[2 * (keptCount + addedCount)];
            int i = 0, j = 0, n = 0;
            while (i < keptCount || j < addedCount)
            {
                SlotRange next = j >= addedCount || (i < keptCount && kept[i].First <= added[j].First) ? kept[i++]
                                                                                                    : added[j++];
                if (n > 0 && next.First <= scratch[n - 1].First + scratch[n - 1].Count)
                {
                    int end = Math.Max(scratch[n - 1].First + scratch[n - 1].Count, next.First + next.Count);
                    scratch[n - 1].Count = end - scratch[n - 1].First;
                }
                else scratch[n++] = next;
            }
            SlotRange[] old = kept;
            kept = scratch;
            scratch = old;
            return n;
        }
    }
}
