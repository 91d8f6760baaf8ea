// The page: scenes (scenes.js) played live by a Pd in an AudioWorklet
// (worklet.js), rendered offline on the main thread by a fresh Pd
// (aero-pd.js), a live spectrogram. window.aero exposes the renders to
// tests (tests/web) and benchmarks.
import { SCENES, controlMessages } from './scenes.js';
import { AeroPd, renderScene, wavBytes, BLOCK } from './aero-pd.js';

const $ = id => document.getElementById(id);
const ABSTRACTIONS = ['draft', 'fence', 'fire', 'swing', 'throw', 'tree',
  'whirl', 'wind'].map(n => `abstractions/aero.${n}~.pd`);
const dB = x => Math.pow(10, x / 20);

const state = {
  scene: SCENES[0],
  values: {},        // scene id -> { control id -> value }
  files: {},         // path -> ArrayBuffer, fetched once
  wasm: null,        // aero.wasm bytes (for the worklet)
  module: null,      // and compiled (for renders on this thread)
  ctx: null, node: null, analyser: null, playing: false,
};

function unsupported(text) {
  const box = $('unsupported');
  box.textContent = text;
  box.hidden = false;
  $('app').hidden = true;
}

function status(text) { $('status').textContent = text; }

async function fetchBytes(path) {
  const r = await fetch(path);
  if (!r.ok) throw new Error(`${path}: HTTP ${r.status}`);
  return r.arrayBuffer();
}

// the files a scene needs, fetched once: { path: ArrayBuffer }
async function sceneFiles(scene) {
  const paths = ['scenes/' + scene.patch, ...ABSTRACTIONS, ...scene.data];
  await Promise.all(paths.filter(p => !state.files[p]).map(async p => {
    state.files[p] = await fetchBytes('aero/' + p);
  }));
  return Object.fromEntries(paths.map(p => [p, state.files[p]]));
}

function values(scene) {
  if (!state.values[scene.id]) {
    state.values[scene.id] = Object.fromEntries(scene.controls.map(c => [c.id, c.value]));
  }
  return state.values[scene.id];
}

function post(msg) { if (state.node) state.node.port.postMessage(msg); }
function sendAll(messages) { for (const m of messages) post({ send: m }); }
function sceneGain() { return dB(Number($('gain').value)); }

// --- live sound ---------------------------------------------------------------
async function startAudio() {
  const ctx = new AudioContext();
  await ctx.audioWorklet.addModule('worklet.js');
  const node = new AudioWorkletNode(ctx, 'aero', {
    numberOfInputs: 0, numberOfOutputs: 1, outputChannelCount: [2],
    processorOptions: { wasm: state.wasm },
  });
  const ready = new Promise((resolve, reject) => {
    node.port.onmessage = e => {
      const d = e.data;
      if (d.ready) resolve();
      if (d.error) { console.warn('aero: ' + d.error); status('Error: ' + d.error); reject(new Error(d.error)); }
      if (d.print) logPd(d.print);
    };
  });
  const analyser = ctx.createAnalyser();
  analyser.fftSize = 2048;
  analyser.smoothingTimeConstant = 0;
  node.connect(analyser);
  analyser.connect(ctx.destination);
  Object.assign(state, { ctx, node, analyser });
  await ready;
  drawSpectrogram();
}

async function loadLive(scene) {
  if (!state.node) return;
  post({ files: await sceneFiles(scene) });
  post({ open: scene.patch });
  post({ gain: sceneGain() });
  sendAll(controlMessages(scene, values(scene)));
}

async function togglePlay() {
  const button = $('play');
  try {
    if (!state.ctx) {
      status('Starting Pd in the audio thread ...');
      await startAudio();
      await loadLive(state.scene);
    }
    if (state.playing) await state.ctx.suspend();
    else await state.ctx.resume();
    state.playing = !state.playing;
    button.textContent = state.playing ? 'Stop' : 'Play';
    button.setAttribute('aria-pressed', String(state.playing));
    status(state.playing ? `Playing ${state.scene.title} at ${state.ctx.sampleRate} Hz` : 'Stopped');
  } catch (err) {
    status('Cannot start audio: ' + err.message);
  }
}

