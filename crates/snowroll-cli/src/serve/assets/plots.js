// The plots: each quantity of the runs against t (and the per-turn means of
// the turn models against the turn), drawn on canvases. Only drawing: every
// number is one the server sent; a is shown over g sin α, the scale the
// server sends with each run (X-Snowroll-G-Along).
'use strict';

const Plots = (function () {
  const SPECS = [
    { id: 'a', title: 'a/(g sin α) against t (s)', need: 'a_m_s2', y: (s, r) => s.a_m_s2 / r.gAlong },
    { id: 'v', title: 'v (m/s) against t (s)', need: 'v_m_s', y: (s) => s.v_m_s },
    { id: 'x', title: 'x (m) against t (s)', need: 'x_m', y: (s) => s.x_m },
    { id: 'n', title: 'N (N) against t (s)', need: 'normal_n', y: (s) => s.normal_n },
    { id: 'fn', title: 'F/N against t (s)', need: 'friction_ratio', y: (s) => s.friction_ratio },
  ];
  const MAX_POINTS = 2000;

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

  // Every `stride`-th point and the last, at most MAX_POINTS.
  function thin(n) {
    const stride = Math.max(1, Math.ceil(n / MAX_POINTS));
    const idx = [];
    for (let i = 0; i < n; i += stride) idx.push(i);
    if (idx[idx.length - 1] !== n - 1) idx.push(n - 1);
    return idx;
  }

  // Draws `series` ({xs, ys, color, dash, mark}) on `canvas`.
  function plot(canvas, series) {
    const ratio = window.devicePixelRatio || 1;
    const w = canvas.clientWidth || 420, h = canvas.clientHeight || 260;
    canvas.width = Math.round(w * ratio);
    canvas.height = Math.round(h * ratio);
    const ctx = canvas.getContext('2d');
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, w, h);
    const all = (k) => series.flatMap((s) => s[k]).filter(Number.isFinite);
    const xs = all('xs'), ys = all('ys');
    if (xs.length === 0) return;
    let [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
    if (x1 === x0) x1 = x0 + 1;
    if (y1 === y0) { y0 -= 0.5; y1 += 0.5; }
    const pad = (y1 - y0) * 0.05;
    y0 -= pad; y1 += pad;
    const L = 56, R = 10, T = 10, B = 26;
    const px = (x) => L + ((x - x0) / (x1 - x0)) * (w - L - R);
    const py = (y) => h - B - ((y - y0) / (y1 - y0)) * (h - T - B);
    ctx.font = '11px system-ui, sans-serif';
    ctx.strokeStyle = '#eaeef2';
    ctx.fillStyle = '#57606a';
    ctx.lineWidth = 1;
    for (const t of ticks(y0, y1)) {
      ctx.beginPath(); ctx.moveTo(L, py(t)); ctx.lineTo(w - R, py(t)); ctx.stroke();
      ctx.fillText(label(t), 4, py(t) + 4);
    }
    for (const t of ticks(x0, x1)) {
      ctx.beginPath(); ctx.moveTo(px(t), T); ctx.lineTo(px(t), h - B); ctx.stroke();
      ctx.fillText(label(t), px(t) - 10, h - 8);
    }
    for (const s of series) {
      ctx.strokeStyle = s.color;
      ctx.lineWidth = 1.6;
      ctx.setLineDash(s.dash ? [5, 4] : []);
      ctx.beginPath();
      s.xs.forEach((x, i) => (i ? ctx.lineTo(px(x), py(s.ys[i])) : ctx.moveTo(px(x), py(s.ys[i]))));
      ctx.stroke();
      ctx.setLineDash([]);
      if (s.mark) {
        ctx.fillStyle = '#b42318';
        const mx = px(s.xs[s.xs.length - 1]), my = py(s.ys[s.ys.length - 1]);
        ctx.beginPath(); ctx.arc(mx, my, 4, 0, 2 * Math.PI); ctx.fill();
        ctx.fillText(s.mark, Math.min(mx + 5, w - 40), my - 5);
      }
    }
  }

  function figure(box, id, title) {
    let fig = box.querySelector('figure[data-plot="' + id + '"]');
    if (!fig) {
      fig = document.createElement('figure');
      fig.dataset.plot = id;
      fig.innerHTML = '<canvas width="420" height="260"></canvas><figcaption></figcaption>';
      box.appendChild(fig);
    }
    fig.querySelector('figcaption').textContent = title;
    return fig.querySelector('canvas');
  }

  function drawAll(box, runs) {
    const ok = runs.filter((r) => !r.error && r.samples.length > 0);
    const shown = new Set();
    for (const spec of SPECS) {
      const with_ = ok.filter((r) => r.samples[0][spec.need] !== undefined);
      if (with_.length === 0) continue;
      shown.add(spec.id);
      plot(figure(box, spec.id, spec.title), with_.map((r) => {
        const idx = thin(r.samples.length);
        return {
          xs: idx.map((i) => r.samples[i].t_s),
          ys: idx.map((i) => spec.y(r.samples[i], r)),
          color: r.color, dash: r.dash, mark: Race.MARKS[r.stop.reason],
        };
      }));
    }
    const turned = ok.filter((r) => r.turns && r.turns.ok && r.turns.body.turns.length > 0);
    if (turned.length > 0) {
      shown.add('turns');
      const series = turned.flatMap((r) => {
        const rows = r.turns.body.turns, g = r.turns.gAlong;
        const xs = rows.map((t) => t.turn);
        return [
          { xs, ys: rows.map((t) => t.mean_a_turn_m_s2 / g), color: r.color },
          { xs, ys: rows.map((t) => t.mean_a_with_collision_m_s2 / g), color: r.color, dash: true },
        ];
      });
      plot(figure(box, 'turns', 'per-turn mean a/(g sin α) against the turn: in the turn (solid), with the collision (dashed)'), series);
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

  return { drawAll, signature };
})();
