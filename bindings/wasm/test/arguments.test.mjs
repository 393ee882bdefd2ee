// Wrong arguments to every call of the JS API (arguments.js): each throws a HedgeError of kind
// 'invalid-argument' that names the call and the argument, before the call runs, and leaves the
// mesh as it was.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { hedge, HedgeError, grid, sample } from './support.mjs';

const mesh = grid(2);
const render = mesh.createRenderBuffers();

// Values that are no element index, no point, no string.
const NOT_ELEMENT = [null, undefined, '1', 1.5, [0], {}];
const NOT_POINT = [null, '1,2,3', [1, 2], [1, 2, 3, 4], new Float32Array(2), [1, 'a', 3], {}, 7];
const NOT_POINT_OR_NOTHING = NOT_POINT.filter((x) => x !== undefined && x !== null).concat([null]);
const NOT_STRING = [null, undefined, 3, {}, ['loop']];
const NOT_OPTIONS = [null, 3, 'fast', [1]];

// [call, good arguments, index of the argument to spoil, its name in the message, bad values].
const E = (call, args, at, name) => [call, args, at, name, NOT_ELEMENT];
const meshCases = [
  E('position', [0], 0, 'v'),
  ['setPosition', [0, [0, 0, 0]], 1, 'point', NOT_POINT.concat([undefined])],
  E('setPosition', [0, [0, 0, 0]], 0, 'v'),
  E('halfedge', [0], 0, 'h'),
  E('vertex', [0], 0, 'v'),
  E('edge', [0], 0, 'e'),
  E('face', [0], 0, 'f'),
  E('oneRing', [0], 0, 'v'),
  [
    'pick',
    [
      [0.5, 0.5, 1],
      [0, 0, -1],
    ],
    0,
    'origin',
    NOT_POINT.concat([undefined]),
  ],
  [
    'pick',
    [
      [0.5, 0.5, 1],
      [0, 0, -1],
    ],
    1,
    'direction',
    NOT_POINT.concat([undefined]),
  ],
  ['pickMany', [new Float32Array(6)], 0, 'rays', [null, undefined, new Float32Array(7), 'rays']],
  ['pickMany', [new Float32Array(6), new Int32Array(1)], 1, 'out', [null, [0], new Uint32Array(1)]],
  ['refusal', ['flip', 0], 0, 'edit', NOT_STRING],
  ['refusal', ['cutFace', 0, 1], 2, 'elements[1]', NOT_ELEMENT.filter((x) => x !== undefined)],
  ['whyNot', ['flip', 0], 0, 'op', NOT_STRING],
  E('whyNot', ['flip', 0], 1, 'element'),
  E('canSplitEdge', [0], 0, 'e'),
  E('canFlip', [0], 0, 'e'),
  E('canCollapse', [0], 0, 'h'),
  E('canSplitFace', [0], 0, 'f'),
  E('canCutFace', [0, 1], 0, 'h0'),
  E('canCutFace', [0, 1], 1, 'h1'),
  E('canFillHole', [0], 0, 'h'),
  E('splitEdge', [0], 0, 'e'),
  ['splitEdge', [0, [0, 0, 0]], 1, 'point', NOT_POINT_OR_NOTHING],
  E('flip', [0], 0, 'e'),
  E('collapse', [0], 0, 'h'),
  ['collapse', [0, [0, 0, 0]], 1, 'point', NOT_POINT_OR_NOTHING],
  E('splitFace', [0], 0, 'f'),
  ['splitFace', [0, [0, 0, 0]], 1, 'point', NOT_POINT_OR_NOTHING],
  E('cutFace', [0, 1], 0, 'h0'),
  E('cutFace', [0, 1], 1, 'h1'),
  E('fillHole', [0], 0, 'h'),
  ['subdivide', ['loop', 1], 0, 'scheme', NOT_STRING.filter((x) => x !== undefined)],
  ['subdivide', ['loop', 1], 1, 'steps', [null, -1, 1.5, '2']],
  ['smooth', [{}], 0, 'options', NOT_OPTIONS],
  ['smooth', [{ iterations: 'ten' }], 0, 'options.iterations', [{ iterations: 'ten' }]],
  ['smooth', [{}], 0, 'options.method', [{ method: 3 }]],
  ['decimate', [{}], 0, 'options', NOT_OPTIONS],
  ['decimate', [{}], 0, 'options.ratio', [{ ratio: 'half' }, { ratio: null }]],
  ['decimate', [{}], 0, 'options.targetFaces', [{ targetFaces: -3 }, { targetFaces: '10' }]],
  ['decimate', [{}], 0, 'options.relaxNormalChange', [{ relaxNormalChange: 1 }]],
  ['computeCornerNormals', [45], 0, 'creaseDegrees', ['wide', [45]]],
  ['fracture', [[0.5, 0.5, 0]], 0, 'impact', NOT_POINT.concat([undefined])],
  ['fracture', [[0.5, 0.5, 0], {}], 1, 'options', NOT_OPTIONS],
  ['fracture', [[0.5, 0.5, 0], {}], 1, 'options.seed', [{ seed: '4' }]],
  ['fractureSolid', [[0.5, 0.5, 0]], 0, 'impact', NOT_POINT.concat([undefined])],
  ['fractureSolid', [[0.5, 0.5, 0], {}], 1, 'options', NOT_OPTIONS],
  ['fractureSolid', [[0.5, 0.5, 0], {}], 1, 'options.radius', [{ radius: '1' }]],
  ['fractureSolid', [[0.5, 0.5, 0], {}], 1, 'options.hulls', [{ hulls: 1 }]],
  ['fractureSolid', [[0.5, 0.5, 0], {}], 1, 'options.kind', [{ kind: 2 }]],
  ['fractureSolid', [[0.5, 0.5, 0], {}], 1, 'options.surface', [{ surface: 'thick' }]],
  ['solidFractureRefusal', [[0.5, 0.5, 0]], 0, 'impact', NOT_POINT.concat([undefined])],
  ['solidFractureRefusal', [[0.5, 0.5, 0], {}], 1, 'options', NOT_OPTIONS],
  ['solidFractureRefusal', [[0.5, 0.5, 0], {}], 1, 'options.seed', [{ seed: '4' }]],
  ['solidFractureRefusalCode', [[0.5, 0.5, 0]], 0, 'impact', NOT_POINT.concat([undefined])],
  ['solidFractureRefusalCode', [[0.5, 0.5, 0], {}], 1, 'options.seed', [{ seed: '4' }]],
  ['toArrays', [{}], 0, 'options', NOT_OPTIONS],
  ['toFile', ['m.obj'], 0, 'name', NOT_STRING],
  ['createRenderBuffers', [{}], 0, 'options', NOT_OPTIONS],
  ['createRenderBuffers', [{}], 0, 'options.normals', [{ normals: 1 }]],
];
const hedgeCases = [
  ['fromBuffers', [{}], 0, 'arrays', [null, undefined, 'grid', [1]]],
  [
    'fromBuffers',
    [{}],
    0,
    'arrays.positions',
    [{ indices: [0, 1, 2] }, { positions: 3, indices: [] }],
  ],
  ['fromBuffers', [{}], 0, 'arrays.indices', [{ positions: [0, 0, 0] }]],
  ['fromBuffers', [{}], 0, 'arrays.faceSizes', [{ positions: [], indices: [], faceSizes: 3 }]],
  ['fromEngineStreams', [{}], 0, 'streams', [null, undefined, 'grid', [1]]],
  ['fromEngineStreams', [{}], 0, 'streams.positions', [{ indices: [0, 1, 2] }]],
  ['fromEngineStreams', [{}], 0, 'streams.indices', [{ positions: [0, 0, 0] }]],
  [
    'fromEngineStreams',
    [{}],
    0,
    'streams.texcoords',
    [{ positions: [], indices: [], texcoords: 2 }],
  ],
  [
    'fromEngineStreams',
    [{}],
    0,
    'streams.submeshes',
    [{ positions: [], indices: [], submeshes: 'a' }],
  ],
  ['fromFile', [sample('tet.obj'), 'tet.obj'], 0, 'bytes', [null, undefined, 'v 0 0 0', [118]]],
  ['fromFile', [sample('tet.obj'), 'tet.obj'], 1, 'name', NOT_STRING],
  ['setMaxThreads', [1], 0, 'n', [null, undefined, -1, 1.5, '2']],
];
const renderCases = [
  E('faceTriangles', [0], 0, 'f'),
  [
    'pickTriangles',
    [
      [0, 0, 1],
      [0, 0, -1],
    ],
    0,
    'origin',
    NOT_POINT,
  ],
  [
    'pickTriangles',
    [
      [0, 0, 1],
      [0, 0, -1],
    ],
    1,
    'direction',
    NOT_POINT,
  ],
  ['dirtyViews', [{}], 0, 'result', [null, undefined, 3]],
  ['dirtyViews', [{}], 0, 'result.vertexRanges', [{ indexRanges: [] }]],
];

