// The lab's four views, drawn from one frame of the engine (lab-main.js gets
// them from the worker): v(x) with the exact Burgers velocity, the density,
// the space-time trace and T(t). Every number drawn was computed by the
// library in the worker; here they are only placed on the canvases.
'use strict';

const COLOUR = {particles: '#d95f02', cluster: '#1b6ac9', exact: '#000', shock: '#c00', hull: '#000', T: '#1b6ac9'};

// The axis units of a scene: pointwise scenes in the domain's length, white noise in initial spacings.
function lengthUnit(frame) { return frame.pointwise ? 'domain = 1' : 'initial spacings'; }

// The marks of a view painted as pixels into an image of the plotting area,
// which is then drawn over it in one copy: paths of 10^4 antialiased squares
// and of a few thousand rings took a software rasteriser (a browser without a
// GPU) 15-40 ms a frame, more than the engine and the rest of the drawing
// together. Dots are whole-pixel squares; rings and crosses are stamps drawn
// once by the canvas itself (antialiased) and blended in where they go.
class PixelLayer {
  constructor() {
    this.canvas = document.createElement('canvas');
    this.image = null;
  }

  // An empty layer the size of the plotting area of axes a.
  begin(a) {
    this.a = a;
    const w = Math.max(1, Math.floor(a.width)), h = Math.max(1, Math.floor(a.height));
    if (!this.image || this.image.width !== w || this.image.height !== h) {
      this.canvas.width = w, this.canvas.height = h;
      this.image = this.canvas.getContext('2d').createImageData(w, h);
    }
    this.image.data.fill(0);
  }

  // A square of s pixels at (x, y) in the axes' units.
  square(x, y, s, rgb) {
    const {data, width: w, height: h} = this.image;
    const x0 = Math.round(this.a.px(x) - this.a.m.left - s / 2), y0 = Math.round(this.a.py(y) - this.a.m.top - s / 2);
    for (let j = Math.max(0, y0); j < Math.min(h, y0 + s); ++j)
      for (let i = Math.max(0, x0), k = 4 * (j * w + i); i < Math.min(w, x0 + s); ++i, k += 4)
        data[k] = rgb[0], data[k + 1] = rgb[1], data[k + 2] = rgb[2], data[k + 3] = 255;
  }

  // A stamp (makeStamp) centred at (x, y) in the axes' units, blended over what is there.
  stamp(x, y, st) {
    const {data, width: w, height: h} = this.image;
    const x0 = Math.round(this.a.px(x) - this.a.m.left) - st.half, y0 = Math.round(this.a.py(y) - this.a.m.top) - st.half;
    for (let j = 0; j < st.size; ++j) {
      const row = y0 + j;
      if (row < 0 || row >= h) continue;
      for (let i = 0; i < st.size; ++i) {
        const col = x0 + i, alpha = st.alpha[j * st.size + i];
        if (col < 0 || col >= w || alpha === 0) continue;
        const k = 4 * (row * w + col), below = data[k + 3] / 255, out = alpha + below * (1 - alpha);
        for (let c = 0; c < 3; ++c) data[k + c] = (st.rgb[c] * alpha + data[k + c] * below * (1 - alpha)) / out;
        data[k + 3] = 255 * out;
      }
    }
  }

  // The layer over the plotting area.
  finish() {
    this.canvas.getContext('2d').putImageData(this.image, 0, 0);
    this.a.ctx.drawImage(this.canvas, this.a.m.left, this.a.m.top);
  }
}

// '#rrggbb' as [r, g, b].
function rgbOf(colour) { return [1, 3, 5].map((k) => parseInt(colour.slice(k, k + 2), 16)); }

// A mark drawn by draw(ctx, centre) on a canvas of size x size pixels, kept as its coverage (0..1) per pixel.
function makeStamp(size, colour, draw) {
  const canvas = Object.assign(document.createElement('canvas'), {width: size, height: size});
  const c = canvas.getContext('2d');
  draw(c, size / 2);
  const px = c.getImageData(0, 0, size, size).data, alpha = new Float32Array(size * size);
  for (let k = 0; k < alpha.length; ++k) alpha[k] = px[4 * k + 3] / 255;
  return {size, half: Math.floor(size / 2), alpha, rgb: rgbOf(colour)};
}

