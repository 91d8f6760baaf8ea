// The AudioWorklet: the module (embed.js) instantiated from the bytes the
// page hands over, the patch written into its file system and opened,
// 128 frames per call. Messages from the page: [receiver, selector, ...atoms].
// An AudioWorkletGlobalScope has no fetch, URL or performance clock.
if (typeof globalThis.performance === 'undefined') {
  globalThis.performance = { now: () => currentTime * 1000 };
}
import createEmbed from './embed.js';

class Embed extends AudioWorkletProcessor {
  constructor(options) {
    super();
    const { wasm, patch, files } = options.processorOptions;
    this.m = null;
    createEmbed({
      instantiateWasm: (imports, done) => {
        WebAssembly.instantiate(wasm, imports).then(r => done(r.instance, r.module));
        return {};
      },
      locateFile: path => path, // no URL in this scope: nothing is fetched
    }).then(m => {
      for (const [path, bytes] of Object.entries(files)) {
        m.FS.mkdirTree(path.slice(0, path.lastIndexOf('/')));
        m.FS.writeFile(path, new Uint8Array(bytes));
      }
      if (m._embed_init(sampleRate) !== 0) throw new Error('libpd did not start');
      const open = m.cwrap('embed_open', 'number', ['string', 'string']);
      if (!open(patch, '/aero')) throw new Error('cannot open ' + patch);
      this.addSymbol = m.cwrap('libpd_add_symbol', null, ['string']);
      this.finish = m.cwrap('libpd_finish_message', 'number', ['string', 'string']);
      this.m = m;
      this.port.postMessage({ ready: true });
    }).catch(err => this.port.postMessage({ error: String(err) }));
    this.port.onmessage = e => this.send(e.data);
  }

  send([receiver, selector, ...atoms]) {
    const m = this.m;
    if (!m) return;
    m._libpd_start_message(atoms.length);
    for (const a of atoms) {
      if (typeof a === 'number') m._libpd_add_float(a);
      else this.addSymbol(a);
    }
    this.finish(receiver, selector);
  }

  process(inputs, outputs) {
    if (!this.m) return true;
    const [l, r] = outputs[0];
    // the heap may grow (and move) at any call: a fresh view each time
    const p = this.m._embed_process() >> 2, out = this.m.HEAPF32;
    for (let i = 0; i < 128; i++) {
      l[i] = out[p + 2 * i];
      r[i] = out[p + 2 * i + 1];
    }
    return true;
  }
}
registerProcessor('embed', Embed);
