// Axes on a canvas for the lab's views: linear or logarithmic scales, ticks at
// round numbers, labels with units, a legend. Only drawing; no physics here.
'use strict';

// Round tick values covering [lo, hi]: about `count` of them at 1, 2 or 5 times a power of ten.
function niceTicks(lo, hi, count) {
  const span = hi - lo;
  if (!(span > 0)) return [lo];
  const raw = span / count;
  const power = Math.pow(10, Math.floor(Math.log10(raw)));
  const step = [1, 2, 5, 10].map((k) => k * power).find((s) => s >= raw);
  const ticks = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) ticks.push(Math.abs(v) < step * 1e-9 ? 0 : v);
  return ticks;
}

// A number as a tick label: short, exponent form for the very large or small.
function tickText(v) {
  if (v === 0) return '0';
  const a = Math.abs(v);
  if (a >= 1e4 || a < 1e-3) {
    const e = Math.floor(Math.log10(a));
    const m = v / Math.pow(10, e);
    return (Math.abs(m - 1) < 1e-9 ? '' : (Math.round(m * 10) / 10) + '·') + '10' + superscript(e);
  }
  return String(Number(v.toPrecision(4)));
}

function superscript(n) {
  const digits = '⁰¹²³⁴⁵⁶⁷⁸⁹';
  return (n < 0 ? '⁻' : '') + String(Math.abs(n)).split('').map((d) => digits[Number(d)]).join('');
}

