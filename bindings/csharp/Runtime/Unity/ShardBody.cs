// A shard's mass properties as Unity's Rigidbody takes them: mass, centerOfMass, inertiaTensor (the
// principal moments) and inertiaTensorRotation (the rotation of the principal axes). The binding
// keeps doubles in the mesh's own coordinates; here they become floats, the coordinates unchanged.
// A mesh read from a Unity Mesh (UnityMeshes.FromUnityMesh) keeps Unity's local coordinates, so its
// shards' values are in the object's local space, as Rigidbody wants them: the tensor and its
// rotation are the same numbers in a left-handed frame (R diag(m) R^T does not depend on the
// handedness the numbers are read in). A mesh whose axes were changed on the way in (x mirrored, for
// one) needs the same change on the way out.
using System;
using UnityEngine;

namespace Hedge.Unity
{
    /// <summary>What a Unity Rigidbody needs from a <see cref="FractureShard"/>.</summary>
    public struct ShardBody
    {
        /// <summary>The shard's mass at the options' density (0 when the shard is open: give a thickness).</summary>
        public float mass;
        /// <summary>The centre of mass, in the shard mesh's coordinates.</summary>
        public Vector3 centerOfMass;
        /// <summary>The principal moments of inertia about the centre of mass, ascending.</summary>
        public Vector3 inertiaTensor;
        /// <summary>The rotation of the principal axes: with R its matrix, the full tensor is
        /// R diag(inertiaTensor) R^T.</summary>
        public Quaternion inertiaTensorRotation;

        /// <summary>The shard's values (FractureShard.Mass, CentreOfMass, PrincipalMoments, PrincipalRotation()).</summary>
        /// An open shard (no thickness) has the mass properties of a thin shell (FractureOptions.ShellThickness).
        /// <exception cref="ArgumentException">The shard has no mass (no area).</exception>
        public static ShardBody Of(FractureShard shard)
        {
            if (shard == null) throw new ArgumentNullException("shard");
            if (!(shard.Mass > 0))
                throw new ArgumentException("the shard has no mass (no area)", "shard");
            double[] c = shard.CentreOfMass, m = shard.PrincipalMoments, q = shard.PrincipalRotation();
            return new ShardBody
            {
                mass = (float)shard.Mass,
                centerOfMass = new Vector3((float)c[0], (float)c[1], (float)c[2]),
                inertiaTensor = new Vector3((float)m[0], (float)m[1], (float)m[2]),
                inertiaTensorRotation = new Quaternion((float)q[0], (float)q[1], (float)q[2], (float)q[3]),
            };
        }

        /// <summary>A solid fracture piece's values (SolidPiece.Mass, CentreOfMass, PrincipalMoments,
        /// PrincipalRotation()): a piece is always closed, with mass.</summary>
        public static ShardBody Of(SolidPiece piece)
        {
            if (piece == null) throw new ArgumentNullException("piece");
            double[] c = piece.CentreOfMass, m = piece.PrincipalMoments, q = piece.PrincipalRotation();
            return new ShardBody
            {
                mass = (float)piece.Mass,
                centerOfMass = new Vector3((float)c[0], (float)c[1], (float)c[2]),
                inertiaTensor = new Vector3((float)m[0], (float)m[1], (float)m[2]),
                inertiaTensorRotation = new Quaternion((float)q[0], (float)q[1], (float)q[2], (float)q[3]),
            };
        }

        /// <summary>Sets the body's mass, centerOfMass, inertiaTensor and inertiaTensorRotation to these values
        /// (which turns off Unity's automatic centre and tensor for it).</summary>
        public void ApplyTo(Rigidbody body)
        {
            if (body == null) throw new ArgumentNullException("body");
            body.mass = mass;
            body.centerOfMass = centerOfMass;
            body.inertiaTensor = inertiaTensor;
            body.inertiaTensorRotation = inertiaTensorRotation;
        }
    }
}
