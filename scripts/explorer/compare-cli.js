// Byte-for-byte check of the explorer's WebAssembly against the command
// line: for every model, on both bodies (where the model takes the ball),
// with losses, a hop, a slip, sampling by dt and by times, in CSV and JSON,
// runs `snowroll simulate` (and `snowroll turns` for the turn models) and
// the module with the same parameters, and compares the bytes.
//
//   node scripts/explorer/compare-cli.js SNOWROLL MODULE.wasm
//
// Exits non-zero on any difference (printing the first differing line) or
// when the module and the CLI disagree on refusing a run.
'use strict';
const fs = require('fs');
const { execFileSync } = require('child_process');

const [snowroll, wasmPath] = process.argv.slice(2);
if (!snowroll || !wasmPath) {
  console.error('usage: node scripts/explorer/compare-cli.js SNOWROLL MODULE.wasm');
  process.exit(2);
}

// The page's ABI (crates/snowroll-wasm/src/abi.rs): request in, bytes out.
const progress = [];
const { instance } = { instance: new WebAssembly.Instance(new WebAssembly.Module(fs.readFileSync(wasmPath)), { env: { progress: (f) => progress.push(f) } }) };
const abi = instance.exports;
function call(command, request) {
  const bytes = Buffer.from(JSON.stringify(request), 'utf8');
  const at = abi.request_buffer(bytes.length);
  new Uint8Array(abi.memory.buffer, at, bytes.length).set(bytes);
  const status = abi.run(command);
  const out = Buffer.from(new Uint8Array(abi.memory.buffer, abi.answer_ptr(), abi.answer_len()));
  return { status, out };
}

// The CLI's flags for the same request (key alpha_deg -> --alpha-deg).
function cli(command, request) {
  const args = [command];
  for (const [k, v] of Object.entries(request)) {
    if (v === 'true') args.push('--' + k.replace(/_/g, '-'));
    else args.push('--' + k.replace(/_/g, '-') + '=' + v);
  }
  try {
    return { status: 0, out: execFileSync(snowroll, args, { stdio: ['ignore', 'pipe', 'pipe'], maxBuffer: 1 << 28 }) };
  } catch (e) {
    return { status: 1, out: e.stderr };
  }
}

const circular = ['snowless', 'torque-cm', 'torque-contact', 'energy', 'energy-thin', 'lagrangian-printed',
  'quasi-circular', 'quasi-circular-lift', 'loney'];
const turnModels = ['turns', 'turns-exact'];
const losses = { mu: '0.3', drag_coefficient: '0.8', air_density: '1.2', rolling_resistance: '0.01', compaction_energy: '200' };
const cases = [];
for (const m of circular) {
  for (const shape of ['cylinder', 'sphere']) {
    cases.push(['simulate', { model: m, shape }]);
    cases.push(['simulate', { model: m, shape, alpha_deg: '65', t_end: '5', dt: '0.01' }]);
    cases.push(['simulate', { model: m, shape, times: '0.5,1,2,40', t_end: '40', ...losses }]);
  }
  cases.push(['simulate', { model: m, alpha_deg: '12', mu: '0.05', ledger: 'true', t_end: '3' }]);
}
for (const m of turnModels) {
  cases.push(['simulate', { model: m }]);
  cases.push(['simulate', { model: m, alpha_deg: '65' }]);
  cases.push(['simulate', { model: m, alpha_deg: '20', on_hop: 'continue', dt: '0.05', collision: 'pivot', t_end: '20' }]);
  cases.push(['simulate', { model: m, turns: '30', t_end: '100', mu: '0.1' }]);
  cases.push(['turns', { model: m }]);
  cases.push(['turns', { model: m, turns: '2000', alpha_deg: '45' }]);
  cases.push(['turns', { model: m, alpha_deg: '65' }]);
  cases.push(['turns', { model: m, collision: 'pivot', turns: '50' }]);
  // A slip in the middle of the run (F/N grows turn by turn at 60 degrees).
  cases.push(['simulate', { model: m, alpha_deg: '60', mu: '2' }]);
  cases.push(['turns', { model: m, alpha_deg: '60', mu: '2' }]);
}
// Refused by both: a bad angle, a key the command does not take.
cases.push(['simulate', { model: 'energy', alpha_deg: '95' }]);
cases.push(['turns', { model: 'energy' }]);

let failed = 0, compared = 0, bytes = 0;
for (const [command, base] of cases) {
  for (const format of ['csv', 'json']) {
    const request = { ...base, format };
    const mine = call(command === 'simulate' ? 1 : 2, request);
    const theirs = cli(command, request);
    const what = command + ' ' + JSON.stringify(request);
    if ((mine.status === 0) !== (theirs.status === 0)) {
      failed++;
      console.error('FAIL ' + what + ': module ' + (mine.status ? 'refused: ' + mine.out : 'ran') + '; CLI ' + (theirs.status ? 'refused: ' + theirs.out : 'ran'));
      continue;
    }
    if (mine.status !== 0) { compared++; continue; }
    if (!mine.out.equals(theirs.out)) {
      failed++;
      const a = mine.out.toString().split('\n'), b = theirs.out.toString().split('\n');
      const i = a.findIndex((line, k) => line !== b[k]);
      console.error('FAIL ' + what + ': differs at line ' + (i + 1) + '\n  module: ' + a[i] + '\n  CLI:    ' + b[i]);
      continue;
    }
    compared++;
    bytes += mine.out.length;
  }
}
// A long table reports its progress (every 1024 turns).
progress.length = 0;
call(2, { model: 'turns', turns: '5000', format: 'csv' });
if (progress.length !== 4) { failed++; console.error('FAIL progress: ' + progress.length + ' reports for 5000 turns, expected 4'); }
console.log((failed ? 'FAIL' : 'ok  ') + ' ' + compared + ' outputs (' + bytes + ' bytes) the same as the CLI\'s, ' + failed + ' differ');
process.exit(failed ? 1 : 0);
