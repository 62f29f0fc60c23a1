// The report's layout in a real browser (headless Chromium, driven by
// playwright-core over the DevTools protocol), at a desktop's and two
// phones' widths.
//
//   node .ci/browser/report-layout.js --chromium BIN --page REPORT.html [--shots DIR] [--measure]
//
// At 1400, 400 and 360 px wide (a viewport of that width, as a phone has):
//   - the page does not scroll sideways (document scrollWidth ≤ innerWidth);
//   - every element lies inside the viewport's width (its bounding box's
//     left ≥ 0 and right ≤ innerWidth), figures (img, svg, canvas) above all;
//     elements inside a closed <details> are not laid out and not counted;
//   - the page's height is at most 15,000 px at 1400 px and 25,000 px at
//     the phones' widths, with every <details> as the page opens it;
//   - the first screen (the viewport's height from the top: 900 px at
//     1400 px, 800 px at the phones) holds the abstract's five headline
//     results, each a link to its claim's row, and the scenario (α, b, r0);
//   - every figure's legend lies below its plot area at the phones' widths
//     or inside it at 1400 px, and no figure text is smaller than 9 px;
//   - nothing is written to the console and no script error is raised.
// --shots DIR writes browser-report.png (1400 px) and
// browser-report-phone.png (400 px): the first screen of each. --measure prints the heights and the tallest
// sections and checks nothing.
'use strict';
const path = require('path');

const args = {};
for (let i = 2; i < process.argv.length; i++) {
  const k = process.argv[i].replace(/^--/, '');
  const next = process.argv[i + 1];
  if (next !== undefined && !next.startsWith('--')) { args[k] = next; i++; } else args[k] = true;
}
for (const k of ['chromium', 'page']) if (!args[k]) { console.error('missing --' + k); process.exit(2); }
const { chromium } = require(process.env.PLAYWRIGHT_CORE || 'playwright-core');

let failures = 0;
function check(ok, what, detail) {
  console.log((ok ? 'ok   ' : 'FAIL ') + what + (ok || detail === undefined ? '' : '\n     ' + detail));
  if (!ok) failures++;
  return ok;
}

// Widths (px), the first screen's height there, and the page's height limit.
const SCREENS = [
  { width: 1400, height: 900, limit: 15000, shot: 'browser-report.png' },
  { width: 400, height: 800, limit: 25000, shot: 'browser-report-phone.png' },
  { width: 360, height: 740, limit: 25000 },
];
// The smallest readable figure text on screen, px.
const MIN_FONT_PX = 9;

// Everything the checks need, read in the page.
function measure() {
  const d = document.documentElement;
  const w = window.innerWidth;
  const visible = (e) => {
    for (let p = e.parentElement; p; p = p.parentElement) {
      if (p.tagName === 'DETAILS' && !p.open && e.parentElement !== p) {
        // Only the summary of a closed <details> is shown.
        const s = p.querySelector(':scope > summary');
        if (!s || !s.contains(e)) return false;
      }
    }
    const r = e.getBoundingClientRect();
    return r.width > 0 || r.height > 0;
  };
  const name = (e) => {
    const owner = e.closest('[id]');
    return e.tagName.toLowerCase() + (e.className && typeof e.className === 'string' ? '.' + e.className.split(' ')[0] : '')
      + (owner ? ' in #' + owner.id : '');
  };
  const wide = [];
  const figures = [];
  document.querySelectorAll('body *').forEach((e) => {
    if (e.closest('svg') && e.tagName.toLowerCase() !== 'svg') return;
    if (!visible(e)) return;
    const r = e.getBoundingClientRect();
    const isFigure = /^(img|svg|canvas)$/i.test(e.tagName);
    if (isFigure) figures.push({ name: name(e), left: r.left, right: r.right, width: r.width });
    if (r.left < -0.5 || r.right > w + 0.5) wide.push(name(e) + ' [' + Math.round(r.left) + ', ' + Math.round(r.right) + ']');
  });
  // Each chart's legend: below its plot area (the legend box's top at or
  // under the plot frame's bottom) or inside it; and its smallest text.
  const legends = [];
  let fontMin = 1e9, fontAt = '';
  document.querySelectorAll('figure.figure svg').forEach((svg) => {
    const fig = svg.closest('figure').id;
    svg.querySelectorAll('text').forEach((t) => {
      const r = t.getBoundingClientRect();
      const m = t.getScreenCTM();
      const f = parseFloat(t.getAttribute('font-size') || window.getComputedStyle(t).fontSize || '0');
      if (m && f > 0 && t.textContent.trim() && r.width > 0) {
        const px = f * Math.sqrt(m.a * m.a + m.b * m.b);
        if (px < fontMin) { fontMin = px; fontAt = fig + ' "' + t.textContent.trim().slice(0, 20) + '"'; }
      }
    });
    const g = svg.querySelector('g.legend');
    if (!g || !visible(svg)) return;
    const b = g.getBoundingClientRect();
    const s = svg.getBoundingClientRect();
    // The plot's lowest text (the x axis's title) is above the legend's box.
    let plotBottom = s.top;
    svg.querySelectorAll('text').forEach((t) => {
      if (!g.contains(t)) plotBottom = Math.max(plotBottom, t.getBoundingClientRect().bottom);
    });
    legends.push({ fig, below: b.top >= plotBottom - 0.5, left: b.left, right: b.right, svgRight: s.right });
  });
  // The first screen: the links of the abstract that lie above the fold.
  const fold = window.innerHeight;
  const abstractLinks = [...document.querySelectorAll('#abstract a[href^="#claim-"]')]
    .filter((a) => a.getBoundingClientRect().bottom <= fold + window.scrollY)
    .map((a) => a.getAttribute('href').slice(1))
    .filter((id) => document.getElementById(id));
  const scenario = document.querySelector('#scenario');
  const scenarioText = scenario && scenario.getBoundingClientRect().bottom <= fold ? scenario.textContent : '';
  const sections = [...document.querySelectorAll('body > main > section, body > header')].map((s) => ({
    id: s.id || s.tagName.toLowerCase(), height: Math.round(s.getBoundingClientRect().height),
  })).sort((a, b) => b.height - a.height);
  return {
    innerWidth: w, scrollWidth: d.scrollWidth, height: d.scrollHeight, wide, figures, legends,
    fontMin, fontAt, abstractLinks, scenarioText, sections,
    jsErrors: d.getAttribute('data-js-errors'),
  };
}

