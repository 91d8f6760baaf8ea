// a float WAV's samples (any chunks, e.g. libsndfile's PEAK):
// { x: interleaved Float32Array, channels }; tests/web's scripts share it
import { readFileSync } from 'node:fs';

export function floats(path) {
  const b = readFileSync(path);
  const v = new DataView(b.buffer, b.byteOffset, b.byteLength);
  let channels = 0, bits = 0, format = 0;
  for (let o = 12; o + 8 <= b.length;) {
    const id = b.toString('latin1', o, o + 4), size = v.getUint32(o + 4, true);
    if (id === 'fmt ') {
      format = v.getUint16(o + 8, true); channels = v.getUint16(o + 10, true);
      bits = v.getUint16(o + 22, true);
      if (format === 0xfffe) format = v.getUint16(o + 32, true);
    } else if (id === 'data') {
      if (format !== 3 || bits !== 32) throw new Error(`${path}: not 32-bit float`);
      const n = Math.min(size, b.length - o - 8) / 4;
      const x = new Float32Array(n);
      for (let i = 0; i < n; i++) x[i] = v.getFloat32(o + 8 + 4 * i, true);
      return { x, channels };
    }
    o += 8 + size + (size & 1);
  }
  throw new Error(`${path}: no data chunk`);
}

