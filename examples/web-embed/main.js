// The page: Play makes the AudioContext (browsers start audio only from a
// click), loads the worklet with the wasm bytes and the patch; the slider
// sends the wind speed to the patch's [r speed].
const $ = id => document.getElementById(id);
const bytes = async path => {
  const r = await fetch(path);
  if (!r.ok) throw new Error(`${path}: HTTP ${r.status}`);
  return r.arrayBuffer();
};
let node = null;

async function start() {
  $('play').disabled = true;
  const ctx = new AudioContext();
  await ctx.audioWorklet.addModule('worklet.js');
  node = new AudioWorkletNode(ctx, 'embed', {
    numberOfInputs: 0, numberOfOutputs: 1, outputChannelCount: [2],
    processorOptions: { wasm: await bytes('embed.wasm'), patch: 'wind.pd',
      files: { '/aero/wind.pd': await bytes('wind.pd') } },
  });
  const analyser = ctx.createAnalyser();
  node.connect(analyser);
  analyser.connect(ctx.destination);
  await new Promise((resolve, reject) => {
    node.port.onmessage = e => (e.data.ready ? resolve() : reject(new Error(e.data.error)));
  });
  window.embed = { ctx, node, analyser, ready: true };
  $('status').textContent = 'Playing: move the wind speed.';
  $('speed').disabled = false;
}

$('play').addEventListener('click', () => start().catch(err => {
  $('status').textContent = 'Error: ' + err.message;
}));
$('speed').addEventListener('input', e => {
  node.port.postMessage(['speed', 'float', Number(e.target.value)]);
  $('speed-out').textContent = `${e.target.value} m/s`;
});
