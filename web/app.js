// The page: scenes (scenes.js) played live by a Pd in an AudioWorklet
// (worklet.js, through the master limiter of limiter.js), rendered offline
// by a fresh Pd in a worker (render-worker.js), a live spectrogram and a
// level meter. window.aero exposes the renders, the levels and the state
// to tests (tests/web) and benchmarks.
import { SCENES, controlMessages } from './scenes.js';
import { AeroPd, wavBytes, BLOCK } from './aero-pd.js';

const $ = id => document.getElementById(id);
const ABSTRACTIONS = ['draft', 'drone', 'fan', 'fence', 'fire', 'propeller',
  'swing', 'throw', 'tree', 'turbine', 'whirl', 'wind'].map(n => `abstractions/aero.${n}~.pd`);
const dB = x => Math.pow(10, x / 20);

const state = {
  scene: SCENES[0],  // the scene shown: the latest one clicked
  playingScene: null, // the scene the worklet says it plays
  values: {},        // scene id -> { control id -> value }
  files: {},         // path -> Promise of ArrayBuffer, fetched once
  wasm: null,        // aero.wasm bytes (for the worklet)
  module: null,      // and compiled (for renders on this thread)
  ctx: null, node: null, analyser: null, playing: false,
  starting: null,    // the one start of the AudioContext, while it runs
  levels: { peak: 0, input: 0, reduction: 1, limited: 0 }, // since reset
  recording: null,   // { l: [], r: [] } chunks while recording
  renderWorker: null,
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

// the files a scene needs, fetched once (one fetch per file however often
// asked): { path: ArrayBuffer }
async function sceneFiles(scene) {
  const paths = ['scenes/' + scene.patch, ...ABSTRACTIONS, ...scene.data];
  for (const p of paths) {
    if (!state.files[p]) {
      state.files[p] = fetchBytes('aero/' + p);
      state.files[p].catch(() => { delete state.files[p]; });
    }
  }
  const bytes = await Promise.all(paths.map(p => state.files[p]));
  return Object.fromEntries(paths.map((p, i) => [p, bytes[i]]));
}

function values(scene) {
  if (!state.values[scene.id]) {
    state.values[scene.id] = Object.fromEntries(scene.controls.map(c => [c.id, c.value]));
  }
  return state.values[scene.id];
}

function post(msg) { if (state.node) state.node.port.postMessage(msg); }
// messages to the scene shown, once the worklet has it (until then the
// scene's message carries the controls' values)
function sendAll(messages) {
  if (state.postedScene !== state.scene) return;
  for (const m of messages) post({ send: m });
}
function sceneGain() { return dB(Number($('gain').value)); }

// --- live sound ---------------------------------------------------------------
// One AudioContext for the page's life, made by the first Play; the one
// worklet in it plays the scene the latest click chose.
async function startAudio() {
  const ctx = new AudioContext();
  state.ctx = ctx;
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
      if (d.meter) showMeter(d.meter);
      if (d.opened) opened(d.opened);
      if (d.recorded) recorded(d.recorded, d.last);
    };
  });
  const analyser = ctx.createAnalyser();
  analyser.fftSize = 2048;
  analyser.smoothingTimeConstant = 0;
  node.connect(analyser);
  analyser.connect(ctx.destination);
  Object.assign(state, { node, analyser });
  await ready;
  drawSpectrogram();
}

// the worklet plays scene ID now: the status line says what plays
function opened(id) {
  state.playingScene = SCENES.find(s => s.id === id);
  showStatus();
}

function showStatus() {
  if (state.starting) status('Starting Pd in the audio thread ...');
  else if (!state.ctx) status('Ready: press Play.');
  else if (!state.playing) status('Stopped.');
  else if (!state.playingScene || state.playingScene !== state.scene) status(`Loading ${state.scene.title} ...`);
  else status(`Playing ${state.playingScene.title} at ${state.ctx.sampleRate} Hz`);
}

// Scene switching has one owner: each call takes a ticket; after its files
// arrive, only the latest ticket is sent to the worklet, so whatever
// arrives late, the scene heard is the one clicked last. The worklet fades
// out, opens it with its gain already set, and fades in.
let ticket = 0;
async function loadLive(scene) {
  const mine = ++ticket;
  if (!state.node) return;
  showStatus();
  const files = await sceneFiles(scene);
  if (mine !== ticket || !state.node) return;
  state.postedScene = scene;
  state.node.port.postMessage({ scene: { id: scene.id, files, open: scene.patch,
    gain: sceneGain(), messages: controlMessages(scene, values(scene)) } });
}

