// node compare.mjs A.wav B.wav RATE: two float WAVs (any chunks, e.g.
// libsndfile's PEAK) compared sample by sample against the float-rounding
// bound of tests/web/run.sh: |b - a| at time t <= peak(a) eps (16 +
// 2 pi (RATE/2) t), eps = 2^-24. Prints the largest difference relative to
// the peak and to the bound; "ok" when within it everywhere and the lengths
// match, else "FAIL"
import { floats } from './wav.mjs';

const [a, b, rateArg] = process.argv.slice(2);
const rate = Number(rateArg), eps = 2 ** -24;
const name = b.replace(/.*\/web-|\.wav$/g, '');
try {
  const A = floats(a), B = floats(b);
  let peak = 0, diff = 0, at = 0, bad = 0, worst = 0, worstAt = 0;
  for (let i = 0; i < A.x.length; i++) peak = Math.max(peak, Math.abs(A.x[i]));
  const n = Math.min(A.x.length, B.x.length), ch = A.channels || 1;
  for (let i = 0; i < n; i++) {
    const d = Math.abs(A.x[i] - B.x[i]);
    const t = Math.floor(i / ch) / rate;
    const bound = peak * eps * (16 + 2 * Math.PI * (rate / 2) * t);
    if (!(d <= diff)) { diff = d; at = i; }
    if (!(d / bound <= worst)) { worst = d / bound; worstAt = i; }
    if (!Number.isFinite(B.x[i])) bad++;
  }
  const ok = A.x.length === B.x.length && A.channels === B.channels && !bad &&
    peak > 0 && worst <= 1;
  const sec = i => (Math.floor(i / ch) / rate).toFixed(3);
  console.log(`${ok ? 'ok   ' : 'FAIL '} ${name}: max |web - native| = ` +
    `${(diff / peak).toExponential(2)} x peak ${peak.toExponential(3)} Pa (at ${sec(at)} s), ` +
    `${worst.toFixed(3)} x the bound (at ${sec(worstAt)} s)` +
    `${A.x.length === B.x.length ? '' : `; lengths ${A.x.length} / ${B.x.length}`}`);
  process.exit(ok ? 0 : 1);
} catch (err) {
  console.log(`FAIL  ${name}: ${err.message}`);
  process.exit(1);
}
