// Click to break: a scene-free sample of the hedge package's fracture.
//
// Put it on any GameObject with a MeshFilter (a mesh with Read/Write enabled, e.g. a Cube or a
// Plane), a MeshRenderer and a MeshCollider, with a Camera tagged MainCamera in the scene. Press
// Play. A left click on the surface breaks the object there: the broken faces leave its mesh, and
// each shard becomes a GameObject of its own that falls, with a Rigidbody and a convex MeshCollider.
//
// What it shows: the break radius is set as a game designer thinks of it, a fraction of the object's
// size (FractureOptions.WithBreakRadiusFraction), so a coarse and a finely tessellated object break
// alike; each shard is a closed solid (the preset's thickness, a twentieth of the break radius), so
// it has a mass, a centre of mass and an inertia tensor, which ShardBody hands to the Rigidbody
// (mass, centerOfMass, inertiaTensor, inertiaTensorRotation) at the given density; its convex hull,
// computed by the fracture, is the collider's mesh; the remaining object uploads only the ranges the
// strike rewrote (NativeMeshUploader.Upload). The masses are those of the mesh's own units (an object
// scaled in its Transform gets the unscaled mesh's values: scale the density by the cube of the
// scale to match). The shards' cut faces (their backs and side walls) are a submesh of their own,
// drawn with innerMaterial: the renderer gets the object's materials and then that one. Clicks come
// from either input system (Hedge.Unity.PointerInput).
using System.Collections.Generic;
using Hedge;
using Hedge.Unity;
using UnityEngine;

[RequireComponent(typeof(MeshFilter))]
[RequireComponent(typeof(MeshCollider))]
public sealed class BreakOnClick : MonoBehaviour
{
    /// <summary>How the object breaks.</summary>
    public FracturePreset material = FracturePreset.Glass;
    /// <summary>The break radius as a fraction of the diagonal of the object's bounding box.</summary>
    public float breakRadiusFraction = 0.2f;
    /// <summary>Mass per unit volume of the mesh's units (2500 for glass in kg per cubic metre).</summary>
    public float density = 2500;
    /// <summary>The shards' outer material; none: the object's own.</summary>
    public Material shardMaterial;
    /// <summary>The material of the shards' cut faces (their inner submesh); none: the outer one.</summary>
    public Material innerMaterial;

    HalfEdgeMesh halfEdgeMesh;
    RenderBuffers buffers;
    NativeMeshUploader uploader;
    Mesh rendered;
    MeshCollider meshCollider;
    FractureOptions options;
    ulong strikes;
    readonly List<GameObject> shards = new List<GameObject>();

    /// <summary>The breakable mesh (null before Start).</summary>
    public HalfEdgeMesh HalfEdgeMesh { get { return halfEdgeMesh; } }
    /// <summary>The mesh rendered and collided with.</summary>
    public Mesh RenderedMesh { get { return rendered; } }
    /// <summary>The options of every strike: the preset at the break radius, the density.</summary>
    public FractureOptions Options { get { return options; } }
    /// <summary>The shards made so far.</summary>
    public IList<GameObject> Shards { get { return shards; } }

    void Start()
    {
        MeshFilter filter = GetComponent<MeshFilter>();
        Mesh source = filter.sharedMesh;
        halfEdgeMesh = UnityMeshes.FromMesh(source); // every submesh (material) kept
        buffers = halfEdgeMesh.CreateRenderBuffers(RenderOptions.Unity);
        rendered = new Mesh();
        rendered.name = source.name + " (hedge)";
        rendered.MarkDynamic();
        uploader = new NativeMeshUploader(buffers, rendered);
        uploader.UploadAll();
        filter.sharedMesh = rendered;
        meshCollider = GetComponent<MeshCollider>();
        meshCollider.sharedMesh = rendered;
        options = FractureOptions.Preset(material).WithBreakRadiusFraction(breakRadiusFraction);
        options.Density = density;
        // The shards' cut faces get the submesh after the object's own, settled once here (left at -1, each
        // strike would look through every face for the largest).
        options.InnerSubmesh = NextSubmesh(halfEdgeMesh);
        // Locating a strike uses the mesh's picking tree: build it now rather than at the first click.
        halfEdgeMesh.UpdatePickingTree();
    }

