// The page's master limiter and meter (web/worklet.js runs it on the
// output, tests/web/limiter.mjs checks it): a true-peak, look-ahead
// limiter with a -1 dBTP ceiling (the maximum true-peak level for
// production of EBU Tech 3343 2011).
//
// True peak: the peak of the signal between its samples too, found as
// ITU-R BS.1770-4 2015 (Annex 2) does, by 4x oversampling; here a 128-tap
// windowed-sinc interpolator (4 phases of 32 taps). A sample stream whose
// samples stay under the ceiling can still swing over it between them
// (up to +3 dB for a tone near fs/4), which a DAC's reconstruction filter
// then plays.
//
// Gain: each detected peak asks for the gain ceiling/peak. That request is
// held (minimum) over the look-ahead, released exponentially, then
// averaged over the look-ahead, and the audio is delayed by the look-ahead:
// the gain is down to the request by the time the peak comes out, with a
// smooth ramp (no click), and at exactly 1 wherever nothing in the
// look-ahead reaches the ceiling: below it the limiter is transparent
// (the audio delayed, unchanged).

const PHASES = 4, TAPS = 32, HALF = TAPS / 2;

// the interpolator: phase p (1..3) gives the value at p/4 of the way from
// the sample HALF-1 back to the next; a Hann-windowed sinc, each phase's
// taps normalised to a DC gain of 1
function interpolator() {
  const h = [];
  for (let p = 1; p < PHASES; p++) {
    const f = new Float64Array(TAPS);
    let sum = 0;
    for (let k = 0; k < TAPS; k++) {
      const t = k - (HALF - 1) - p / PHASES; // time of tap k from the point
      const x = Math.PI * t;
      const w = 0.5 + 0.5 * Math.cos(Math.PI * t / (HALF + 0.5));
      f[k] = (t === 0 ? 1 : Math.sin(x) / x) * w;
      sum += f[k];
    }
    for (let k = 0; k < TAPS; k++) f[k] /= sum;
    h.push(f);
  }
  return h;
}

export const CEILING_DB = -1;

// pushes X into HIST (a ring of TAPS samples kept twice, so that the
// window ending at the newest is contiguous; POS[0] the next write) and
// returns the largest of the sample HALF-1 back and the three points
// after it that the interpolator H gives. The caller advances POS[0].
function truePeakPush(hist, pos, h, x) {
  const p = pos[0];
  hist[p] = x;
  hist[p + TAPS] = x;
  const o = p + 1; // hist[o .. o + TAPS - 1]: oldest to newest
  let m = Math.abs(hist[o + HALF - 1]);
  for (let j = 0; j < h.length; j++) {
    const f = h[j];
    let s = 0;
    for (let k = 0; k < TAPS; k++) s += f[k] * hist[o + k];
    if (s > m) m = s;
    else if (-s > m) m = -s;
  }
  return m;
}

export class Limiter {
  // RATE in Hz; CEILING in dBFS (true peak); LOOKAHEAD and RELEASE in s
  constructor(rate, channels = 2, ceilingDb = CEILING_DB, lookahead = 0.0015,
              release = 0.08) {
    // aim 0.4 dB under the ceiling: between samples a 4x interpolator
    // under-reads content near Nyquist (white noise at +12 dBTP came out
    // at -1.2 dBTP measured 8x with this margin, tests/web/limiter.mjs)
    this.ceiling = Math.pow(10, (ceilingDb - 0.4) / 20);
    this.channels = channels;
    this.L = Math.max(2, Math.round(lookahead * rate));
    this.release = 1 - Math.exp(-1 / (release * rate));
    this.h = interpolator();
    // input history per channel (the interpolator's), the delay line of
    // the audio (look-ahead + the interpolator's centre), the held and
    // averaged gain
    this.hist = Array.from({ length: channels }, () => new Float64Array(2 * TAPS));
    this.histPos = [0];
    this.delay = this.L - 1 + HALF;
    this.line = Array.from({ length: channels }, () => new Float64Array(this.delay + 1));
    this.pos = 0;
    this.req = new Float64Array(this.L + 1); // the last L + 1 requests (min-hold)
    this.reqPos = 0;
    this.env = 1;
    this.avg = new Float64Array(this.L);   // the last L envelope values
    this.avgPos = 0;
    this.avgSum = this.L;
    this.req.fill(1);
    this.avg.fill(1);
    this.gain = 1;
    this.reduction = 1; // the smallest gain since the meter read it
  }

  // the true peak of the newest stretch of channel C after pushing X
  _peak(c, x) {
    return truePeakPush(this.hist[c], this.histPos, this.h, x);
  }

  // limits CHANNELS (arrays of Float32Array, in place) over N frames
  process(chans, n) {
    const L = this.L, line = this.line, D = this.delay;
    for (let i = 0; i < n; i++) {
      let peak = 0;
      for (let c = 0; c < this.channels; c++) {
        const x = chans[c][i];
        const p = this._peak(c, Number.isFinite(x) ? x : 0);
        if (p > peak) peak = p;
      }
      this.histPos[0] = (this.histPos[0] + 1) % TAPS;
      const want = peak > this.ceiling ? this.ceiling / peak : 1;
      this.req[this.reqPos] = want;
      this.reqPos = (this.reqPos + 1) % (L + 1);
      let held = 1;
      for (let k = 0; k <= L; k++) if (this.req[k] < held) held = this.req[k];
      // attack at once (the average below smooths it), release slowly
      this.env = held < this.env ? held : this.env + this.release * (held - this.env);
      if (this.env > 1 - 1e-9 && held === 1) this.env = 1;
      this.avgSum += this.env - this.avg[this.avgPos];
      this.avg[this.avgPos] = this.env;
      this.avgPos = (this.avgPos + 1) % L;
      // the running sum drifts by rounding: exact 1 when all are 1
      let g = this.avgSum / L;
      if (g > 1 || (this.env === 1 && held === 1 && g > 1 - 1e-12)) g = 1;
      if (g < this.reduction) this.reduction = g;
      const out = (this.pos + 1) % (D + 1); // the oldest: D samples ago
      for (let c = 0; c < this.channels; c++) {
        const x = chans[c][i];
        line[c][this.pos] = Number.isFinite(x) ? x : 0;
        chans[c][i] = line[c][out] * g;
      }
      this.pos = out;
      this.gain = g;
    }
  }
}

// a meter of the limiter's input and output: the largest true peak (4x
// oversampled as above) and the mean square since the last read
export class Meter {
  constructor(channels = 2) {
    this.h = interpolator();
    this.hist = Array.from({ length: channels }, () => new Float64Array(2 * TAPS));
    this.pos = 0;
    this.channels = channels;
    this.reset();
  }

  reset() { this.peak = 0; this.sum = 0; this.n = 0; }

  add(chans, n) {
    for (let c = 0; c < this.channels; c++) {
      const x = chans[c], hist = this.hist[c];
      const pos = [this.pos];
      for (let i = 0; i < n; i++) {
        const v = Number.isFinite(x[i]) ? x[i] : 0;
        const m = truePeakPush(hist, pos, this.h, v);
        pos[0] = (pos[0] + 1) % TAPS;
        if (m > this.peak) this.peak = m;
        this.sum += v * v;
      }
      if (c === this.channels - 1) this.pos = pos[0];
    }
    this.n += n * this.channels;
  }
}
