// The lab's driver: starts the engine's Web Worker from the generated source
// (worker-source.js; a page from file:// may not load a worker from a file),
// and keeps it one frame ahead of the display: while the page draws frame k on
// the display's clock, the worker computes frame k + 1. Every frame received is
// added to the space-time trace and to T(t); the newest is drawn. Play, pause,
// step, reset; a changed setting restarts the run.
'use strict';

// Collisions a frame may take before it comes back (then the time lags and the page says so).
const FRAME_BUDGET = 1 << 18;
// Frames from t = 0 to the scene's t_end at speed 1, and the cells of the exact solution.
const FRAMES_PER_RUN = 400;
const CELLS = 512;

const lab = {
  worker: null, playing: false, pending: false, started: false, scene: null,
  t: 0, target: 0, frames: 0, rateFrames: 0, rateSince: 0, fps: 0, lastCollisions: 0, lastT: 0, lagging: false,
  waiting: null,  // a frame received and not yet drawn
  drawMs: 0,
  drawn: 0,  // frames drawn since the page opened (its frame rate: tests/lab/check_lab_page.py)
};

function startWorker() {
  const blob = new Blob([window.SHOCKGAS_WORKER_SOURCE], {type: 'text/javascript'});
  const url = URL.createObjectURL(blob);
  lab.worker = new Worker(url);
  URL.revokeObjectURL(url);
  lab.worker.onmessage = (e) => receive(e.data);
  lab.worker.onerror = (e) => lab.controls.say('The engine stopped: ' + e.message, 'error');
}

// A new run from the controls' settings; the worker answers 'started' or 'refused'.
function restart() {
  lab.pending = true;
  lab.started = false;
  lab.worker.postMessage({type: 'start', settings: lab.controls.settings()});
}

function receive(msg) {
  if (msg.type === 'ready') return;
  if (msg.type === 'fatal') return lab.controls.say(msg.message, 'error');
  if (msg.type === 'refused') {
    lab.pending = false;
    setPlaying(false);
    return lab.controls.say('Not run: ' + msg.message, 'error');
  }
  if (msg.type === 'started') return started();
  if (msg.type === 'frame') return received(msg);
}

function started() {
  lab.scene = lab.controls.current();
  lab.started = true;
  lab.pending = false;
  lab.t = 0, lab.target = 0, lab.frames = 0, lab.lastCollisions = 0, lab.lastT = 0;
  lab.rateFrames = 0, lab.rateSince = performance.now(), lab.waiting = null;
  lab.controls.say('');
  lab.views.velocity.reset(), lab.views.cooling.reset();  // the trace: at the first frame, which knows L
  request(0);  // the initial state
}

function request(t) {
  lab.pending = true;
  lab.target = t;
  lab.worker.postMessage({type: 'frame', t, budget: FRAME_BUDGET, cells: CELLS});
}

// The time of the next frame: equal steps, or equal ratios for a scene drawn on a log time axis.
function nextTime() {
  const d = lab.scene.defaults, s = lab.controls.speed();
  if (d.spacing === 'log') return lab.t < d.t_min ? d.t_min : lab.t * Math.pow(d.t_end / d.t_min, s / FRAMES_PER_RUN);
  return lab.t + s * d.t_end / FRAMES_PER_RUN;
}

// A frame from the worker: into the trace and T(t) at once; the next one asked for while this one waits to be drawn.
function received(msg) {
  lab.pending = false;
  if (!lab.started) return;  // a frame of a run that was replaced
  const frame = Object.assign({pointwise: lab.scene.pointwise, ms: msg.ms, code: msg.code}, msg.values, msg.arrays);
  lab.t = frame.t;
  lab.lagging = msg.code === 1;
  if (lab.frames === 0) lab.views.spacetime.reset(lab.scene, frame.L);
  ++lab.frames;
  lab.views.spacetime.mark(frame);
  lab.views.cooling.add(frame);
  const behind = lab.waiting !== null;  // the display has not drawn the last one yet: no further ahead
  lab.waiting = frame;
  if (msg.code === 2) {
    setPlaying(false);
    lab.controls.say(`The run stopped at t = ${fmt(frame.t)}: inelastic collapse (δ = 0, 0 < r < 1) at x = ${fmt(frame.stop_position)}; ` +
                     'a threshold δ > 0 avoids it (the gallery\'s three-particle scene).', 'error');
  } else if (lab.playing && lab.t >= lab.scene.defaults.t_end && msg.code === 0) {
    setPlaying(false);
    lab.controls.say(`The scene's t_end = ${lab.scene.defaults.t_end} is reached; play goes on past it.`);
  }
  if (lab.playing && !behind) askNext();
}

