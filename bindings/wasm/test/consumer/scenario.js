// What the consumer project does with hedge-mesh, in node and in both pages: load the module, read
// a mesh from file bytes, draw it (RenderBuffers), pick a face, split an edge and sync only what
// changed. Returns what the checks compare.
const SQUARE = 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n';

export async function scenario(loadHedge) {
  const hedge = await loadHedge();
  const mesh = hedge.fromFile(new TextEncoder().encode(SQUARE), 'square.obj');
  const render = mesh.createRenderBuffers({ normals: 'computed' });
  render.sync();
  const hit = mesh.pick([0.6, 0.4, 1], [0, 0, -1]); // near the diagonal
  mesh.splitEdge(hit.edge);
  const changed = render.sync();
  const result = {
    version: hedge.version,
    hitFace: hit.face,
    faces: mesh.counts().faces,
    problems: mesh.validate(),
    partialSync: !changed.full,
    globals: [typeof globalThis.require, typeof globalThis.__dirname],
  };
  mesh.dispose();
  return result;
}
