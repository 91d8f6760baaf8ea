// The scenes of the page: each is a patch in scenes/ (played by libpd +
// aero in the page, and by native Pd in `make check-web`), the data files
// it needs in the module's file system, a short text on the physics it
// follows, and its controls. A control sends its messages only when moved
// away from its default (the default is what the patch's arguments set),
// so a render with every control at its default is the patch as it is.

const wind = (speed, gust) => [
  { id: 'speed', label: 'Wind speed', unit: 'm/s', min: 1, max: 30, step: 0.5,
    value: speed, send: v => [['aero-scene', 'speed', v]] },
  { id: 'gust', label: 'Gustiness', unit: '', min: 0, max: 1, step: 0.05,
    value: gust, send: v => [['aero-scene', 'gust', v]] },
];

// the wires of the wires scene, in metres from the listener (x right,
// y ahead): their ears in the patch are (listener -+ 0.1 m) - wire
const WIRES = [[2, -2], [-1, -3], [-3, -1.5], [0, -5]];
const wireEars = (lx, ly) => WIRES.map(([wx, wy], i) => [
  `aero-wire${i + 1}`, 'ears',
  lx - 0.1 - wx, ly - wy, 0, lx + 0.1 - wx, ly - wy, 0]);

export const SCENES = [
  {
    id: 'wires', title: 'Wind on wires', patch: 'wires.pd', gain: 10, data: [],
    text: 'Four wires and rods (3, 6, 12 and 25 mm) in a gusting wind. Each ' +
      'sheds vortices at f = St U / d, the Strouhal number St following the ' +
      'Reynolds number (Williamson, Roshko: about 0.2); the lift force ' +
      'radiates a dipole whose pressure grows as U^3 (Curle), so a wind twice ' +
      'as fast sings an octave higher and 18 dB louder. The wire spans ' +
      'sound as incoherent segments; distance lowers the level as 1/r.',
    controls: [
      ...wind(12, 0.4),
      // 0: every wire; 1-4: that wire alone (3, 6, 12, 25 mm), the others
      // 200 dB down
      { id: 'solo', label: 'Solo wire', unit: '', value: 0,
        options: [[0, 'All four'], [1, '3 mm wire'], [2, '6 mm rod'],
          [3, '12 mm rod'], [4, '25 mm rod']],
        send: v => WIRES.map((w, i) =>
          [`aero-wire${i + 1}`, 'gain', v === 0 || v === i + 1 ? 0 : -200]) },
      { id: 'lx', label: 'Listener x', unit: 'm', min: -5, max: 5, step: 0.1,
        value: 0, group: 'listener',
        send: (v, c) => wireEars(v, c.ly) },
      { id: 'ly', label: 'Listener y', unit: 'm', min: -3, max: 3, step: 0.1,
        value: 0, group: 'listener',
        send: (v, c) => wireEars(c.lx, v) },
    ],
    actions: [{ label: 'Squall', send: [['aero-scene', 'squall']] }],
  },
  {
    id: 'fence', title: 'Fence', patch: 'fence.pd', gain: 20, data: [],
    text: 'Six fence wires of 3 to 7 mm, 1.5 m apart, 3 m away, in one ' +
      'gusting wind: six Aeolian tones at St U / d that rise and fall ' +
      'together with the gusts, each from its own place in the stereo ' +
      'image, beating where their frequencies are close.',
    controls: wind(12, 0.5),
    actions: [{ label: 'Squall', send: [['aero-scene', 'squall']] }],
  },
  {
    id: 'draft', title: 'Window draft', patch: 'draft.pd', gain: 7, data: [],
    text: 'Air across a 2 cm window gap 16 cm deep. The shear layer over the ' +
      'gap oscillates at the Rossiter modes f_n = U/L (n - 0.25)/(M + 1/0.57); ' +
      'the gap\'s depth resonates as a quarter-wave tube with end ' +
      'correction. When a Rossiter mode crosses the depth resonance, they ' +
      'lock in and the gap whistles. Level grows as U^2 here.',
    controls: [
      ...wind(9, 0.5),
      { id: 'dist', label: 'Listener distance', unit: 'm', min: 0.3, max: 10,
        step: 0.1, value: 1, send: v => [['aero-scene', 'listener', 0, v, 0]] },
    ],
    actions: [{ label: 'Squall', send: [['aero-scene', 'squall']] }],
  },
  {
    id: 'sword', title: 'Sword swing', patch: 'sword.pd', gain: 20,
    data: ['textures/sword.wav'], swing: true, blade: 0.8,
    text: 'A sword swung in first person. The blade plays a sound texture ' +
      'computed by aero\'s flow solver for its cross-section (Dobashi et ' +
      'al.): each point along the blade moves at its own speed (faster ' +
      'towards the tip), its force scales as (v/v0)^3 and is heard r/c0 ' +
      'later at each ear, with Doppler. Drag across the pad and the blade ' +
      'follows your hand: the faster the drag, the higher and louder the ' +
      'swoosh (pitch ~ v, level ~ v^3).',
    controls: [
      { id: 'roll', label: 'Blade roll', unit: 'deg', min: 0, max: 90, step: 1,
        value: 20, send: v => [['aero-scene', 'roll', v]] },
    ],
    actions: [{ label: 'Swing', send: [['aero-scene', 'swing']] }],
  },
  {
    id: 'club', title: 'Club swing', patch: 'club.pd', gain: 43,
    data: ['textures/cylinder.wav'], swing: true, blade: 0.6,
    text: 'A club: a 4 cm rod 60 cm long, swung in first person with the ' +
      'circular cylinder\'s texture. A thick rod sheds at a lower ' +
      'frequency (f = St v / d) than a thin blade at the same speed: a ' +
      'low whoomph instead of a swish.',
    controls: [],
    actions: [{ label: 'Swing', send: [['aero-scene', 'swing']] }],
  },
  {
    id: 'throw', title: 'Thrown stick', patch: 'throw.pd', gain: 19,
    data: ['textures/cylinder.wav'],
    text: 'A 50 cm stick thrown past the listener at 15 m/s, spinning end ' +
      'over end. Its tips move faster than its centre, so they whoosh ' +
      'twice a turn; the pitch falls as it passes (Doppler) and the level ' +
      'follows 1/r.',
    controls: [
      { id: 'speed', label: 'Throw speed', unit: 'm/s', min: 3, max: 40,
        step: 0.5, value: 15, send: v => [['aero-scene', 'speed', v]] },
      { id: 'spin', label: 'Spin', unit: 'turns/s', min: 0, max: 12, step: 0.5,
        value: 4, send: v => [['aero-scene', 'spin', v]] },
      { id: 'miss', label: 'Listener distance (miss)', unit: 'm', min: 0.5,
        max: 10, step: 0.1, value: 2, send: v => [['aero-scene', 'miss', v]] },
    ],
    actions: [{ label: 'Throw', send: [['aero-scene', 'throw']] }],
  },
  {
    id: 'whirl', title: 'Whirled ball', patch: 'whirl.pd', gain: 49,
    data: ['textures/sphere.wav', 'textures/cylinder.wav'],
    text: 'A 5 cm ball whirled overhead on a cord. The ball plays the 3D ' +
      'sphere texture (the force on each region of the sphere from aero\'s ' +
      '3D flow solver), the cord a cylinder whose speed grows along it. ' +
      'Each turn the pitch and level rise and fall with the speed, the ' +
      'Doppler shift and the distance.',
    controls: [
      { id: 'rate', label: 'Turns per second', unit: '/s', min: 0.5, max: 5,
        step: 0.1, value: 2, send: v => [['aero-scene', 'rate', v]] },
      { id: 'radius', label: 'Cord radius', unit: 'm', min: 0.3, max: 2,
        step: 0.05, value: 1.2, send: v => [['aero-scene', 'radius', v]] },
    ],
    actions: [
      { label: 'Stop whirling', send: [['aero-scene', 'whirl', 0]] },
      { label: 'Whirl again', send: [['aero-scene', 'whirl', 1]] },
    ],
  },
  {
    id: 'fire', title: 'Campfire, flamethrower, explosion', patch: 'fire.pd',
    gain: -6, data: ['textures/fire.wav'],
    text: 'Flames: combustion noise of the heat release (a monopole, its ' +
      'power following the fuel burnt: 30 kW for a 40 cm fire) plus vortex ' +
      'sound, with a flickering flame speed, crackle, hiss and lapping. ' +
      'Burst is a 50 kW flamethrower jet at 15 m/s; explode a 300 kW blast, ' +
      'clipped at 1 Pa like a microphone.',
    controls: [
      { id: 'intensity', label: 'Fire power (flame speed)', unit: 'm/s',
        min: 0.5, max: 8, step: 0.1, value: 3,
        send: v => [['aero-scene', 'intensity', v]] },
      { id: 'size', label: 'Size', unit: 'm', min: 0.1, max: 2, step: 0.05,
        value: 0.4, send: v => [['aero-scene', 'size', v]] },
      { id: 'distance', label: 'Listener distance', unit: 'm', min: 0.5,
        max: 20, step: 0.1, value: 1.5,
        send: v => [['aero-scene', 'distance', v]] },
    ],
    actions: [
      { label: 'Flamethrower', send: [['aero-scene', 'burst', 1.5]] },
      { label: 'Explode', send: [['aero-scene', 'explode']] },
    ],
  },
  {
    id: 'tree', title: 'Tree in gusts', patch: 'tree.pd', gain: 12,
    data: ['trees/medium.tree'],
    text: 'A tree 8 m away: each of its 126 branches sings its own Aeolian ' +
      'tone (St U / d for its diameter) and its 4860 leaves rustle as they ' +
      'collide and rub, all swaying in step with one gusting wind, so a ' +
      'gust swells branches and leaves together.',
    controls: [
      ...wind(9, 0.5),
      { id: 'distance', label: 'Listener distance', unit: 'm', min: 2, max: 40,
        step: 0.5, value: 8, send: v => [['aero-scene', 'distance', v]] },
    ],
    actions: [{ label: 'Squall', send: [['aero-scene', 'squall']] }],
  },
  {
    id: 'fan', title: 'Desk fan', patch: 'fan.pd', gain: 30, data: [],
    text: 'A desk fan 1 m in front, pointed at you: five 15 cm blades spin ' +
      'up to 1200 rpm over 3 s. What you hear is the blades\' broadband ' +
      'self-noise (Brooks, Pope and Marcolini 1989), rising with the speed. ' +
      'Each blade\'s steady thrust and torque turn with it, a rotating ' +
      'dipole heard with its retarded time (compact Farassat 1A), whose ' +
      'tone is the blade-passing frequency B rpm / 60 = 100 Hz and its ' +
      'harmonics; near the fan\'s axis, where you sit, those steady-loading ' +
      'tones all but vanish (Gutin 1936). The hum you hear is the blades\' ' +
      'unsteady loading: each blade crosses the slower air behind the ' +
      'motor\'s neck once a turn, and that loading harmonic of order 5 ' +
      'radiates along the axis at 100 Hz (Lowson 1965).',
    controls: [
      { id: 'rpm', label: 'Speed', unit: 'rpm', min: 300, max: 2400, step: 50,
        value: 1200, send: v => [['aero-scene', 'rpm', v]] },
    ],
    actions: [
      { label: 'Switch off', send: [['aero-scene', 'fan', 0]] },
      { label: 'Switch on', send: [['aero-scene', 'fan', 1]] },
    ],
  },
  {
    id: 'drone', title: 'Drone', patch: 'drone.pd', gain: 9, data: [],
    text: 'A 1 kg quadcopter hovering 3 m in front, 2 m up: four two-bladed ' +
      '12 cm rotors, each turning at the rpm that gives a quarter of the ' +
      'thrust asked (thrust as rpm squared: 4700 rpm to hover), so they hum ' +
      'at the blade-passing frequency 2 rpm / 60, about 157 Hz. More thrust ' +
      'spins them faster; yaw speeds one diagonal pair and slows the other, ' +
      'and the two tones beat. Fly past sends it across at 8 m/s: the hum ' +
      'rises and falls with the Doppler shift and the distance.',
    controls: [
      { id: 'thrust', label: 'Thrust (x weight)', unit: '', min: 0, max: 1.5,
        step: 0.05, value: 1, send: v => [['aero-scene', 'thrust', v]] },
      { id: 'yaw', label: 'Yaw', unit: '', min: -0.5, max: 0.5, step: 0.05,
        value: 0, send: v => [['aero-scene', 'yaw', v]] },
    ],
    actions: [
      { label: 'Fly past', send: [['aero-flypast', 'bang']] },
      { label: 'Hover in front', send: [['aero-scene', 'place', 0, 3, 2]] },
    ],
  },
  {
    id: 'propeller', title: 'Propeller aircraft', patch: 'propeller.pd',
    gain: -14, data: ['abstractions/propeller.blade'],
    text: 'A light aircraft\'s two-bladed 1.9 m propeller at 2400 rpm ' +
      '(2000 N of thrust, about 100 kW) passing 30 m to the side and 20 m ' +
      'up at 50 m/s. Its blade-passing tone of 80 Hz and harmonics are ' +
      'loudest near the propeller\'s plane (Gutin 1936); each strip is heard ' +
      'with its own retarded time and Doppler shift, so the tone is high ' +
      'as the aircraft comes, falls as it passes and the level follows ' +
      'the distance and the directivity.',
    controls: [
      { id: 'rpm', label: 'Engine speed', unit: 'rpm', min: 1200, max: 2700,
        step: 50, value: 2400, send: v => [['aero-scene', 'rpm', v]] },
    ],
    actions: [{ label: 'Fly past', send: [['aero-flypast', 'bang']] }],
  },
  {
    id: 'turbine', title: 'Wind turbine', patch: 'turbine.pd', gain: 10,
    data: ['abstractions/turbine.blade'],
    text: 'A wind turbine on a hill (three 47 m blades at 16 rpm on a 100 m ' +
      'tower, the size Oerlemans and Schepers 2009 measured), heard 200 m ' +
      'from the tower, 60 degrees from downwind. The noise is the blades\' ' +
      'trailing-edge self-noise (Brooks, Pope and Marcolini 1989), loudest ' +
      'near the tips; its convective amplification and directivity make it ' +
      'swell as each blade comes down towards you: the swish, 3 x 16 / 60 ' +
      '= 0.8 times a second.',
    controls: [
      { id: 'wind', label: 'Wind speed', unit: 'm/s', min: 4, max: 14,
        step: 0.5, value: 8, send: v => [['aero-scene', 'wind', v]] },
      { id: 'rpm', label: 'Rotor speed', unit: 'rpm', min: 6, max: 20,
        step: 0.5, value: 16, send: v => [['aero-scene', 'rpm', v]] },
    ],
    actions: [],
  },
];

// the messages that put a scene's controls at VALUES (id -> value): those
// of every control away from its default
export function controlMessages(scene, values) {
  const all = {};
  for (const c of scene.controls) all[c.id] = values[c.id] ?? c.value;
  const out = [];
  const groups = new Set();
  for (const c of scene.controls) {
    if (all[c.id] === c.value) continue;
    if (c.group) {
      if (groups.has(c.group)) continue;
      groups.add(c.group);
    }
    out.push(...c.send(all[c.id], all));
  }
  return out;
}
