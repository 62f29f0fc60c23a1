// The explorer in a real browser (headless Chromium, driven by playwright-core
// over the DevTools protocol): the built one-file page from file://, and the
// same page under `snowroll serve`.
//
//   node scripts/explorer/browser-test.js --chromium BIN --cli SNOWROLL --page EXPLORER.html \
//        [--serve] [--shots DIR] [--bench FILE.json]
//
// For each page (file://, then with --serve the server's):
//   - nothing is written to the browser console and no script error is raised;
//   - the alpha slider is moved as a hand moves it (the mouse pressed on the
//     slider's track and released: input events), the page recomputes, and
//     the readout's speed (table#readout, td.v of the torque-cm row) is the
//     CLI's: `snowroll simulate` with the parameters the page shows, its
//     stop's v_m_s as JSON writes it;
//   - the CSV and the JSON the page downloads (for a circular model and for
//     the turn model's table) are byte for byte what the command lines the
//     page shows write (each run as a shell would split it);
//   - the permalink holds the slider's alpha, and opening it shows the same;
//   - every plot has a legend entry per run and a caption with units;
//   - the choice of body: the unwinding roll fills the form (a level floor,
//     a negative snow depth, a core radius), ticks energy-thin, energy,
//     torque-cm and quasi-circular and no turn model, says what it is; every
//     run runs; the energy balances stop `unwound`, energy-thin at its
//     energy integral's speed (the hollow roll on its tube), the torque
//     balance and eq. (32)
//     `does-not-start`; a in m/s^2 on the level floor; the command line
//     shown writes the same stop (also with a snow depth in exponent form);
//     the permalink reopens it (body, form, readout), its race with the
//     paper laid behind the rolls that unwound only; a value set back to the
//     table's default stays in the permalink; the log again restores its
//     defaults; the ball is a sphere with no turn model.
// At 400 px (a phone): no horizontal overflow, the race and the readout
// above the parameters, which are folded; the unwinding roll's page does not
// overflow either. A 10^5-turn run (file:// only):
// runs in the worker with a progress line while the page keeps drawing
// frames (no gap over 500 ms on a loaded 2-core machine, against the whole
// run's second or more were it on the page's thread), and ends with 100000
// turns.
// --shots DIR writes explorer.png (1400 px), explorer-phone.png (400 px) and
// explorer-roll.png (the unwinding roll, 1400 px).
// --bench FILE writes the time from a slider's input event to the redrawn
// page (the Performance API's measure), 15 moves per configuration.
'use strict';
const fs = require('fs');
const path = require('path');
const { execFileSync, spawn } = require('child_process');

const args = {};
for (let i = 2; i < process.argv.length; i++) {
  const k = process.argv[i].replace(/^--/, '');
  const next = process.argv[i + 1];
  if (next !== undefined && !next.startsWith('--')) { args[k] = next; i++; } else args[k] = true;
}
for (const k of ['chromium', 'cli', 'page']) if (!args[k]) { console.error('missing --' + k); process.exit(2); }
const { chromium } = require(process.env.PLAYWRIGHT_CORE || 'playwright-core');

let failures = 0;
function check(ok, what, detail) {
  console.log((ok ? 'ok   ' : 'FAIL ') + what + (ok || detail === undefined ? '' : '\n     ' + detail));
  if (!ok) failures++;
  return ok;
}