// Pd's messages: errors (Pd prefixes them with "error") go to the console
// as errors, the rest as debug lines
let pdLine = '';
function logPd(text) {
  pdLine += text;
  if (!pdLine.endsWith('\n')) return;
  const line = pdLine.trimEnd();
  pdLine = '';
  if (/error|couldn't create|no method|connection failed/i.test(line)) console.error('Pd: ' + line);
  else console.debug('Pd: ' + line);
}

// --- the spectrogram: a column per animation frame, 30 Hz - 12 kHz on a
// log axis (the scenes' tones span 30 Hz to several kHz), dB as colour --
const SPEC_LO = 30, SPEC_HI = 12000;
function drawSpectrogram() {
  const canvas = $('spectrogram'), g = canvas.getContext('2d');
  const bins = new Float32Array(state.analyser.frequencyBinCount);
  const hzPerBin = state.ctx.sampleRate / state.analyser.fftSize;
  // the FFT bin of each pixel row, bottom = SPEC_LO
  const rowBin = Array.from({ length: canvas.height }, (_, y) => Math.min(bins.length - 1,
    Math.round(SPEC_LO * Math.pow(SPEC_HI / SPEC_LO, (canvas.height - 1 - y) / (canvas.height - 1)) / hzPerBin)));
  const column = g.createImageData(1, canvas.height);
  const frame = () => {
    if (state.playing) {
      state.analyser.getFloatFrequencyData(bins);
      g.drawImage(canvas, -1, 0);
      for (let y = 0; y < canvas.height; y++) {
        const v = Math.max(0, Math.min(1, (bins[rowBin[y]] + 110) / 80));
        const i = 4 * y;
        column.data[i] = 255 * Math.min(1, v * 2);
        column.data[i + 1] = 255 * Math.max(0, v * 2 - 1);
        column.data[i + 2] = 120 * (1 - v) * (v > 0.02);
        column.data[i + 3] = 255;
      }
      g.putImageData(column, canvas.width - 1, 0);
    }
    requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);
}

// --- offline renders (main thread, a fresh Pd each) --------------------------
const printQuiet = text => logPd(text);

// renders scene ID for SECONDS at RATE with control VALUES (default: the
// page's current ones): { left, right } in pascals, before the gain
async function render(id, seconds, rate = 48000, vals) {
  const scene = SCENES.find(s => s.id === id);
  const files = await sceneFiles(scene);
  return renderScene(state.module, files, scene.patch,
    controlMessages(scene, vals ?? values(scene)), seconds, rate, printQuiet);
}

// the cost of scene ID per 128-frame block (two Pd blocks, as the
// AudioWorklet runs them), ms: after a second of warm-up, the fastest of
// REPS runs of BLOCKS blocks (the fastest: the least disturbed by other
// work on the machine)
async function blockCost(id, rate = 48000, blocks = 400, reps = 7) {
  const scene = SCENES.find(s => s.id === id);
  const pd = await AeroPd.create(state.module, rate, printQuiet);
  pd.addFiles(await sceneFiles(scene));
  pd.open(scene.patch);
  for (let i = 0; i < rate / 128; i++) pd.process(128 / BLOCK);
  let best = Infinity;
  for (let r = 0; r < reps; r++) {
    const t0 = performance.now();
    for (let i = 0; i < blocks; i++) pd.process(128 / BLOCK);
    best = Math.min(best, (performance.now() - t0) / blocks);
  }
  pd.close();
  return best;
}

async function renderDownload() {
  const seconds = Math.max(1, Math.min(60, Number($('seconds').value) || 5));
  const scene = state.scene, button = $('render');
  button.disabled = true;
  status(`Rendering ${seconds} s of ${scene.title} ...`);
  try {
    const t0 = performance.now();
    const { left, right } = await render(scene.id, seconds);
    const blob = new Blob([wavBytes(left, right, 48000, sceneGain())], { type: 'audio/wav' });
    const a = $('download');
    if (a.href) URL.revokeObjectURL(a.href);
    a.href = URL.createObjectURL(blob);
    a.download = `aero-${scene.id}.wav`;
    a.textContent = `aero-${scene.id}.wav`;
    a.hidden = false;
    a.click();
    status(`Rendered ${seconds} s in ${((performance.now() - t0) / 1000).toFixed(1)} s: ${a.download}`);
  } catch (err) {
    status('Render failed: ' + err.message);
  } finally {
    button.disabled = false;
  }
}

// --- the scene panel ---------------------------------------------------------
function showScene(scene) {
  state.scene = scene;
  for (const b of document.querySelectorAll('#scenes button')) {
    b.setAttribute('aria-current', String(b.dataset.id === scene.id));
  }
  $('scene-title').textContent = scene.title;
  $('scene-text').textContent = scene.text;
  const vals = values(scene);
  const box = $('controls');
  box.replaceChildren();
  for (const c of scene.controls) {
    const id = `c-${c.id}`;
    const label = Object.assign(document.createElement('label'), { htmlFor: id,
      textContent: c.label });
    const input = Object.assign(document.createElement('input'), { id, type: 'range',
      min: c.min, max: c.max, step: c.step, value: vals[c.id] });
    input.dataset.control = c.id;
    const out = document.createElement('output');
    out.htmlFor = id;
    const show = () => { out.textContent = `${vals[c.id]} ${c.unit}`; };
    show();
    input.addEventListener('input', () => {
      vals[c.id] = Number(input.value);
      show();
      sendAll(c.send(vals[c.id], vals));
    });
    box.append(label, input, out);
  }
  const actions = $('actions');
  actions.replaceChildren();
  for (const a of scene.actions) {
    const b = Object.assign(document.createElement('button'), { type: 'button',
      textContent: a.label });
    b.addEventListener('click', () => sendAll(a.send));
    actions.append(b);
  }
  $('swingpad').hidden = !scene.swing;
  // the scene's make-up gain: its level in pascals made comfortable
  $('gain').value = scene.gain;
  $('gain-out').textContent = `${scene.gain} dB`;
  loadLive(scene).catch(err => status('Cannot load: ' + err.message));
}

// a keyboard swing: aero.swing~'s own arc ((1 - cos)/2 speed profile)
function swing(direction, duration, arc) {
  sendAll([['aero-scene', 'direction', direction], ['aero-scene', 'duration', duration],
    ['aero-scene', 'arc', arc], ['aero-scene', 'swing']]);
  status(`Swing ${direction > 0 ? 'left' : 'right'}, ${Math.round(duration)} ms over ${Math.round(arc)} deg`);
}

// The blade's pose as aero.swing~ makes it (its [expr]): the hand 30 cm in
// front of the head, the blade from 0.2 m to 0.2 + L m along the angle A
// (deg, 90 = straight ahead) in the horizontal plane at 1.3 m, its chord
// along the motion (DIR +1: A increasing), edge first
function bladePose(angle, dir, length) {
  const a = angle * Math.PI / 180, c = Math.cos(a), s = Math.sin(a);
  return [0.2 * c, 0.3 + 0.2 * s, 1.3, (length + 0.2) * c, 0.3 + (length + 0.2) * s, 1.3,
    -dir * s, dir * c, 0];
}

// Dragging across the pad moves the blade live: the pointer's position
// across the pad is the blade's angle (left edge 165 deg, right edge 15),
// each pointer move a pose glided to over the time since the last one, so
// the drag's speed is the blade's speed (and its sound: pitch ~ v, level
// ~ v^3 at every point along the blade)
function setupSwingPad() {
  const pad = $('swingpad');
  let drag = null;
  const angleAt = e => {
    const r = pad.getBoundingClientRect();
    const x = Math.max(0, Math.min(1, (e.clientX - r.left) / (r.width || 1)));
    return 165 - 150 * x;
  };
  pad.addEventListener('pointerdown', e => {
    pad.setPointerCapture(e.pointerId);
    const angle = angleAt(e);
    drag = { angle, t: e.timeStamp, dir: 1, top: 0 };
    sendAll([['aero-scene', 'ramp', 5],
      ['aero-scene', 'place', ...bladePose(angle, 1, state.scene.blade)]]);
  });
  pad.addEventListener('pointermove', e => {
    if (!drag) return;
    const angle = angleAt(e), dt = e.timeStamp - drag.t;
    if (dt <= 0 || angle === drag.angle) return;
    const dir = angle > drag.angle ? 1 : -1;
    // the glide: the time since the last move, but no faster than a tip
    // speed of 60 m/s (a hard sword swing's tip moves at 30-50 m/s)
    const arm = Math.abs(angle - drag.angle) * Math.PI / 180 * (state.scene.blade + 0.2);
    const ramp = Math.max(5, Math.min(200, Math.max(dt, 1000 * arm / 60)));
    drag.top = Math.max(drag.top, arm / (ramp / 1000));
    sendAll([['aero-scene', 'ramp', ramp],
      ['aero-scene', 'pose', ...bladePose(angle, dir, state.scene.blade)]]);
    Object.assign(drag, { angle, t: e.timeStamp, dir });
  });
  const end = () => {
    if (!drag) return;
    status(`Swing by hand: the tip reached ${drag.top.toFixed(1)} m/s`);
    drag = null;
    post({ send: ['aero-scene', 'ramp', 5] });
  };
  pad.addEventListener('pointerup', end);
  pad.addEventListener('pointercancel', end);
  pad.addEventListener('keydown', e => {
    if (!['ArrowLeft', 'ArrowRight', 'Enter', ' '].includes(e.key)) return;
    e.preventDefault();
    swing(e.key === 'ArrowRight' ? -1 : 1, e.shiftKey ? 160 : 300, 150);
  });
}

function setupGain() {
  const gain = $('gain');
  gain.addEventListener('input', () => {
    $('gain-out').textContent = `${gain.value} dB`;
    post({ gain: sceneGain() });
  });
}

async function main() {
  if (typeof WebAssembly !== 'object' || typeof WebAssembly.instantiate !== 'function') {
    unsupported('This browser has no WebAssembly, which aero needs to run Pd. ' +
      'Use a current Chromium, Firefox or Safari.');
    return;
  }
  if (typeof AudioWorkletNode !== 'function' || !window.isSecureContext) {
    unsupported('This browser (or this page\'s address) offers no AudioWorklet, ' +
      'which aero needs to play live: use a current browser, and open the page ' +
      'from https:// or http://localhost.');
    return;
  }
  $('app').hidden = false;
  const list = $('scenes');
  for (const s of SCENES) {
    const b = Object.assign(document.createElement('button'), { type: 'button',
      textContent: s.title });
    b.dataset.id = s.id;
    b.addEventListener('click', () => showScene(s));
    const li = document.createElement('li');
    li.append(b);
    list.append(li);
  }
  $('play').addEventListener('click', togglePlay);
  $('render').addEventListener('click', renderDownload);
  setupSwingPad();
  setupGain();
  status('Loading Pd (aero.wasm) ...');
  state.wasm = await fetchBytes('aero.wasm');
  state.module = await WebAssembly.compile(state.wasm);
  showScene(SCENES[0]);
  status('Ready: press Play.');
  window.aero = { SCENES, render, blockCost, wav: wavBytes, state, ready: true };
}

main().catch(err => { console.error(err); status('Error: ' + err.message); });
