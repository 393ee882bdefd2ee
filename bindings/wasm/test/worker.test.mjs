// The worker helper (worker.js, worker_client.js): hedge's heavy calls in a worker (node's
// worker_threads runs worker.js as a module worker), results equal to the same calls on this
// thread, typed arrays transferred and not copied, errors as HedgeErrors of the same kind.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { MessageChannel } from 'node:worker_threads';
import { dist, hedge, HedgeError, sample, grid, gridArrays } from './support.mjs';

const { createHedgeWorker, HedgeWorker } = await import(new URL('worker_client.js', dist).href);
const { serveHedge } = await import(new URL('worker.js', dist).href);

const SPOT = 'spot_triangulated.obj';

/** Every typed array in value, depth first. */
function typedArrays(value, out = []) {
  if (ArrayBuffer.isView(value)) out.push(value);
  else if (Array.isArray(value)) value.forEach((v) => typedArrays(v, out));
  else if (value && typeof value === 'object')
    Object.values(value).forEach((v) => typedArrays(v, out));
  return out;
}

/** The draw buffers as worker.js's buffers() makes them, on this thread. */
function localBuffers(mesh) {
  const render = mesh.createRenderBuffers({
    normals: 'auto',
    interleaved: false,
    texcoords: false,
    colors: false,
  });
  render.sync();
  const out = {
    positions: render.vertices.slice(),
    indices: render.indices.slice(),
    normals: render.normals.slice(),
  };
  render.dispose();
  return out;
}

test('solid fracture in a worker gives what it gives here, the pieces kept there', async () => {
  const remote = await createHedgeWorker();
  try {
    const local = hedge.fromFile(sample(SPOT), SPOT);
    const { id } = await remote.load(sample(SPOT), SPOT);
    const at = local.pick([0, 2, 0.1], [0, -1, 0]).point;
    const options = { material: 'stone', seed: 3, radiusFraction: 0.2 };
    const here = local.fractureSolid(at, options);
    const there = await remote.fractureSolid(id, at, options);
    assert.equal(there.kind, 'solid');
    assert.ok(here.pieces.length >= 2);
    assert.equal(there.pieces.length, here.pieces.length);
    assert.deepEqual(there.bonds, here.bonds);
    for (let i = 0; i < here.pieces.length; ++i) {
      const { id: pieceId, ...values } = there.pieces[i];
      const { mesh, ...expected } = here.pieces[i];
      assert.deepEqual(values, { ...expected });
      assert.deepEqual(await remote.counts(pieceId), mesh.counts());
      assert.deepEqual(await remote.validate(pieceId), []);
      await remote.dispose(pieceId);
      mesh.dispose();
    }
    assert.deepEqual(await remote.counts(id), local.counts());
    assert.deepEqual(await remote.validate(id), []);
    await assert.rejects(remote.fractureSolid(id, [NaN, 0, 0]), { kind: 'invalid-argument' });
    local.dispose();
  } finally {
    await remote.terminate();
  }
});

test('the worker answers the solid refusal as here, and kind auto falls back by its code', async () => {
  const remote = await createHedgeWorker();
  try {
    // A plate is open: struck near its border, solid fracture is refused for its shape.
    const plate = grid(20);
    const { id } = await remote.fromBuffers(gridArrays(20));
    const near = [1.2, 1.7, 0];
    const off = [1.2, 1.7, 3];
    const why = plate.solidFractureRefusal(near);
    assert.match(why, /open/);
    assert.equal(await remote.solidFractureRefusal(id, near), why);
    assert.equal(await remote.solidFractureRefusalCode(id, near), 'open');
    assert.equal(await remote.solidFractureRefusalCode(id, off), 'off_surface');
    assert.equal(
      await remote.solidFractureRefusalCode(id, near, { density: -1 }),
      plate.solidFractureRefusalCode(near, { density: -1 }),
    );
    // 'auto': the shape's refusal breaks the surface, its code and text in the result.
    const options = { kind: 'auto', material: 'glass', seed: 1 };
    const here = plate.fractureSolid(near, options);
    const there = await remote.fractureSolid(id, near, options);
    assert.equal(there.kind, 'surface');
    assert.equal(there.refusalCode, 'open');
    assert.equal(there.refusal, why);
    assert.equal(there.shards.length, here.shards.length);
    assert.ok(there.shards.length > 0);
    for (const shard of there.shards) {
      assert.deepEqual(await remote.validate(shard.id), []);
      await remote.dispose(shard.id);
    }
    assert.deepEqual(await remote.counts(id), plate.counts());
    assert.deepEqual(await remote.validate(id), []);
    // Any other refusal rejects with 'auto' too, the mesh unchanged.
    await assert.rejects(remote.fractureSolid(id, off, { kind: 'auto' }), {
      kind: 'invalid-argument',
      message: /fracture_solid: the impact/,
    });
    assert.deepEqual(await remote.counts(id), plate.counts());
    here.shards.forEach((s) => s.dispose());
    plate.dispose();
    await remote.dispose(id);
    // A closed mesh: no refusal.
    const local = hedge.fromFile(sample(SPOT), SPOT);
    const loaded = await remote.load(sample(SPOT), SPOT);
    const at = local.pick([0, 2, 0.1], [0, -1, 0]).point;
    assert.equal(await remote.solidFractureRefusalCode(loaded.id, at), 'none');
    assert.equal(await remote.solidFractureRefusal(loaded.id, at), null);
    // A point that is not one rejects, as the call throws here.
    assert.throws(() => local.solidFractureRefusalCode([NaN, 0, 0]), { kind: 'invalid-argument' });
    await assert.rejects(remote.solidFractureRefusalCode(loaded.id, [NaN, 0, 0]), {
      kind: 'invalid-argument',
      message: /not finite/,
    });
    await assert.rejects(remote.solidFractureRefusalCode(loaded.id, undefined), {
      kind: 'invalid-argument',
      message: /solidFractureRefusalCode: impact/,
    });
    local.dispose();
  } finally {
    await remote.terminate();
  }
});

