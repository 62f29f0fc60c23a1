// The explorer's page: the form is built from the parameter table, every
// number comes from the snowroll library, and this file only asks and draws.
//
// Two engines, one page. Built by scripts/build-explorer.sh, the page holds
// the library compiled to WebAssembly (SNOWROLL_WASM, base64) and runs it in
// a Web Worker: no server, works from file://. Served by `snowroll serve`
// (no WebAssembly inlined), it asks the server's API instead, which runs the
// command line. Either way a run is `snowroll simulate` (circular models)
// or `snowroll turns` (turn models) with the same parameters, and what the
// page offers to download is that command's output, byte for byte.
'use strict';

const COLORS = ['#0969da', '#cf222e', '#1a7f37', '#8250df', '#bf8700', '#0598bc', '#6e7781', '#e16f24', '#57606a', '#a40e26', '#116329'];
// Turns a turn model runs for when the turns field is left empty: the run
// then ends at t_end (100 s by default) long before.
const PAGE_TURNS = 100000;
const state = { params: [], models: [], inputs: {}, runs: [], seq: 0, timer: null, busy: false, dirty: false, limits: null };
const $ = (id) => document.getElementById(id);

// A command's JSON output as columns (Float64Array per numeric field), its
// stop and summary. Runs in the worker too (its source is sent there).
function shapeOutput(body) {
  const rows = body.samples || body.turns || [];
  const cols = {};
  if (rows.length > 0) {
    for (const k of Object.keys(rows[0])) {
      if (typeof rows[0][k] !== 'number') continue;
      const a = new Float64Array(rows.length);
      for (let i = 0; i < rows.length; i++) a[i] = rows[i][k] === null || rows[i][k] === undefined ? NaN : rows[i][k];
      cols[k] = a;
    }
  }
  return { cols, n: rows.length, stop: body.stop, summary: body.summary || null };
}

// The worker: instantiates the module once, then answers runs. The module's
// ABI is crates/snowroll-wasm/src/abi.rs (request in, bytes out).
function workerMain() {
  let current = null;
  let ready = null;
  const enc = new TextEncoder(), dec = new TextDecoder();
  self.onmessage = async (e) => {
    const m = e.data;
    if (m.module) {
      ready = WebAssembly.instantiate(m.module, { env: { progress: (f) => self.postMessage({ id: current, progress: f }) } });
      return;
    }
    const abi = (await ready).exports;
    current = m.id;
    const bytes = enc.encode(JSON.stringify(m.request));
    const at = abi.request_buffer(bytes.length);
    new Uint8Array(abi.memory.buffer, at, bytes.length).set(bytes);
    const status = abi.run(m.command);
    const text = dec.decode(new Uint8Array(abi.memory.buffer, abi.answer_ptr(), abi.answer_len()));
    const g = abi.g_along();
    if (status !== 0 || m.raw) {
      self.postMessage({ id: m.id, status, text, g });
      return;
    }
    // eslint-disable-next-line no-undef
    const data = shapeOutput(JSON.parse(text));
    self.postMessage({ id: m.id, status, g, data }, Object.values(data.cols).map((a) => a.buffer));
  };
}

