// make check-web: the page as a sound designer uses it (issue 50), in the
// same headless Chromium as check.mjs, each case on a fresh page:
//   levels   nothing the page plays goes over -1 dBFS: wires at 30 m/s, the
//            fence at full wind with a squall, the fire at gain +50 dB with
//            an explosion, scene switches from the loud swings to the
//            fire; measured twice: by an AnalyserNode the test hangs on the
//            page's output (sample peak) and by the page's own true-peak
//            meter. At a switch the scene's gain must be set before it is
//            heard: the new scene's level before the limiter stays under
//            0 dBFS from its first sample (the page without this peaked
//            at +4 to +14 dBFS there)
//   races    on a slow connection (the tree's data delayed 2 s) Tree then
//            Wind on wires within 0.2 s: the wires are shown and heard and
//            the status says so; a double-click on Play before Pd runs
//            makes one AudioContext, which plays
//   renders  a 60 s render runs in a worker: the page answers within
//            0.25 s meanwhile, shows progress, and Cancel stops it; a short
//            render and "record what I play" give WAVs under -1 dBFS
//   phone    390 x 844 and 360 px: no element wider than the screen, Play
//            within the first screen (a screenshot, OUT/phone.png); opened
//            from disk (file://) the page says why it cannot run
//   small    one button per label in the whirl scene, "Solo wire" a named
//            choice, the spectrogram's axes drawn
//   rotors   each rotor scene's buttons do what they say, heard on the
//            page's output: the fan's Switch off silences it and Switch on
//            brings it back; the drone's and the propeller's Fly past
//            come from far (quieter than before), pass close (louder) and
//            go (quieter); Hover in front brings the drone back; never
//            over -1 dBFS
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';

const CEIL = Math.pow(10, -1 / 20);
const dB = v => (v > 0 ? (20 * Math.log10(v)).toFixed(1) : '-inf');

// counts the AudioContexts a page makes (window.__contexts)
function countContexts() {
  const Orig = window.AudioContext;
  window.__contexts = [];
  window.AudioContext = class extends Orig {
    constructor(...a) { super(...a); window.__contexts.push(this); }
  };
}

