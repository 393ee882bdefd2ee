// What every part of the playground shares: the page state, element lookup, number formats and
// error reporting. Errors show over the top of the view (index.html), which does not scroll, so a
// message is in sight whichever control below the fold caused it; a message may offer a way out
// (a button next to it), found by the remedies registered with offerRemedy().

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

// Functions (message) => {label, run} or null, asked in order for a way out of an error.
const remedies = [];

//! Registers `find(message)`: a {label, run} offered next to an error it recognises, else null.
export function offerRemedy(find) {
  remedies.push(find);
}

export function showError(message) {
  $('error-text').textContent = message;
  let offer = null;
  for (const find of remedies) if ((offer = find(message))) break;
  const button = $('error-action');
  button.hidden = !offer;
  button.textContent = offer ? offer.label : '';
  button.onclick = offer ? () => offer.run() : null;
  $('error').hidden = false;
  document.body.dataset.error = message;
}

export function clearError() {
  $('error').hidden = true;
  $('error-action').onclick = null;
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
