// The AudioWorklet processor: a Pd (aero-pd.js) in the audio thread,
// 128-frame render quanta as two Pd blocks, then the scene's gain, then the
// master limiter (limiter.js: nothing leaves over -1 dBTP). The page sends
// the wasm bytes at construction and then messages through the port:
//   { scene: { id, files, open, gain, messages } }   switch scenes: fade
//       out, close the old patch, open the new one with its gain set,
//       send its controls, fade in (the new gain applies before a sample
//       of the new scene is heard)
//   { send: [recv, sel, ...] }   { gain: linear }   { record: true|false }
// It answers { ready: true } once Pd runs, { opened: id } when a scene
// plays, { meter: {...} } about 20 times a second (levels since the last
// one, and the peak before the limiter since the scene opened), { recorded: [Float32Array
// left, right] } chunks while recording, { error: text } on failure.

// an AudioWorkletGlobalScope has no performance clock; emscripten's clock
// (which Pd reads for its logical time at start) falls back to the audio
// thread's own time
if (typeof globalThis.performance === 'undefined') {
  globalThis.performance = { now: () => currentTime * 1000 };
}

import { AeroPd, BLOCK } from './aero-pd.js';
import { Limiter, Meter } from './limiter.js';

const FADE = 0.03;         // s: the fade out and in around a scene switch
const GAIN_GLIDE = 0.02;   // s: the time constant of a gain change
const METER_EVERY = 0.05;  // s
const RECORD_CHUNK = 8192; // frames per recorded chunk sent to the page

class AeroProcessor extends AudioWorkletProcessor {
  constructor(options) {
    super();
    this.pd = null;
    this.queue = [];
    this.gain = 0;          // the gain applied (glides to target)
    this.target = 0;
    this.glide = 1 - Math.exp(-1 / (GAIN_GLIDE * sampleRate));
    this.fade = 0;          // 0 silent .. 1 open
    this.fadeStep = 1 / (FADE * sampleRate);
    this.pending = null;    // the scene to open once faded out
    this.sceneId = null;
    this.limiter = new Limiter(sampleRate);
    this.inMeter = { peak: 0 };
    this.outMeter = new Meter();
    this.meterCount = 0;
    this.clips = 0;         // blocks whose input the limiter had to reduce
    this.scenePeak = 0;
    this.recording = null;  // { l, r, n } while recording
    this.l = new Float32Array(128);
    this.r = new Float32Array(128);
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
      // the latest scene wins: one that waits for the fade is replaced
      if (msg.scene) this.pending = msg.scene;
      if (msg.send && !this.pending) this.pd.send(msg.send);
      if (msg.send && this.pending) this.pending.messages.push(msg.send);
      if (msg.gain !== undefined) {
        if (this.pending) this.pending.gain = msg.gain;
        else this.target = msg.gain;
      }
      if (msg.record === true) this.recording = this.newChunk();
      if (msg.record === false && this.recording) {
        this.flush(true);
        this.recording = null;
      }
    } catch (err) {
      this.port.postMessage({ error: String(err) });
    }
  }

  newChunk() {
    return { l: new Float32Array(RECORD_CHUNK), r: new Float32Array(RECORD_CHUNK), n: 0 };
  }

  flush(last) {
    const c = this.recording;
    this.port.postMessage({ recorded: [c.l.slice(0, c.n), c.r.slice(0, c.n)], last });
    this.recording = last ? null : this.newChunk();
  }

  // the pending scene, now that the output is silent: opened at its gain
  openPending() {
    const s = this.pending;
    this.pending = null;
    try {
      this.pd.close();
      if (s.files) this.pd.addFiles(s.files);
      this.pd.open(s.open);
      for (const m of s.messages) this.pd.send(m);
      this.gain = this.target = s.gain;
      this.sceneId = s.id;
      this.scenePeak = 0;
      this.port.postMessage({ opened: s.id });
    } catch (err) {
      this.port.postMessage({ error: String(err) });
    }
  }

  process(inputs, outputs) {
    const out = outputs[0];
    const frames = out[0].length;
    const l = this.l, r = this.r;
    if (this.pending && this.pd && (this.fade === 0 || !this.pd.patch)) {
      this.fade = 0;
      this.openPending();
    }
    if (this.pd && this.pd.patch) {
      const buf = this.pd.process(frames / BLOCK);
      let peak = 0;
      for (let i = 0; i < frames; i++) {
        this.gain += this.glide * (this.target - this.gain);
        if (this.pending) this.fade = Math.max(0, this.fade - this.fadeStep);
        else if (this.fade < 1) this.fade = Math.min(1, this.fade + this.fadeStep);
        const g = this.gain * this.fade;
        l[i] = buf[2 * i] * g;
        r[i] = buf[2 * i + 1] * g;
        const a = Math.max(Math.abs(l[i]), Math.abs(r[i]));
        if (a > peak) peak = a;
      }
      if (peak > this.inMeter.peak || !(peak === peak)) this.inMeter.peak = peak;
      // the scene's own, from its first sample (not the old scene's fade)
      if (!this.pending && (peak > this.scenePeak || !(peak === peak))) this.scenePeak = peak;
    } else {
      l.fill(0);
      r.fill(0);
    }
    this.limiter.process([l, r], frames);
    if (this.limiter.gain < 1) this.clips++;
    this.outMeter.add([l, r], frames);
    out[0].set(l);
    if (out[1]) out[1].set(r);
    if (this.recording) {
      const c = this.recording;
      const n = Math.min(frames, RECORD_CHUNK - c.n);
      c.l.set(l.subarray(0, n), c.n);
      c.r.set(r.subarray(0, n), c.n);
      c.n += n;
      if (c.n === RECORD_CHUNK) {
        this.flush(false);
        this.recording.l.set(l.subarray(n), 0);
        this.recording.r.set(r.subarray(n), 0);
        this.recording.n = frames - n;
      }
    }
    this.meterCount += frames;
    if (this.meterCount >= METER_EVERY * sampleRate) {
      const m = this.outMeter;
      this.port.postMessage({ meter: {
        peak: m.peak,                       // true peak of the output
        rms: Math.sqrt(m.sum / Math.max(1, m.n)),
        input: this.inMeter.peak,           // sample peak before the limiter
        reduction: this.limiter.reduction,  // smallest limiter gain
        limited: this.clips,                // blocks the limiter reduced
        scene: this.sceneId,
        scenePeak: this.scenePeak,          // sample peak before the limiter
                                            // since this scene opened
      } });
      m.reset();
      this.inMeter.peak = 0;
      this.limiter.reduction = 1;
      this.clips = 0;
      this.meterCount = 0;
    }
    return true;
  }
}

registerProcessor('aero', AeroProcessor);
