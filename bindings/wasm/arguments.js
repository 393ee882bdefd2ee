// The arguments of hedge's JS API (hedge.js), checked and converted before a call.
//
// Every public call's arguments are checked here, in one place, before the call runs: a wrong one
// (null, undefined, a wrong type, an array of the wrong length) throws a HedgeError of kind
// 'invalid-argument' naming the call and the argument ("pick: origin must be [x, y, z] ..., got
// null"). Checking before the call matters: a JS exception raised inside the module (converting a
// bad value) would unwind wasm frames without their destructors. Values of the right type that the
// library refuses (an element out of range, an unknown scheme) are the library's to report.

import { HedgeError } from './native.js';

export const isArrayLike = (x) => ArrayBuffer.isView(x) || Array.isArray(x);
const isNumber = (x) => typeof x === 'number';
//! The units of a fracture's break radius (FractureUnits in fracture.h).
export const UNITS = Object.freeze(['diagonal_fraction', 'model', 'edge_lengths']);
/** A point the argument check has approved, as the module takes it. */
export const point3 = (p) => Array.from(p, Number);

const describe = (x) => {
  if (x === null || x === undefined) return String(x);
  if (typeof x === 'string') return `'${x.length > 40 ? `${x.slice(0, 40)}...` : x}'`;
  if (typeof x === 'number' || typeof x === 'boolean') return String(x);
  if (Array.isArray(x)) return `an array of ${x.length}`;
  if (ArrayBuffer.isView(x)) return `a ${x.constructor.name} of ${x.length}`;
  return `a ${typeof x === 'object' ? (x.constructor?.name ?? 'object') : typeof x}`;
};

// An argument kind: what it must be, in words, and its test.
const kind = (text, test) => ({ text, test });
const optional = (k) => kind(`${k.text} or undefined`, (x) => x === undefined || k.test(x));
const ELEMENT = kind('an element index (a whole number)', Number.isInteger);
const COUNT = kind('a whole number >= 0', (x) => Number.isInteger(x) && x >= 0);
const NUMBER = kind('a number', isNumber);
const STRING = kind('a string', (x) => typeof x === 'string');
const BOOLEAN = kind('a boolean', (x) => typeof x === 'boolean');
const VEC3 = kind('[x, y, z] (an array or typed array of 3 numbers)', (x) => {
  if (!isArrayLike(x) || x.length !== 3) return false;
  for (let i = 0; i < 3; ++i) if (typeof x[i] !== 'number') return false;
  return true;
});
const OBJECT = kind('an object', (x) => x !== null && typeof x === 'object' && !Array.isArray(x));
const ARRAY = kind('an array or typed array', isArrayLike);
const BYTES = kind(
  'a Uint8Array or ArrayBuffer',
  (x) => x instanceof Uint8Array || x instanceof ArrayBuffer,
);
const RAYS = kind(
  'a Float32Array of 6 numbers per ray',
  (x) => isArrayLike(x) && x.length % 6 === 0,
);
const NOTHING_OR_ARRAY = kind(
  'an array, a typed array or nothing',
  (x) => x == null || isArrayLike(x),
);
// An options object (or nothing): its named fields, when present, checked as the kinds given.
const options = (fields) => ({
  ...optional(OBJECT),
  fields: Object.fromEntries(Object.entries(fields).map(([n, k]) => [n, optional(k)])),
});
const e = (name) => [name, ELEMENT];
// The arguments of the two questions asked before a solid strike (why not, and its code).
const SOLID_CHECK = [
  ['impact', VEC3],
  [
    'options',
    options({
      seed: NUMBER,
      radius: NUMBER,
      radiusFraction: NUMBER,
      innerSubmesh: NUMBER,
      density: NUMBER,
      tolerance: NUMBER,
    }),
  ],
];