const Engine = {
  wasm: typeof SNOWROLL_WASM === 'string',
  worker: null,
  pending: new Map(),
  next: 0,

  async init() {
    if (!this.wasm) return;
    // eslint-disable-next-line no-undef
    const bin = atob(SNOWROLL_WASM);
    const bytes = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
    this.module = await WebAssembly.compile(bytes);
    this.spawn();
  },

  spawn() {
    const src = shapeOutput.toString() + '\n(' + workerMain.toString() + ')();';
    const url = URL.createObjectURL(new Blob([src], { type: 'text/javascript' }));
    this.worker = new Worker(url);
    URL.revokeObjectURL(url);
    this.worker.onmessage = (e) => {
      const m = e.data, p = this.pending.get(m.id);
      if (!p) return;
      if (m.progress !== undefined) { if (p.onProgress) p.onProgress(m.progress); return; }
      this.pending.delete(m.id);
      p.resolve(m.status === 0 ? { ok: true, g: m.g, data: m.data, text: m.text } : { ok: false, error: m.text });
    };
    this.worker.postMessage({ module: this.module });
  },

  // Ends the runs in flight (a new scenario replaces them): the worker is
  // ended and a fresh one started.
  cancel() {
    if (!this.wasm || this.pending.size === 0) return;
    this.worker.terminate();
    for (const p of this.pending.values()) p.resolve({ ok: false, cancelled: true, error: 'cancelled' });
    this.pending.clear();
    this.spawn();
  },

  // Runs `command` ('simulate', 'turns') with `request` (key: value text);
  // `raw`: the output's text, else its columns.
  async call(command, request, raw, onProgress) {
    if (this.wasm) {
      const id = ++this.next;
      return new Promise((resolve) => {
        this.pending.set(id, { resolve, onProgress });
        this.worker.postMessage({ id, command: command === 'simulate' ? 1 : 2, request, raw });
      });
    }
    const r = await fetch('api/' + command + '?' + new URLSearchParams(request).toString());
    const text = await r.text();
    if (!r.ok) {
      let error = text;
      try { error = JSON.parse(text).error; } catch (e) { /* the text as it came */ }
      return { ok: false, error };
    }
    const g = Number(r.headers.get('X-Snowroll-G-Along'));
    return raw ? { ok: true, g, text } : { ok: true, g, data: shapeOutput(JSON.parse(text)) };
  },

  async params() {
    if (this.wasm) {
      const r = await new Promise((resolve) => {
        const id = ++this.next;
        this.pending.set(id, { resolve });
        this.worker.postMessage({ id, command: 0, request: {}, raw: true });
      });
      return JSON.parse(r.text);
    }
    const r = await fetch('api/params');
    return r.json();
  },
};

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
      input.range.id = 'slider-' + p.key;
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
  $('body-choice').addEventListener('change', () => { applyBody($('body-choice').value); changed(); });
  // The shape chosen by hand for the log or the ball: the body follows.
  state.inputs.shape.select.addEventListener('change', () => {
    if (state.body === 'roll') return;
    showBody(state.inputs.shape.select.value === 'sphere' ? 'ball' : 'log');
    writePermalink();
  });
  $('replay').addEventListener('click', () => race(false));
}

const isTurn = (id) => state.models.some((m) => m.id === id && m.turn_model);
const chosen = () => [...$('models').querySelectorAll('input:checked')].map((c) => c.value);

// The request of one run: the model, then every parameter given that the
// command and the model take. A turn model runs `turns` up to the page's
// t_end (its field's value or default) for as many turns as fit, unless
// the turns field says otherwise.
function request(cmd, model, shape) {
  const q = { model };
  for (const p of state.params) {
    if (!p.commands.includes(cmd)) continue;
    if (p.applies === 'turn-models' && !isTurn(model)) continue;
    if (p.key === 'shape' && shape) continue;
    if (p.applies === 'sphere' && (shape || given('shape') || 'cylinder') !== 'sphere') continue;
    const v = given(p.key);
    if (v !== '') q[p.key] = v;
  }
  if (shape) q.shape = shape;
  if (cmd === 'turns') {
    if (q.t_end === undefined) q.t_end = state.inputs.t_end.p.default_text;
    if (q.turns === undefined) q.turns = String(pageTurns());
  }
  return q;
}

const pageTurns = () => (state.limits ? Math.min(PAGE_TURNS, state.limits.max_turns) : PAGE_TURNS);

