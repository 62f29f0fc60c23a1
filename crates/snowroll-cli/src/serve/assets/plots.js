// The plots: each quantity of the runs against t, drawn on canvases with a
// legend and units. Only drawing: every number is one the library computed
// (a is shown over g sin α, the scale the library sends with each run, or
// in m/s² on a level floor, where g sin α = 0).
// A turn model is drawn from its turn table (`snowroll turns`): the mean a
// of each turn with the turn's range as a light band, v and x at the turns'
// ends, the least N and the largest F/N of each turn. A run that stopped on
// a hop, a slip or a stall has its event marked; the N and F/N axes keep the
// range of the run before the event (N reaches 0 and F/N grows without
// bound there), the points beyond it marked off scale.
'use strict';

const Plots = (function () {
  // Each run's line: solid for the first, then dashes, so that curves that
  // coincide (eq. (4) and Loney's fn. 4) are both seen.
  const DASHES = [[], [8, 5], [2, 5], [10, 4, 2, 4], [4, 6], [1, 4]];
  const MARKS = { hop: 'hop', slip: 'slip', stalled: 'stall', 'does-not-start': 'does not start', stuck: 'stuck' };
  const MAX_POINTS = 2000;

  // What each panel shows: for a trajectory (sim) and for a turn table.
  const SPECS = [
    { id: 'a', title: 'acceleration over g sin α', y: 'a/(g sin α)',
      sim: (c, g) => ({ x: c.t_s, y: scale(c.a_m_s2, 1 / g) }),
      table: (c, g) => ({ x: mid(c), y: scale(c.mean_a_turn_m_s2, 1 / g), lo: scale(c.min_a_m_s2, 1 / g), hi: scale(c.max_a_m_s2, 1 / g) }),
      tableNote: 'mean of each turn, its range shaded' },
    { id: 'v', title: 'speed', y: 'v (m/s)',
      sim: (c) => ({ x: c.t_s, y: c.v_m_s }),
      table: (c) => ends(c, 'v_start_m_s', 'v_end_m_s', 'v_after_m_s'),
      tableNote: 'at the turns\' ends, the collision\'s drop a step' },
    { id: 'x', title: 'distance down the slope', y: 'x (m)',
      sim: (c) => ({ x: c.t_s, y: c.x_m }),
      table: (c) => ({ x: c.t_start_s, y: c.x_start_m }),
      tableNote: 'at each turn\'s start' },
    { id: 'n', title: 'normal force', y: 'N (N)', cut: true,
      sim: (c) => c.normal_n && { x: c.t_s, y: c.normal_n },
      table: (c) => ({ x: mid(c), y: c.min_normal_n }),
      tableNote: 'least N of each turn' },
    { id: 'fn', title: 'friction over normal force', y: 'F/N', cut: true,
      sim: (c) => c.friction_ratio && { x: c.t_s, y: c.friction_ratio },
      table: (c) => ({ x: mid(c), y: c.max_friction_ratio }),
      tableNote: 'largest F/N of each turn' },
  ];

  function scale(a, k) {
    if (!a) return null;
    const out = new Float64Array(a.length);
    for (let i = 0; i < a.length; i++) out[i] = a[i] * k;
    return out;
  }
  function mid(c) {
    const out = new Float64Array(c.t_start_s.length);
    for (let i = 0; i < out.length; i++) out[i] = 0.5 * (c.t_start_s[i] + c.t_end_s[i]);
    return out;
  }
  // v at each turn's start and end, and after its collision.
  function ends(c, start, end, after) {
    const n = c[start].length;
    const xs = new Float64Array(2 * n + 1), ys = new Float64Array(2 * n + 1);
    if (n > 0) { xs[0] = c.t_start_s[0]; ys[0] = c[start][0]; }
    for (let i = 0; i < n; i++) {
      xs[2 * i + 1] = xs[2 * i + 2] = c.t_end_s[i];
      ys[2 * i + 1] = c[end][i];
      ys[2 * i + 2] = c[after][i];
    }
    return { x: n > 0 ? xs : xs.subarray(0, 0), y: n > 0 ? ys : ys.subarray(0, 0) };
  }

  // Round tick steps (1, 2, 5 × 10^k) over [lo, hi].
  function ticks(lo, hi) {
    const span = hi - lo || Math.abs(hi) || 1;
    const raw = span / 5;
    const mag = Math.pow(10, Math.floor(Math.log10(raw)));
    const step = [1, 2, 5, 10].map((m) => m * mag).find((s) => s >= raw);
    const out = [];
    for (let t = Math.ceil(lo / step) * step; t <= hi + step * 1e-9; t += step) out.push(Math.abs(t) < step * 1e-9 ? 0 : t);
    return out;
  }

  function label(x) {
    const a = Math.abs(x);
    return a !== 0 && (a < 1e-3 || a >= 1e5) ? x.toExponential(1) : String(Number(x.toPrecision(4)));
  }

  // Every `stride`-th index and the last, at most MAX_POINTS.
  function thin(n) {
    const stride = Math.max(1, Math.ceil(n / MAX_POINTS));
    const idx = [];
    for (let i = 0; i < n; i += stride) idx.push(i);
    if (n > 0 && idx[idx.length - 1] !== n - 1) idx.push(n - 1);
    return idx;
  }

  // The event a run stopped on (or, going on through a hop, its first hop).
  function eventOf(run) {
    const mark = MARKS[run.stop.reason];
    if (mark) return { t: run.stop.t_s, label: mark };
    if (run.firstHop) return { t: run.firstHop.t, label: 'hop' };
    return null;
  }

  // Draws `series` ({xs, ys, lo, hi, color, dash, event, t0}) on `canvas`.
  function plot(canvas, series, spec) {
    const ratio = window.devicePixelRatio || 1;
    const w = canvas.clientWidth || 420, h = canvas.clientHeight || 260;
    canvas.width = Math.round(w * ratio);
    canvas.height = Math.round(h * ratio);
    const ctx = canvas.getContext('2d');
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, w, h);
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity, cutAny = false;
    for (const s of series) {
      // The N and F/N axes: the run's range up to 80% of the time to its event.
      const cut = spec.cut && s.event ? s.t0 + 0.8 * (s.event.t - s.t0) : Infinity;
      for (let i = 0; i < s.xs.length; i++) {
        const x = s.xs[i];
        if (!Number.isFinite(x)) continue;
        if (x < x0) x0 = x;
        if (x > x1) x1 = x;
        if (x > cut && i > 0) { cutAny = true; continue; }
        const y = s.ys[i], lo = s.lo ? s.lo[i] : y, hi = s.hi ? s.hi[i] : y;
        if (Number.isFinite(y)) { if (y < y0) y0 = y; if (y > y1) y1 = y; }
        if (Number.isFinite(lo) && lo < y0) y0 = lo;
        if (Number.isFinite(hi) && hi > y1) y1 = hi;
      }
    }
    if (!(x1 >= x0) || !(y1 >= y0)) return;
    if (x1 === x0) x1 = x0 + 1;
    if (y1 === y0) { y0 -= 0.5; y1 += 0.5; }
    const pad = (y1 - y0) * 0.06;
    y0 -= pad; y1 += pad;
    const L = 58, R = 12, T = 12, B = 36;
    const px = (x) => L + ((x - x0) / (x1 - x0)) * (w - L - R);
    const py = (y) => h - B - ((y - y0) / (y1 - y0)) * (h - T - B);
    ctx.font = '11px system-ui, sans-serif';
    ctx.strokeStyle = '#eaeef2';
    ctx.fillStyle = '#57606a';
    ctx.lineWidth = 1;
    for (const t of ticks(y0, y1)) {
      ctx.beginPath(); ctx.moveTo(L, py(t)); ctx.lineTo(w - R, py(t)); ctx.stroke();
      ctx.textAlign = 'right';
      ctx.fillText(label(t), L - 4, py(t) + 4);
    }
    ctx.textAlign = 'center';
    for (const t of ticks(x0, x1)) {
      ctx.beginPath(); ctx.moveTo(px(t), T); ctx.lineTo(px(t), h - B); ctx.stroke();
      ctx.fillText(label(t), px(t), h - B + 14);
    }
    // Axis titles, with units.
    ctx.fillStyle = '#1c2733';
    ctx.fillText('t (s)', L + (w - L - R) / 2, h - 4);
    ctx.save();
    ctx.translate(12, T + (h - T - B) / 2);
    ctx.rotate(-Math.PI / 2);
    ctx.fillText(spec.y, 0, 0);
    ctx.restore();
    ctx.textAlign = 'left';
    ctx.save();
    ctx.beginPath();
    ctx.rect(L, T, w - L - R, h - T - B);
    ctx.clip();
    for (const s of series) {
      if (s.lo && s.hi) {
        ctx.fillStyle = s.color;
        ctx.globalAlpha = 0.16;
        ctx.beginPath();
        const idx = thin(s.xs.length);
        idx.forEach((i, k) => (k ? ctx.lineTo(px(s.xs[i]), py(s.hi[i])) : ctx.moveTo(px(s.xs[i]), py(s.hi[i]))));
        for (let k = idx.length - 1; k >= 0; k--) ctx.lineTo(px(s.xs[idx[k]]), py(s.lo[idx[k]]));
        ctx.closePath();
        ctx.fill();
        ctx.globalAlpha = 1;
      }
    }
    series.forEach((s) => {
      // The solid line wide and a little light, the dashed ones over it.
      ctx.strokeStyle = s.color;
      ctx.globalAlpha = s.dash.length ? 1 : 0.7;
      ctx.lineWidth = s.dash.length ? 2.2 : 3.2;
      ctx.lineCap = 'round';
      ctx.setLineDash(s.dash);
      ctx.beginPath();
      let started = false;
      for (const i of thin(s.xs.length)) {
        const x = px(s.xs[i]), y = py(s.ys[i]);
        if (!Number.isFinite(y)) { started = false; continue; }
        if (started) ctx.lineTo(x, y); else { ctx.moveTo(x, y); started = true; }
      }
      ctx.stroke();
      ctx.setLineDash([]);
      ctx.globalAlpha = 1;
    });
    ctx.restore();
    // Events: a dashed red line at the time, its name, and a note when the
    // curve leaves the axis after it.
    ctx.font = '11px system-ui, sans-serif';
    for (const s of series) {
      if (!s.event) continue;
      const ex = px(s.event.t);
      ctx.strokeStyle = '#b42318';
      ctx.lineWidth = 1;
      ctx.setLineDash([3, 3]);
      ctx.beginPath(); ctx.moveTo(ex, T); ctx.lineTo(ex, h - B); ctx.stroke();
      ctx.setLineDash([]);
      ctx.fillStyle = '#b42318';
      const text = '✕ ' + s.event.label + (cutAny && spec.cut ? ' (off scale after)' : '');
      const tw = ctx.measureText(text).width;
      ctx.fillText(text, Math.max(L + 2, Math.min(ex - tw - 3, w - R - tw)), T + 11);
    }
  }

  // The legend of a panel: each run's line (its colour and dash) and name.
  function legend(el, series, notes) {
    el.innerHTML = '';
    for (const s of series) {
      const span = document.createElement('span');
      const dash = s.dash.join(' ');
      span.innerHTML = '<svg width="28" height="10" aria-hidden="true">' +
        (s.lo ? '<rect x="0" y="0" width="28" height="10" fill="' + s.color + '" fill-opacity="0.16"></rect>' : '') +
        '<line x1="0" y1="5" x2="28" y2="5" stroke="' + s.color + '" stroke-linecap="round" stroke-width="' + (s.dash.length ? 2.2 : 3.2) +
        '" stroke-dasharray="' + dash + '"></line></svg>';
      span.appendChild(document.createTextNode(s.label + (s.note ? ' (' + s.note + ')' : '')));
      el.appendChild(span);
    }
    if (notes) {
      const n = document.createElement('span');
      n.textContent = notes;
      el.appendChild(n);
    }
  }

  function figure(box, id, title) {
    let fig = box.querySelector('figure[data-plot="' + id + '"]');
    if (!fig) {
      fig = document.createElement('figure');
      fig.dataset.plot = id;
      fig.innerHTML = '<figcaption></figcaption><div class="legend"></div><canvas width="420" height="260"></canvas>';
      box.appendChild(fig);
    }
    fig.querySelector('figcaption').textContent = title;
    return fig;
  }

  // Draws every panel for `runs` ({label, color, index, kind, cols, stop,
  // g, firstHop}) into `box`.
  function drawAll(box, runs) {
    const ok = runs.filter((r) => !r.error && r.n > 0);
    const shown = new Set();
    // A level floor (the unwinding roll): a itself, in m/s².
    const level = ok.some((r) => !(r.g > 0));
    for (const plain of SPECS) {
      const spec = level && plain.id === 'a' ? Object.assign({}, plain, { title: 'acceleration (level floor)', y: 'a (m/s²)' }) : plain;
      const series = [];
      for (const r of ok) {
        const g = level ? 1 : r.g;
        const d = r.kind === 'table' ? spec.table(r.cols, g) : spec.sim(r.cols, g);
        if (!d || !d.y) continue;
        series.push({
          xs: d.x, ys: d.y, lo: d.lo, hi: d.hi, color: r.color, dash: DASHES[r.index % DASHES.length],
          label: r.label, note: r.kind === 'table' ? spec.tableNote : '', event: eventOf(r), t0: d.x[0],
        });
      }
      if (series.length === 0) continue;
      shown.add(spec.id);
      const fig = figure(box, spec.id, spec.title + ', ' + spec.y + ' against t (s)');
      legend(fig.querySelector('.legend'), series);
      plot(fig.querySelector('canvas'), series, spec);
    }
    for (const fig of [...box.querySelectorAll('figure')]) if (!shown.has(fig.dataset.plot)) fig.remove();
  }

  // A short hash of what the plots show (for the browser test).
  function signature(box) {
    let h = 0;
    for (const c of box.querySelectorAll('canvas')) {
      const s = c.toDataURL();
      for (let i = 0; i < s.length; i += 7) h = (h * 31 + s.charCodeAt(i)) | 0;
    }
    return String(h >>> 0);
  }

  return { drawAll, signature, MARKS, DASHES };
})();
