// The explorer's page: the form comes from /api/params (one field per
// parameter of the table), every number from /api/simulate and /api/turns.
// No physics here: this file only builds the form, asks the server, and draws.
'use strict';

const COLORS = ['#0969da', '#cf222e', '#1a7f37', '#8250df', '#bf8700', '#0598bc', '#6e7781', '#e16f24', '#57606a', '#a40e26', '#116329'];
const state = { params: [], models: [], inputs: {}, runs: [], seq: 0, timer: null };
const $ = (id) => document.getElementById(id);

// Text for a slider's number: short, and read back to about the same value.
function fmt(x) {
  if (x === 0) return '0';
  const a = Math.abs(x);
  if (a >= 1e-3 && a < 1e6) return String(Number(x.toPrecision(4)));
  return x.toExponential(2).replace(/\.?0+e/, 'e').replace('e+', 'e');
}

// The slider's position (0..1000) and its value, both ways.
function toValue(sl, pos) {
  const f = pos / 1000;
  if (sl.log) return Math.pow(10, Math.log10(sl.min) + (Math.log10(sl.max) - Math.log10(sl.min)) * f);
  return sl.min + (sl.max - sl.min) * f;
}
function toPos(sl, x) {
  const f = sl.log ? (Math.log10(x) - Math.log10(sl.min)) / (Math.log10(sl.max) - Math.log10(sl.min)) : (x - sl.min) / (sl.max - sl.min);
  return Math.round(1000 * Math.min(1, Math.max(0, f)));
}

function paramField(p) {
  const div = document.createElement('div');
  div.className = 'param';
  div.title = p.help + ' [default: ' + p.default_text + ']';
  const unit = p.unit ? ' (' + p.unit + ')' : '';
  div.innerHTML = '<div class="name"><label for="in-' + p.key + '">' + p.key + unit + '</label><span class="range"></span></div><div class="inputs"></div>';
  div.querySelector('.range').textContent = p.range;
  const box = div.querySelector('.inputs');
  const input = { p };
  if (p.kind === 'flag') {
    input.check = document.createElement('input');
    input.check.type = 'checkbox';
    input.check.id = 'in-' + p.key;
    input.check.addEventListener('change', changed);
    box.appendChild(input.check);
  } else if (p.kind === 'choice') {
    input.select = document.createElement('select');
    input.select.id = 'in-' + p.key;
    for (const c of p.choices) input.select.add(new Option(c, c));
    input.select.value = p.default;
    input.select.addEventListener('change', changed);
    box.appendChild(input.select);
  } else {
    if (p.slider) {
      input.range = document.createElement('input');
      input.range.type = 'range';
      input.range.min = 0;
      input.range.max = 1000;
      input.range.setAttribute('aria-label', p.key + ' slider');
      input.range.addEventListener('input', () => {
        input.text.value = fmt(toValue(p.slider, Number(input.range.value)));
        changed();
      });
      box.appendChild(input.range);
    }
    input.text = document.createElement('input');
    input.text.type = 'text';
    input.text.id = 'in-' + p.key;
    input.text.placeholder = p.default === null ? 'none' : p.default_text;
    input.text.value = p.default === null ? '' : p.default_text;
    input.text.addEventListener('input', () => { syncSlider(input); changed(); });
    box.appendChild(input.text);
  }
  state.inputs[p.key] = input;
  syncSlider(input);
  return div;
}

function syncSlider(input) {
  if (!input.range) return;
  const x = parseFloat(input.text.value);
  input.range.value = Number.isFinite(x) ? toPos(input.p.slider, x) : 0;
}

// The value given for a parameter: '' when it is at its default.
function given(key) {
  const input = state.inputs[key];
  if (!input) return '';
  const p = input.p;
  if (input.check) return input.check.checked ? 'true' : '';
  const v = (input.select ? input.select.value : input.text.value).trim();
  return v === p.default_text || (p.default === null && v === '') ? '' : v;
}

function setGiven(key, value) {
  const input = state.inputs[key];
  if (!input) return;
  if (input.check) input.check.checked = value === 'true';
  else if (input.select) input.select.value = value;
  else { input.text.value = value; syncSlider(input); }
}