class VelocityView {
  constructor(canvas) {
    this.axes = new Axes(canvas, {title: 'velocity v(x)', ylabel: 'v  [length / time]'});
    this.range = null;
    this.layer = new PixelLayer();
    this.particleRgb = rgbOf(COLOUR.particles);
    this.ring = makeStamp(14, COLOUR.cluster, (c, o) => {
      c.strokeStyle = COLOUR.cluster, c.lineWidth = 1.5, c.beginPath(), c.arc(o, o, 5, 0, 2 * Math.PI), c.stroke();
    });
    this.cross = makeStamp(12, COLOUR.hull, (c, o) => {
      c.strokeStyle = COLOUR.hull, c.lineWidth = 1, c.beginPath();
      c.moveTo(o - 4, o - 4), c.lineTo(o + 4, o + 4), c.moveTo(o - 4, o + 4), c.lineTo(o + 4, o - 4), c.stroke();
    });
  }
  reset() { this.range = null; }

  // The velocity axis follows the gas: it grows at once and shrinks when the data fill less than half of it.
  fit(frame) {
    let lo = Infinity, hi = -Infinity;
    for (const a of [frame.v, frame.exact_v]) for (const v of a) lo = Math.min(lo, v), hi = Math.max(hi, v);
    if (!(hi > lo)) lo -= 1, hi += 1;
    const pad = 0.08 * (hi - lo);
    lo -= pad, hi += pad;
    const r = this.range;
    if (!r || lo < r[0] || hi > r[1] || hi - lo < 0.5 * (r[1] - r[0])) this.range = [lo, hi];
  }

  draw(frame) {
    const a = this.axes;
    this.fit(frame);
    a.o.xlabel = `position x  [${lengthUnit(frame)}]`;
    a.setRange(0, frame.L, this.range[0], this.range[1]);
    a.clear();
    a.clipped((c) => {
      // The particles (a dot's size grows with its mass), the clusters as rings and, at r = 0, the
      // exact sticky gas's clusters (the hull) as crosses, on which the engine's should sit.
      const m0 = frame.particle_mass, p = this.layer;
      p.begin(a);
      for (let i = 0; i < frame.x.length; ++i)
        p.square(frame.x[i], frame.v[i], Math.max(1, Math.round(Math.min(6, 1.2 + Math.sqrt(frame.m[i] / m0) * 0.6))),
                 this.particleRgb);
      for (let k = 0; k < frame.cluster_x.length; ++k) p.stamp(frame.cluster_x[k], frame.cluster_v[k], this.ring);
      for (let k = 0; k < frame.hull_x.length; ++k)
        if (frame.hull_m[k] >= 1.5 * m0) p.stamp(frame.hull_x[k], frame.hull_v[k], this.cross);
      p.finish();
      // The exact solution dashed over the dots, so that both show where they agree.
      c.setLineDash([5, 4]);
      if (frame.exact_v.length > 0) drawCells(a, c, frame.L, frame.exact_v, COLOUR.exact, 1.3);
      c.setLineDash([]);
      c.strokeStyle = COLOUR.shock;
      c.lineWidth = 2;
      c.beginPath();
      for (const x of frame.shock_x) c.moveTo(a.px(x), a.m.top), c.lineTo(a.px(x), a.m.top + 9);
      c.stroke();
    });
    const items = [{label: 'particles (dot ~ mass)', colour: COLOUR.particles, kind: 'dot'},
                   {label: 'clusters (≥ 2 particles)', colour: COLOUR.cluster, kind: 'ring'}];
    if (frame.hull_x.length > 0) items.push({label: 'exact sticky clusters (hull)', colour: COLOUR.hull, kind: 'cross'});
    if (frame.exact_v.length > 0) {
      items.push({label: 'exact Burgers (Hopf–Lax)', colour: COLOUR.exact, kind: 'dash'});
      items.push({label: 'its shocks', colour: COLOUR.shock, kind: 'tick'});
    }
    a.decorate(items);
  }
}

// The powers of ten at or above and at or below v > 0: log axes that change range only a decade at a time.
function decadeAbove(v) { return Math.pow(10, Math.ceil(Math.log10(v))); }
function decadeBelow(v) { return Math.pow(10, Math.floor(Math.log10(v))); }

