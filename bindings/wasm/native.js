// What every object of the JS API that holds a native one shares (hedge.js, render_buffers.js):
// the error hedge raises, and the freeing of natives on dispose() or when their JS object is
// collected.

/** An error raised by hedge. kind names the C ABI's status (hedge_status), one to one:
 *  'invalid-argument', 'bad-handle' (a disposed object, an element out of range or deleted),
 *  'refused', 'io', 'topology', 'out-of-memory', 'buffer-too-small', 'internal' or 'busy'. A
 *  refused edit's error also carries refusal: the library's reason, the same text as the C ABI's
 *  hedge_last_refusal() and C#'s LastRefusal (null for other errors). */
export class HedgeError extends Error {
  constructor(kind, message, refusal = null) {
    super(message);
    this.name = 'HedgeError';
    this.kind = kind;
    this.refusal = refusal;
  }
}

// Natives are deleted when their JS object is collected; the held value is the native itself.
const registry = new FinalizationRegistry((native) => {
  if (!native.isDeleted()) native.delete();
});

/** What Mesh and RenderBuffers share: a native object freed on dispose() or when collected. */
export class NativeOwner {
  constructor(hedge, native, what) {
    this.hedge = hedge;
    this._native = native;
    this._what = what;
    registry.register(this, native, this);
  }

  /** Frees the native object now. Idempotent. */
  dispose() {
    if (this._native) {
      registry.unregister(this);
      this._native.delete();
      this._native = null;
    }
  }

  get disposed() {
    return this._native === null;
  }

  _n() {
    if (!this._native) throw new HedgeError('bad-handle', `this ${this._what} was disposed`);
    return this._native;
  }

  _call(name, ...args) {
    return this.hedge._check(this._n()[name](...args));
  }
}
