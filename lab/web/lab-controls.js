// The lab's controls: each setting as a slider and a number box kept in step,
// the scene's text with its exact values, and the message line. The settings
// go to the engine as typed; the engine alone decides what it accepts
// (lab/engine/lab_session.cpp), and its refusal is shown here.
'use strict';

// Sliders on a logarithmic scale keep log10 of the value.
const SETTINGS = [
  {id: 'N', label: 'N, particles', log: true, min: 1, max: 5, step: 0.01, whole: true},
  {id: 'r', label: 'r, restitution', min: 0, max: 1, step: 0.01},
  {id: 'delta', label: 'δ, sub-threshold speed', log: true, min: -4, max: 0, step: 0.05},
  {id: 'seed', label: 'seed (white noise)', min: 1, max: 100, step: 1, whole: true},
  {id: 'speed', label: 'speed', log: true, min: -1, max: 1, step: 0.05},
];

class Controls {
  // onChange(): a setting changed (the run restarts).
  constructor(root, scenes, onChange) {
    this.scenes = scenes;
    this.onChange = onChange;
    this.el = {};
    this.scene = root.querySelector('#scene');
    for (const s of scenes) this.scene.add(new Option(s.title, s.name));
    this.scene.addEventListener('change', () => { this.applyDefaults(); onChange('scene'); });
    const table = root.querySelector('#settings');
    for (const s of SETTINGS) this.addSetting(table, s);
    for (const id of ['subthreshold', 'geometry']) {
      this.el[id] = root.querySelector('#' + id);
      this.el[id].addEventListener('change', () => onChange(id));
    }
    this.message = root.querySelector('#message');
    this.applyDefaults();
  }

  addSetting(table, s) {
    const row = table.insertRow();
    const label = row.insertCell();
    label.innerHTML = `<label for="${s.id}-number">${s.label}</label>`;
    const cell = row.insertCell();
    const slider = Object.assign(document.createElement('input'), {type: 'range', id: `${s.id}-slider`, min: s.min, max: s.max, step: s.step});
    const number = Object.assign(document.createElement('input'), {type: 'number', id: `${s.id}-number`});
    slider.setAttribute('aria-label', s.label);
    cell.append(slider, number);
    // The slider sets the box (a round value); the box moves the slider; either restarts the run.
    slider.addEventListener('input', () => { number.value = this.fromSlider(s, slider.value); });
    slider.addEventListener('change', () => this.onChange(s.id));
    number.addEventListener('change', () => { this.toSlider(s, number.value); this.onChange(s.id); });
    this.el[s.id] = {slider, number, spec: s};
  }

  fromSlider(s, value) {
    const v = s.log ? Math.pow(10, Number(value)) : Number(value);
    return s.whole ? Math.round(v) : Number(v.toPrecision(2));
  }
  toSlider(s, text) {
    const v = Number(text);
    if (text === '' || !isFinite(v)) return;
    this.el[s.id].slider.value = s.log ? Math.log10(Math.max(v, 1e-300)) : v;
  }
  set(id, value) {
    const e = this.el[id];
    e.number.value = value;
    this.toSlider(e.spec, String(value));
  }

  current() { return this.scenes.find((s) => s.name === this.scene.value); }

  // The scene file's settings (lab/tools/make_lab_page.py reads them from the gallery).
  applyDefaults() {
    const d = this.current().defaults;
    this.set('N', d.N), this.set('r', d.r), this.set('delta', d.delta), this.set('seed', d.seed), this.set('speed', 1);
    this.el.subthreshold.value = d.sticky ? 'sticky' : 'elastic';
    this.el.geometry.value = d.line ? 'line' : 'ring';
    this.describe(this.current());
  }

  // The settings as typed: an empty or unreadable box is NaN, which the engine refuses by name.
  settings() {
    const number = (id) => (this.el[id].number.value === '' ? NaN : Number(this.el[id].number.value));
    return {scene: this.scene.value, N: number('N'), r: number('r'), delta: number('delta'), seed: number('seed'),
            sticky: this.el.subthreshold.value === 'sticky', line: this.el.geometry.value === 'line'};
  }
  speed() {
    const v = Number(this.el.speed.number.value);
    return isFinite(v) && v > 0 ? v : 1;
  }

  say(text, kind) {
    this.message.textContent = text;
    this.message.className = kind || '';
  }

  describe(scene) {
    const d = scene.defaults;
    const box = document.querySelector('#about');
    box.innerHTML = '';
    const h = document.createElement('h2');
    h.textContent = scene.title;
    const p = document.createElement('p');
    p.textContent = scene.description;
    const src = document.createElement('p');
    src.className = 'source';
    src.textContent = `From ${scene.file} (the gallery: N = ${d.N_gallery}, r = ${d.r}, t_end = ${d.t_end}). ` +
        'Exact values at the scene\'s t_end, from theory, as the gallery\'s tests hold them (ctest -L scene):';
    const list = document.createElement('ul');
    list.id = 'exact-values';
    for (const e of scene.exact) {
      const li = document.createElement('li');
      const value = Array.isArray(e.value) ? `between ${fmt(e.value[0])} and ${fmt(e.value[1])}` : fmt(e.value);
      li.innerHTML = `<b>${value}</b> <span class="key">${e.key}</span>: `;
      li.append(document.createTextNode(e.why));
      list.append(li);
    }
    box.append(h, p, src, list);
  }
}

function fmt(v) { return typeof v === 'number' ? String(Number(v.toPrecision(6))) : String(v); }