// Cell averages on `cells` equal cells of [0, L) as a line through the cell centres.
function drawCells(a, c, L, values, colour, width) {
  const n = values.length;
  c.strokeStyle = colour;
  c.lineWidth = width;
  c.beginPath();
  for (let i = 0; i < n; ++i) {
    const x = a.px((i + 0.5) * L / n), y = a.py(values[i]);
    i === 0 ? c.moveTo(x, y) : c.lineTo(x, y);
  }
  c.stroke();
}

class DensityView {
  constructor(canvas) {
    this.axes = new Axes(canvas, {title: 'density ρ(x)  (log scale)', ylabel: 'ρ  [mass / length]', ylog: true});
    this.bins = 128;
  }
  reset() {}

  draw(frame) {
    const a = this.axes, n = this.bins, L = frame.L;
    // The particles' mass per bin, over the bin's width: the histogram the eye compares with the exact ρ.
    const rho = new Float64Array(n);
    for (let i = 0; i < frame.x.length; ++i) rho[Math.min(n - 1, Math.floor(frame.x[i] / L * n))] += frame.m[i];
    for (let b = 0; b < n; ++b) rho[b] /= L / n;
    const mean = frame.mass / L;
    let hi = mean;
    for (const r of rho) hi = Math.max(hi, r);
    for (const r of frame.exact_rho) hi = Math.max(hi, r);
    a.o.xlabel = `position x  [${lengthUnit(frame)}]`;
    a.setRange(0, L, mean * 1e-2, decadeAbove(hi * 1.5));
    a.clear();
    a.clipped((c) => {
      c.fillStyle = '#f4a6c6';
      const floor = a.py(a.y0);
      c.beginPath();
      for (let b = 0; b < n; ++b) {
        if (rho[b] <= 0) continue;
        const x0 = a.px(b * L / n), x1 = a.px((b + 1) * L / n);
        c.rect(x0, a.py(rho[b]), Math.max(1, x1 - x0 - 0.5), floor - a.py(rho[b]));
      }
      c.fill();
      if (frame.exact_rho.length > 0) {
        const floored = Array.from(frame.exact_rho, (r) => Math.max(r, a.y0 * 0.5));
        drawCells(a, c, L, floored, COLOUR.exact, 1.4);
      }
    });
    const items = [{label: `particles: mass per bin (${n} bins)`, colour: '#f4a6c6', kind: 'bar'}];
    if (frame.exact_rho.length > 0) items.push({label: 'exact (Hopf–Lax; shocks: δ-peaks)', colour: COLOUR.exact, kind: 'line'});
    a.decorate(items);
  }
}

class SpaceTimeView {
  constructor(canvas) {
    this.canvas = canvas;
    this.axes = new Axes(canvas, {title: 'space-time: where the mass goes', ylabel: 'time t'});
    this.image = null;
  }
  // A new trace: time from t_min (log) or 0 to t_end upwards.
  reset(scene, L) {
    const d = scene.defaults, a = this.axes;
    a.o.ylog = d.spacing === 'log';
    a.setRange(0, L, a.o.ylog ? d.t_min : 0, d.t_end);
    this.image = a.ctx.createImageData(Math.max(1, Math.floor(a.width)), Math.max(1, Math.floor(a.height)));
    this.image.data.fill(255);
    this.lastRow = null;
  }

  // Marks the row of time t: each pixel column shaded by the mass in it against the mean
  // (the even gas light grey, clusters dark); the exact shocks in red.
  mark(frame) {
    const a = this.axes, img = this.image, w = img.width, h = img.height;
    if (frame.t > a.y1 || (a.o.ylog && frame.t < a.y0)) return;
    const row = Math.min(h - 1, Math.max(0, Math.round(a.py(frame.t) - a.m.top)));
    const rows = this.lastRow === null ? [row] : span(row, this.lastRow);
    this.lastRow = row;
    const mass = new Float64Array(w);
    for (let i = 0; i < frame.x.length; ++i) mass[Math.min(w - 1, Math.floor(frame.x[i] / frame.L * w))] += frame.m[i];
    const mean = frame.mass / w;
    for (let col = 0; col < w; ++col) {
      if (mass[col] <= 0) continue;
      const dark = Math.min(235, 45 * Math.log2(1 + mass[col] / mean));
      for (const r of rows) shade(img, col, r, dark);
    }
    for (const x of frame.shock_x) {
      const col = Math.min(w - 1, Math.floor(x / frame.L * w));
      for (const r of rows) paint(img, col, r, [204, 0, 0]);
    }
  }