async function atWidth(browser, url, screen) {
  const context = await browser.newContext({ viewport: { width: screen.width, height: screen.height } });
  const page = await context.newPage();
  const problems = [];
  page.on('console', (m) => problems.push('console ' + m.type() + ': ' + m.text()));
  page.on('pageerror', (e) => problems.push('script error: ' + e.message));
  await page.goto(url, { waitUntil: 'load' });
  await page.waitForTimeout(300);
  const m = await page.evaluate(measure);
  const where = 'at ' + screen.width + ' px';
  if (args.measure) {
    console.log(where + ': height ' + m.height + ' px, scrollWidth ' + m.scrollWidth + ' / ' + m.innerWidth
      + '; tallest: ' + m.sections.slice(0, 8).map((s) => s.id + ' ' + s.height).join(', ')
      + '; too wide: ' + m.wide.length + ' ' + m.wide.slice(0, 6).join('; '));
  } else {
    check(problems.length === 0 && !m.jsErrors, where + ': no console message or script error', problems.slice(0, 3).join('; '));
    check(m.scrollWidth <= m.innerWidth, where + ': the page does not scroll sideways (scrollWidth '
      + m.scrollWidth + ' ≤ innerWidth ' + m.innerWidth + ')');
    const outside = m.figures.filter((f) => f.left < -0.5 || f.right > m.innerWidth + 0.5);
    check(m.figures.length > 10 && outside.length === 0, where + ': every figure (' + m.figures.length
      + ' img/svg/canvas) lies inside the viewport\'s width', outside.slice(0, 5).map((f) => f.name + ' right ' + Math.round(f.right)).join('; '));
    check(m.wide.length === 0, where + ': no element is wider than the screen', m.wide.slice(0, 8).join('; '));
    check(m.height <= screen.limit, where + ': the page is ' + m.height + ' px tall (at most ' + screen.limit + ')');
    const phone = screen.width < 1000;
    const misplaced = m.legends.filter((l) => (phone && !l.below) || l.right > m.innerWidth + 0.5);
    check(m.legends.length > 10 && misplaced.length === 0, where + ': every chart\'s legend ('
      + m.legends.length + ') lies ' + (phone ? 'below its plot' : 'on the figure') + ' and inside the screen',
      misplaced.slice(0, 5).map((l) => l.fig).join(', '));
    check(m.fontMin >= MIN_FONT_PX, where + ': figure text at least ' + MIN_FONT_PX + ' px as rendered (smallest '
      + m.fontMin.toFixed(1) + ' px, ' + m.fontAt + ')');
    const uniq = new Set(m.abstractLinks);
    check(uniq.size === 5, where + ': the first screen holds the abstract\'s five results, each linked to its claim ('
      + [...uniq].join(', ') + ')');
    check(/α = [0-9]/.test(m.scenarioText) && /b = [0-9]/.test(m.scenarioText) && /r0 = [0-9]/.test(m.scenarioText),
      where + ': the first screen states the scenario (α, b, r0)', JSON.stringify(m.scenarioText.slice(0, 200)));
    console.log('     height at ' + screen.width + ' px: ' + m.height + ' px');
  }
  if (args.shots && screen.shot) {
    await page.screenshot({ path: path.join(args.shots, screen.shot) });
  }
  await context.close();
}

(async () => {
  const browser = await chromium.launch({
    executablePath: args.chromium,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--host-resolver-rules=MAP * ~NOTFOUND'],
    headless: true,
  });
  try {
    const url = 'file://' + path.resolve(args.page);
    for (const screen of SCREENS) await atWidth(browser, url, screen);
  } finally {
    await browser.close();
  }
  if (args.measure) process.exit(0);
  console.log(failures ? 'report-layout: ' + failures + ' FAILED' : 'report-layout: passed');
  process.exit(failures ? 1 : 0);
})().catch((e) => { console.error('report-layout: FAIL: ' + (e.stack || e)); process.exit(1); });