async function open(browser, url, errors, options = {}) {
  const context = await browser.newContext({ viewport: { width: 1200, height: 900 },
    acceptDownloads: true, ...options });
  const page = await context.newPage();
  page.on('console', m => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', e => errors.push(String(e)));
  await page.addInitScript(countContexts);
  page.setDefaultTimeout(30000);
  await page.goto(url);
  await page.waitForFunction(() => window.aero && window.aero.ready, null, { timeout: 120000 });
  return page;
}

const scenePlays = (page, id) => page.waitForFunction(id =>
  window.aero.state.playingScene && window.aero.state.playingScene.id === id, id,
  { timeout: 30000 });

async function play(page) {
  await page.click('#play');
  await page.waitForFunction(() => window.aero.state.playing, null, { timeout: 60000 });
  await scenePlays(page, 'wires');
}

// an AnalyserNode on the page's output, read often enough that its 32768
// samples (0.68 s) overlap: window.__probe.max, the largest |sample|
async function probe(page) {
  await page.evaluate(() => {
    const { ctx, node } = window.aero.state;
    if (!window.__probe) {
      const a = ctx.createAnalyser();
      a.fftSize = 32768;
      node.connect(a);
      const x = new Float32Array(a.fftSize);
      window.__probe = { max: 0 };
      setInterval(() => {
        a.getFloatTimeDomainData(x);
        for (const v of x) if (!(Math.abs(v) <= window.__probe.max)) window.__probe.max = Math.abs(v);
      }, 150);
    }
  });
}
const resetLevels = page => page.evaluate(() => {
  if (window.__probe) window.__probe.max = 0;
  if (window.aero.resetLevels) window.aero.resetLevels();
});
// { probe, peak, input } after WAIT ms
async function levels(page, wait) {
  await page.waitForTimeout(wait);
  return page.evaluate(() => ({ probe: window.__probe.max,
    peak: window.aero.state.levels ? window.aero.state.levels.peak : NaN,
    input: window.aero.state.levels ? window.aero.state.levels.input : NaN,
    reduction: window.aero.state.levels ? window.aero.state.levels.reduction : NaN }));
}
const slide = (page, control, value) => page.$eval(control, (el, v) => {
  el.value = v;
  el.dispatchEvent(new Event('input', { bubbles: true }));
}, value);
const action = (page, label) => page.click(`#actions button:text-is("${label}")`);
async function scene(page, id) {
  await page.click(`#scenes button[data-id="${id}"]`);
  await scenePlays(page, id);
}

async function caseLevels(browser, url, say, errors) {
  const page = await open(browser, url, errors);
  try {
    await play(page);
    await probe(page);
    const judge = (name, m) => say(m.probe <= CEIL && m.peak <= CEIL && Number.isFinite(m.probe),
      `levels: ${name}: output sample peak ${dB(m.probe)} dBFS (probe), true peak ` +
      `${dB(m.peak)} dBTP (page meter), limiter ${dB(m.reduction)} dB; ceiling -1`);
    await slide(page, '#c-speed', 30);
    await page.waitForTimeout(300);
    await resetLevels(page);
    judge('wires at 30 m/s', await levels(page, 2500));

    await scene(page, 'fence');
    await slide(page, '#c-speed', 30);
    await slide(page, '#c-gust', 1);
    await resetLevels(page);
    await action(page, 'Squall');
    judge('the fence at 30 m/s, gusts 1, a squall', await levels(page, 3000));

    await scene(page, 'fire');
    await slide(page, '#gain', 50);
    await resetLevels(page);
    await action(page, 'Explode');
    judge('the fire at gain +50 dB, an explosion', await levels(page, 2500));

    // switches from a loud swing to the fire, three times: the output,
    // and the fire's own level before the limiter from its first sample
    // (the old scene's gain on it was the burst)
    let worst = { probe: 0, peak: 0, input: 0, reduction: 1 }, fire = 0;
    for (const from of ['club', 'sword', 'club']) {
      await scene(page, from);
      await action(page, 'Swing');
      await page.waitForTimeout(150);
      await resetLevels(page);
      await page.click('#scenes button[data-id="fire"]');
      const m = await levels(page, 700);
      for (const k of ['probe', 'peak', 'input']) worst[k] = Math.max(worst[k], m[k]);
      worst.reduction = Math.min(worst.reduction, m.reduction);
      const own = await page.evaluate(() => window.aero.state.levels.scene === 'fire' ?
        window.aero.state.levels.scenePeak : NaN);
      fire = own > fire || !(own === own) ? own : fire;
    }
    judge('switching from the club and the sword to the fire (3 times)', worst);
    say(fire <= 1, `levels: at a switch the new gain applies from the new scene's first ` +
      `sample: the fire's largest sample before the limiter in its first 0.7 s ${dB(fire)} dBFS ` +
      `(under 0; its default gain -6 dB)`);
  } catch (err) {
    say(false, `levels: ${err.message.split('\n')[0]}`);
  }
  await page.context().close();
}

async function caseRaces(browser, url, say, errors) {
  // a slow connection: the tree's data 2 s late
  let page = await open(browser, url, errors);
  try {
    await play(page);
    await page.route('**/aero/trees/**', r => setTimeout(() => r.continue().catch(() => {}), 2000));
    await page.click('#scenes button[data-id="tree"]');
    await page.waitForTimeout(200);
    await page.click('#scenes button[data-id="wires"]');
    await page.waitForTimeout(3500);
    const r = await page.evaluate(() => ({
      shown: document.getElementById('scene-title').textContent,
      current: document.querySelector('#scenes button[aria-current="true"]').dataset.id,
      heard: window.aero.state.playingScene && window.aero.state.playingScene.id,
      status: document.getElementById('status').textContent,
    }));
    say(r.shown === 'Wind on wires' && r.current === 'wires' && r.heard === 'wires' &&
      /^Playing Wind on wires/.test(r.status),
      `races: Tree (its data 2 s late) then Wind on wires 0.2 s later: shown "${r.shown}", ` +
      `heard "${r.heard}", status "${r.status}"`);
    await page.click('#scenes button[data-id="fence"]');
    await scenePlays(page, 'fence');
    const st = await page.textContent('#status');
    say(/^Playing Fence/.test(st), `races: the status line after a switch to the fence: "${st}"`);
  } catch (err) {
    say(false, `races: ${err.message.split('\n')[0]}`);
  }
  await page.context().close();

  page = await open(browser, url, errors);
  try {
    await page.dblclick('#play');
    await page.waitForFunction(() => window.aero.state.playingScene, null, { timeout: 60000 })
      .catch(() => {});
    await page.waitForTimeout(500);
    const r = await page.evaluate(() => ({
      n: window.__contexts.length,
      states: window.__contexts.map(c => c.state).join(','),
      status: document.getElementById('status').textContent,
      button: document.getElementById('play').textContent,
    }));
    say(r.n === 1 && r.states === 'running' && /^Playing/.test(r.status),
      `races: a double-click on Play before Pd runs: ${r.n} AudioContext(s) (${r.states}), ` +
      `status "${r.status}", button "${r.button}"`);
  } catch (err) {
    say(false, `races: double-click on Play: ${err.message.split('\n')[0]}`);
  }
  await page.context().close();
}

// a float WAV's peak and duration
function wavPeak(path) {
  const b = readFileSync(path);
  const v = new DataView(b.buffer, b.byteOffset, b.byteLength);
  let o = 12, rate = 0, ch = 2;
  while (o + 8 <= b.length) {
    const id = b.toString('latin1', o, o + 4), size = v.getUint32(o + 4, true);
    if (id === 'fmt ') { ch = v.getUint16(o + 10, true); rate = v.getUint32(o + 12, true); }
    if (id === 'data') {
      let peak = 0, sum = 0;
      const n = Math.min(size, b.length - o - 8) / 4;
      for (let i = 0; i < n; i++) {
        const x = v.getFloat32(o + 8 + 4 * i, true);
        if (!(Math.abs(x) <= peak)) peak = Math.abs(x);
        sum += x * x;
      }
      return { peak, rms: Math.sqrt(sum / n), seconds: n / ch / rate };
    }
    o += 8 + size + (size & 1);
  }
  return { peak: NaN, rms: 0, seconds: 0 };
}

async function caseRenders(browser, url, out, say, errors) {
  const page = await open(browser, url, errors);
  try {
    await page.click('#scenes button[data-id="whirl"]');
    await page.fill('#seconds', '60');
    await page.click('#render', { timeout: 5000 });
    await page.waitForTimeout(1000);
    // the main thread's worst gap between 25 ms timers over ~1 s
    const gap = await Promise.race([
      page.evaluate(() => new Promise(r => {
        let t = performance.now(), worst = 0, n = 0;
        const tick = () => {
          const now = performance.now();
          worst = Math.max(worst, now - t);
          t = now;
          if (++n < 40) setTimeout(tick, 25); else r(worst);
        };
        setTimeout(tick, 25);
      })),
      new Promise(r => setTimeout(() => r(Infinity), 10000))]);
    const p1 = await page.evaluate(() => document.getElementById('render-progress')?.value);
    await page.waitForTimeout(2500);
    const p2 = await page.evaluate(() => document.getElementById('render-progress')?.value);
    say(gap < 250 && p2 > p1 && p1 >= 0,
      `renders: during a 60 s render of the whirl the page answers within ${gap.toFixed(0)} ms ` +
      `(< 250), its progress ${(100 * p1).toFixed(0)} -> ${(100 * p2).toFixed(0)} %`);
    await page.click('#render-cancel', { timeout: 5000 });
    await page.waitForFunction(() => !window.aero.state.renderWorker, null, { timeout: 5000 });
    const st = await page.textContent('#status');
    say(/cancelled/.test(st) && await page.isEnabled('#render'),
      `renders: Cancel stops it (status "${st}")`);

    // a short render as heard: the fire at +50 dB with its gain and limiter
    await page.click('#scenes button[data-id="fire"]');
    await slide(page, '#gain', 50);
    await page.fill('#seconds', '2');
    const [dl] = await Promise.all([page.waitForEvent('download'), page.click('#render')]);
    await dl.saveAs(`${out}/render-fire.wav`);
    const w = wavPeak(`${out}/render-fire.wav`);
    say(w.peak <= CEIL && w.rms > 0 && Math.abs(w.seconds - 2) < 0.01,
      `renders: Render WAV of the fire at gain +50 dB: ${w.seconds.toFixed(2)} s, peak ${dB(w.peak)} dBFS`);

    // record what I play
    await slide(page, '#gain', -6);
    await page.click('#play');
    await scenePlays(page, 'fire');
    await page.click('#record');
    await page.waitForTimeout(1500);
    const [rec] = await Promise.all([page.waitForEvent('download'), page.click('#record')]);
    await rec.saveAs(`${out}/recording.wav`);
    const r = wavPeak(`${out}/recording.wav`);
    say(r.seconds > 1.2 && r.rms > 1e-4 && r.peak <= CEIL,
      `renders: "Record what I play", 1.5 s of the fire: a WAV of ${r.seconds.toFixed(2)} s, ` +
      `peak ${dB(r.peak)} dBFS, rms ${dB(r.rms)} dBFS`);
  } catch (err) {
    say(false, `renders: ${err.message.split('\n')[0]}`);
  }
  await page.context().close();
}

// the elements wider than the window (and the page's scroll width)
const overflow = page => page.evaluate(() => {
  const w = window.innerWidth, wide = [];
  for (const el of document.querySelectorAll('body *')) {
    const r = el.getBoundingClientRect();
    if (r.width && r.right > w + 0.5) wide.push(`${el.tagName.toLowerCase()}${el.id ? '#' + el.id : ''}`);
  }
  return { width: w, scroll: document.documentElement.scrollWidth, wide: wide.slice(0, 5) };
});

async function casePhone(browser, url, out, say, errors) {
  for (const [w, h] of [[390, 844], [360, 740]]) {
    const page = await open(browser, url, errors, { viewport: { width: w, height: h },
      isMobile: true, hasTouch: true, deviceScaleFactor: 1 });
    try {
      const worst = { scroll: 0, wide: [] };
      for (const id of await page.evaluate(() => window.aero.SCENES.map(s => s.id))) {
        await page.click(`#scenes button[data-id="${id}"]`);
        const o = await overflow(page);
        if (o.scroll > worst.scroll) worst.scroll = o.scroll;
        if (o.wide.length) worst.wide.push(`${id}: ${o.wide.join(' ')}`);
      }
      await page.click('#scenes button[data-id="wires"]');
      const play = await page.locator('#play').boundingBox();
      if (w === 390) await page.screenshot({ path: `${out}/phone.png` });
      say(worst.scroll <= w && !worst.wide.length && play && play.y + play.height <= h,
        `phone ${w} x ${h}: page width ${worst.scroll} px in every scene` +
        `${worst.wide.length ? ` (too wide: ${worst.wide.slice(0, 3).join('; ')})` : ''}, ` +
        `Play at ${play ? Math.round(play.y) : '?'}-${play ? Math.round(play.y + play.height) : '?'} px` +
        `${w === 390 ? ` (${out}/phone.png)` : ''}`);
    } catch (err) {
      say(false, `phone ${w} px: ${err.message.split('\n')[0]}`);
    }
    await page.context().close();
  }
  // from disk: no server, so no console is watched (the browser itself
  // reports the module it refuses to load)
  const context = await browser.newContext();
  const page = await context.newPage();
  try {
    await page.goto('file://' + resolve(process.env.WEB_DIR || 'build/web', 'index.html'));
    await page.waitForTimeout(1000);
    const box = page.locator('#unsupported');
    const text = (await box.isVisible()) ? await box.textContent() : '';
    say(/file:\/\//.test(text) && /web-serve|http\.server/.test(text),
      `file://: the page says "${text.slice(0, 70)}..."`);
  } catch (err) {
    say(false, `file://: ${err.message.split('\n')[0]}`);
  }
  await context.close();
}

async function caseSmall(browser, url, out, say, errors) {
  const page = await open(browser, url, errors);
  try {
    await play(page);
    await scene(page, 'whirl');
    const labels = await page.$$eval('button', bs => bs.filter(b => b.offsetParent)
      .map(b => b.textContent.trim()));
    const dup = labels.filter((l, i) => labels.indexOf(l) !== i);
    say(!dup.length, `small: the whirl scene's buttons each say one thing (${labels.join(', ')})`);

    await scene(page, 'wires');
    const solo = await page.evaluate(() => {
      const el = document.getElementById('c-solo');
      const label = document.querySelector('label[for="c-solo"]');
      return { tag: el.tagName, label: label && label.textContent,
        options: el.options ? [...el.options].map(o => o.textContent) : [] };
    });
    say(solo.tag === 'SELECT' && /^Solo wire/.test(solo.label) && solo.options.includes('25 mm rod'),
      `small: "${solo.label}" is a ${solo.tag.toLowerCase()} of ${solo.options.join(', ') || 'numbers'}`);

    // the axes: light grey text in the left and bottom margins (the
    // spectrogram's own colours are never grey)
    await page.waitForTimeout(1500);
    const axes = await page.evaluate(() => {
      const c = document.getElementById('spectrogram'), g = c.getContext('2d');
      const grey = (x, y, w, h) => {
        const d = g.getImageData(x, y, w, h).data;
        let n = 0;
        for (let i = 0; i < d.length; i += 4) {
          if (d[i] > 120 && Math.abs(d[i] - d[i + 1]) < 16 && Math.abs(d[i + 1] - d[i + 2]) < 16) n++;
        }
        return n;
      };
      return { left: grey(0, 0, 46, c.height - 26), bottom: grey(60, c.height - 20, c.width - 60, 20) };
    });
    await page.locator('#spectrogram').screenshot({ path: `${out}/spectrogram.png` });
    say(axes.left > 40 && axes.bottom > 40,
      `small: the spectrogram has a frequency axis (${axes.left} label pixels) and a time axis ` +
      `(${axes.bottom}) (${out}/spectrogram.png)`);
  } catch (err) {
    say(false, `small: ${err.message.split('\n')[0]}`);
  }
  await page.context().close();
}

// the page output's mean power over the next WAIT ms (dB, full scale 0),
// from an AnalyserNode read every 50 ms (its 4096 samples, 85 ms, overlap)
async function power(page, wait) {
  await page.evaluate(() => {
    const { ctx, node } = window.aero.state;
    if (!window.__power) {
      const a = ctx.createAnalyser();
      a.fftSize = 4096;
      node.connect(a);
      const x = new Float32Array(a.fftSize);
      window.__power = { sum: 0, n: 0 };
      setInterval(() => {
        a.getFloatTimeDomainData(x);
        let s = 0;
        for (const v of x) s += v * v;
        window.__power.sum += s / x.length;
        window.__power.n++;
      }, 50);
    }
    window.__power.sum = 0;
    window.__power.n = 0;
  });
  await page.waitForTimeout(wait);
  const p = await page.evaluate(() => window.__power.sum / Math.max(1, window.__power.n));
  return p > 0 ? 10 * Math.log10(p) : -Infinity;
}

// a fly-past heard in steps of STEP ms for SPAN ms after its button
async function flyPast(page, span, step) {
  await action(page, 'Fly past');
  const trace = [];
  for (let t = 0; t < span; t += step) trace.push(await power(page, step));
  return trace;
}

async function caseRotors(browser, url, say, errors) {
  const page = await open(browser, url, errors);
  const f1 = v => v.toFixed(1);
  try {
    await play(page);
    await probe(page);
    // the fan spins up over 3 s from its start, and down over 3 s
    await scene(page, 'fan');
    await page.waitForTimeout(3500);
    await resetLevels(page);
    const on = await power(page, 1000);
    await action(page, 'Switch off');
    await page.waitForTimeout(3500);
    const off = await power(page, 1000);
    await action(page, 'Switch on');
    await page.waitForTimeout(3500);
    const again = await power(page, 1000);
    say(off < on - 30 && Math.abs(again - on) < 2,
      `rotors: the fan at speed ${f1(on)} dB, Switch off ${f1(off)} dB (30 dB under or more), ` +
      `Switch on ${f1(again)} dB (within 2 dB of before)`);

    // the drone hovers 3.6 m away; flown past from 20 m left to 20 m
    // right, 3 m in front, in 5 s
    await scene(page, 'drone');
    await page.waitForTimeout(1500);
    const hover = await power(page, 1000);
    const d = await flyPast(page, 5500, 500);
    const dMax = Math.max(...d), dAt = d.indexOf(dMax);
    say(d[1] < hover - 8 && dMax > d[1] + 10 && d[d.length - 1] < dMax - 10 &&
      dAt >= 3 && dAt <= 8,
      `rotors: the drone hovering ${f1(hover)} dB; Fly past every 0.5 s: ${d.map(f1).join(' ')} dB ` +
      `(far, then 10 dB louder near the middle, then 10 dB quieter)`);
    await action(page, 'Hover in front');
    await page.waitForTimeout(1000);
    const back = await power(page, 1000);
    say(Math.abs(back - hover) < 2,
      `rotors: Hover in front brings the drone back: ${f1(back)} dB (hovering ${f1(hover)})`);

    // the propeller passes from 150 m before to 150 m past in 6 s, 36 m
    // from the listener at its closest
    await scene(page, 'propeller');
    const p = await flyPast(page, 7000, 500);
    const pMax = Math.max(...p), pAt = p.indexOf(pMax);
    say(pMax > p[1] + 10 && pMax > p[p.length - 1] + 10 && pAt >= 3 && pAt <= 10,
      `rotors: the propeller's Fly past every 0.5 s: ${p.map(f1).join(' ')} dB (10 dB louder ` +
      `as it passes than as it comes and goes)`);
    const m = await levels(page, 0);
    say(m.probe <= CEIL && m.peak <= CEIL,
      `rotors: the whole case's output sample peak ${dB(m.probe)} dBFS, true peak ` +
      `${dB(m.peak)} dBTP (ceiling -1)`);
  } catch (err) {
    say(false, `rotors: ${err.message.split('\n')[0]}`);
  }
  await page.context().close();
}

export async function usability(browser, url, out, say, errors) {
  await caseLevels(browser, url, say, errors);
  await caseRaces(browser, url, say, errors);
  await caseRenders(browser, url, out, say, errors);
  await casePhone(browser, url, out, say, errors);
  await caseSmall(browser, url, out, say, errors);
  await caseRotors(browser, url, say, errors);
}
