// hedge-mesh with three.js, as the adapter (hedge-mesh/three) is meant to be used: a geometry made
// by three.js becomes a hedge mesh, is drawn from the mesh's RenderBuffers, raycast through hedge's
// picking tree, edited, and brought up to date by a partial upload; then drawn again.
import * as THREE from 'three';
import { loadHedge } from 'hedge-mesh';
import {
  fromBufferGeometry,
  hedgeRaycast,
  syncBufferGeometry,
  toBufferGeometry,
} from 'hedge-mesh/three';

async function run() {
  const hedge = await loadHedge();
  const mesh = fromBufferGeometry(hedge, new THREE.BoxGeometry(1, 1, 1, 4, 4, 4));
  const render = mesh.createRenderBuffers();
  const geometry = toBufferGeometry(mesh, { renderBuffers: render });
  const object = new THREE.Mesh(geometry, new THREE.MeshNormalMaterial());
  object.raycast = hedgeRaycast;
  const scene = new THREE.Scene().add(object);
  const camera = new THREE.PerspectiveCamera(50, 1, 0.1, 100);
  camera.position.set(1.5, 1.2, 2.5);
  camera.lookAt(0, 0, 0);
  const renderer = new THREE.WebGLRenderer({ canvas: document.querySelector('canvas') });
  renderer.render(scene, camera);

  const raycaster = new THREE.Raycaster(
    new THREE.Vector3(0.1, 0.2, 5),
    new THREE.Vector3(0, 0, -1),
  );
  const [hit] = raycaster.intersectObject(object);
  const picked = mesh.pick([0.1, 0.2, 5], [0, 0, -1]);
  mesh.splitFace(picked.face);
  const sync = syncBufferGeometry(geometry, render);
  renderer.render(scene, camera);
  return {
    hitDistance: Math.round(hit.distance * 1000) / 1000,
    faces: mesh.counts().faces,
    problems: mesh.validate(),
    partialUpload: !sync.full && sync.ranges > 0,
    uploadedBytes: sync.bytes,
    glError: renderer.getContext().getError(),
  };
}

run().then(
  (result) => (document.querySelector('#result').textContent = JSON.stringify(result)),
  (error) =>
    (document.querySelector('#result').textContent = JSON.stringify({ error: `${error}` })),
);