function askNext() {
  if (lab.started && !lab.pending) request(lab.lagging ? lab.target : nextTime());
}

// The newest frame received, drawn; the frame rate counts the frames drawn.
function drawFrame(frame) {
  const begin = performance.now();
  ++lab.rateFrames, ++lab.drawn;
  if (begin - lab.rateSince >= 1000) lab.fps = lab.rateFrames * 1000 / (begin - lab.rateSince), lab.rateFrames = 0, lab.rateSince = begin;
  lab.views.velocity.draw(frame);
  lab.views.density.draw(frame);
  lab.views.spacetime.draw(frame);
  lab.views.cooling.draw();
  showCounters(frame, frame.ms);
  lab.drawMs = performance.now() - begin;
}

function showCounters(f, ms) {
  const rate = f.t > lab.lastT ? (f.collisions - lab.lastCollisions) / (f.t - lab.lastT) : 0;
  lab.lastCollisions = f.collisions, lab.lastT = f.t;
  const text = {
    'frame-count': String(lab.frames),
    'frame-rate': lab.fps ? lab.fps.toFixed(1) : '–',
    'sim-time': fmt(f.t) + (lab.lagging ? ' (held back: a frame makes at most 2¹⁸ collisions)' : ''),
    'collisions': String(f.collisions),
    'collision-kinds': `merges ${f.merges}, inelastic ${f.inelastic}, elastic ${f.elastic}`,
    'collision-rate': fmt(rate),
    'bodies': `${f.alive} bodies, ${f.cluster_x.length} clusters` +
        (f.hull_x.length ? ` (exact sticky gas: ${f.hull_x.length} clusters)` : ''),
    'temperature': fmt(f.T),
    'frame-ms': `${ms.toFixed(1)} (drawing ${lab.drawMs.toFixed(1)})`,
    'running': `N = ${f.N}, r = ${f.r}, δ = ${f.delta}, ${f.sticky ? 'sticky' : 'elastic'} below δ, ` +
        `${f.ring ? 'ring' : 'line'}` + (lab.scene.pointwise ? '' : `, seed ${f.seed}`),
  };
  for (const [id, value] of Object.entries(text)) document.getElementById(id).textContent = value;
  document.getElementById('exact-note').textContent =
      f.exact_v.length ? '' : 'On a line the exact solution is not drawn: it is that of the periodic problem (the ring).';
}

function setPlaying(on) {
  lab.playing = on;
  document.getElementById('play').textContent = on ? 'Pause' : 'Play';
}

// On the display's clock: the waiting frame drawn, and the next asked for if none is on its way.
function tick() {
  if (lab.waiting) {
    const frame = lab.waiting;
    lab.waiting = null;
    drawFrame(frame);
  }
  if (lab.playing && !lab.waiting) askNext();
  requestAnimationFrame(tick);
}

function main() {
  lab.controls = new Controls(document, window.SHOCKGAS_SCENES, () => restart());
  lab.views = {
    velocity: new VelocityView(document.getElementById('velocity')),
    density: new DensityView(document.getElementById('density')),
    spacetime: new SpaceTimeView(document.getElementById('spacetime')),
    cooling: new CoolingView(document.getElementById('cooling')),
  };
  document.getElementById('play').addEventListener('click', () => setPlaying(!lab.playing));
  document.getElementById('step').addEventListener('click', () => {
    setPlaying(false);
    askNext();
  });
  document.getElementById('reset').addEventListener('click', () => restart());
  startWorker();
  restart();
  setPlaying(true);
  requestAnimationFrame(tick);
}

window.addEventListener('DOMContentLoaded', main);
