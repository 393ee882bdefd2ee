// The Unity glue (Runtime/Unity, assembly Hedge.HalfEdge.Unity) builds meshes from Unity's arrays and
// wraps the native buffers without copies, through the internal handles of this assembly.
using System;
using System.Runtime.CompilerServices;

[assembly: InternalsVisibleTo("Hedge.HalfEdge.Unity")]
// The tests (Tests/Runtime/, assembly Hedge.HalfEdge.Tests in Unity) check internals too.
[assembly: InternalsVisibleTo("Hedge.HalfEdge.Tests")]

namespace Hedge
{
    public sealed partial class HalfEdgeMesh
    {
        // A mesh from the status and handle of a creating call made by the glue's own P/Invoke overloads.
        internal static HalfEdgeMesh Adopt(int status, IntPtr id) { return Created(status, id); }
    }
}