test('load, subdivide, decimate, pick and fracture in a worker give what they give here', async () => {
  const remote = await createHedgeWorker();
  try {
    assert.equal(await remote.version(), hedge.version);
    const local = hedge.fromFile(sample(SPOT), SPOT);
    const loaded = await remote.load(sample(SPOT), SPOT);
    assert.deepEqual(loaded.counts, local.counts());
    assert.deepEqual(loaded.report, local.buildReport());
    const { id } = loaded;

    local.subdivide('loop', 1);
    assert.deepEqual(await remote.subdivide(id, 'loop', 1), local.counts());
    assert.deepEqual(await remote.decimate(id, { ratio: 0.5 }), local.decimate({ ratio: 0.5 }));

    const tree = await remote.buildPickingTree(id);
    assert.ok(tree.seconds >= 0);
    const rays = new Float32Array([0, 0, 5, 0, 0, -1, 0.1, 0.5, 5, 0, 0, -1, 9, 9, 9, 1, 0, 0]);
    assert.deepEqual(await remote.pickMany(id, rays), local.pickMany(rays));
    assert.deepEqual(
      await remote.pick(id, [0, 0.5, 5], [0, 0, -1]),
      local.pick([0, 0.5, 5], [0, 0, -1]),
    );

    const got = await remote.buffers(id);
    assert.deepEqual(got, localBuffers(local));
    assert.ok(got.positions.length > 0 && got.indices.length > 0 && got.normals.length > 0);

    const at = local.position(100);
    const options = { material: 'wood', seed: 5 };
    const here = local.fracture(at, options);
    const there = await remote.fracture(id, at, options);
    assert.equal(there.shards.length, here.shards.length);
    assert.deepEqual(there.impactPoint, here.impactPoint);
    for (let i = 0; i < here.shards.length; ++i) {
      const { id: shardId, ...values } = there.shards[i];
      const { mesh, ...expected } = here.shards[i];
      assert.deepEqual(values, { ...expected });
      assert.deepEqual(await remote.counts(shardId), mesh.counts());
      assert.deepEqual(await remote.validate(shardId), []);
      await remote.dispose(shardId);
      mesh.dispose();
    }
    assert.deepEqual(await remote.counts(id), local.counts());
    assert.deepEqual(await remote.toArrays(id), local.toArrays());
    assert.deepEqual(await remote.validate(id), []);
    assert.deepEqual(local.validate(), []);
    await remote.dispose(id);
    local.dispose();
  } finally {
    remote.terminate();
  }
});

test('an error in the worker arrives as a HedgeError of the same kind and message', async () => {
  const remote = await createHedgeWorker();
  try {
    const bad = new TextEncoder().encode('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n');
    let thrown;
    try {
      hedge.fromFile(bad, 'bad.obj');
    } catch (e) {
      thrown = e;
    }
    assert.ok(thrown instanceof HedgeError);
    await assert.rejects(remote.load(bad, 'bad.obj'), (e) => {
      assert.ok(e instanceof HedgeError, `${e}`);
      assert.equal(e.kind, thrown.kind);
      assert.equal(e.message, thrown.message);
      return true;
    });

    const { id } = await remote.fromBuffers(gridArrays(2));
    await assert.rejects(remote.subdivide(id, 'nonsense', 1), {
      name: 'HedgeError',
      kind: 'invalid-argument',
    });
    await assert.rejects(remote.fracture(id, [NaN, 0, 0]), { kind: 'invalid-argument' });
    await assert.rejects(remote.pick(id, null, [0, 0, 1]), {
      kind: 'invalid-argument',
      message: /^pick: origin/,
    });
    await remote.dispose(id);
    await assert.rejects(remote.counts(id), {
      kind: 'bad-handle',
      message: `worker: no mesh ${id} (disposed, or never made)`,
    });
    await assert.rejects(remote.call('nonsense'), { kind: 'invalid-argument' });
    // The worker still answers after its errors.
    const again = await remote.fromBuffers(gridArrays(2));
    assert.deepEqual(await remote.validate(again.id), []);
  } finally {
    remote.terminate();
  }
  await assert.rejects(remote.counts(1), { kind: 'bad-handle' });
});

