// Click to split, right-click to collapse: a scene-free sample of the hedge package.
//
// Put it on any GameObject with a MeshFilter (a mesh with Read/Write enabled, e.g. a Plane or a
// Sphere), a MeshRenderer and a MeshCollider, with a Camera tagged MainCamera in the scene. Press
// Play. A left click on the surface splits the edge of the clicked triangle nearest to the click, at
// the point of that edge nearest to it; a right click collapses that edge into its end nearer to
// the click (refused collapses, which would break the surface, are logged and change nothing).
//
// What it shows: Unity's own physics finds the triangle (RaycastHit.triangleIndex), the render
// buffers map it back to the half-edge face (RenderBuffers.FaceOfTriangle), the edit runs on the
// half-edge mesh, and NativeMeshUploader uploads only what the edit rewrote, straight from the
// native buffers. The collider is given the new mesh after each edit, so that the next click sees it.
// It reads the mouse with either input system, the Input System package or the legacy Input Manager
// (Hedge.Unity.PointerInput).
using Hedge;
using Hedge.Unity;
using UnityEngine;

[RequireComponent(typeof(MeshFilter))]
[RequireComponent(typeof(MeshCollider))]
public sealed class ClickToSplit : MonoBehaviour
{
    HalfEdgeMesh halfEdgeMesh;
    RenderBuffers buffers;
    NativeMeshUploader uploader;
    Mesh rendered;
    MeshCollider meshCollider;
    readonly HalfEdge[] loop = new HalfEdge[64];

    /// <summary>The editable mesh (null before Start).</summary>
    public HalfEdgeMesh HalfEdgeMesh { get { return halfEdgeMesh; } }
    /// <summary>The mesh rendered and collided with.</summary>
    public Mesh RenderedMesh { get { return rendered; } }

    void Start()
    {
        if (PointerInput.Source == "none")
            Debug.LogWarning("hedge: ClickToSplit reads no input: enable the Input Manager or install the Input " +
                             "System package (Project Settings > Player > Active Input Handling)");
        MeshFilter filter = GetComponent<MeshFilter>();
        Mesh source = filter.sharedMesh;
        halfEdgeMesh = UnityMeshes.FromUnityMesh(source.vertices, source.triangles, source.normals, source.uv,
                                                 source.colors);
        buffers = halfEdgeMesh.CreateRenderBuffers(RenderOptions.Unity);
        rendered = new Mesh();
        rendered.name = source.name + " (hedge)";
        rendered.MarkDynamic();
        uploader = new NativeMeshUploader(buffers, rendered);
        uploader.UploadAll();
        filter.sharedMesh = rendered;
        meshCollider = GetComponent<MeshCollider>();
        meshCollider.sharedMesh = rendered;
    }

    void Update()
    {
        Vector3 pointer;
        bool split = PointerInput.ButtonDown(0, out pointer);
        bool collapse = !split && PointerInput.ButtonDown(1, out pointer);
        if (!split && !collapse) return;
        RaycastHit hit;
        if (!Physics.Raycast(Camera.main.ScreenPointToRay(pointer), out hit) || hit.collider != meshCollider)
            return;
        Face face = buffers.FaceOfTriangle(hit.triangleIndex);
        if (!face.IsValid) return; // a triangle of a face deleted since the last upload
        Vector3 click = transform.InverseTransformPoint(hit.point);
        float along;
        HalfEdge h = NearestEdge(face, click, out along);
        if (split)
        {
            Vector3 a = halfEdgeMesh.GetPositionVector(halfEdgeMesh.FromVertex(h));
            Vector3 b = halfEdgeMesh.GetPositionVector(halfEdgeMesh.ToVertex(h));
            // Not too close to an end, which would make a sliver.
            halfEdgeMesh.SplitEdge(h.Edge, a + Mathf.Clamp(along, 0.1f, 0.9f) * (b - a));
        }
        else
        {
            // Keep the end nearer to the click: collapse the half-edge that points to it.
            HalfEdge toward = along >= 0.5f ? h : h.Twin;
            if (!halfEdgeMesh.CanCollapse(toward) || !halfEdgeMesh.Collapse(toward).IsValid)
            {
                Debug.Log("hedge: collapsing " + toward.Edge + " would break the surface; refused");
                return;
            }
        }
        uploader.Upload(); // syncs, then uploads what changed
        meshCollider.sharedMesh = null; // let the collider take in the new triangles
        meshCollider.sharedMesh = rendered;
    }

    // The edge of the face nearest to p, and where along it (0 at its from-vertex, 1 at its to-vertex)
    // p's nearest point on it lies.
    HalfEdge NearestEdge(Face face, Vector3 p, out float along)
    {
        int n = halfEdgeMesh.GetFaceHalfEdges(face, loop);
        HalfEdge best = loop[0];
        float bestDistance = float.PositiveInfinity;
        along = 0.5f;
        for (int i = 0; i < n; ++i)
        {
            Vector3 a = halfEdgeMesh.GetPositionVector(halfEdgeMesh.FromVertex(loop[i]));
            Vector3 b = halfEdgeMesh.GetPositionVector(halfEdgeMesh.ToVertex(loop[i]));
            Vector3 ab = b - a;
            float t = ab.sqrMagnitude > 0 ? Mathf.Clamp(Vector3.Dot(p - a, ab) / ab.sqrMagnitude, 0, 1) : 0;
            float d = (a + t * ab - p).sqrMagnitude;
            if (d < bestDistance)
            {
                bestDistance = d;
                best = loop[i];
                along = t;
            }
        }
        return best;
    }

    void OnDestroy()
    {
        if (uploader != null) uploader.Dispose();
        if (buffers != null) buffers.Dispose();
        if (halfEdgeMesh != null) halfEdgeMesh.Dispose();
        if (rendered != null) Destroy(rendered);
    }
}
