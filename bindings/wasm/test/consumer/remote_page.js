// hedge-mesh/worker: the page starts hedge's worker (worker.js, bundled by vite from the
// package's own `new Worker(new URL(...))`), loads a mesh there, picks it, and takes its draw
// buffers back; shows what it computed.
import { createHedgeWorker } from 'hedge-mesh/worker';

const SQUARE = 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n';
const show = (value) => (document.querySelector('#result').textContent = JSON.stringify(value));

async function run() {
  const remote = await createHedgeWorker();
  const { id, counts } = await remote.load(new TextEncoder().encode(SQUARE), 'square.obj');
  const hit = await remote.pick(id, [0.6, 0.4, 1], [0, 0, -1]);
  const { positions, indices } = await remote.buffers(id);
  let kind = null;
  try {
    await remote.subdivide(id, 'nonsense', 1);
  } catch (e) {
    kind = `${e.name}: ${e.kind}`;
  }
  const result = {
    version: await remote.version(),
    faces: counts.faces,
    hitFace: hit.face,
    drawn: [positions.length, indices.length],
    problems: await remote.validate(id),
    error: kind,
  };
  remote.terminate();
  return result;
}

run().then(show, (error) => show({ error: `${error}` }));
