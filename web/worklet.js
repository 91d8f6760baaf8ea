// The AudioWorklet processor: a Pd (aero-pd.js) in the audio thread,
// 128-frame render quanta as two Pd blocks. The page sends the wasm bytes
// at construction and then messages through the port:
//   { files: {path: ArrayBuffer} }  { open: 'x.pd' }  { send: [recv, sel, ...] }
//   { gain: linear }
// It answers { ready: true } once Pd runs and { error: text } on failure.

// an AudioWorkletGlobalScope has no performance clock; emscripten's clock
// (which Pd reads for its logical time at start) falls back to the audio
// thread's own time
if (typeof globalThis.performance === 'undefined') {
  globalThis.performance = { now: () => currentTime * 1000 };
}

import { AeroPd, BLOCK } from './aero-pd.js';

class AeroProcessor extends AudioWorkletProcessor {
  constructor(options) {
    super();
    this.pd = null;
    this.queue = [];
    this.gain = 1;
    this.port.onmessage = e => this.pd ? this.handle(e.data) : this.queue.push(e.data);
    AeroPd.create(options.processorOptions.wasm, sampleRate,
      text => this.port.postMessage({ print: text }))
      .then(pd => {
        this.pd = pd;
        for (const msg of this.queue) this.handle(msg);
        this.queue = [];
        this.port.postMessage({ ready: true });
      })
      .catch(err => this.port.postMessage({ error: String(err) }));
  }

  handle(msg) {
    try {
      if (msg.files) this.pd.addFiles(msg.files);
      if (msg.open) this.pd.open(msg.open);
      if (msg.send) this.pd.send(msg.send);
      if (msg.gain !== undefined) this.gain = msg.gain;
    } catch (err) {
      this.port.postMessage({ error: String(err) });
    }
  }

  process(inputs, outputs) {
    const out = outputs[0];
    if (!this.pd || !this.pd.patch) return true;
    const frames = out[0].length, ticks = frames / BLOCK;
    const buf = this.pd.process(ticks);
    const l = out[0], r = out[1] || out[0], g = this.gain;
    for (let i = 0; i < frames; i++) {
      l[i] = buf[2 * i] * g;
      r[i] = buf[2 * i + 1] * g;
    }
    return true;
  }
}

registerProcessor('aero', AeroProcessor);