// A command line as the page shows it, split as a shell splits it (words,
// and single-quoted words).
function words(line) {
  const out = [];
  const re = /'((?:[^']|'\\'')*)'|(\S+)/g;
  let m;
  while ((m = re.exec(line))) out.push(m[1] !== undefined ? m[1].replace(/'\\''/g, "'") : m[2]);
  return out;
}
function runCli(argv) {
  return execFileSync(args.cli, argv, { stdio: ['ignore', 'pipe', 'pipe'], maxBuffer: 1 << 28 });
}

async function openPage(browser, url, width, height) {
  const context = await browser.newContext({ viewport: { width, height }, acceptDownloads: true });
  const page = await context.newPage();
  const problems = [];
  page.on('console', (m) => problems.push('console ' + m.type() + ': ' + m.text()));
  page.on('pageerror', (e) => problems.push('script error: ' + e.message));
  page.on('response', (r) => { if (r.status() >= 400) problems.push('HTTP ' + r.status() + ': ' + r.url()); });
  await page.goto(url);
  await page.waitForSelector('html[data-refreshed]', { timeout: 60000 });
  return { context, page, problems };
}

async function refreshedAfter(page, before) {
  await page.waitForFunction((b) => document.documentElement.dataset.refreshed !== b, before, { timeout: 60000 });
  // The run in flight may be followed by the newest scenario's.
  await page.waitForFunction(() => !document.querySelector('#status').textContent.startsWith('computing'), null, { timeout: 60000 });
}

// Presses the mouse on the slider's track at `frac` of its width and lets
// go: the browser moves the thumb there and fires input events.
async function moveSlider(page, key, frac) {
  const slider = page.locator('#slider-' + key);
  await slider.scrollIntoViewIfNeeded();
  const box = await slider.boundingBox();
  const before = await page.evaluate(() => document.documentElement.dataset.refreshed);
  await page.mouse.click(box.x + box.width * frac, box.y + box.height / 2);
  await refreshedAfter(page, before);
}

async function download(page, label, format) {
  await page.selectOption('#download-model', label);
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click('#download-' + format)]);
  return fs.readFileSync(await dl.path());
}

