// Inspecting: what is under the pointer (a face, or an edge or corner near the hit), its half-edge
// records in the side panel, and the overlays that draw it (one-ring, half-edge arrows).
import { COLORS } from './viewer.js';
import { $, state } from './page.js';

// Distance from p to segment ab, all [x, y, z].
function segmentDistance(p, a, b) {
  const ab = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const ap = [p[0] - a[0], p[1] - a[1], p[2] - a[2]];
  const len2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
  const t =
    len2 > 0 ? Math.min(1, Math.max(0, (ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / len2)) : 0;
  const d = [ap[0] - t * ab[0], ap[1] - t * ab[1], ap[2] - t * ab[2]];
  return Math.hypot(d[0], d[1], d[2]);
}

const VERTEX_PIXELS = 8;
const EDGE_PIXELS = 6;

//! What is under the pointer: the face hit, or its edge or corner when the hit is within a few
//! pixels of one. The reach shrinks on faces that look small, so that a face's middle always picks
//! the face and an edge's middle the edge. Null when the ray misses.
export function elementAt(event) {
  const s = state.current;
  if (!s) return null;
  const ray = state.viewer.rayAt(event);
  const hit = s.pick(ray.origin, ray.direction);
  if (!hit) return null;
  const ppu = state.viewer.pixelsPerUnit(hit.point);
  const loop = s.faceHalfedges(hit.face).map((h) => {
    const r = s.record(h);
    return { h, r, a: s.position(r.origin), b: s.position(r.target) };
  });
  const centre = [0, 1, 2].map((i) => loop.reduce((sum, c) => sum + c.a[i], 0) / loop.length);
  const distance = (p, q) => Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
  let shortest = Infinity;
  for (const c of loop) shortest = Math.min(shortest, distance(c.a, c.b));
  const vertexReach = Math.min(VERTEX_PIXELS / ppu, 0.25 * shortest);
  let best = null;
  for (const c of loop) {
    const d = distance(c.a, hit.point);
    if (d < vertexReach && (!best || d < best.d)) best = { d, h: c.h, v: c.r.origin };
  }
  if (best)
    return { kind: 'vertex', face: hit.face, halfedge: best.h, vertex: best.v, point: hit.point };
  let bestEdge = null;
  for (const c of loop) {
    const d = segmentDistance(hit.point, c.a, c.b);
    const reach = Math.min(EDGE_PIXELS / ppu, 0.4 * segmentDistance(centre, c.a, c.b));
    if (d < reach && (!bestEdge || d < bestEdge.d)) bestEdge = { d, h: c.h };
  }
  if (bestEdge) return { kind: 'edge', face: hit.face, halfedge: bestEdge.h, point: hit.point };
  return { kind: 'face', face: hit.face, halfedge: loop[0].h, point: hit.point };
}

function recordLines(s, h, label) {
  const r = s.record(h);
  return [
    `${label} h${h}  (edge e${r.edge})`,
    `  origin  v${r.origin}`,
    `  twin    h${r.twin}`,
    `  face    ${r.face < 0 ? 'boundary' : 'f' + r.face}`,
    `  next    h${r.next}`,
    `  prev    h${r.prev}`,
  ];
}

function describe(el) {
  const s = state.current;
  const lines = [];
  if (el.kind === 'face') {
    const loop = s.faceHalfedges(el.face);
    lines.push(
      `face f${el.face}: ${loop.length} corners, half-edges ${loop.map((h) => 'h' + h).join(' ')}`,
    );
    lines.push(...recordLines(s, el.halfedge, 'halfedge(f)'));
  } else if (el.kind === 'edge') {
    const r = s.record(el.halfedge);
    lines.push(`edge e${r.edge}: v${r.origin} - v${r.target}`);
    lines.push(...recordLines(s, el.halfedge, 'half-edge'));
    lines.push(...recordLines(s, r.twin, 'twin'));
  } else {
    const ring = s.oneRing(el.vertex);
    const p = s
      .position(el.vertex)
      .map((x) => x.toFixed(3))
      .join(', ');
    lines.push(`vertex v${el.vertex}: (${p}), valence ${ring.length}`);
    lines.push(
      `  one-ring ${ring
        .slice(0, 12)
        .map((v) => 'v' + v)
        .join(' ')}${ring.length > 12 ? ' ...' : ''}`,
    );
    lines.push(...recordLines(s, s.outgoing(el.vertex), 'outgoing'));
  }
  return lines.join('\n');
}

export function faceCentre(s, f) {
  const loop = s.faceHalfedges(f);
  const c = [0, 0, 0];
  for (const h of loop) {
    const p = s.position(s.record(h).origin);
    for (let i = 0; i < 3; ++i) c[i] += p[i] / loop.length;
  }
  return c;
}

function drawArrow(s, h, color) {
  const r = s.record(h);
  if (r.face < 0) {
    // A boundary half-edge: bend it away from its twin's face.
    const inside = faceCentre(s, s.record(r.twin).face);
    const a = s.position(r.origin),
      b = s.position(r.target);
    const outside = [0, 1, 2].map((i) => a[i] + b[i] - inside[i]);
    state.viewer.addHalfedgeArrow(a, b, outside, color);
    return;
  }
  state.viewer.addHalfedgeArrow(
    s.position(r.origin),
    s.position(r.target),
    faceCentre(s, r.face),
    color,
  );
}

export function drawHover() {
  const viewer = state.viewer;
  viewer.clearOverlay();
  const el = state.hover;
  const s = state.current;
  if (!el || !s) return;
  const loopPoints = (f) => s.faceHalfedges(f).map((h) => s.position(s.record(h).origin));
  // Overlay sizes follow the hovered face's edges, so they read the same at any zoom and density.
  const points = loopPoints(el.face);
  let unit = 0;
  for (let i = 0; i < points.length; ++i) {
    const a = points[i],
      b = points[(i + 1) % points.length];
    unit += Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) / points.length;
  }
  if (el.kind === 'face') viewer.addPolygon(points, COLORS.face);
  if (el.kind === 'edge') {
    const r = s.record(el.halfedge);
    viewer.addSegment(s.position(r.origin), s.position(r.target), COLORS.edge, unit * 0.035);
  }
  const ringVertex = el.kind === 'vertex' ? el.vertex : s.record(el.halfedge).origin;
  if (el.kind === 'vertex') viewer.addPoint(s.position(el.vertex), COLORS.vertex, unit * 0.1);
  if ($('show-ring').checked) {
    const centre = s.position(ringVertex);
    viewer.addPoint(centre, COLORS.ring, unit * 0.08);
    for (const v of s.oneRing(ringVertex)) {
      viewer.addSegment(centre, s.position(v), COLORS.ring, unit * 0.02);
      viewer.addPoint(s.position(v), COLORS.ring, unit * 0.06);
    }
  }
  if ($('show-arrows').checked) {
    const h = el.kind === 'vertex' ? s.outgoing(el.vertex) : el.halfedge;
    const r = s.record(h);
    if (el.kind === 'face') {
      for (const g of s.faceHalfedges(el.face)) if (g !== h) drawArrow(s, g, COLORS.next);
    } else {
      if (r.face >= 0) {
        drawArrow(s, r.next, COLORS.next);
        drawArrow(s, r.prev, COLORS.prev);
      }
      drawArrow(s, r.twin, COLORS.twin);
    }
    drawArrow(s, h, COLORS.halfedge);
  }
  viewer.requestRender();
}

export function setHover(el) {
  const same = (a, b) =>
    a &&
    b &&
    a.kind === b.kind &&
    a.face === b.face &&
    a.halfedge === b.halfedge &&
    a.vertex === b.vertex;
  if (same(el, state.hover) || (!el && !state.hover)) return;
  state.hover = el;
  $('records').textContent = el ? describe(el) : 'Hover the mesh.';
  document.body.dataset.hover = el ? el.kind : '';
  drawHover();
}
