// The stand-in's Mesh.isReadable. In Unity it is read-only and comes from the model's import
// settings (Read/Write); a mesh without it gives empty vertex and triangle arrays to scripts. The
// stand-in lets tests set it, and then gives empty arrays as Unity does.
namespace UnityEngine
{
    public sealed partial class Mesh
    {
        bool readable = true;

        public bool isReadable
        {
            get { return readable; }
            set
            {
                readable = value;
                if (!value)
                {
                    vertices = new Vector3[0];
                    normals = new Vector3[0];
                    uv = new Vector2[0];
                    colors = new Color[0];
                    triangles = new int[0];
                }
            }
        }
    }
}
