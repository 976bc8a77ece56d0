// The lab's Web Worker (its source is generated into worker-source.js, after
// the engine's Emscripten loader and LAB_WASM_BASE64): it runs the engine and
// answers the page's requests one at a time, so the page never waits on it.
//   {type: 'start', settings}          -> {type: 'started'} or {type: 'refused', message}
//   {type: 'frame', t, budget, cells}  -> {type: 'frame', code, values, arrays, ms} or {type: 'refused', message}
// A frame runs the collisions up to time t, at most about `budget` of them
// (lab_api.hpp): a heavy frame comes back early with code 1, never a hang.
'use strict';

const ARRAYS = ['x', 'v', 'm', 'exact_v', 'exact_rho', 'shock_x', 'shock_v', 'shock_mass', 'hull_x', 'hull_v', 'hull_m',
                'cluster_x', 'cluster_v', 'cluster_m'];
const VALUES = ['t', 'T', 'collisions', 'inelastic', 'elastic', 'merges', 'dissipated', 'mass', 'alive', 'L', 'ring',
                'particle_mass', 'stop_position', 'N', 'r', 'delta', 'sticky', 'seed'];

let lab = null;
const waiting = [];

function decodeBase64(text) {
  const bytes = atob(text);
  const out = new Uint8Array(bytes.length);
  for (let i = 0; i < bytes.length; ++i) out[i] = bytes.charCodeAt(i);
  return out;
}

createLabEngine({wasmBinary: decodeBase64(LAB_WASM_BASE64)}).then((engine) => {
  lab = {
    engine,
    start: engine.cwrap('lab_start', 'number', ['string', 'number', 'number', 'number', 'number', 'number', 'number']),
    advance: engine.cwrap('lab_advance', 'number', ['number', 'number', 'number']),
    array: engine.cwrap('lab_array', 'number', ['string']),
    size: engine.cwrap('lab_size', 'number', ['string']),
    value: engine.cwrap('lab_value', 'number', ['string']),
    message: engine.cwrap('lab_message', 'string', []),
  };
  postMessage({type: 'ready'});
  while (waiting.length) handle(waiting.shift());
}, (error) => postMessage({type: 'fatal', message: 'the engine did not load: ' + error}));

onmessage = (event) => (lab ? handle(event.data) : waiting.push(event.data));

function handle(request) {
  if (request.type === 'start') return start(request.settings);
  if (request.type === 'frame') return frame(request);
}

function start(s) {
  const code = lab.start(s.scene, s.N, s.r, s.delta, s.sticky ? 1 : 0, s.line ? 1 : 0, s.seed);
  postMessage(code === 0 ? {type: 'started'} : {type: 'refused', message: lab.message()});
}

function frame(request) {
  const begin = performance.now();
  const code = lab.advance(request.t, request.budget, request.cells);
  if (code < 0) return postMessage({type: 'refused', message: lab.message()});
  const arrays = {}, values = {};
  for (const name of ARRAYS) {
    // A copy out of the WebAssembly memory (which may grow, and moves): handed over, not copied again.
    const n = lab.size(name), at = lab.array(name);
    arrays[name] = n > 0 ? new Float64Array(lab.engine.HEAPF64.buffer, at, n).slice() : new Float64Array(0);
  }
  for (const name of VALUES) values[name] = lab.value(name);
  const ms = performance.now() - begin;
  postMessage({type: 'frame', code, values, arrays, ms}, Object.values(arrays).map((a) => a.buffer));
}
