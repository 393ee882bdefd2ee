// What every part of the playground shares: the page state, element lookup, number formats and
// error reporting.

export const $ = (id) => document.getElementById(id);
export const fmt = (n) => n.toLocaleString('en-US');
export const ms = (t) => `${t.toFixed(t < 10 ? 2 : 1)} ms`;

export const state = {
  hedge: null,
  current: null, // the PageMesh shown
  viewer: null,
  hover: null, // { kind: 'face' | 'edge' | 'vertex', face, halfedge, vertex, point }
  busy: false,
  lastUpload: null, // { bytes, full, ranges, gl: meter delta }
  mode: 'edit', // 'break' in a break scene: a click strikes
};

export function showError(message) {
  $('error-text').textContent = message;
  $('error').hidden = false;
  document.body.dataset.error = message;
}

export function clearError() {
  $('error').hidden = true;
  delete document.body.dataset.error;
}

export function messageOf(error) {
  if (error && typeof error.message === 'string') return error.message;
  return String(error);
}

// Runs an action so that a failure is reported on the page and leaves it usable.
export async function guard(what, action) {
  if (state.busy) return undefined;
  state.busy = true;
  document.body.dataset.busy = '1';
  try {
    return await action();
  } catch (error) {
    // hedge's messages name their call already ("decimate: face 0 has 4 corners ..."): the label
    // is added only to a message that does not start with it.
    const message = messageOf(error);
    showError(message.startsWith(`${what}:`) ? message : `${what}: ${message}`);
    return undefined;
  } finally {
    state.busy = false;
    delete document.body.dataset.busy;
  }
}
