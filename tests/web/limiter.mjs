// node tests/web/limiter.mjs: the page's master limiter (web/limiter.js)
// on test signals, its true peak measured independently of it by 8x
// oversampling (a 256-tap windowed-sinc interpolator; BS.1770-4 asks for
// at least 4x): under its -1 dBTP ceiling it must pass the audio unchanged
// (delayed only), above it keep every true peak at or under -1 dBTP
// (0.01 dB for the measuring interpolator's own error)
import { Limiter } from '../../web/limiter.js';

const RATE = 48000;
let failed = 0;
const say = (ok, text) => { if (!ok) failed++; console.log(`${ok ? 'ok   ' : 'FAIL '} limiter: ${text}`); };

// the true peak of X: 8 points between each pair of samples, away from
// its two ends (where the cut itself would ring)
function truePeak(x) {
  const up = 8, half = 16;
  let m = 0;
  for (let i = half; i < x.length - half; i++) {
    m = Math.max(m, Math.abs(x[i]));
    for (let p = 1; p < up; p++) {
      let s = 0;
      for (let k = -half + 1; k <= half; k++) {
        const j = i + k;
        if (j < 0 || j >= x.length) continue;
        const t = k - p / up, w = 0.5 + 0.5 * Math.cos(Math.PI * t / (half + 1));
        s += x[j] * Math.sin(Math.PI * t) / (Math.PI * t) * w;
      }
      m = Math.max(m, Math.abs(s));
    }
  }
  return m;
}
const dBFS = v => 20 * Math.log10(v);

function run(sig) {
  const lim = new Limiter(RATE);
  const l = Float32Array.from(sig[0]), r = Float32Array.from(sig[1]);
  for (let i = 0; i < l.length; i += 128) {
    const n = Math.min(128, l.length - i);
    lim.process([l.subarray(i, i + n), r.subarray(i, i + n)], n);
  }
  return { l, r, delay: lim.delay };
}

// 1. under the ceiling: a -6 dBFS tone and noise pass unchanged
{
  const n = RATE, a = new Float32Array(n), b = new Float32Array(n);
  let seed = 1;
  for (let i = 0; i < n; i++) {
    a[i] = 0.5 * Math.sin(2 * Math.PI * 997 * i / RATE);
    seed = (seed * 1103515245 + 12345) >>> 0;
    b[i] = 0.1 * (seed / 2 ** 32 - 0.5);
  }
  const { l, r, delay } = run([a, b]);
  let diff = 0;
  for (let i = delay; i < n; i++) diff = Math.max(diff, Math.abs(l[i] - a[i - delay]), Math.abs(r[i] - b[i - delay]));
  say(diff === 0, `a -6 dBFS tone and -26 dBFS noise pass bit for bit, delayed ${delay} samples (${(1000 * delay / RATE).toFixed(2)} ms; largest difference ${diff})`);
}
// 2. over it: a +20 dBFS tone near fs/4 with inter-sample peaks, a click
// of +34 dBFS, loud noise bursts: every true peak <= -1 dBTP
for (const [name, f] of [
  ['a +20 dBFS tone at 11.9 kHz', i => 10 * Math.sin(2 * Math.PI * 11900 * i / RATE + 0.7)],
  ['a +34 dBFS click on silence', i => (i === 10000 ? 50 : 0)],
  ['+14 dBFS noise bursts', (i, u) => ((i >> 11) & 1 ? 5 * (u - 0.5) : 0.05 * (u - 0.5))],
  ['a tone stepping 0 -> +24 dBFS', i => (i < 12000 ? 0.3 : 16) * Math.sin(2 * Math.PI * 440 * i / RATE)],
]) {
  const n = RATE / 2, a = new Float32Array(n), b = new Float32Array(n);
  let seed = 7;
  for (let i = 0; i < n; i++) {
    seed = (seed * 1103515245 + 12345) >>> 0;
    a[i] = f(i, seed / 2 ** 32);
    b[i] = -0.5 * a[i];
  }
  const { l, r } = run([a, b]);
  const tp = Math.max(truePeak(l), truePeak(r));
  say(dBFS(tp) <= -1 + 0.01, `${name}: true peak ${dBFS(Math.max(truePeak(a), truePeak(b))).toFixed(1)} dBTP in, ${dBFS(tp).toFixed(2)} dBTP out (ceiling -1)`);
}
// 3. NaN and Inf in: finite out
{
  const a = new Float32Array(1024).fill(NaN), b = new Float32Array(1024).fill(Infinity);
  const { l, r } = run([a, b]);
  say(l.every(Number.isFinite) && r.every(Number.isFinite), 'NaN and Inf in: finite out');
}
process.exit(failed ? 1 : 0);