const ARGUMENTS = {
  Hedge: {
    fromBuffers: [
      [
        'arrays',
        {
          ...OBJECT,
          fields: {
            positions: ARRAY,
            indices: ARRAY,
            faceSizes: NOTHING_OR_ARRAY,
            policy: optional(STRING),
            weld: optional(STRING),
          },
        },
      ],
    ],
    fromEngineStreams: [
      [
        'streams',
        {
          ...OBJECT,
          fields: {
            positions: ARRAY,
            indices: ARRAY,
            normals: NOTHING_OR_ARRAY,
            texcoords: NOTHING_OR_ARRAY,
            colors: NOTHING_OR_ARRAY,
            submeshes: NOTHING_OR_ARRAY,
            policy: optional(STRING),
            weld: optional(STRING),
          },
        },
      ],
    ],
    fromFile: [
      ['bytes', BYTES],
      ['name', STRING],
    ],
    setMaxThreads: [['n', COUNT]],
  },
  Mesh: {
    position: [e('v')],
    setPosition: [e('v'), ['point', VEC3]],
    halfedge: [e('h')],
    vertex: [e('v')],
    edge: [e('e')],
    face: [e('f')],
    oneRing: [e('v')],
    pick: [
      ['origin', VEC3],
      ['direction', VEC3],
    ],
    pickMany: [
      ['rays', RAYS],
      ['out', optional(kind('an Int32Array', (x) => x instanceof Int32Array))],
    ],
    refusal: [
      ['edit', STRING],
      ['...elements', ELEMENT],
    ],
    whyNot: [['op', STRING], e('element')],
    canSplitEdge: [e('e')],
    canFlip: [e('e')],
    canCollapse: [e('h')],
    canSplitFace: [e('f')],
    canCutFace: [e('h0'), e('h1')],
    canFillHole: [e('h')],
    splitEdge: [e('e'), ['point', optional(VEC3)]],
    flip: [e('e')],
    collapse: [e('h'), ['point', optional(VEC3)]],
    splitFace: [e('f'), ['point', optional(VEC3)]],
    cutFace: [e('h0'), e('h1')],
    fillHole: [e('h')],
    subdivide: [
      ['scheme', optional(STRING)],
      ['steps', optional(COUNT)],
    ],
    smooth: [
      ['options', options({ method: STRING, iterations: COUNT, lambda: NUMBER, mu: NUMBER })],
    ],
    decimate: [
      [
        'options',
        options({
          ratio: NUMBER,
          targetFaces: COUNT,
          targetVertices: COUNT,
          maxError: NUMBER,
          relaxNormalChange: BOOLEAN,
        }),
      ],
    ],
    fracture: [
      ['impact', VEC3],
      [
        'options',
        options({
          seed: NUMBER,
          breakRadius: NUMBER,
          units: optional(STRING),
          radius: NUMBER,
          thickness: NUMBER,
          density: NUMBER,
          shellThickness: NUMBER,
          tolerance: NUMBER,
        }),
      ],
    ],
    fractureSolid: [
      ['impact', VEC3],
      [
        'options',
        options({
          kind: STRING,
          surface: OBJECT,
          seed: NUMBER,
          radius: NUMBER,
          radiusFraction: NUMBER,
          innerSubmesh: NUMBER,
          density: NUMBER,
          tolerance: NUMBER,
          hulls: BOOLEAN,
        }),
      ],
    ],
    solidFractureRefusal: SOLID_CHECK,
    solidFractureRefusalCode: SOLID_CHECK,
    computeCornerNormals: [['creaseDegrees', optional(NUMBER)]],
    toArrays: [['options', options({})]],
    toFile: [['name', STRING]],
    createRenderBuffers: [['options', options({ normals: STRING })]],
  },
  RenderBuffers: {
    faceTriangles: [e('f')],
    pickTriangles: [
      ['origin', VEC3],
      ['direction', VEC3],
    ],
    dirtyViews: [['result', { ...OBJECT, fields: { vertexRanges: ARRAY, indexRanges: ARRAY } }]],
  },
};

function invalid(call, name, k, value) {
  return new HedgeError(
    'invalid-argument',
    `${call}: ${name} must be ${k.text}, got ${describe(value)}`,
  );
}

// Checks one argument, and the fields of an options object.
function check(call, [name, k], value) {
  if (!k.test(value)) throw invalid(call, name, k, value);
  if (k.fields && value !== undefined)
    for (const field in k.fields)
      if (!k.fields[field].test(value[field]))
        throw invalid(call, `${name}.${field}`, k.fields[field], value[field]);
}

// A method that checks its arguments, then runs `body`; named as the call (for stack traces).
// Calls of up to two arguments get a wrapper without an argument array, for the hot paths (pick
// while hovering).
function checked(call, specs, body) {
  const last = specs[specs.length - 1];
  if (last[0].startsWith('...')) {
    const fixed = specs.length - 1;
    const name = last[0].slice(3);
    return {
      [call](...args) {
        for (let i = 0; i < fixed; ++i) check(call, specs[i], args[i]);
        for (let j = fixed; j < args.length; ++j)
          check(call, [`${name}[${j - fixed}]`, last[1]], args[j]);
        return body.apply(this, args);
      },
    }[call];
  }
  if (specs.length > 2) throw new Error(`${call}: more than two arguments to check`);
  const [first, second] = specs;
  return {
    [call](a, b) {
      check(call, first, a);
      if (second !== undefined) check(call, second, b);
      return body.call(this, a, b);
    },
  }[call];
}

/** Puts the check in front of every call of ARGUMENTS on the classes given by name. */
export function installArgumentChecks(classes) {
  for (const [name, calls] of Object.entries(ARGUMENTS))
    for (const [call, specs] of Object.entries(calls))
      classes[name].prototype[call] = checked(call, specs, classes[name].prototype[call]);
}

// A custom fracture material as the module takes it: every field typed, the rings flattened.
// The values themselves (ranges, a zero grain with a stretch) are checked by fracture().
export function customMaterial(m, call = 'fracture') {
  const bad = (what) => new HedgeError('invalid-argument', `${call}: material.${what}`);
  if (m === null || typeof m !== 'object')
    throw new HedgeError(
      'invalid-argument',
      `${call}: material must be a preset name or an object`,
    );
  const {
    name = 'custom',
    rings,
    grain = [0, 0, 0],
    grainStretch = 1,
    refineEdge = 1.5,
    units = 'diagonal_fraction',
    radius = 0.1,
  } = m;
  if ('absolute' in m)
    throw bad(
      "absolute was replaced by units and radius (absolute true: units 'model' and the spacings summed as radius)",
    );
  if (!Array.isArray(rings)) throw bad('rings must be an array of {points, spacing, jitter}');
  const flat = new Float64Array(rings.length * 3);
  rings.forEach((ring, i) => {
    const { points, spacing, jitter = 0 } = ring ?? {};
    if (!isNumber(points) || !isNumber(spacing) || !isNumber(jitter))
      throw bad(`rings[${i}] must have numbers points, spacing and jitter`);
    flat.set([points, spacing, jitter], i * 3);
  });
  if (!isArrayLike(grain) || grain.length !== 3 || !Array.from(grain).every(isNumber))
    throw bad('grain must be [x, y, z]');
  if (!isNumber(grainStretch)) throw bad('grainStretch must be a number');
  if (!isNumber(refineEdge)) throw bad('refineEdge must be a number');
  if (!UNITS.includes(units)) throw bad(`units must be one of ${UNITS.join(', ')}`);
  if (!isNumber(radius)) throw bad('radius must be a number');
  return {
    name: String(name),
    rings: flat,
    grain: Array.from(grain),
    grainStretch,
    refineEdge,
    units,
    radius,
  };
}