function expectInvalid(target, [call, args, at, name, values]) {
  for (const value of values) {
    const spoiled = [...args];
    spoiled[at] = value;
    assert.throws(
      () => target[call](...spoiled),
      (e) => {
        assert.ok(e instanceof HedgeError, `${call}: ${e}`);
        assert.equal(e.kind, 'invalid-argument', e.message);
        assert.ok(e.message.startsWith(`${call}: ${name} must be `), e.message);
        return true;
      },
      `${call} with ${name} = ${String(value)}`,
    );
  }
}

test('every call given a wrong argument throws invalid-argument naming the call and the argument', () => {
  const before = mesh.toArrays();
  for (const c of meshCases) expectInvalid(mesh, c);
  for (const c of hedgeCases) expectInvalid(hedge, c);
  for (const c of renderCases) expectInvalid(render, c);
  // Nothing was changed.
  assert.deepEqual(mesh.toArrays(), before);
  assert.deepEqual(mesh.validate(), []);
});

test('the messages say what the argument must be and what it was', () => {
  assert.throws(
    () => mesh.pick(null, [0, 0, -1]),
    (e) =>
      e.kind === 'invalid-argument' &&
      e.message ===
        'pick: origin must be [x, y, z] (an array or typed array of 3 numbers), got null',
  );
  assert.throws(
    () => mesh.position('2'),
    (e) => e.message === "position: v must be an element index (a whole number), got '2'",
  );
  assert.throws(
    () => mesh.pickMany(new Float32Array(7)),
    (e) =>
      e.message ===
      'pickMany: rays must be a Float32Array of 6 numbers per ray, got a Float32Array of 7',
  );
  assert.deepEqual(mesh.validate(), []);
});