class Axes {
  // options: xlabel, ylabel, xlog, ylog, title; margins leave room for the labels.
  constructor(canvas, options) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d');
    this.o = Object.assign({xlog: false, ylog: false, title: ''}, options);
    this.m = {left: 62, right: 12, top: 24, bottom: 42};
    this.setRange(0, 1, 0, 1);
  }

  get width() { return this.canvas.width - this.m.left - this.m.right; }
  get height() { return this.canvas.height - this.m.top - this.m.bottom; }

  setRange(x0, x1, y0, y1) {
    this.x0 = x0, this.x1 = x1, this.y0 = y0, this.y1 = y1;
  }

  // Data to pixels (a logarithmic axis takes log10 of positive values).
  px(x) {
    const f = this.o.xlog ? (Math.log10(x) - Math.log10(this.x0)) / (Math.log10(this.x1) - Math.log10(this.x0))
                          : (x - this.x0) / (this.x1 - this.x0);
    return this.m.left + f * this.width;
  }
  py(y) {
    const f = this.o.ylog ? (Math.log10(y) - Math.log10(this.y0)) / (Math.log10(this.y1) - Math.log10(this.y0))
                          : (y - this.y0) / (this.y1 - this.y0);
    return this.m.top + (1 - f) * this.height;
  }

  clear() {
    const c = this.ctx;
    c.setTransform(1, 0, 0, 1, 0, 0);
    c.fillStyle = '#fff';
    c.fillRect(0, 0, this.canvas.width, this.canvas.height);
  }

  ticks(lo, hi, log) {
    if (!log) return niceTicks(lo, hi, 5);
    const out = [];
    const first = Math.ceil(Math.log10(lo)), last = Math.floor(Math.log10(hi));
    const stride = Math.max(1, Math.ceil((last - first + 1) / 6));
    for (let e = first; e <= last; e += stride) out.push(Math.pow(10, e));
    return out;
  }

  // The frame, ticks, tick labels, axis labels and title.
  drawFrame() {
    const c = this.ctx, m = this.m;
    c.save();
    c.strokeStyle = '#222';
    c.lineWidth = 1;
    c.strokeRect(m.left + 0.5, m.top + 0.5, this.width, this.height);
    c.fillStyle = '#222';
    c.font = '11px sans-serif';
    c.textAlign = 'center';
    c.textBaseline = 'top';
    for (const x of this.ticks(this.x0, this.x1, this.o.xlog)) {
      const p = Math.round(this.px(x)) + 0.5;
      c.beginPath(), c.moveTo(p, m.top + this.height), c.lineTo(p, m.top + this.height + 4), c.stroke();
      c.fillText(tickText(x), p, m.top + this.height + 6);
    }
    c.textAlign = 'right';
    c.textBaseline = 'middle';
    for (const y of this.ticks(this.y0, this.y1, this.o.ylog)) {
      const p = Math.round(this.py(y)) + 0.5;
      c.beginPath(), c.moveTo(m.left - 4, p), c.lineTo(m.left, p), c.stroke();
      c.fillText(tickText(y), m.left - 6, p);
    }
    c.font = '12px sans-serif';
    c.textAlign = 'center';
    c.textBaseline = 'bottom';
    c.fillText(this.o.xlabel, m.left + this.width / 2, this.canvas.height - 4);
    c.fillText(this.o.title, m.left + this.width / 2, m.top - 6);
    c.translate(14, m.top + this.height / 2);
    c.rotate(-Math.PI / 2);
    c.textBaseline = 'middle';
    c.fillText(this.o.ylabel, 0, 0);
    c.restore();
  }

  // Runs draw(ctx) clipped to the plotting area.
  clipped(draw) {
    const c = this.ctx;
    c.save();
    c.beginPath();
    c.rect(this.m.left, this.m.top, this.width, this.height);
    c.clip();
    draw(c);
    c.restore();
  }

  // The frame and the legend over the data, drawn once into a layer of their own
  // and copied on each frame until the ranges, labels or legend change: text is
  // the dearest thing a frame would draw.
  decorate(items) {
    const key = JSON.stringify([this.x0, this.x1, this.y0, this.y1, this.o, items]);
    if (key !== this.layerKey) {
      if (!this.layer) this.layer = Object.assign(document.createElement('canvas'), {width: this.canvas.width, height: this.canvas.height});
      const own = this.ctx;
      this.ctx = this.layer.getContext('2d');
      this.ctx.clearRect(0, 0, this.layer.width, this.layer.height);
      this.drawFrame();
      if (items.length) this.legend(items);
      this.ctx = own;
      this.layerKey = key;
    }
    this.ctx.drawImage(this.layer, 0, 0);
  }

  // items: {label, colour, kind: 'line' | 'dash' | 'dot' | 'ring' | 'bar' | 'tick' | 'cross'}; top right.
  legend(items) {
    const c = this.ctx;
    c.save();
    c.font = '11px sans-serif';
    const w = Math.max(...items.map((i) => c.measureText(i.label).width)) + 34;
    const x = this.m.left + this.width - w - 6, y = this.m.top + 6;
    c.fillStyle = 'rgba(255,255,255,0.88)';
    c.strokeStyle = '#999';
    c.fillRect(x, y, w, items.length * 16 + 6);
    c.strokeRect(x + 0.5, y + 0.5, w, items.length * 16 + 6);
    items.forEach((item, k) => {
      const cy = y + 11 + k * 16;
      legendMark(c, item, x + 6, cy);
      c.fillStyle = '#222';
      c.textBaseline = 'middle';
      c.fillText(item.label, x + 28, cy);
    });
    c.restore();
  }
}

function legendMark(c, item, x, y) {
  c.strokeStyle = item.colour;
  c.fillStyle = item.colour;
  c.lineWidth = 2;
  c.setLineDash(item.kind === 'dash' ? [5, 3] : []);
  if (item.kind === 'line' || item.kind === 'dash') c.beginPath(), c.moveTo(x, y), c.lineTo(x + 18, y), c.stroke();
  if (item.kind === 'dot') c.beginPath(), c.arc(x + 9, y, 3, 0, 2 * Math.PI), c.fill();
  if (item.kind === 'ring') c.beginPath(), c.arc(x + 9, y, 4.5, 0, 2 * Math.PI), c.stroke();
  if (item.kind === 'bar') c.fillRect(x + 3, y - 5, 12, 10);
  if (item.kind === 'cross') c.lineWidth = 1, c.beginPath(), c.moveTo(x + 5, y - 4), c.lineTo(x + 13, y + 4), c.moveTo(x + 5, y + 4), c.lineTo(x + 13, y - 4), c.stroke();
  if (item.kind === 'tick') c.beginPath(), c.moveTo(x + 9, y - 6), c.lineTo(x + 9, y + 6), c.stroke();
  c.setLineDash([]);
}