// The command line of a request (what the downloaded CSV is the output of).
function commandLine(cmd, q) {
  const words = ['snowroll', cmd];
  for (const [k, v] of Object.entries(q)) {
    const p = state.params.find((x) => x.key === k);
    const flag = '--' + (p ? p.flag : k);
    if (p && p.kind === 'flag') { if (v === 'true') words.push(flag); continue; }
    const word = /^[A-Za-z0-9_.,+-]+$/.test(v) ? v : "'" + v.replace(/'/g, "'\\''") + "'";
    // A negative number joined to its flag: `--snow-depth -4e-4` would be
    // read as a flag of its own.
    if (v.startsWith('-')) words.push(flag + '=' + word); else words.push(flag, word);
  }
  return words.join(' ');
}

// The runs the page asks for: each model chosen, and with the ball box
// ticked each circular model on the other body too.
function plan() {
  const runs = [];
  const shape = given('shape') || 'cylinder';
  const other = shape === 'sphere' ? 'cylinder' : 'sphere';
  for (const m of chosen()) {
    const cmd = isTurn(m) ? 'turns' : 'simulate';
    runs.push({ model: m, label: m, shape: null, cmd });
    if ($('ball-too').checked && !isTurn(m)) runs.push({ model: m, label: m + ' (' + other + ')', shape: other, cmd });
  }
  runs.forEach((r, i) => { r.color = COLORS[i % COLORS.length]; r.index = i; r.request = request(r.cmd, r.model, r.shape); });
  return runs;
}

// The race's track of a run: its rows' t, x (r and the turn angle where it
// has them); a turn table's turns' starts and its stop.
function track(run) {
  const c = run.cols;
  if (run.kind === 'sim') return { t: c.t_s, x: c.x_m, r: c.r_m, angle: c.theta_rad || null };
  const n = run.n;
  const t = new Float64Array(n + 1), x = new Float64Array(n + 1), angle = new Float64Array(n + 1);
  for (let i = 0; i < n; i++) { t[i] = c.t_start_s[i]; x[i] = c.x_start_m[i]; angle[i] = 2 * Math.PI * i; }
  t[n] = run.stop.t_s; x[n] = run.stop.x_m;
  angle[n] = 2 * Math.PI * (run.stop.turn || n) + (run.stop.theta_rad || 0);
  return { t, x, r: null, angle };
}

// The first row whose normal force is <= 0 (a run going on through a hop).
function firstHop(run) {
  const c = run.cols;
  const n = run.kind === 'sim' ? c.normal_n : c.min_normal_n;
  if (!n) return null;
  const ts = run.kind === 'sim' ? c.t_s : c.t_start_s, xs = run.kind === 'sim' ? c.x_m : c.x_start_m;
  for (let i = 0; i < n.length; i++) if (n[i] <= 0) return { t: ts[i], x: xs[i] };
  return null;
}

function changed() {
  if (typeof performance.mark === 'function') performance.mark('snowroll-input');
  writePermalink();
  clearTimeout(state.timer);
  if (!Engine.wasm) { state.timer = setTimeout(refresh, 100); return; }
  // WebAssembly: at once; while a run is in flight the newest scenario
  // waits for it (a slider dragged), unless it has run for long (a long
  // run is ended and replaced).
  if (state.busy) {
    state.dirty = true;
    if (performance.now() - state.started > 300) Engine.cancel();
    return;
  }
  refresh();
}

function showProgress(run, f) {
  const box = $('progress');
  box.hidden = false;
  box.querySelector('progress').value = f;
  const what = run.cmd === 'turns' ? 'of ' + run.request.turns + ' turns (or t_end = ' + run.request.t_end + ' s)' : 'of t_end';
  box.querySelector('span').textContent = run.label + ': ' + (100 * f).toFixed(0) + '% ' + what + ', in a Web Worker';
}

async function refresh() {
  const seq = ++state.seq;
  state.busy = true;
  state.dirty = false;
  state.started = performance.now();
  const runs = plan();
  $('status').textContent = 'computing ' + runs.length + ' runs…';
  const answers = await Promise.all(runs.map(async (run) => {
    const r = await Engine.call(run.cmd, run.request, false, (f) => showProgress(run, f));
    if (!r.ok) return Object.assign(run, { error: r.error, cancelled: r.cancelled });
    return Object.assign(run, r.data, { g: r.g, kind: run.cmd === 'turns' ? 'table' : 'sim' });
  }));
  state.busy = false;
  $('progress').hidden = true;
  if (seq !== state.seq) return;
  if (state.dirty || answers.some((r) => r.cancelled)) { refresh(); return; }
  const computed = performance.now();
  for (const r of answers) if (!r.error) { r.track = track(r); r.firstHop = firstHop(r); }
  state.runs = answers;
  readout();
  Plots.drawAll($('plots'), answers);
  downloads();
  commands();
  race(location.hash === '#end');
  const drawn = performance.now();
  state.timing = { compute_ms: computed - state.started, draw_ms: drawn - computed };
  if (performance.getEntriesByName('snowroll-input', 'mark').length > 0) {
    performance.measure('snowroll-update', 'snowroll-input');
    performance.clearMarks('snowroll-input');
  }
  const bad = answers.filter((r) => r.error).length;
  $('status').textContent = answers.length + ' runs computed in ' + state.timing.compute_ms.toFixed(0) + ' ms, drawn in ' +
    state.timing.draw_ms.toFixed(0) + ' ms' + (bad ? ', ' + bad + ' refused (see the readout)' : '');
  $('status').className = bad ? 'error' : '';
  document.documentElement.dataset.refreshed = String(seq);
}

// Plays the race (`atEnd`: shows its last frame at once).
function race(atEnd) {
  const alpha = parseFloat(given('alpha_deg') || state.inputs.alpha_deg.p.default_text) * Math.PI / 180;
  Race.start($('race'), $('race-clock'), state.runs.filter((r) => !r.error), alpha, atEnd === true);
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
      // a at the end: the last row's (a turn table's: the last turn's mean);
      // on a level floor (g sin α = 0, the unwinding roll) in m/s².
      const a = r.kind === 'sim' ? r.cols.a_m_s2 : r.cols.mean_a_turn_m_s2;
      const level = !(r.g > 0);
      const end = a && a.length ? (level ? a[a.length - 1].toPrecision(6) + ' m/s² (g sin α = 0)' : (a[a.length - 1] / r.g).toPrecision(6)) +
        (r.kind === 'sim' ? '' : ' (last turn\'s mean)') : '';
      tr.innerHTML = name + '<td></td><td></td><td></td><td class="v"></td><td></td>';
      const cells = tr.querySelectorAll('td');
      cells[1].textContent = r.stop.reason;
      cells[1].title = r.stop.description;
      cells[2].textContent = String(r.stop.t_s);
      cells[3].textContent = String(r.stop.x_m);
      cells[4].textContent = String(r.stop.v_m_s);
      cells[5].textContent = end;
      tr.dataset.v = String(r.stop.v_m_s);
    }
    body.appendChild(tr);
  }
}