  draw(frame) {
    const a = this.axes;
    a.o.xlabel = `position x  [${lengthUnit(frame)}]`;
    a.clear();
    a.ctx.putImageData(this.image, a.m.left, a.m.top);
    a.clipped((c) => {
      c.strokeStyle = '#00a0c0';
      c.lineWidth = 1;
      const y = Math.round(a.py(Math.max(frame.t, a.y0))) + 0.5;
      c.beginPath(), c.moveTo(a.m.left, y), c.lineTo(a.m.left + a.width, y), c.stroke();
    });
    const items = [{label: 'mass (darker: denser)', colour: '#555', kind: 'bar'}, {label: 'now', colour: '#00a0c0', kind: 'line'}];
    if (frame.exact_v.length > 0) items.splice(1, 0, {label: 'exact shocks (Hopf–Lax)', colour: COLOUR.shock, kind: 'bar'});
    a.decorate(items);
  }
}

// The rows between two frames' rows, so that the trace has no gaps (at most 6 rows: a jump is a jump).
function span(row, last) {
  const out = [];
  const step = row < last ? 1 : -1;
  for (let r = row; r !== last && out.length < 6; r -= -step) out.push(r);
  return out.length ? out : [row];
}
function shade(img, col, row, dark) {
  const k = 4 * (row * img.width + col), v = 255 - dark;
  if (img.data[k] > v) img.data[k] = img.data[k + 1] = img.data[k + 2] = v;
}
function paint(img, col, row, rgb) {
  const k = 4 * (row * img.width + col);
  img.data[k] = rgb[0], img.data[k + 1] = rgb[1], img.data[k + 2] = rgb[2];
}

class CoolingView {
  constructor(canvas) {
    this.axes = new Axes(canvas, {title: 'temperature T(t) = ⟨v²⟩ − ⟨v⟩²  (log–log)', xlabel: 'time t',
                                  ylabel: 'T  [length² / time²]', xlog: true, ylog: true});
    this.reset();
  }
  reset() { this.t = [], this.T = []; }
  add(frame) {
    if (frame.t > 0 && frame.T > 0) this.t.push(frame.t), this.T.push(frame.T);
  }

  draw() {
    const a = this.axes, n = this.t.length;
    a.clear();
    if (n < 1) return a.decorate([]);
    let tlo = this.t[0], thi = this.t[n - 1], Tlo = Math.min(...this.T), Thi = Math.max(...this.T);
    if (!(thi > tlo)) thi = tlo * 10;
    if (!(Thi > Tlo * 10)) Tlo = Thi / 10;
    a.setRange(decadeBelow(tlo), decadeAbove(thi * 1.2), decadeBelow(Tlo / 1.5), decadeAbove(Thi * 1.5));
    a.clipped((c) => {
      // The law of the sticky gas and of Burgers' shocks, T ∝ t^(−2/3), through the last point: compare slopes.
      const t1 = this.t[n - 1], T1 = this.T[n - 1];
      c.strokeStyle = '#777';
      c.lineWidth = 1.5;
      c.setLineDash([6, 4]);
      c.beginPath(), c.moveTo(a.px(a.x0), a.py(T1 * Math.pow(a.x0 / t1, -2 / 3)));
      c.lineTo(a.px(a.x1), a.py(T1 * Math.pow(a.x1 / t1, -2 / 3))), c.stroke();
      c.setLineDash([]);
      c.strokeStyle = COLOUR.T;
      c.lineWidth = 2;
      c.beginPath();
      for (let k = 0; k < n; ++k) k === 0 ? c.moveTo(a.px(this.t[k]), a.py(this.T[k])) : c.lineTo(a.px(this.t[k]), a.py(this.T[k]));
      c.stroke();
    });
    a.decorate([{label: 'the particles', colour: COLOUR.T, kind: 'line'},
                {label: 'slope −2/3: T ∝ t^(−2/3)', colour: '#777', kind: 'dash'}]);
  }
}
