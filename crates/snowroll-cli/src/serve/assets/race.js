// The race: every run of the page on one slope, side by side, each body
// rolling to its x(t) as the library computed it (no physics here: positions
// are the run's rows, interpolated in time for drawing; a turn model's are
// its turns' starts). Hops, slips and stalls are marked where the run
// stopped for them. An unwinding roll (a negative snow depth, down to its
// core radius) is drawn to scale, its cardboard tube inside it, with the
// paper it has laid down as a strip on the ground behind it.
'use strict';

const Race = (function () {
  const MARKS = { hop: 'hop', slip: 'slip', stalled: 'stall', 'does-not-start': 'does not start', stuck: 'stuck' };
  let frame = null;

  // The row index at or before time t (rows ascend in t).
  function before(ts, t) {
    let lo = 0, hi = ts.length - 1;
    if (t >= ts[hi]) return hi;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (ts[mid] <= t) lo = mid; else hi = mid;
    }
    return lo;
  }

  // The drawn state of a run at time t: x, r and the turn angle, from its
  // track ({t, x, r, angle}: arrays; r and angle may be absent).
  function at(track, t) {
    const i = before(track.t, t);
    const j = Math.min(i + 1, track.t.length - 1);
    const f = track.t[j] > track.t[i] ? Math.min(1, Math.max(0, (t - track.t[i]) / (track.t[j] - track.t[i]))) : 0;
    const mix = (a) => a[i] + (a[j] - a[i]) * f;
    const x = mix(track.x), r = track.r ? mix(track.r) : null;
    const angle = track.angle ? mix(track.angle) : (r ? x / r : 0);
    return { x, r, angle };
  }

  const LANE = 30, MARGIN = 20, TOP = 34;
  // An unwinding roll's largest drawn radius (px); the laid paper's drawn
  // thickness (px: the real |b|, a fraction of a millimetre, would not show).
  const ROLL = LANE / 2 - 2, PAPER = 3;

  // The core radius of a run that unwinds (its request's snow depth < 0),
  // else null.
  function coreOf(run) {
    const q = run.request || {};
    const b = parseFloat(q.snow_depth), core = parseFloat(q.core_radius);
    return b < 0 && core > 0 ? core : null;
  }
  // Room for the runs' names at the slope's foot: less on a narrow screen.
  const labelRoom = (w) => Math.min(170, Math.round(w * 0.3));

  // The range of r over the runs, for the bodies' drawn sizes.
  function radii(runs) {
    const rs = runs.filter((r) => r.track.r).flatMap((r) => [r.track.r[0], r.track.r[r.track.r.length - 1]]);
    return rs.length ? [Math.min(...rs), Math.max(...rs)] : [0, 0];
  }

  function draw(ctx, w, h, runs, alpha, t) {
    ctx.clearRect(0, 0, w, h);
    const n = runs.length;
    const cos = Math.cos(alpha), sin = Math.sin(alpha);
    const x0 = MARGIN, y0 = TOP;
    // Across the width, and down the height left below the lanes (a level
    // floor needs none: the canvas is then only as tall as its lanes).
    const down = sin > 1e-9 ? Math.max(0, h - y0 - n * LANE - MARGIN) / sin : Infinity;
    const length = Math.min((w - 2 * MARGIN - labelRoom(w)) / cos, down);
    const xMax = Math.max(1e-9, ...runs.map((r) => r.stop.x_m));
    const [rMin, rMax] = radii(runs);
    ctx.font = '12px system-ui, sans-serif';
    runs.forEach((run, k) => {
      const s = at(run.track, Math.min(t, run.stop.t_s));
      const along = (s.x / xMax) * length;
      const core = s.r === null ? null : coreOf(run);
      // An unwinding roll to scale (its tube a third of it, say); else from
      // 5 px at the smallest radius to the lane's half-width at the largest.
      const rad = s.r === null ? LANE / 4 : core !== null ? ROLL * s.r / rMax :
        5 + (LANE / 2 - 7) * (rMax > rMin ? (s.r - rMin) / (rMax - rMin) : 0);
      // Each run on its own lane, parallel to the slope; the surface under it.
      const bx = x0, by = y0 + (k + 1) * LANE;
      ctx.strokeStyle = k === n - 1 ? '#57606a' : '#d0d7de';
      ctx.lineWidth = k === n - 1 ? 2 : 1;
      ctx.beginPath();
      ctx.moveTo(bx, by);
      ctx.lineTo(bx + length * cos, by + length * sin);
      ctx.stroke();
      const cx = bx + along * cos + sin * rad, cy = by + along * sin - cos * rad;
      if (core !== null && along > 0) {
        // The paper laid down, at rest on the ground from the start to the
        // roll's contact point (none ahead of it).
        const up = PAPER / 2;
        ctx.strokeStyle = run.color;
        ctx.globalAlpha = 0.45;
        ctx.lineWidth = PAPER;
        ctx.beginPath();
        ctx.moveTo(bx + sin * up, by - cos * up);
        ctx.lineTo(bx + along * cos + sin * up, by + along * sin - cos * up);
        ctx.stroke();
        ctx.globalAlpha = 1;
      }
      ctx.fillStyle = run.color;
      ctx.beginPath();
      ctx.arc(cx, cy, rad, 0, 2 * Math.PI);
      ctx.fill();
      ctx.strokeStyle = '#fff';
      ctx.lineWidth = 1.5;
      ctx.beginPath();
      ctx.moveTo(cx, cy);
      ctx.lineTo(cx + rad * Math.cos(s.angle), cy + rad * Math.sin(s.angle));
      ctx.stroke();
      if (core !== null) {
        // The cardboard tube the roll shrinks to.
        ctx.fillStyle = '#d9bf94';
        ctx.strokeStyle = '#7a5a32';
        ctx.lineWidth = 1;
        ctx.beginPath();
        ctx.arc(cx, cy, ROLL * core / rMax, 0, 2 * Math.PI);
        ctx.fill();
        ctx.stroke();
      }
      ctx.fillStyle = '#1c2733';
      // The name past the slope's foot, clear of a body that has arrived.
      ctx.fillText(run.label, bx + length * cos + LANE + 6, by + length * sin);
      const mark = MARKS[run.stop.reason];
      if (mark && t >= run.stop.t_s) {
        ctx.fillStyle = '#b42318';
        // A roll's beside it, clear of the paper on the lane above.
        ctx.fillText('✕ ' + mark + ' at x = ' + run.stop.x_m.toPrecision(3) + ' m', cx + rad + 4, core !== null ? cy + 4 : cy - rad);
      } else if (run.stop.reason === 'unwound' && t >= run.stop.t_s) {
        // Left of the roll, which has reached the lane's end.
        ctx.fillStyle = '#1a7f37';
        ctx.textAlign = 'right';
        ctx.fillText('unwound at x = ' + run.stop.x_m.toPrecision(3) + ' m', cx - rad - 4, cy - rad);
        ctx.textAlign = 'left';
      }
      // A run that goes on through a hop (on_hop = continue): the first
      // row whose normal force the library gave as <= 0, once passed.
      const off = run.firstHop;
      if (off && t >= off.t && run.stop.reason !== 'hop') {
        const hx = bx + (off.x / xMax) * length * cos, hy = by + (off.x / xMax) * length * sin;
        ctx.fillStyle = '#b42318';
        ctx.fillText('✕ hop', hx, hy - LANE / 2);
      }
    });
  }

  // Plays `runs` ({label, color, track, stop, firstHop}) on `canvas` at slope angle
  // alpha (radians); `clock` shows the time. The race lasts at most 8 s.
  function start(canvas, clock, runs, alpha, atEnd) {
    if (frame !== null) cancelAnimationFrame(frame);
    frame = null;
    canvas.dataset.done = '';
    const ctx = canvas.getContext('2d');
    const ratio = window.devicePixelRatio || 1;
    const ok = runs.filter((r) => r.track && r.track.t.length > 0);
    // Tall enough for the slope at its true angle across the width, within
    // 220 to 560 px.
    const wide = canvas.clientWidth || 900;
    const drop = (wide - 2 * MARGIN - labelRoom(wide)) * Math.tan(alpha);
    // At most 0.8 of its width (a phone: the readout stays near).
    const tallest = Math.max(220, Math.min(560, 0.8 * wide));
    canvas.style.height = Math.round(Math.min(tallest, Math.max(220, TOP + ok.length * LANE + MARGIN + drop))) + 'px';
    const w = canvas.clientWidth || 900, h = canvas.clientHeight || 300;
    canvas.width = Math.round(w * ratio);
    canvas.height = Math.round(h * ratio);
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    if (ok.length === 0) {
      ctx.clearRect(0, 0, w, h);
      clock.textContent = 'no run to race';
      canvas.dataset.done = '1';
      return;
    }
    const tEnd = Math.max(...ok.map((r) => r.stop.t_s));
    const speed = Math.max(1, tEnd / 8);
    // atEnd: the race's last frame at once (an address ending in #end, for
    // screenshots).
    const t0 = performance.now() - (atEnd ? (tEnd / speed) * 1000 : 0);
    function step(now) {
      const t = Math.min(tEnd, ((now - t0) / 1000) * speed);
      draw(ctx, w, h, ok, alpha, t);
      clock.textContent = 't = ' + t.toFixed(2) + ' s of ' + tEnd.toPrecision(4) + ' s (' + speed.toPrecision(3) + '× real time)';
      frame = t < tEnd ? requestAnimationFrame(step) : null;
      canvas.dataset.done = frame === null ? '1' : '';
    }
    frame = requestAnimationFrame(step);
  }

  // The lanes' geometry (the browser test finds a lane's laid paper by it).
  return { start, MARKS, layout: { LANE, MARGIN, TOP, PAPER, labelRoom } };
})();