function commands() {
  $('command').textContent = state.runs.map((r) => commandLine(r.cmd, r.request)).join('\n') +
    (state.runs.length ? '\n# each writes CSV (the download\'s bytes); add --format json for the JSON' : '');
}

function downloads() {
  const sel = $('download-model');
  const keep = sel.value;
  sel.innerHTML = '';
  for (const r of state.runs) sel.add(new Option(r.label + (r.cmd === 'turns' ? ' (turn table)' : ''), r.label));
  if (keep) sel.value = keep;
}

// Writes the chosen run's output in `format` to a file, as the command line
// writes it (the same bytes).
async function download(format) {
  const r = state.runs.find((x) => x.label === $('download-model').value) || state.runs[0];
  if (!r) return;
  const q = Object.assign({}, r.request, { format });
  const out = await Engine.call(r.cmd, q, true);
  if (!out.ok) { $('status').textContent = 'error: ' + out.error; $('status').className = 'error'; return; }
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([out.text], { type: format === 'csv' ? 'text/csv' : 'application/json' }));
  a.download = 'snowroll-' + r.label.replace(/[^a-z0-9-]+/gi, '-').replace(/-+$/, '') + '.' + format;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 60000);
}

// The scenario in the address: the body (but the log, the page's own), the
// models, the ball box, and every value not the body's default (a value
// the body changes, set back to the table's default, is written too).
function writePermalink() {
  const q = new URLSearchParams();
  const body = BODIES[state.body];
  if (state.body !== 'log') q.set('body', state.body);
  q.set('models', chosen().join(','));
  if ($('ball-too').checked) q.set('ball', '1');
  for (const p of state.params) {
    const v = given(p.key);
    const preset = body.values[p.key];
    const base = preset === undefined || preset === p.default_text ? '' : preset;
    if (v !== base) q.set(p.key, v !== '' ? v : p.default === null ? '' : p.default_text);
  }
  const url = location.pathname + '?' + q.toString() + location.hash;
  history.replaceState(null, '', url);
  $('permalink').href = url;
}

// The body's defaults, then what the address gives over them.
function readPermalink() {
  const q = new URLSearchParams(location.search);
  applyBody(Object.hasOwn(BODIES, q.get('body')) ? q.get('body') : bodyOf(q));
  if (q.has('models')) {
    const models = q.get('models').split(',');
    for (const c of $('models').querySelectorAll('input')) c.checked = models.includes(c.value);
  }
  $('ball-too').checked = q.get('ball') === '1';
  for (const [k, v] of q.entries()) setGiven(k, v);
}

async function main() {
  await Engine.init();
  $('engine').textContent = Engine.wasm ? 'in this page (WebAssembly), with no server' : 'by the snowroll program serving this page';
  const table = await Engine.params();
  state.params = table.params;
  state.models = table.models;
  state.limits = table.limits || null;
  buildForm();
  readPermalink();
  // A phone: the race and the readout first, the parameters folded below.
  if (window.matchMedia('(max-width: 800px)').matches) $('panel').open = false;
  $('download-model').addEventListener('change', downloads);
  $('download-csv').addEventListener('click', () => download('csv'));
  $('download-json').addEventListener('click', () => download('json'));
  writePermalink();
  await refresh();
}

main().catch((e) => { $('status').textContent = 'error: ' + e; $('status').className = 'error'; });