function buildForm() {
  const form = $('form');
  const groups = { scenario: 'the slope, the snow, the body', run: 'the run', losses: 'losses (circular models)' };
  for (const g of Object.keys(groups)) {
    const set = document.createElement('fieldset');
    set.innerHTML = '<legend>' + groups[g] + '</legend>';
    for (const p of state.params.filter((q) => q.group === g)) set.appendChild(paramField(p));
    form.appendChild(set);
  }
  const box = $('models');
  for (const m of state.models) {
    const label = document.createElement('label');
    label.className = 'check';
    label.title = m.description;
    label.innerHTML = '<input type="checkbox" value="' + m.id + '"> ' + m.id + ' <small>' + m.equation + '</small>';
    label.querySelector('input').addEventListener('change', changed);
    box.appendChild(label);
  }
  $('ball-too').addEventListener('change', changed);
  $('replay').addEventListener('click', race);
}

const isTurn = (id) => state.models.some((m) => m.id === id && m.turn_model);
const chosen = () => [...$('models').querySelectorAll('input:checked')].map((c) => c.value);

// The query of one run: the model, then every parameter given that the
// command and the model take.
function query(cmd, model, shape, extra) {
  const q = new URLSearchParams();
  q.set('model', model);
  for (const p of state.params) {
    if (!p.commands.includes(cmd)) continue;
    if (p.applies === 'turn-models' && !isTurn(model)) continue;
    if (p.key === 'shape' && shape) continue;
    if (p.applies === 'sphere' && (shape || given('shape') || 'cylinder') !== 'sphere') continue;
    const v = given(p.key);
    if (v !== '') q.set(p.key, v);
  }
  if (shape) q.set('shape', shape);
  for (const [k, v] of Object.entries(extra || {})) q.set(k, v);
  return q.toString();
}

// The runs the page asks for: each model chosen, and with the ball box
// ticked each circular model on the other body too.
function plan() {
  const runs = [];
  const shape = given('shape') || 'cylinder';
  const other = shape === 'sphere' ? 'cylinder' : 'sphere';
  for (const m of chosen()) {
    runs.push({ model: m, label: m, shape: null });
    if ($('ball-too').checked && !isTurn(m)) runs.push({ model: m, label: m + ' (' + other + ')', shape: other, dash: true });
  }
  runs.forEach((r, i) => { r.color = COLORS[i % COLORS.length]; });
  return runs;
}

async function fetchJson(url) {
  const r = await fetch(url);
  const text = await r.text();
  let body;
  try { body = JSON.parse(text); } catch (e) { body = { error: text }; }
  return { ok: r.ok, body, gAlong: Number(r.headers.get('X-Snowroll-G-Along')) };
}

function changed() {
  clearTimeout(state.timer);
  state.timer = setTimeout(refresh, 100);
}

async function refresh() {
  const seq = ++state.seq;
  const runs = plan();
  writePermalink();
  const started = performance.now();
  $('status').textContent = 'computing ' + runs.length + ' runs…';
  const answers = await Promise.all(runs.map(async (run) => {
    const q = query('simulate', run.model, run.shape);
    run.query = q;
    const sim = await fetchJson('/api/simulate?' + q);
    if (sim.ok && isTurn(run.model)) run.turns = await fetchJson('/api/turns?' + query('turns', run.model, run.shape));
    return Object.assign(run, sim.ok ? { samples: sim.body.samples, stop: sim.body.stop, gAlong: sim.gAlong } : { error: sim.body.error });
  }));
  if (seq !== state.seq) return;
  state.runs = answers;
  const ms = performance.now() - started;
  const bad = answers.filter((r) => r.error).length;
  $('status').textContent = answers.length + ' runs in ' + ms.toFixed(0) + ' ms' + (bad ? ', ' + bad + ' refused (see the readout)' : '');
  $('status').className = bad ? 'error' : '';
  readout();
  Plots.drawAll($('plots'), answers);
  downloads();
  race();
  document.documentElement.dataset.refreshed = String(seq);
  if (state.onRefresh) state.onRefresh();
}

