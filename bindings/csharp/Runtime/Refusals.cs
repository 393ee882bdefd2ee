// Why an edit was refused, as a code: HalfEdgeMesh.LastRefusalCode, which a game can check every
// frame without allocating, and the text on demand (LastRefusal, RefusalCodes.Text). The codes are
// the library's one table of refusals (hedge/core/refusal.h, the C ABI's hedge_refusal): each keeps
// its value in every later release.
using System;
using System.Runtime.InteropServices;

namespace Hedge
{
    /// <summary>Why an edit was refused: the C ABI's HEDGE_REFUSAL_* in PascalCase, value for value.</summary>
    public enum RefusalCode
    {
        /// <summary>Not refused.</summary>
        None = 0,
        /// <summary>The edge is not live</summary>
        EdgeNotLive = 1,
        /// <summary>The half-edge is not live</summary>
        HalfedgeNotLive = 2,
        /// <summary>The face is not live</summary>
        FaceNotLive = 3,
        /// <summary>The vertex is not live</summary>
        VertexNotLive = 4,
        /// <summary>It would join the two sides of a seam at the surviving vertex</summary>
        CollapseJoinsSeamSides = 5,
        /// <summary>It would pull a seam vertex off its seam</summary>
        CollapsePullsSeamVertex = 6,
        /// <summary>It would shorten a seam that ends at the merged vertex</summary>
        CollapseShortensSeam = 7,
        /// <summary>The edge has the same face on both sides</summary>
        CollapseSameFaceBothSides = 8,
        /// <summary>An interior edge joins two boundary vertices (the surface would pinch)</summary>
        CollapsePinchesBoundary = 9,
        /// <summary>A second edge joins its ends</summary>
        CollapseSecondEdge = 10,
        /// <summary>Its ends share a neighbour besides the tips of its triangles (the link condition)</summary>
        CollapseLinkCondition = 11,
        /// <summary>A triangle on the edge has the boundary on both other sides (an edge would dangle)</summary>
        CollapseDanglingEdge = 12,
        /// <summary>A tip of its triangles would be left with too few edges</summary>
        CollapseTipTooFewEdges = 13,
        /// <summary>The surviving vertex would be left with too few edges</summary>
        CollapseSurvivorTooFewEdges = 14,
        /// <summary>The two triangles on the edge share their tip</summary>
        FlipTipsShared = 15,
        /// <summary>An end is an interior vertex of valence 3 (the flip would leave it with 2)</summary>
        FlipValenceThree = 16,
        /// <summary>The tips of its triangles are already joined by an edge</summary>
        FlipTipsJoined = 17,
        /// <summary>The edge is on the boundary (a flip needs a triangle on both sides)</summary>
        FlipBoundaryEdge = 18,
        /// <summary>A face on the edge is not a triangle</summary>
        FlipNotTriangle = 19,
        /// <summary>A half-edge is not live</summary>
        CutHalfedgeNotLive = 20,
        /// <summary>The two half-edges are the same</summary>
        CutSameHalfedge = 21,
        /// <summary>The half-edges are on a boundary, not in a face</summary>
        CutOnBoundary = 22,
        /// <summary>The half-edges are in different faces</summary>
        CutDifferentFaces = 23,
        /// <summary>Their targets are neighbours in the face (the cut would double an edge)</summary>
        CutNeighbourTargets = 24,
        /// <summary>An edge already joins their targets</summary>
        CutTargetsJoined = 25,
        /// <summary>A face needs at least 3 corners</summary>
        AddFaceTooFewCorners = 26,
        /// <summary>A corner is not a live vertex</summary>
        AddFaceCornerNotLive = 27,
        /// <summary>A corner is repeated</summary>
        AddFaceCornerRepeated = 28,
        /// <summary>An edge of the face already has a face on that side</summary>
        AddFaceEdgeTaken = 29,
        /// <summary>A corner is an interior vertex (its fan of faces is closed)</summary>
        AddFaceInteriorCorner = 30,
        /// <summary>The face would meet a corner's faces at the vertex only (a second gap in its fan)</summary>
        AddFaceSecondGap = 31,
        /// <summary>A corner would be left with two gaps in its fan of faces (pinched)</summary>
        RemoveFacePinches = 32,
        /// <summary>A corner of its faces would be left with two gaps in its fan of faces (pinched)</summary>
        RemoveVertexPinches = 33,
        /// <summary>The half-edge is not on a boundary (it has a face)</summary>
        FillHoleNotBoundary = 34,
        /// <summary>Its boundary loop is damaged (it never closes)</summary>
        FillHoleLoopDamaged = 35,
        /// <summary>Its boundary loop has fewer than 3 edges (no room for a face)</summary>
        FillHoleLoopTooShort = 36,
    }

    /// <summary>The text of a refusal code.</summary>
    public static class RefusalCodes
    {
        // One string per code, made the first time it is asked for: a refusal's text allocates once per
        // code in the process, never per edit.
        static readonly string[] texts = new string[Native.RefusalCount];

        /// <summary>The refusal's text in a few words ("the edge is on the boundary (a flip needs a triangle on
        /// both sides)"), as the C ABI's hedge_refusal_text() and the JS API's lastRefusal give it; null for
        /// <see cref="RefusalCode.None"/>, "" for a value that is no code.</summary>
        public static string Text(this RefusalCode code)
        {
            if (code == RefusalCode.None) return null;
            int i = (int)code;
            if (i < 0 || i >= texts.Length) return Status.FromUtf8(Native.hedge_refusal_text(i));
            string text = texts[i];
            if (text == null) texts[i] = text = Status.FromUtf8(Native.hedge_refusal_text(i));
            return text;
        }
    }

    public sealed partial class HalfEdgeMesh
    {
        /// <summary>Why the last edit of this mesh was refused, as a code; <see cref="RefusalCode.None"/> if the
        /// last edit was done. Every edit (split, collapse, flip, cut, add, remove, fill) sets it, and so does
        /// every predicate (CanFlip, CanCollapse, ...): after one that answered false, it says why that edit
        /// would be refused. Reading it, and refusing, allocate nothing: check it every frame.</summary>
        /// <exception cref="ObjectDisposedException">The mesh was disposed.</exception>
        public RefusalCode LastRefusalCode
        {
            get
            {
                IntPtr live = id;  // throws for a disposed mesh
                return lastRefusalCode;
            }
            private set { lastRefusalCode = value; }
        }
        RefusalCode lastRefusalCode;

        /// <summary>Why the last edit of this mesh was refused: the text of <see cref="LastRefusalCode"/>
        /// (e.g. "it would pull a seam vertex off its seam"), as hedge_last_refusal() gave it right after the
        /// call, the same text as the JS API's lastRefusal; or null if the last edit was done. Made on
        /// demand: the first read of each code allocates its string, once per process.</summary>
        public string LastRefusal { get { return LastRefusalCode.Text(); } }

        // True if the status says "refused" (then LastRefusalCode holds the reason); throws for any other failure.
        bool WasRefused(int status)
        {
            if (status == Refused)
            {
                LastRefusalCode = (RefusalCode)Native.hedge_last_refusal_code();
                return true;
            }
            LastRefusalCode = RefusalCode.None;
            Status.Check(status);
            return false;
        }
    }

    internal static partial class Native
    {
        // HEDGE_REFUSAL_COUNT of the header this binding was written against.
        internal const int RefusalCount = 37;

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_last_refusal_code();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern IntPtr hedge_refusal_text(int code);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern IntPtr hedge_refusal_name(int code);
    }
}
