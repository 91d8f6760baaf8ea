// node tests/web/embed.mjs URL: examples/web-embed as built by its own
// build.sh in an empty folder (tests/web/run.sh), in headless Chromium:
// Play, then the rod is silent at 0 m/s and sounds once the page's slider
// has sent "speed 15" through libpd's message calls (without them
// exported the message would do nothing). Prints ok/FAIL lines.
import { chromium } from 'playwright-core';

const [url] = process.argv.slice(2);
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium', headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--disable-background-networking',
    '--disable-component-update', '--disable-sync', '--no-first-run',
    '--autoplay-policy=no-user-gesture-required'],
});
const page = await browser.newPage();
const errors = [];
page.on('console', m => { if (m.type() === 'error') errors.push(m.text()); });
page.on('pageerror', e => errors.push(String(e)));
const say = (ok, text) => console.log(`${ok ? 'ok  ' : 'FAIL'}  ${text}`);
const rms = () => page.evaluate(() => new Promise(r => setTimeout(() => {
  const a = window.embed.analyser, x = new Float32Array(a.fftSize);
  a.getFloatTimeDomainData(x);
  r(Math.sqrt(x.reduce((s, v) => s + v * v, 0) / x.length));
}, 600)));
try {
  await page.goto(url);
  await page.click('#play');
  await page.waitForFunction(() => window.embed && window.embed.ready, null, { timeout: 60000 });
  const still = await rms();
  await page.$eval('#speed', el => { el.value = 15; el.dispatchEvent(new Event('input')); });
  const wind = await rms();
  say(still < 1e-6 && wind > 1e-4 && Number.isFinite(wind),
    `examples/web-embed: built from its README's steps in an empty folder, it plays: ` +
    `output rms ${still.toExponential(1)} at 0 m/s, ${wind.toExponential(2)} after "speed 15"`);
} catch (err) {
  say(false, `examples/web-embed: ${err.message.split('\n')[0]}`);
}
say(errors.length === 0, `examples/web-embed: no console error (${errors.length})`);
for (const e of errors.slice(0, 5)) console.log(`        ${e}`);
await browser.close();