function race() {
  const alpha = parseFloat(given('alpha_deg') || state.inputs.alpha_deg.p.default_text) * Math.PI / 180;
  Race.start($('race'), $('race-clock'), state.runs.filter((r) => !r.error), alpha);
}

function readout() {
  const body = $('readout').querySelector('tbody');
  body.innerHTML = '';
  for (const r of state.runs) {
    const tr = document.createElement('tr');
    tr.dataset.run = r.label;
    const name = '<td><span class="swatch" style="background:' + r.color + '"></span>' + r.label + '</td>';
    if (r.error) {
      tr.innerHTML = name + '<td class="err" colspan="5"></td>';
      tr.querySelector('.err').textContent = r.error;
    } else {
      const last = r.samples[r.samples.length - 1];
      const a = last ? last.a_m_s2 / r.gAlong : NaN;
      tr.innerHTML = name + '<td title="' + r.stop.description + '">' + r.stop.reason + '</td><td>' + String(r.stop.t_s) + '</td><td>' + String(r.stop.x_m) + '</td><td class="v">' + String(r.stop.v_m_s) + '</td><td>' + a.toPrecision(6) + '</td>';
      tr.dataset.v = String(r.stop.v_m_s);
    }
    body.appendChild(tr);
  }
}

function downloads() {
  const sel = $('download-model');
  const keep = sel.value;
  sel.innerHTML = '';
  for (const r of state.runs) sel.add(new Option(r.label, r.label));
  if (keep) sel.value = keep;
  const r = state.runs.find((x) => x.label === sel.value) || state.runs[0];
  for (const f of ['csv', 'json']) {
    const a = $('download-' + f);
    if (!r) { a.removeAttribute('href'); continue; }
    a.href = '/api/simulate?' + r.query + '&format=' + f;
    a.download = 'snowroll-' + r.label.replace(/[^a-z0-9-]+/gi, '-') + '.' + f;
  }
}

// The scenario in the address: models, the ball box, every value given.
function writePermalink() {
  const q = new URLSearchParams();
  const models = chosen();
  if (models.length) q.set('models', models.join(','));
  if ($('ball-too').checked) q.set('ball', '1');
  for (const p of state.params) { const v = given(p.key); if (v !== '') q.set(p.key, v); }
  const url = location.pathname + '?' + q.toString() + location.hash;
  history.replaceState(null, '', url);
  $('permalink').href = url;
}

function readPermalink() {
  const q = new URLSearchParams(location.search);
  const models = (q.get('models') || 'torque-cm,loney,turns').split(',');
  for (const c of $('models').querySelectorAll('input')) c.checked = models.includes(c.value);
  $('ball-too').checked = q.get('ball') === '1';
  for (const [k, v] of q.entries()) setGiven(k, v);
}

// The browser test's hook (page address ending in #selftest): records the
// readout and the plots, moves the alpha slider to its middle as a hand
// would, and records them again once the new answers are drawn.
const SelfTest = {
  run(st) {
    const root = document.documentElement.dataset;
    const cell = () => $('readout').querySelector('td.v');
    const first = () => st.runs.find((r) => !r.error);
    root.beforeV = String(first().stop.v_m_s);
    root.beforeReadout = cell().textContent;
    root.beforeSig = Plots.signature($('plots'));
    st.onRefresh = () => {
      st.onRefresh = null;
      root.afterAlpha = st.inputs.alpha_deg.text.value;
      root.afterQuery = first().query;
      root.afterV = String(first().stop.v_m_s);
      root.afterReadout = cell().textContent;
      root.afterSig = Plots.signature($('plots'));
      root.selftest = 'done';
    };
    const range = st.inputs.alpha_deg.range;
    range.value = 500;
    range.dispatchEvent(new Event('input'));
  },
};

async function main() {
  const r = await fetchJson('/api/params');
  state.params = r.body.params;
  state.models = r.body.models;
  buildForm();
  readPermalink();
  $('download-model').addEventListener('change', downloads);
  await refresh();
  if (location.hash === '#selftest') SelfTest.run(state);
}

main().catch((e) => { $('status').textContent = 'error: ' + e; $('status').className = 'error'; });
