// The Unity glue (Runtime/Unity, assembly Hedge.HalfEdge.Unity) builds meshes from Unity's arrays and
// wraps the native buffers without copies, through the internals of this assembly.
using System.Runtime.CompilerServices;

[assembly: InternalsVisibleTo("Hedge.HalfEdge.Unity")]
// The tests (Tests/Runtime/, assembly Hedge.HalfEdge.Tests in Unity) check internals too.
[assembly: InternalsVisibleTo("Hedge.HalfEdge.Tests")]
