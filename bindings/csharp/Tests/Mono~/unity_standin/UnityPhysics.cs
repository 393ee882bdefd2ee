// The stand-in's GameObjects, transforms and physics components for the fracture glue
// (Runtime/Unity/ShardBody.cs, Samples~/BreakOnClick): Quaternion, Rigidbody (each assignment
// recorded), MeshRenderer, a convex MeshCollider, GameObjects created by name with a transform of
// their own. Signatures follow Unity's scripting reference; no physics runs.
using System;
using System.Collections.Generic;

namespace UnityEngine
{
    public struct Quaternion
    {
        public float x, y, z, w;
        public Quaternion(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; }
        public static Quaternion identity { get { return new Quaternion(0, 0, 0, 1); } }
    }

    public partial class GameObject
    {
        public static readonly List<GameObject> Created = new List<GameObject>();
        readonly Transform own = new Transform();
        public GameObject() { Created.Add(this); }
        public GameObject(string name) : this() { this.name = name; }
        public Transform transform { get { return own; } }
    }

    public partial class Transform
    {
        public Vector3 position { get; set; }
        public Quaternion rotation { get; set; } = Quaternion.identity;
        public Vector3 localScale { get; set; } = new Vector3(1, 1, 1);
        public Vector3 lossyScale { get { return localScale; } }
        public void SetPositionAndRotation(Vector3 p, Quaternion r) { position = p; rotation = r; }
    }

    public sealed partial class MeshCollider
    {
        public bool convex { get; set; }
    }

    public class Material : Object { }

    public sealed class MeshRenderer : Component
    {
        public Material sharedMaterial { get; set; }
        public Material[] sharedMaterials { get; set; }
    }

    public sealed class Rigidbody : Component
    {
        // Every assignment, in order: "mass", "centerOfMass", "inertiaTensor", "inertiaTensorRotation".
        public readonly List<string> Assigned = new List<string>();
        float m = 1;
        Vector3 centre, tensor = new Vector3(1, 1, 1);
        Quaternion rotation = Quaternion.identity;

        public float mass { get { return m; } set { m = value; Assigned.Add("mass"); } }
        public Vector3 centerOfMass { get { return centre; } set { centre = value; Assigned.Add("centerOfMass"); } }
        public Vector3 inertiaTensor { get { return tensor; } set { tensor = value; Assigned.Add("inertiaTensor"); } }
        public Quaternion inertiaTensorRotation
        {
            get { return rotation; }
            set { rotation = value; Assigned.Add("inertiaTensorRotation"); }
        }
    }
}
