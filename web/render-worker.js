// The page's offline renders, in a worker so that the page stays live: a
// fresh Pd (aero-pd.js) renders the scene, reports its progress, and
// answers the left and right channels (transferred, not copied). Cancel is
// the page terminating the worker. With LIMIT, the render is what the page
// plays: times GAIN, through the master limiter (limiter.js), its delay
// taken off.
//   in:  { wasm, files, patch, messages, seconds, rate, gain, limit }
//   out: { progress: 0..1 } ... { left, right }  or  { error }
import { renderScene } from './aero-pd.js';
import { Limiter } from './limiter.js';

let pdLine = '';
const print = text => {
  pdLine += text;
  if (!pdLine.endsWith('\n')) return;
  postMessage({ print: pdLine.trimEnd() });
  pdLine = '';
};

onmessage = async e => {
  const { wasm, files, patch, messages, seconds, rate, gain = 1, limit = false } = e.data;
  try {
    const lim = limit ? new Limiter(rate) : null;
    let { left, right } = await renderScene(wasm, files, patch, messages, seconds,
      rate, print, p => postMessage({ progress: p }), lim ? lim.delay : 0);
    if (lim) {
      for (let i = 0; i < left.length; i++) { left[i] *= gain; right[i] *= gain; }
      for (let i = 0; i < left.length; i += 128) {
        const n = Math.min(128, left.length - i);
        lim.process([left.subarray(i, i + n), right.subarray(i, i + n)], n);
      }
      const n = Math.floor(seconds * rate / 64) * 64;
      left = left.slice(lim.delay, lim.delay + n);
      right = right.slice(lim.delay, lim.delay + n);
    }
    postMessage({ progress: 1 });
    postMessage({ left, right }, [left.buffer, right.buffer]);
  } catch (err) {
    postMessage({ error: String(err && err.message || err) });
  }
};
