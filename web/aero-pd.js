// aero-pd.js: one Pd (libpd 0.16.1 + aero, compiled to WebAssembly by
// `make web`) as a JavaScript object. Used on the page's main thread (offline
// renders) and in the AudioWorklet (live sound): neither fetches anything
// itself, the caller hands over the wasm bytes and the data files.
import createAero from './aero.js';

export const BLOCK = 64; // Pd's block: libpd processes in ticks of 64 frames

export class AeroPd {
  // WASM: aero.wasm, its bytes (ArrayBuffer) or compiled; RATE: the sample rate;
  // PRINT: where Pd's messages go (errors included)
  static async create(wasm, rate, print) {
    const pd = new AeroPd();
    pd.log = print;
    pd.m = await createAero({
      instantiateWasm(imports, done) {
        // bytes give { instance, module }; a compiled module an instance
        WebAssembly.instantiate(wasm, imports).then(r =>
          r instanceof WebAssembly.Instance ? done(r, wasm) : done(r.instance, r.module));
        return {};
      },
      // with a locateFile, emscripten's loader does not build a URL (an
      // AudioWorklet's scope has no URL); nothing is fetched anyway
      locateFile: path => path,
      print, printErr: print,
    });
    const m = pd.m;
    pd.addSymbol = m.cwrap('libpd_add_symbol', null, ['string']);
    pd.finishMessage = m.cwrap('libpd_finish_message', 'number', ['string', 'string']);
    pd.finishList = m.cwrap('libpd_finish_list', 'number', ['string']);
    pd.openFile = m.cwrap('aero_web_open', 'number', ['string', 'string']);
    if (m._aero_web_init(rate) !== BLOCK) throw new Error('libpd did not start');
    pd.rate = rate;
    pd.patch = 0;
    return pd;
  }

  // FILES: { 'scenes/x.pd': ArrayBuffer, ... } into /aero/ (once each)
  addFiles(files) {
    const FS = this.m.FS;
    for (const [path, bytes] of Object.entries(files)) {
      const full = '/aero/' + path;
      if (FS.analyzePath(full).exists) continue;
      FS.mkdirTree(full.slice(0, full.lastIndexOf('/')));
      FS.writeFile(full, new Uint8Array(bytes));
    }
  }

  // opens /aero/scenes/NAME (closing the patch open before)
  open(name) {
    this.close();
    this.patch = this.openFile(name, '/aero/scenes');
    if (!this.patch) throw new Error('cannot open ' + name);
  }

  close() {
    if (this.patch) this.m._aero_web_close(this.patch);
    this.patch = 0;
  }

  // a message [RECEIVER, SELECTOR, ...atoms] (numbers and symbols)
  send([receiver, selector, ...atoms]) {
    const m = this.m;
    m._libpd_start_message(atoms.length);
    for (const a of atoms) {
      if (typeof a === 'number') m._libpd_add_float(a);
      else this.addSymbol(String(a));
    }
    this.finishMessage(receiver, selector);
  }

  // TICKS blocks of 64 frames: a Float32Array view of the interleaved
  // stereo output (valid until the next call)
  process(ticks) {
    const ptr = this.m._aero_web_process(ticks);
    if (!ptr) throw new Error('aero_web_process failed');
    return this.m.HEAPF32.subarray(ptr >> 2, (ptr >> 2) + ticks * BLOCK * 2);
  }
}

// renders SECONDS of a scene patch offline in a fresh Pd (a fresh one so
// that Pd's process state, e.g. [noise~]'s seed, is as in a fresh native
// Pd): { left, right } Float32Arrays, after MESSAGES at time 0; EXTRA
// frames more; PROGRESS(fraction) now and then
export async function renderScene(wasm, files, patch, messages, seconds, rate,
                                  print, progress = () => {}, extra = 0) {
  const pd = await AeroPd.create(wasm, rate, print);
  pd.addFiles(files);
  pd.open(patch);
  for (const msg of messages) pd.send(msg);
  const ticks = Math.floor(seconds * rate / BLOCK) + Math.ceil(extra / BLOCK);
  const left = new Float32Array(ticks * BLOCK);
  const right = new Float32Array(ticks * BLOCK);
  const chunk = 32;
  for (let t = 0; t < ticks; t += chunk) {
    const n = Math.min(chunk, ticks - t);
    const out = pd.process(n);
    for (let i = 0; i < n * BLOCK; i++) {
      left[t * BLOCK + i] = out[2 * i];
      right[t * BLOCK + i] = out[2 * i + 1];
    }
    if (t % (chunk * 8) === 0) progress(t / ticks);
  }
  pd.close();
  return { left, right };
}

// a float WAV (stereo, 32-bit float, as Pd's and aero's renders)
export function wavBytes(left, right, rate, gain = 1) {
  const n = left.length, data = n * 8;
  const buf = new ArrayBuffer(44 + data);
  const v = new DataView(buf);
  const str = (o, s) => { for (let i = 0; i < s.length; i++) v.setUint8(o + i, s.charCodeAt(i)); };
  str(0, 'RIFF'); v.setUint32(4, 36 + data, true); str(8, 'WAVE');
  str(12, 'fmt '); v.setUint32(16, 16, true); v.setUint16(20, 3, true);
  v.setUint16(22, 2, true); v.setUint32(24, rate, true);
  v.setUint32(28, rate * 8, true); v.setUint16(32, 8, true);
  v.setUint16(34, 32, true); str(36, 'data'); v.setUint32(40, data, true);
  for (let i = 0; i < n; i++) {
    v.setFloat32(44 + 8 * i, left[i] * gain, true);
    v.setFloat32(48 + 8 * i, right[i] * gain, true);
  }
  return buf;
}