    void Update()
    {
        Vector3 pointer;
        if (!PointerInput.ButtonDown(0, out pointer)) return;
        RaycastHit hit;
        if (!Physics.Raycast(Camera.main.ScreenPointToRay(pointer), out hit) || hit.collider != meshCollider)
            return;
        Break(transform.InverseTransformPoint(hit.point));
    }

    /// <summary>Breaks the object at a point of its surface (in its local coordinates). Returns the shards'
    /// GameObjects (none when the strike is refused, which is logged and changes nothing).</summary>
    public List<GameObject> Break(Vector3 localPoint)
    {
        var made = new List<GameObject>();
        options.Seed = ++strikes;
        FractureShard[] pieces;
        try
        {
            pieces = halfEdgeMesh.Fracture(localPoint.ToVec3(), options);
        }
        catch (HedgeException e)
        {
            Debug.Log("hedge: no break at " + localPoint + ": " + e.Message);
            return made;
        }
        uploader.Upload(); // syncs, then uploads what changed
        meshCollider.sharedMesh = null; // let the collider take in the hole
        meshCollider.sharedMesh = rendered;
        foreach (FractureShard piece in pieces)
        {
            made.Add(MakeShard(piece));
            piece.Dispose(); // the Unity meshes hold their own copies
        }
        shards.AddRange(made);
        return made;
    }

    // A GameObject where the object is, with the shard's mesh, a convex collider of its hull and a
    // Rigidbody of its mass properties.
    GameObject MakeShard(FractureShard piece)
    {
        var go = new GameObject(name + " shard " + shards.Count);
        go.transform.SetPositionAndRotation(transform.position, transform.rotation);
        go.transform.localScale = transform.lossyScale;
        go.AddComponent<MeshFilter>().sharedMesh = ToUnityMesh(piece.Mesh, go.name);
        go.AddComponent<MeshRenderer>().sharedMaterials = ShardMaterials();
        MeshCollider collider = go.AddComponent<MeshCollider>();
        collider.convex = true; // a moving body's mesh collider must be convex
        collider.sharedMesh = ToUnityMesh(piece.Hull != null ? piece.Hull : piece.Mesh, go.name + " hull");
        ShardBody.Of(piece).ApplyTo(go.AddComponent<Rigidbody>());
        return go;
    }

    // One material per submesh of a shard: the object's own (or shardMaterial), then innerMaterial for
    // the cut faces' submesh (options.InnerSubmesh).
    Material[] ShardMaterials()
    {
        MeshRenderer own = GetComponent<MeshRenderer>();
        Material[] outer = own != null && own.sharedMaterials != null ? own.sharedMaterials : new Material[0];
        var materials = new Material[options.InnerSubmesh + 1];
        for (int i = 0; i < options.InnerSubmesh; ++i)
            materials[i] = shardMaterial != null ? shardMaterial : i < outer.Length ? outer[i] : null;
        materials[options.InnerSubmesh] = innerMaterial != null ? innerMaterial : materials[0];
        return materials;
    }

    // One more than the largest submesh of the mesh's faces (1 when it has none).
    static int NextSubmesh(HalfEdgeMesh mesh)
    {
        var submeshes = new int[mesh.CopyFaceSubmeshes(null)];
        mesh.CopyFaceSubmeshes(submeshes);
        int largest = 0;
        foreach (int s in submeshes) largest = s > largest ? s : largest;
        return largest + 1;
    }

    static Mesh ToUnityMesh(HalfEdgeMesh source, string meshName)
    {
        var mesh = new Mesh();
        mesh.name = meshName;
        using (RenderBuffers b = source.CreateRenderBuffers(RenderOptions.Unity))
        using (var u = new NativeMeshUploader(b, mesh))
            u.UploadAll();
        return mesh;
    }

    void OnDestroy()
    {
        if (uploader != null) uploader.Dispose();
        if (buffers != null) buffers.Dispose();
        if (halfEdgeMesh != null) halfEdgeMesh.Dispose();
        if (rendered != null) Destroy(rendered);
    }
}