// Play and Pause: one change at a time; clicks while one runs (a
// double-click on Play while Pd starts) do nothing more, so there is one
// AudioContext and the button and status line say what it does
async function togglePlay() {
  const button = $('play');
  if (state.busy) return;
  state.busy = true;
  button.disabled = true;
  button.setAttribute('aria-busy', 'true');
  try {
    if (!state.ctx) {
      state.starting = startAudio();
      showStatus();
      await state.starting;
      state.starting = null;
      loadLive(state.scene).catch(err => status('Cannot load: ' + err.message));
    }
    if (state.playing) await state.ctx.suspend();
    else await state.ctx.resume();
    state.playing = !state.playing;
  } catch (err) {
    state.starting = null;
    status('Cannot start audio: ' + err.message);
    return;
  } finally {
    state.busy = false;
    button.disabled = false;
    button.removeAttribute('aria-busy');
  }
  button.textContent = state.playing ? 'Pause' : 'Play';
  button.setAttribute('aria-pressed', String(state.playing));
  showStatus();
}

// --- the level meter: the output's true peak (dBTP) and rms; the limiter
// light turns on when the limiter reduced the output and stays on until
// clicked
const toDb = v => (v > 0 ? 20 * Math.log10(v) : -Infinity);
let peakHold = { db: -Infinity, t: 0 };
function showMeter(m) {
  const L = state.levels;
  L.peak = Math.max(L.peak, m.peak);
  L.input = Math.max(L.input, m.input);
  L.reduction = Math.min(L.reduction, m.reduction);
  L.limited += m.limited;
  L.scene = m.scene;
  L.scenePeak = m.scenePeak;
  const db = toDb(m.peak), now = performance.now();
  if (db > peakHold.db || now - peakHold.t > 1500) peakHold = { db, t: now };
  const pos = d => `${Math.max(0, Math.min(100, (d + 60) / 60 * 100))}%`;
  $('meter-bar').style.width = pos(toDb(m.rms) + 3);
  $('meter-peak').style.left = pos(peakHold.db);
  $('meter').setAttribute('aria-valuenow', Math.max(-60, db).toFixed(1));
  $('meter-text').textContent = `${Number.isFinite(peakHold.db) ? peakHold.db.toFixed(1) : '-inf'} dBTP`;
  if (m.reduction < 0.999) {
    const led = $('limit-led');
    led.dataset.on = 'true';
    led.textContent = `limiter ${toDb(Math.min(m.reduction, Number(led.dataset.worst || 1))).toFixed(1)} dB`;
    led.dataset.worst = String(Math.min(m.reduction, Number(led.dataset.worst || 1)));
  }
}

function resetLevels() {
  state.levels = { peak: 0, input: 0, reduction: 1, limited: 0 };
  const led = $('limit-led');
  led.dataset.on = 'false';
  delete led.dataset.worst;
  led.textContent = 'limiter';
}

// --- record what I play: the limiter's output, as heard, into a WAV -----
function toggleRecord() {
  const button = $('record');
  if (!state.node) { status('Press Play first: the recording is what plays.'); return; }
  if (!state.recording) {
    state.recording = { l: [], r: [], t0: performance.now() };
    state.node.port.postMessage({ record: true });
    button.textContent = 'Stop recording';
    button.setAttribute('aria-pressed', 'true');
    status('Recording what plays ...');
  } else {
    state.node.port.postMessage({ record: false });
    button.textContent = 'Record what I play';
    button.setAttribute('aria-pressed', 'false');
  }
}

function recorded([l, r], last) {
  const rec = state.recording;
  if (!rec) return;
  rec.l.push(l);
  rec.r.push(r);
  if (!last) return;
  state.recording = null;
  const join = parts => {
    const out = new Float32Array(parts.reduce((n, p) => n + p.length, 0));
    let o = 0;
    for (const p of parts) { out.set(p, o); o += p.length; }
    return out;
  };
  const left = join(rec.l), right = join(rec.r);
  offer(wavBytes(left, right, state.ctx.sampleRate), `aero-${state.scene.id}-recording.wav`);
  status(`Recorded ${(left.length / state.ctx.sampleRate).toFixed(1)} s: aero-${state.scene.id}-recording.wav`);
}

