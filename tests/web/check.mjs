// make check-web, the browser half (tests/web/run.sh runs it): Debian's
// Chromium headless, driven by playwright-core, opens the page served from
// build/web and
//   - records every console error and uncaught exception while it loads,
//     plays a scene live in the AudioWorklet and renders;
//   - renders each scene offline (window.aero.render: a fresh Pd in the
//     page, default controls) into OUT/web-SCENE.wav;
//   - moves a control as a user would (the wires scene: the 25 mm rod
//     alone, no gusts, the wind-speed slider at 12 then 24 m/s) and renders
//     OUT/wires-u12.wav and OUT/wires-u24.wav;
//   - with BENCH set, measures the time per 128-frame block of each scene;
//   - then the page as a sound designer uses it (usability(), below):
//     levels, races, renders, the phone, the small things.
// Prints "ok"/"FAIL" lines; run.sh counts them and judges the WAVs.
//   node check.mjs URL OUT SECONDS [bench]
import { chromium } from 'playwright-core';
import { writeFileSync } from 'node:fs';
import { usability } from './usability.mjs';

const [url, out, secondsArg, bench] = process.argv.slice(2);
const seconds = Number(secondsArg);
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking',
    '--disable-component-update', '--disable-sync', '--no-first-run',
    '--autoplay-policy=no-user-gesture-required'],
});
const page = await browser.newPage({ viewport: { width: 1200, height: 900 } });
const errors = [];
page.on('console', m => { if (m.type() === 'error') errors.push(m.text()); });
page.on('pageerror', e => errors.push(String(e)));
const say = (ok, text) => console.log(`${ok ? 'ok  ' : 'FAIL'}  ${text}`);

try {
  await page.goto(url);
  await page.waitForFunction(() => window.aero && window.aero.ready, null,
    { timeout: 120000 });
  if (bench === 'bench-only') {
    const scenes = await page.evaluate(() => window.aero.SCENES.map(s => s.id));
    for (const id of scenes) {
      const ms = await page.evaluate(id => window.aero.blockCost(id), id);
      console.log(`bench ${id} ${ms.toFixed(4)}`);
    }
    await browser.close();
    process.exit(0);
  }
  say(true, 'the page loads, aero.wasm instantiates in the page');

  // live: Play starts Pd in the AudioWorklet; let it run a second
  await page.click('#play');
  await page.waitForFunction(() => window.aero.state.playing, null, { timeout: 60000 });
  await page.waitForFunction(() => window.aero.state.playingScene, null, { timeout: 30000 })
    .catch(() => {});
  await page.waitForTimeout(1500);
  const live = await page.evaluate(() => {
    const { ctx, analyser } = window.aero.state;
    const x = new Float32Array(analyser.fftSize);
    analyser.getFloatTimeDomainData(x);
    const rms = Math.sqrt(x.reduce((a, v) => a + v * v, 0) / x.length);
    return { rate: ctx.sampleRate, time: ctx.currentTime, rms };
  });
  say(live.time > 0.5 && live.rms > 1e-4 && Number.isFinite(live.rms),
    `the wires scene plays live in an AudioWorklet at ${live.rate} Hz ` +
    `(context time ${live.time.toFixed(2)} s, output rms ${live.rms.toExponential(2)})`);
  await page.screenshot({ path: `${out}/page.png` });
  await page.click('#play');

  const scenes = await page.evaluate(() => window.aero.SCENES.map(s => s.id));
  const wav = async (id, vals, file) => {
    const b64 = await page.evaluate(async ([id, s, vals]) => {
      const { left, right } = await window.aero.render(id, s, 48000, vals);
      const bytes = new Uint8Array(window.aero.wav(left, right, 48000));
      let bin = '';
      for (let i = 0; i < bytes.length; i += 0x8000) {
        bin += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
      }
      return btoa(bin);
    }, [id, seconds, vals]);
    writeFileSync(file, Buffer.from(b64, 'base64'));
  };
  for (const id of scenes) {
    const t0 = Date.now();
    await wav(id, undefined, `${out}/web-${id}.wav`);
    console.log(`      rendered ${id} in the page (${seconds} s in ${(Date.now() - t0) / 1000} s)`);
  }

  // a control moved as a user moves it: the slider's input event
  await page.click('#scenes button[data-id="wires"]');
  const slide = async (control, value) => page.$eval(`#c-${control}`, (el, v) => {
    el.value = v;
    el.dispatchEvent(new Event('input', { bubbles: true }));
  }, value);
  await slide('solo', 4);
  await slide('gust', 0);
  for (const u of [12, 24]) {
    await slide('speed', u);
    await wav('wires', await page.evaluate(() => ({ ...window.aero.state.values.wires })),
      `${out}/wires-u${u}.wav`);
  }
  say(true, 'the wind-speed slider of the wires scene renders at 12 and 24 m/s');

  // keyboard: the sword scene chosen and swung from the keyboard alone
  await page.focus('#scenes button[data-id="sword"]');
  await page.keyboard.press('Enter');
  await page.waitForTimeout(300);
  await page.focus('#swingpad');
  await page.keyboard.press('Shift+ArrowLeft');
  const swung = await page.textContent('#status');
  say(/^Swing left, 160 ms/.test(swung), `keyboard: Enter on a scene, Shift+Left on the swing pad (${swung})`);

  // the mouse: a drag across the swing pad moves the blade live
  await page.click('#play');
  await page.waitForFunction(() => window.aero.state.playing, null, { timeout: 30000 });
  await page.waitForFunction(() => window.aero.state.playingScene?.id === 'sword', null,
    { timeout: 30000 });
  const pad = await page.locator('#swingpad').boundingBox();
  await page.mouse.move(pad.x + 10, pad.y + pad.height / 2);
  await page.mouse.down();
  await page.mouse.move(pad.x + pad.width - 10, pad.y + pad.height / 2, { steps: 12 });
  await page.mouse.up();
  const dragged = await page.textContent('#status');
  say(/tip reached [1-9]/.test(dragged), `mouse: a drag across the swing pad (${dragged})`);
  await page.click('#play');

  // a browser without AudioWorklet: the page says so instead of failing
  const old = await browser.newPage();
  old.on('console', m => { if (m.type() === 'error') errors.push(m.text()); });
  old.on('pageerror', e => errors.push(String(e)));
  await old.addInitScript(() => { delete window.AudioWorkletNode; });
  await old.goto(url);
  await old.waitForSelector('#unsupported:not([hidden])', { timeout: 30000 });
  const text = await old.textContent('#unsupported');
  say(/AudioWorklet/.test(text) && await old.isHidden('#app'),
    `without AudioWorklet the page shows: "${text.slice(0, 60)}..."`);
  await old.close();

  if (bench) {
    for (const id of scenes) {
      const ms = await page.evaluate(id => window.aero.blockCost(id), id);
      console.log(`bench ${id} ${ms.toFixed(4)}`);
    }
  }
} catch (err) {
  say(false, `the page: ${err.message.split('\n')[0]}`);
}
await page.close();
if (!bench) await usability(browser, url, out, say, errors);
say(errors.length === 0, `no console error (${errors.length})`);
for (const e of errors.slice(0, 10)) console.log(`        ${e}`);
await browser.close();