// The checks of one page (file:// or served).
async function checkPage(browser, base, name) {
  const { context, page, problems } = await openPage(browser, base + '?models=torque-cm,loney,turns', 1400, 1000);
  const v0 = await page.textContent('#readout tr[data-run="torque-cm"] td.v');
  await moveSlider(page, 'alpha_deg', 0.75);
  const alpha = await page.inputValue('#in-alpha_deg');
  const v1 = await page.textContent('#readout tr[data-run="torque-cm"] td.v');
  check(v1 !== v0 && alpha !== '30', name + ': the slider moved alpha to ' + alpha + ' and the readout changed (' + v0 + ' -> ' + v1 + ')');
  const cli = JSON.parse(runCli(['simulate', '--model', 'torque-cm', '--alpha-deg', alpha, '--format', 'json']).toString());
  check(Number(v1) === cli.stop.v_m_s && v1 === String(cli.stop.v_m_s), name + ': the readout\'s speed is the CLI\'s for alpha = ' + alpha,
    'page ' + v1 + ', CLI ' + JSON.stringify(cli.stop.v_m_s));
  const lines = (await page.textContent('#command')).split('\n').filter((l) => l.startsWith('snowroll '));
  check(lines.length === 3 && lines.every((l) => l.includes('--alpha-deg ' + alpha)), name + ': the command lines shown hold the new alpha', lines.join('\n'));
  for (const [label, line] of [['torque-cm', lines[0]], ['turns', lines[2]]]) {
    const argv = words(line).slice(1);
    for (const format of ['csv', 'json']) {
      const got = await download(page, label, format);
      const want = runCli(format === 'csv' ? argv : argv.concat(['--format', 'json']));
      check(got.equals(want), name + ': the downloaded ' + format.toUpperCase() + ' of ' + label + ' (' + got.length + ' bytes) is what `' + line + (format === 'json' ? ' --format json' : '') + '` writes',
        'first difference at byte ' + [...got].findIndex((b, i) => b !== want[i]));
    }
  }
  const figs = await page.$$eval('#plots figure', (fs) => fs.map((f) => ({ caption: f.querySelector('figcaption').textContent, legend: f.querySelectorAll('.legend span').length })));
  check(figs.length === 5 && figs.every((f) => f.legend === 3 && /\(|F\/N/.test(f.caption)), name + ': five plots, each with a legend entry per run and units in its caption', JSON.stringify(figs));
  const link = await page.getAttribute('#permalink', 'href');
  check(link.includes('alpha_deg=' + alpha), name + ': the permalink holds alpha_deg=' + alpha, link);
  const reopened = await openPage(browser, new URL(link, page.url()).href, 1400, 1000);
  const v2 = await reopened.page.textContent('#readout tr[data-run="torque-cm"] td.v');
  check(v2 === v1, name + ': the permalink opens the same scenario (v = ' + v2 + ')');
  problems.push(...reopened.problems);
  await reopened.context.close();
  check(problems.length === 0, name + ': nothing written to the console', problems.join('\n'));
  await context.close();
}

// The readout's rows: {run: {stop, v, a}}.
async function readoutRows(page) {
  return page.$$eval('#readout tbody tr', (trs) => Object.fromEntries(trs.map((tr) => {
    const td = tr.querySelectorAll('td');
    return [tr.dataset.run, tr.querySelector('td.err') ? { error: td[1].textContent } :
      { stop: td[1].textContent, v: td[4].textContent, a: td[5].textContent }];
  })));
}

async function formValues(page, keys) {
  return page.evaluate((ks) => Object.fromEntries(ks.map((k) => [k, document.getElementById('in-' + k).value])), keys);
}

// The command line the page shows for a circular model's run.
async function shownLine(page, model) {
  return (await page.textContent('#command')).split('\n').find((l) => l.startsWith('snowroll simulate --model ' + model + ' ')) || '(none shown)';
}

// The stop that a command line as shown writes (its error, if it fails).
function cliStop(line) {
  try {
    return JSON.parse(runCli(words(line).slice(1).concat(['--format', 'json'])).toString()).stop;
  } catch (e) {
    return { error: String(e.stderr || e).trim() };
  }
}

const ticked = (page) => page.$$eval('#models input:checked', (cs) => cs.map((c) => c.value));

// The choice of body: the unwinding roll fills the form with a roll of
// paper on a level floor, the energy balances unwind it to its core and the
// torque balances do not start it; the permalink reopens it; the log again
// restores the log's defaults.
async function checkBodies(browser, base, name) {
  const { context, page, problems } = await openPage(browser, base + '?models=torque-cm,loney,turns', 1400, 1000);
  let before = await page.evaluate(() => document.documentElement.dataset.refreshed);
  await page.selectOption('#body-choice', 'roll');
  await refreshedAfter(page, before);
  const keys = ['alpha_deg', 'snow_depth', 'r0', 'core_radius', 'core_mass', 'g', 'density', 'length'];
  const form = await formValues(page, keys);
  const [alpha, b, r0, core, mc, g, rho, len] = keys.map((k) => Number(form[k]));
  // A tube of a few grams (a toilet roll's: 2 to 10 g), under about 100 g of tissue.
  check(alpha === 0 && b < 0 && core > 0 && core < r0 && mc >= 0.002 && mc <= 0.01,
    name + ': the unwinding roll fills the form: a level floor, a negative snow depth, 0 < core_radius < r0, a tube of a few grams', JSON.stringify(form));
  const models = await ticked(page);
  check(['energy-thin', 'energy', 'torque-cm', 'quasi-circular'].every((m) => models.includes(m)) && !models.some((m) => m.startsWith('turns')),
    name + ': the roll ticks energy-thin, energy, torque-cm and quasi-circular, and no turn model (' + models.join(',') + ')');
  const note = await page.textContent('#body-note');
  check(/lays its paper down/.test(note) && /unwinding roll/.test(note) && !/docs\//.test(note), name + ': the page says what the roll is: "' + note + '"');
  const rows = await readoutRows(page);
  const status = await page.getAttribute('#status', 'class');
  check(Object.values(rows).every((r) => !r.error) && status !== 'error', name + ': every run of the roll runs without error', JSON.stringify(rows));
  const stops = Object.fromEntries(Object.entries(rows).map(([k, r]) => [k, r.stop]));
  check(stops['energy-thin'] === 'unwound' && stops.energy === 'unwound', name + ': the energy balances unwind it to its core on the level floor (stop unwound)', JSON.stringify(stops));
  check(stops['torque-cm'] === 'does-not-start' && stops['quasi-circular'] === 'does-not-start',
    name + ': the torque balance and eq. (32) do not start it on the level floor (stop does-not-start)', JSON.stringify(stops));
  check(Object.values(rows).every((r) => r.a && /m\/s²/.test(r.a) && !/NaN|Infinity/.test(r.a)), name + ': on the level floor the readout gives a in m/s^2',
    JSON.stringify(rows));
  // Eq. (15) reversed on a level floor conserves the energy: from rest at
  // R, v^2 = 2 g (M(R) R - M(r) r)/(M(r) + I(r)/r^2) at r = core_radius
  // (docs/unwinding.md, "The core"), with the hollow roll on its thin tube
  // of mass m_c typed here from its definition: M = m_c + pi rho l (r^2 -
  // r_c^2), I = m_c r_c^2 + (pi rho l/2)(r^4 - r_c^4). Independent of b.
  // The run's rtol is 1e-10, the library's own test holds it to 1e-9; 1e-7
  // leaves room for the stop's root-finding. (A uniform roll, the
  // textbook's 4g(R^3 - r^3)/(3r^2), would be 2.61 m/s here, not 3.90.)
  const vText = rows['energy-thin'].v;
  const k = Math.PI * rho * len;
  const M = (r) => mc + k * (r ** 2 - core ** 2), I = (r) => mc * core ** 2 + (k / 2) * (r ** 4 - core ** 4);
  const want = Math.sqrt(2 * g * (M(r0) * r0 - M(core) * core) / (M(core) + I(core) / core ** 2));
  check(Math.abs(Number(vText) / want - 1) < 1e-7, name + ': energy-thin ends at the energy integral\'s v = sqrt(2g(M(R)R - M(r)r)/(M + I/r^2)) = ' +
    want.toPrecision(10) + ' m/s at the tube (page ' + vText + ')');
  const line = await shownLine(page, 'energy-thin');
  const stop = cliStop(line);
  check(stop.reason === 'unwound' && vText === String(stop.v_m_s), name + ': the command line shown for energy-thin writes the same stop (' + line + ')',
    'page ' + vText + ', CLI ' + JSON.stringify(stop));

  // The permalink reopens the roll, its race drawn at its end: the paper
  // laid behind the rolls that unwound, none on the lanes that did not start.
  const link = await page.getAttribute('#permalink', 'href');
  check(/[?&]body=roll(&|$)/.test(link), name + ': the permalink records the body', link);
  const reopened = await openPage(browser, new URL(link, page.url()).href + '#end', 1400, 1000);
  const rp = reopened.page;
  const again = await readoutRows(rp);
  check(await rp.inputValue('#body-choice') === 'roll' && JSON.stringify(await formValues(rp, Object.keys(form))) === JSON.stringify(form) &&
    JSON.stringify(again) === JSON.stringify(rows), name + ': the permalink reopens the unwinding roll (the body, the form, the readout)', JSON.stringify(again));
  await rp.waitForSelector('#race[data-done="1"]', { timeout: 20000 });
  const paper = await rp.evaluate(() => {
    const c = document.getElementById('race');
    const { LANE, MARGIN, TOP, PAPER, labelRoom } = Race.layout;
    const w = c.clientWidth, ratio = c.width / w;
    const length = w - 2 * MARGIN - labelRoom(w);
    const lanes = state.runs.filter((r) => !r.error).map((r) => r.label);
    // The alpha of the pixel halfway along each lane, in the paper's strip
    // (PAPER px thick on the lane's line), above the line itself (at most
    // 2 px wide). One read of the whole canvas.
    const img = c.getContext('2d').getImageData(0, 0, c.width, c.height);
    return Object.fromEntries(lanes.map((label, k) => {
      const x = Math.floor(ratio * (MARGIN + 0.5 * length)), y = Math.floor(ratio * (TOP + (k + 1) * LANE - PAPER + 0.5));
      return [label, img.data[4 * (y * c.width + x) + 3]];
    }));
  });
  check(paper['energy-thin'] > 0 && paper.energy > 0 && paper['torque-cm'] === 0 && paper['quasi-circular'] === 0,
    name + ': the race lays the paper on the ground behind the rolls that unwound, not on the lanes that did not start', JSON.stringify(paper));
  problems.push(...reopened.problems);
  await reopened.context.close();

  // A value the roll sets, set back to the table's default by hand, is
  // still in the permalink (the roll's own default would come back).
  before = await page.evaluate(() => document.documentElement.dataset.refreshed);
  await page.fill('#in-alpha_deg', '30');
  await refreshedAfter(page, before);
  const link30 = await page.getAttribute('#permalink', 'href');
  const r30 = await openPage(browser, new URL(link30, page.url()).href, 1400, 1000);
  check(await r30.page.inputValue('#in-alpha_deg') === '30', name + ': the roll on a 30 degree board reopens at 30 degrees', link30);
  problems.push(...r30.problems);
  await r30.context.close();

  // A thinner paper typed as the slider writes small numbers (-3e-4): the
  // command line shown runs as it is (`--snow-depth=-3e-4`, not a flag of
  // its own) and writes the page's stop.
  before = await page.evaluate(() => document.documentElement.dataset.refreshed);
  await page.fill('#in-snow_depth', '-3e-4');
  await refreshedAfter(page, before);
  const thin = (await readoutRows(page))['energy-thin'];
  const thinLine = await shownLine(page, 'energy-thin');
  const thinCli = cliStop(thinLine);
  check(thin.v === String(thinCli.v_m_s), name + ': with snow_depth = -3e-4 the command line shown runs and writes the page\'s stop (' + thinLine + ')',
    'page ' + JSON.stringify(thin) + ', CLI ' + JSON.stringify(thinCli));

  // The log again: its defaults back.
  before = await page.evaluate(() => document.documentElement.dataset.refreshed);
  await page.selectOption('#body-choice', 'log');
  await refreshedAfter(page, before);
  const table = await page.evaluate(() => Object.fromEntries(state.params.map((p) => [p.key, p.default === null ? '' : p.default_text])));
  const logForm = await formValues(page, keys);
  const v = (await readoutRows(page))['torque-cm'].v;
  const cliLog = JSON.parse(runCli(['simulate', '--model', 'torque-cm', '--format', 'json']).toString());
  check(Object.keys(logForm).every((k) => logForm[k] === table[k]) && (await ticked(page)).join(',') === 'torque-cm,loney,turns' &&
    v === String(cliLog.stop.v_m_s), name + ': choosing the log again restores its defaults (the form, the models, and torque-cm\'s v = the CLI\'s ' + v + ')',
  JSON.stringify(logForm));
  // The ball: a sphere, no turn model.
  before = await page.evaluate(() => document.documentElement.dataset.refreshed);
  await page.selectOption('#body-choice', 'ball');
  await refreshedAfter(page, before);
  const ball = await readoutRows(page);
  check(await page.inputValue('#in-shape') === 'sphere' && !(await ticked(page)).some((m) => m.startsWith('turns')) && Object.values(ball).every((r) => !r.error),
    name + ': the snowball: shape sphere, no turn model, every run without error', JSON.stringify(ball));
  check(problems.length === 0, name + ': nothing written to the console (bodies)', problems.join('\n'));
  await context.close();
}

// At a phone's width: no sideways scrolling; race and readout first.
async function checkPhone(browser, base, name, shot) {
  const { context, page, problems } = await openPage(browser, base + '?models=torque-cm,loney,turns&alpha_deg=65' + (shot ? '#end' : ''), 400, 900);
  const m = await page.evaluate(() => ({
    scroll: document.documentElement.scrollWidth, client: document.documentElement.clientWidth,
    race: document.getElementById('race').getBoundingClientRect().top,
    readout: document.getElementById('readout').getBoundingClientRect().top,
    controls: document.getElementById('controls').getBoundingClientRect().top,
    open: document.getElementById('panel').open,
  }));
  check(m.scroll <= m.client, name + ': at 400 px no horizontal overflow (scroll width ' + m.scroll + ', view ' + m.client + ')');
  check(m.race < m.controls && m.readout < m.controls && !m.open, name + ': at 400 px the race and the readout come before the parameters, which are folded', JSON.stringify(m));
  await page.click('#panel > summary');
  const open = await page.evaluate(() => ({ scroll: document.documentElement.scrollWidth, client: document.documentElement.clientWidth }));
  check(open.scroll <= open.client, name + ': at 400 px the opened parameters do not overflow either (' + open.scroll + ')');
  await page.click('#panel > summary');
  if (shot) {
    await page.evaluate(() => window.scrollTo(0, 0));
    await page.waitForSelector('#race[data-done="1"]', { timeout: 20000 });
    await page.screenshot({ path: shot, fullPage: false });
  }
  check(problems.length === 0, name + ': nothing written to the console at 400 px', problems.join('\n'));
  await context.close();
  // The unwinding roll (its longer line on the page, its form): no sideways
  // scrolling either, folded or open.
  const roll = await openPage(browser, base + '?body=roll', 400, 900);
  const widths = [];
  for (let i = 0; i < 2; i++) {
    widths.push(await roll.page.evaluate(() => document.documentElement.scrollWidth - document.documentElement.clientWidth));
    await roll.page.click('#panel > summary');
  }
  check(widths.every((d) => d <= 0) && roll.problems.length === 0, name + ': at 400 px the unwinding roll does not overflow, folded or open (' + widths.join(', ') + ' px over)',
    roll.problems.join('\n'));
  await roll.context.close();
}

async function desktopShot(browser, base, shot) {
  // #end: the race drawn at its end at once (it plays for up to 8 s).
  const { context, page } = await openPage(browser, base + '?models=torque-cm,loney,turns&ball=1&alpha_deg=65#end', 1400, 1500);
  await page.waitForSelector('#race[data-done="1"]', { timeout: 20000 });
  await page.screenshot({ path: shot, fullPage: false });
  await context.close();
  // The unwinding roll on its level floor, at its end.
  const roll = await openPage(browser, base + '?body=roll#end', 1400, 900);
  await roll.page.waitForSelector('#race[data-done="1"]', { timeout: 20000 });
  await roll.page.screenshot({ path: path.join(path.dirname(shot), 'explorer-roll.png'), fullPage: false });
  await roll.context.close();
}

// A 10^5-turn run: in the worker, a progress line, frames keep coming.
async function checkLongRun(browser, base, name) {
  const { context, page, problems } = await openPage(browser, base + '?models=torque-cm', 1400, 1000);
  await page.evaluate(() => {
    window.__gaps = [];
    let last = performance.now();
    // Frames while the run computes (the progress line shown): a run on the
    // main thread would stop them for its whole time (about a second).
    const tick = (now) => {
      if (!document.getElementById('progress').hidden) window.__gaps.push(now - last);
      last = now;
      window.__raf = requestAnimationFrame(tick);
    };
    window.__raf = requestAnimationFrame(tick);
  });
  const before = await page.evaluate(() => document.documentElement.dataset.refreshed);
  // The turn model, 10^5 turns, no end time in the way (as a hand would set them).
  await page.fill('#in-t_end', '1e9');
  await page.fill('#in-turns', '100000');
  await page.check('#models input[value="turns"]');
  await page.waitForSelector('#progress:not([hidden])', { timeout: 30000 });
  const line = await page.textContent('#progress span');
  check(/turns: \d+% of 100000 turns/.test(line), name + ': a progress line while 10^5 turns run: "' + line + '"');
  await refreshedAfter(page, before);
  const stop = await page.textContent('#readout tr[data-run="turns"] td:nth-child(2)');
  const gaps = await page.evaluate(() => { cancelAnimationFrame(window.__raf); return window.__gaps; });
  const worst = Math.max(...gaps);
  check(stop === 'turns', name + ': the 10^5-turn run completed its turns (stop: ' + stop + ')');
  check(gaps.length >= 5 && worst < 500, name + ': the page kept drawing frames while it ran (' + gaps.length + ' frames, longest gap ' + worst.toFixed(0) + ' ms)');
  const status = await page.textContent('#status');
  console.log('     ' + status);
  check(problems.length === 0, name + ': nothing written to the console (long run)', problems.join('\n'));
  await context.close();
}

// The time from a slider's input event to the redrawn page, per move.
async function bench(browser, base) {
  const out = {};
  for (const models of ['torque-cm,loney', 'turns', 'torque-cm,loney,turns']) {
    const { context, page } = await openPage(browser, base + '?models=' + models, 1400, 1000);
    const times = [], compute = [], draw = [];
    for (let i = 0; i < 16; i++) {
      await page.evaluate(() => performance.clearMeasures('snowroll-update'));
      // Every move far from the thumb (a click on the thumb moves nothing):
      // to and fro between about 14 and 77 degrees.
      await moveSlider(page, 'alpha_deg', i % 2 ? 0.85 - 0.01 * i : 0.15 + 0.01 * i);
      const m = await page.evaluate(() => {
        const e = performance.getEntriesByName('snowroll-update');
        return { total: e.length ? e[e.length - 1].duration : NaN, timing: state.timing };
      });
      if (i === 0) continue; // the first move warms the page up
      times.push(m.total); compute.push(m.timing.compute_ms); draw.push(m.timing.draw_ms);
    }
    const stat = (a) => { const s = [...a].sort((x, y) => x - y); return { median: s[Math.floor(s.length / 2)], max: s[s.length - 1] }; };
    out[models] = { moves: times.length, input_to_drawn_ms: stat(times), compute_ms: stat(compute), draw_ms: stat(draw) };
    console.log('bench ' + models + ': ' + JSON.stringify(out[models]));
    await context.close();
  }
  return out;
}

async function withServer(fn) {
  const child = spawn(args.cli, ['serve', '--port', '0'], { stdio: ['ignore', 'pipe', 'pipe'] });
  try {
    const url = await new Promise((resolve, reject) => {
      let text = '';
      const timer = setTimeout(() => reject(new Error('the server printed no address')), 20000);
      child.stdout.on('data', (d) => { text += d; const m = /http:\/\/\S+/.exec(text); if (m) { clearTimeout(timer); resolve(m[0]); } });
      child.on('exit', (c) => reject(new Error('the server exited with ' + c)));
    });
    return await fn(url);
  } finally {
    child.kill('SIGINT');
  }
}

(async () => {
  // playwright-core starts it with a fresh, empty profile of its own.
  const browser = await chromium.launch({
    executablePath: args.chromium,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync'],
    headless: true,
  });
  try {
    const file = 'file://' + path.resolve(args.page);
    if (args.bench) {
      const result = { chromium: browser.version(), page: path.basename(args.page), file: await bench(browser, file) };
      fs.writeFileSync(args.bench, JSON.stringify(result, null, 2) + '\n');
      return;
    }
    await checkPage(browser, file, 'file://');
    await checkBodies(browser, file, 'file://');
    await checkPhone(browser, file, 'file://', args.shots && path.join(args.shots, 'explorer-phone.png'));
    await checkLongRun(browser, file, 'file://');
    if (args.shots) await desktopShot(browser, file, path.join(args.shots, 'explorer.png'));
    if (args.serve) {
      await withServer(async (url) => {
        await checkPage(browser, url, 'snowroll serve');
        await checkBodies(browser, url, 'snowroll serve');
        await checkPhone(browser, url, 'snowroll serve');
        // The form's table: the same from the server as from the module.
        const ctx = await browser.newContext();
        const p = await ctx.newPage();
        await p.goto(file);
        await p.waitForSelector('html[data-refreshed]');
        const mine = await p.evaluate(() => Engine.params());
        const theirs = JSON.parse(await (await fetch(url + 'api/params')).text());
        check(JSON.stringify(mine.params) === JSON.stringify(theirs.params) && JSON.stringify(mine.models) === JSON.stringify(theirs.models),
          'the parameter table and the models: the module\'s the same as the server\'s /api/params');
        await ctx.close();
      });
    }
  } finally {
    await browser.close();
  }
  console.log(failures ? 'explorer-browser-test: ' + failures + ' FAILED' : 'explorer-browser-test: passed');
  process.exit(failures ? 1 : 0);
})().catch((e) => { console.error('explorer-browser-test: FAIL: ' + (e.stack || e)); process.exit(1); });