// a WAV to download: the link shown and clicked
function offer(bytes, name) {
  const a = $('download');
  if (a.href) URL.revokeObjectURL(a.href);
  a.href = URL.createObjectURL(new Blob([bytes], { type: 'audio/wav' }));
  a.download = name;
  a.textContent = name;
  a.hidden = false;
  a.click();
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

// --- the spectrogram: 30 Hz - 12 kHz on a log axis (the scenes' tones
// span 30 Hz to several kHz), dB as colour, COLS_PER_S columns per second
// of audio time (so the time axis is true whatever the frame rate); a
// frequency axis on the left, a time axis (seconds before now) below
const SPEC_LO = 30, SPEC_HI = 12000, COLS_PER_S = 50;
const AXIS_LEFT = 52, AXIS_BOTTOM = 24;
function drawAxes(g, W, H, plotH) {
  g.fillStyle = '#000';
  g.fillRect(0, 0, AXIS_LEFT, H);
  g.fillRect(0, plotH, W, H - plotH);
  g.fillStyle = '#ccc';
  g.strokeStyle = '#888';
  g.font = '13px system-ui, sans-serif';
  g.textBaseline = 'middle';
  g.textAlign = 'right';
  for (const f of [50, 100, 200, 500, 1000, 2000, 5000, 10000]) {
    const y = (plotH - 1) * (1 - Math.log(f / SPEC_LO) / Math.log(SPEC_HI / SPEC_LO));
    g.fillText(f >= 1000 ? `${f / 1000}k` : String(f), AXIS_LEFT - 8, y);
    g.beginPath(); g.moveTo(AXIS_LEFT - 5, y + 0.5); g.lineTo(AXIS_LEFT, y + 0.5); g.stroke();
  }
  g.save();
  g.translate(11, plotH / 2);
  g.rotate(-Math.PI / 2);
  g.textAlign = 'center';
  g.fillText('Hz', 0, 0);
  g.restore();
  g.textAlign = 'center';
  g.textBaseline = 'top';
  const span = (W - AXIS_LEFT) / COLS_PER_S;
  for (let t = 0; t <= span; t += 2) {
    const x = W - 1 - t * COLS_PER_S;
    g.fillText(t === 0 ? '0 s' : `-${t}`, Math.max(AXIS_LEFT + 8, Math.min(W - 12, x)), plotH + 5);
    g.beginPath(); g.moveTo(x + 0.5, plotH); g.lineTo(x + 0.5, plotH + 4); g.stroke();
  }
}

function drawSpectrogram() {
  const canvas = $('spectrogram'), g = canvas.getContext('2d');
  const W = canvas.width, H = canvas.height, plotH = H - AXIS_BOTTOM, plotW = W - AXIS_LEFT;
  const bins = new Float32Array(state.analyser.frequencyBinCount);
  const hzPerBin = state.ctx.sampleRate / state.analyser.fftSize;
  // the FFT bin of each pixel row, bottom = SPEC_LO
  const rowBin = Array.from({ length: plotH }, (_, y) => Math.min(bins.length - 1,
    Math.round(SPEC_LO * Math.pow(SPEC_HI / SPEC_LO, (plotH - 1 - y) / (plotH - 1)) / hzPerBin)));
  const column = g.createImageData(1, plotH);
  g.fillStyle = '#000';
  g.fillRect(0, 0, W, H);
  drawAxes(g, W, H, plotH);
  let col = Math.floor(state.ctx.currentTime * COLS_PER_S);
  const frame = () => {
    const now = Math.floor(state.ctx.currentTime * COLS_PER_S);
    const n = Math.min(plotW, now - col);
    if (state.playing && n > 0) {
      state.analyser.getFloatFrequencyData(bins);
      g.drawImage(canvas, AXIS_LEFT + n, 0, plotW - n, plotH, AXIS_LEFT, 0, plotW - n, plotH);
      for (let y = 0; y < plotH; y++) {
        const v = Math.max(0, Math.min(1, (bins[rowBin[y]] + 110) / 80));
        const i = 4 * y;
        column.data[i] = 255 * Math.min(1, v * 2);
        column.data[i + 1] = 255 * Math.max(0, v * 2 - 1);
        column.data[i + 2] = 120 * (1 - v) * (v > 0.02);
        column.data[i + 3] = 255;
      }
      for (let k = 0; k < n; k++) g.putImageData(column, W - 1 - k, 0);
    }
    col = now;
    requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);
}

// --- offline renders: a fresh Pd in a worker each ------------------------
const printQuiet = text => logPd(text);

// runs one render in a worker (render-worker.js): { left, right };
// PROGRESS(fraction); the worker is state.renderWorker while it runs
// (cancelRender ends it)
function renderInWorker(job, progress = () => {}) {
  return new Promise((resolve, reject) => {
    const w = new Worker('render-worker.js', { type: 'module' });
    state.renderWorker = w;
    w.cancel = () => { w.terminate(); reject(new Error('cancelled')); };
    w.onmessage = e => {
      const d = e.data;
      if (d.progress !== undefined) progress(d.progress);
      if (d.print) logPd(d.print + '\n');
      if (d.error) { w.terminate(); reject(new Error(d.error)); }
      if (d.left) { w.terminate(); resolve(d); }
    };
    w.onerror = e => { w.terminate(); reject(new Error(e.message || 'the render worker failed')); };
    w.postMessage(job);
  }).finally(() => { state.renderWorker = null; });
}

// renders scene ID for SECONDS at RATE with control VALUES (default: the
// page's current ones): { left, right } in pascals, before the gain
async function render(id, seconds, rate = 48000, vals, opts = {}) {
  const scene = SCENES.find(s => s.id === id);
  const files = await sceneFiles(scene);
  const { progress, ...job } = opts; // a function does not cross to the worker
  return renderInWorker({ wasm: state.module, files, patch: scene.patch,
    messages: controlMessages(scene, vals ?? values(scene)), seconds, rate, ...job },
    progress);
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

// Render WAV: the scene as the page plays it (its gain, the limiter) in a
// worker, with progress and Cancel; the page stays live meanwhile
async function renderDownload() {
  const seconds = Math.max(1, Math.min(60, Number($('seconds').value) || 5));
  const scene = state.scene, button = $('render'), bar = $('render-progress');
  button.disabled = true;
  bar.value = 0;
  bar.hidden = false;
  $('render-cancel').hidden = false;
  status(`Rendering ${seconds} s of ${scene.title} ...`);
  try {
    const t0 = performance.now();
    const { left, right } = await render(scene.id, seconds, 48000, undefined, {
      gain: sceneGain(), limit: true,
      progress: p => {
        bar.value = p;
        status(`Rendering ${seconds} s of ${scene.title}: ${Math.round(100 * p)} %`);
      } });
    offer(wavBytes(left, right, 48000), `aero-${scene.id}.wav`);
    status(`Rendered ${seconds} s in ${((performance.now() - t0) / 1000).toFixed(1)} s: aero-${scene.id}.wav`);
  } catch (err) {
    status(err.message === 'cancelled' ? 'Render cancelled.' : 'Render failed: ' + err.message);
  } finally {
    button.disabled = false;
    bar.hidden = true;
    $('render-cancel').hidden = true;
  }
}

function cancelRender() {
  if (state.renderWorker) state.renderWorker.cancel();
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
    // a choice among named values (c.options: [[value, name], ...]) or a
    // slider
    let input;
    if (c.options) {
      input = Object.assign(document.createElement('select'), { id });
      for (const [v, name] of c.options) {
        input.append(Object.assign(document.createElement('option'), { value: v, textContent: name }));
      }
      input.value = String(vals[c.id]);
    } else {
      input = Object.assign(document.createElement('input'), { id, type: 'range',
        min: c.min, max: c.max, step: c.step, value: vals[c.id] });
    }
    input.dataset.control = c.id;
    const out = document.createElement('output');
    out.htmlFor = id;
    const show = () => { out.textContent = c.options ? '' : `${vals[c.id]} ${c.unit}`; };
    show();
    const changed = () => {
      if (vals[c.id] === Number(input.value)) return;
      vals[c.id] = Number(input.value);
      show();
      sendAll(c.send(vals[c.id], vals));
    };
    input.addEventListener('input', changed);
    input.addEventListener('change', changed);
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
    sendAll([['aero-scene', 'ramp', 5]]);
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
  $('render-cancel').addEventListener('click', cancelRender);
  $('record').addEventListener('click', toggleRecord);
  $('limit-led').addEventListener('click', resetLevels);
  setupSwingPad();
  setupGain();
  status('Loading Pd (aero.wasm) ...');
  state.wasm = await fetchBytes('aero.wasm');
  state.module = await WebAssembly.compile(state.wasm);
  showScene(SCENES[0]);
  showStatus();
  const c = $('spectrogram');
  drawAxes(c.getContext('2d'), c.width, c.height, c.height - AXIS_BOTTOM);
  window.aero = { SCENES, render, blockCost, wav: wavBytes, state, resetLevels, ready: true };
}

main().catch(err => { console.error(err); status('Error: ' + err.message); });