test('every public call with arguments is checked', () => {
  // Calls that take no arguments need no check; every other public method must have cases above.
  const noArguments = new Set([
    'constructor',
    'clone',
    'buildReport',
    'counts',
    'validate',
    'isValid',
    'isTriangleMesh',
    'garbageCollection',
    'memoryBytes',
    'dispose',
    'maxThreads',
    'heapBytesInUse',
    'sizes',
    'submeshes',
    'sync',
    'rebuild',
    'compact',
    'begin',
    'commit',
    'createRender', // deprecated: calls createRenderBuffers, which is checked
  ]);
  for (const [object, cases] of [
    [mesh, meshCases],
    [hedge, hedgeCases],
    [render, renderCases],
  ]) {
    const covered = new Set(cases.map(([call]) => call));
    for (let proto = Object.getPrototypeOf(object); proto !== Object.prototype;) {
      for (const [name, d] of Object.entries(Object.getOwnPropertyDescriptors(proto))) {
        if (typeof d.value !== 'function' || name.startsWith('_') || noArguments.has(name))
          continue;
        assert.ok(covered.has(name), `${name} has no wrong-argument cases`);
      }
      proto = Object.getPrototypeOf(proto);
    }
  }
});

test('no message repeats its call name ("decimate: decimate: ...")', () => {
  const quads = hedge.fromBuffers({
    positions: new Float32Array([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]),
    indices: new Uint32Array([0, 1, 2, 3]),
    faceSizes: new Uint32Array([4]),
  });
  const failing = [
    () => quads.decimate({ targetFaces: 1 }),
    () => quads.decimate({ ratio: 2 }),
    () => quads.smooth({ method: 'cotangent' }),
    () => quads.subdivide('loop'),
    () => quads.subdivide('sqrt3'),
    () => quads.fracture([0.5, 0.5, 0], { material: { rings: 3 } }),
    () => quads.fracture([9, 9, 9]),
    () => quads.fractureSolid([0.5, 0.5, 0], { material: { rings: 3 } }),
    () => quads.fractureSolid([0.5, 0.5, 0], { seed: 0.5 }),
    () => quads.fractureSolid([0.5, 0.5, 0]),
    () => mesh.pick(null, null),
    () => hedge.fromFile(new Uint8Array([1, 2, 3]), 'm.obj'),
  ];
  for (const f of failing) {
    assert.throws(f, (e) => {
      assert.ok(e instanceof HedgeError, String(e));
      assert.doesNotMatch(e.message, /^([^:]+): \1:/, e.message);
      return true;
    });
  }
  assert.deepEqual(quads.validate(), []);
  quads.dispose();
});