test('the typed arrays of a result are transferred: the worker side is left detached', async () => {
  const { port1, port2 } = new MessageChannel();
  // Every message the serving side posts, with its transfer list, as it was posted.
  const posted = [];
  const post = port1.postMessage.bind(port1);
  port1.postMessage = (message, transfer) => {
    post(message, transfer);
    posted.push({ message, transfer: transfer ?? [] });
  };
  const served = serveHedge(port1);
  const remote = new HedgeWorker(port2);
  try {
    const { id } = await remote.load(sample(SPOT), SPOT);
    const cases = [
      ['buffers', [id]],
      ['toArrays', [id, { triangulate: true }]],
      ['toFile', [id, 'out.ply']],
      ['pickMany', [id, new Float32Array([0, 0.5, 5, 0, 0, -1])]],
      ['fracture', [id, (await remote.toArrays(id)).positions.subarray(300, 303)]],
    ];
    for (const [op, args] of cases) {
      const got = await remote.call(op, args);
      const sent = posted.at(-1);
      const arrays = typedArrays(sent.message.value);
      assert.ok(arrays.length > 0, `${op}: no typed array in the result`);
      assert.ok(sent.transfer.length > 0, `${op}: an empty transfer list`);
      for (const a of arrays) {
        assert.ok(sent.transfer.includes(a.buffer), `${op}: a buffer not in the transfer list`);
        assert.equal(a.buffer.byteLength, 0, `${op}: the worker's copy was not detached`);
      }
      const received = typedArrays(got);
      assert.equal(received.length, arrays.length);
      assert.ok(
        received.some((a) => a.length > 0),
        `${op}: nothing arrived`,
      );
      if (op === 'fracture') for (const s of got.shards) await remote.dispose(s.id);
    }
    assert.deepEqual(await remote.validate(id), []);
    await remote.dispose(id);
    assert.equal((await served.loading).meshes.size, 0);
  } finally {
    served.close();
    port1.close();
    port2.close();
  }
});

test('load with transfer: true hands the file bytes over instead of copying them', async () => {
  const { port1, port2 } = new MessageChannel();
  const served = serveHedge(port1);
  const remote = new HedgeWorker(port2);
  try {
    const bytes = sample(SPOT);
    const { id } = await remote.load(bytes, SPOT, { transfer: true });
    assert.equal(bytes.byteLength, 0);
    const copied = sample(SPOT);
    const second = await remote.load(copied, SPOT);
    assert.ok(copied.byteLength > 0);
    assert.deepEqual(await remote.validate(id), []);
    await remote.dispose(id);
    await remote.dispose(second.id);
  } finally {
    served.close();
    port1.close();
    port2.close();
  }
});

/** Runs call() while a 1 ms timer keeps firing on this thread: how often it fired meanwhile. */
async function ticksDuring(call) {
  let ticks = 0;
  let done = false;
  const tick = () => {
    if (done) return;
    ++ticks;
    setTimeout(tick, 1);
  };
  setTimeout(tick, 1);
  try {
    await call();
  } finally {
    done = true;
  }
  return ticks;
}

test('this thread keeps running while the worker subdivides and builds the picking tree', async () => {
  const heavy = async (remote) => {
    const { id } = await remote.load(sample(SPOT), SPOT);
    const ticks = await ticksDuring(async () => {
      await remote.subdivide(id, 'loop', 3);
      await remote.buildPickingTree(id);
    });
    assert.deepEqual(await remote.validate(id), []);
    await remote.dispose(id);
    return ticks;
  };
  const remote = await createHedgeWorker();
  let inWorker;
  try {
    inWorker = await heavy(remote);
  } finally {
    remote.terminate();
  }
  // The same calls served on this thread block it: the control that shows what is measured.
  const { port1, port2 } = new MessageChannel();
  const served = serveHedge(port1);
  let here;
  try {
    here = await heavy(new HedgeWorker(port2));
  } finally {
    served.close();
    port1.close();
    port2.close();
  }
  assert.ok(inWorker >= 5, `the timer fired ${inWorker} times while the worker ran`);
  assert.ok(here < inWorker, `served here ${here} ticks, in a worker ${inWorker}`);
});
