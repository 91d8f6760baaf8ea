// node tests/web/loudness.mjs RATE [DIR/][native-|loud-]ID.wav ...: each scene's loudness as
// the page plays it at its defaults: the native render of web/scenes/ID.pd
// (in pascals; the page's renders are the same samples, run.sh checks that)
// times the scene's default gain (web/scenes.js), through the page's master
// limiter (web/limiter.js), measured as integrated loudness over the render
// (the scene's first seconds): ITU-R BS.1770-4 2015 K-weighting (its
// 48 kHz filter coefficients), 400 ms blocks overlapping 75 %, the
// absolute gate at -70 LUFS and the relative gate 10 LU under the
// ungated level. A sound designer moving between scenes should not have
// to reach for the gain: every scene within 3 LU of the others (EBU R 128
// s1 2016 allows +-1 LU around its target for short-form programmes, so
// two of them may differ by 2 LU; 3 LU leaves a scene's gain in whole dB
// and the scatter of a gusting scene's first 10 s room). Prints each scene's loudness and true-peak level
// and "ok"/"FAIL" for the spread.
import { floats } from './wav.mjs';
import { SCENES } from '../../web/scenes.js';
import { Limiter } from '../../web/limiter.js';

// BS.1770-4, Table 1 and 2: the shelving pre-filter and the RLB high-pass
// at 48 kHz
const K = [
  { b: [1.53512485958697, -2.69169618940638, 1.19839281085285],
    a: [-1.69065929318241, 0.73248077421585] },
  { b: [1.0, -2.0, 1.0], a: [-1.99004745483398, 0.99007225036621] },
];

function biquad(x, { b, a }) {
  const y = new Float64Array(x.length);
  let x1 = 0, x2 = 0, y1 = 0, y2 = 0;
  for (let i = 0; i < x.length; i++) {
    const v = b[0] * x[i] + b[1] * x1 + b[2] * x2 - a[0] * y1 - a[1] * y2;
    x2 = x1; x1 = x[i]; y2 = y1; y1 = v; y[i] = v;
  }
  return y;
}

// integrated loudness (LUFS) of channels CH (arrays) at 48 kHz
export function integratedLoudness(ch, rate) {
  if (rate !== 48000) throw new Error('K-weighting coefficients are for 48 kHz');
  const z = ch.map(x => biquad(biquad(x, K[0]), K[1]));
  const block = 0.4 * rate, step = 0.1 * rate;
  const powers = [];
  for (let s = 0; s + block <= z[0].length; s += step) {
    let p = 0;
    for (const c of z) {
      let sum = 0;
      for (let i = s; i < s + block; i++) sum += c[i] * c[i];
      p += sum / block;
    }
    powers.push(p);
  }
  const lufs = p => -0.691 + 10 * Math.log10(p);
  const mean = a => a.reduce((u, v) => u + v, 0) / a.length;
  const abs = powers.filter(p => lufs(p) > -70);
  if (!abs.length) return -Infinity;
  const rel = lufs(mean(abs)) - 10;
  const gated = abs.filter(p => lufs(p) > rel);
  return lufs(mean(gated));
}

const isMain = import.meta.url === `file://${process.argv[1]}`;
if (isMain) {
  const [rateArg, ...files] = process.argv.slice(2);
  const rate = Number(rateArg);
  const results = [];
  for (const f of files) {
    const id = f.replace(/.*\//, '').replace(/^(native|loud)-/, '').replace(/\.wav$/, '');
    const scene = SCENES.find(s => s.id === id);
    if (!scene) continue;
    const { x, channels } = floats(f);
    const n = x.length / channels, g = Math.pow(10, scene.gain / 20);
    const l = new Float32Array(n), r = new Float32Array(n);
    for (let i = 0; i < n; i++) { l[i] = x[2 * i] * g; r[i] = x[2 * i + 1] * g; }
    const lim = new Limiter(rate);
    let worst = 1;
    for (let i = 0; i < n; i += 128) {
      const k = Math.min(128, n - i);
      lim.process([l.subarray(i, i + k), r.subarray(i, i + k)], k);
      worst = Math.min(worst, lim.reduction);
      lim.reduction = 1;
    }
    const lufs = integratedLoudness([l, r], rate);
    results.push({ id, lufs });
    console.log(`      ${id.padEnd(6)} ${lufs.toFixed(1)} LUFS over ${(n / rate).toFixed(0)} s at gain ${scene.gain} dB (limiter at most ${(20 * Math.log10(worst)).toFixed(1)} dB)`);
  }
  const lo = Math.min(...results.map(r => r.lufs)), hi = Math.max(...results.map(r => r.lufs));
  const ok = results.length === SCENES.length && hi - lo <= 3 && Number.isFinite(lo);
  console.log(`${ok ? 'ok   ' : 'FAIL '} loudness: every scene at its defaults within 3 LU of the others ` +
    `(${lo.toFixed(1)} to ${hi.toFixed(1)} LUFS, spread ${(hi - lo).toFixed(1)} LU over ${results.length} scenes)`);
  process.exit(ok ? 0 : 1);
}
