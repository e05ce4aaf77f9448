// The page's one Web Worker (web/worker.js, which loads the wasm module), shared by every view.
//
// request(message) posts {...message, id} and resolves with the worker's answer for that id
// (a 'result' or an 'error' message: the caller reads its type). It rejects with an Error whose
// `cancelled` is true when restart() dropped the worker (Cancel), or with the worker's crash.
// 'progress' messages with the id ({done, total}) go to the request's onProgress, if any.
// 'ready' ({algorithms, delaunay, route}) and 'load-error' ({message}) go to listeners added
// with on(); `info` keeps the last 'ready' message for views that start later.

export class WorkerClient {
  #url;
  #worker = null;
  #seq = 0;
  #pending = new Map(); // id -> {resolve, reject, onProgress}
  #listeners = { ready: [], 'load-error': [], crash: [] };

  constructor(url) {
    this.#url = url;
    /** The last 'ready' message, or null while the module loads. */
    this.info = null;
    /** The message of a failed module load, or null. */
    this.loadError = null;
    this.#spawn();
  }

  /** True when the current worker has loaded the wasm module. */
  get ready() {
    return this.info !== null && this.#worker !== null;
  }

  on(type, fn) {
    this.#listeners[type].push(fn);
  }

  #emit(type, payload) {
    for (const fn of this.#listeners[type]) fn(payload);
  }

  #spawn() {
    const worker = new Worker(this.#url, { type: 'module' });
    this.#worker = worker;
    this.info = null;
    worker.onmessage = (event) => this.#onMessage(event.data);
    worker.onerror = (event) => {
      event.preventDefault();
      this.#crash(`Worker error: ${event.message || 'the worker script failed to load or crashed'}`);
    };
    worker.onmessageerror = () => this.#crash('Worker error: a message could not be deserialised');
  }

  #onMessage(msg) {
    if (!msg) return;
    if (msg.type === 'ready') {
      this.info = msg;
      this.loadError = null;
      this.#emit('ready', msg);
      return;
    }
    if (msg.type === 'load-error') {
      this.loadError = msg.message;
      this.#emit('load-error', msg);
      return;
    }
    const entry = this.#pending.get(msg.id);
    if (!entry) return; // a stale answer from a dropped request
    if (msg.type === 'progress') {
      entry.onProgress?.(msg);
      return;
    }
    this.#pending.delete(msg.id);
    entry.resolve(msg);
  }

  #rejectAll(makeError) {
    const pending = [...this.#pending.values()];
    this.#pending.clear();
    for (const entry of pending) entry.reject(makeError());
  }

  #crash(message) {
    console.error(`[hullkit] ${message}`);
    this.#worker?.terminate();
    this.#worker = null; // a fresh one is started by the next request (no respawn loop)
    this.info = null;
    this.#rejectAll(() => Object.assign(new Error(message), { crashed: true }));
    this.#emit('crash', { message });
  }

  /** Posts `message` (with a fresh id) and resolves with the answer; `onProgress` gets its progress messages. */
  request(message, transfer = [], { onProgress } = {}) {
    if (!this.#worker) this.#spawn();
    const id = ++this.#seq;
    return new Promise((resolve, reject) => {
      this.#pending.set(id, { resolve, reject, onProgress });
      this.#worker.postMessage({ ...message, id }, transfer);
    });
  }

  /** Whether the worker had loaded the module when the request was made (for "includes loading"). */
  get warm() {
    return this.info !== null;
  }

  /**
   * Drops the worker (a wasm call cannot be interrupted) and starts a fresh one; every pending
   * request rejects with `cancelled`.
   */
  restart() {
    this.#worker?.terminate();
    this.#rejectAll(() => Object.assign(new Error('cancelled'), { cancelled: true }));
    this.#spawn();
  }
}
