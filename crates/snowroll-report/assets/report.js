// Plays each animation of the page from its JSON (script.anim-data, whose
// data-prefix P names its elements: P-canvas, P-status, P-play, P-speed,
// P-scrub; P is `anim` for the log, `ball-anim` for the snowball).
// For a log: the cross-section on the slope, wooden core, the snow layers
// picked up in completed turns, and the arc being picked up in the current
// turn; for a snowball: a shaded ball whose radius grows. P-status records
// the frame shown (data-frame), the furthest frame reached (data-max-frame)
// and the ticks played (data-ticks).
(function () {
  'use strict';
  function play(dataEl) {
    var P = dataEl.getAttribute('data-prefix') || 'anim';
    var canvas = document.getElementById(P + '-canvas');
    if (!canvas || !canvas.getContext) { return; }
    var A = JSON.parse(dataEl.textContent);
    var ctx = canvas.getContext('2d');
    var statusEl = document.getElementById(P + '-status');
    var playBtn = document.getElementById(P + '-play');
    var speedSel = document.getElementById(P + '-speed');
    var scrub = document.getElementById(P + '-scrub');

    var TAU = 2 * Math.PI;
    var TICK_MS = 40;          // one tick of the clock, ms of wall time
    var HOLD_S = 0.8;          // pause at the end before looping, s of wall time
    var LABEL_GAP_PX = 12;     // least blank space between two distance labels, px
    var n = A.t.length;
    var alpha = A.alpha_deg * Math.PI / 180;
    var rMax = Math.max.apply(null, A.r.concat(A.ring_r)) + (A.circular ? 0 : A.snow_depth);
    var state = { frame: 0, maxFrame: 0, ticks: 0, simT: A.t[0], playing: true, hold: 0 };
    var W = 960, H = 540;

    var SNOW = ['#ffffff', '#dbe9f7'];
    var FRESH = '#9fd0ff';
    var WOOD = '#9a6b3f', WOOD_DARK = '#6d4626';

    function resize() {
      var dpr = window.devicePixelRatio || 1;
      var w = canvas.clientWidth || 960;
      W = w;
      H = Math.round(w * (w < 600 ? 0.9 : 9 / 16));
      canvas.width = Math.round(W * dpr);
      canvas.height = Math.round(H * dpr);
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      draw();
    }

    // The smallest of 1, 2, 5 times a power of ten that is at least raw.
    function niceStep(raw) {
      var p = Math.pow(10, Math.floor(Math.log10(raw)));
      var m = raw / p;
      return (m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10) * p;
    }

    // Decimals that show a multiple of step exactly (step = 1, 2 or 5 x 10^p).
    function decimalsOf(step) { return Math.max(0, -Math.floor(Math.log10(step) + 1e-9)); }

    function fmt(v, d) { return Number(v).toFixed(d); }

    function disk(r, fill, stroke) {
      ctx.beginPath();
      ctx.arc(0, 0, r, 0, TAU);
      ctx.fillStyle = fill;
      ctx.fill();
      if (stroke) { ctx.strokeStyle = stroke; ctx.lineWidth = 1; ctx.stroke(); }
    }

    function draw() {
      var i = state.frame;
      var x = A.x[i], r = A.r[i], th = A.theta[i], k = A.turn[i];
      var rk = A.ring_r[Math.min(k, A.ring_r.length - 1)];
      var inTurn = th - TAU * k;
      var b = A.snow_depth;
      // Zoom follows the log once it has grown past a quarter of its final size.
      var s = 0.26 * H / Math.max(r, rMax / 4);
      var yc = A.circular ? r : rk;

      ctx.clearRect(0, 0, W, H);
      var sky = ctx.createLinearGradient(0, 0, 0, H);
      sky.addColorStop(0, '#cfe3f5');
      sky.addColorStop(1, '#f2f7fc');
      ctx.fillStyle = sky;
      ctx.fillRect(0, 0, W, H);

      ctx.save();
      ctx.translate(W * 0.45, H * (W < 600 ? 0.56 : 0.42));
      ctx.rotate(alpha);
      // World (along slope X, normal Y up) relative to the log's centre -> screen.
      var far = 4 * Math.max(W, H);
      var ground = (yc + b) * s;      // screen depth of the bare ground under the snow
      var surface = yc * s;           // screen depth of the snow surface
      ctx.fillStyle = '#8c9a72';
      ctx.fillRect(-far, ground, 2 * far, far);
      ctx.fillStyle = '#f7fbff';
      ctx.fillRect(0, surface, far, ground - surface);
      ctx.strokeStyle = '#7d93a8';
      ctx.lineWidth = 1;
      ctx.beginPath();
      ctx.moveTo(0, surface); ctx.lineTo(far, surface);
      ctx.moveTo(-far, ground); ctx.lineTo(far, ground);
      ctx.stroke();

      // Distance markers on the ground: at most six across the width, and
      // never closer than the widest label plus LABEL_GAP_PX, measured in the
      // font they are drawn in, so that on a narrow screen they thin out.
      ctx.fillStyle = '#27321d';
      ctx.font = '12px sans-serif';
      ctx.textAlign = 'center';
      var lo = x - W / s, hi = x + W / s;
      var widest = Math.max(ctx.measureText(fmt(lo, 2) + ' m').width,
                            ctx.measureText(fmt(hi, 2) + ' m').width);
      var step = niceStep(Math.max(W / s / 6, (widest + LABEL_GAP_PX) / s));
      var digits = decimalsOf(step);
      var first = Math.ceil(lo / step) * step;
      var gap = Infinity, lastRight = -Infinity;
      for (var m = first; m < hi; m += step) {
        var px = (m - x) * s;
        var text = fmt(m, digits) + ' m';
        var half = ctx.measureText(text).width / 2;
        gap = Math.min(gap, px - half - lastRight);
        lastRight = px + half;
        ctx.fillRect(px - 0.75, ground, 1.5, 8);
        ctx.fillText(text, px, ground + 22);
      }
      // The narrowest space between two neighbouring labels, px (for the browser test).
      document.documentElement.setAttribute('data-' + P + '-label-gap', isFinite(gap) ? gap.toFixed(1) : 'none');

      // The snowball (issue 11): a shaded ball of snow whose radius grows, a
      // line from the centre to show it turning; no layers, no wooden core.
      if (A.shape === 'sphere') {
        ctx.save();
        ctx.rotate(th);
        var R = r * s;
        var shade = ctx.createRadialGradient(-0.35 * R, -0.35 * R, 0.1 * R, 0, 0, R);
        shade.addColorStop(0, '#ffffff');
        shade.addColorStop(0.6, '#dfe9f3');
        shade.addColorStop(1, '#9fb4c8');
        ctx.beginPath();
        ctx.arc(0, 0, R, 0, TAU);
        ctx.fillStyle = shade;
        ctx.fill();
        ctx.strokeStyle = '#5f7890';
        ctx.lineWidth = 1.5;
        ctx.stroke();
        ctx.strokeStyle = '#5f7890';
        ctx.beginPath(); ctx.moveTo(0, 0); ctx.lineTo(0, -R); ctx.stroke();
        ctx.restore();
      } else {
      // The log.
      var outer = A.circular ? r : rk;
      ctx.save();
      ctx.rotate(th);
      disk(outer * s, SNOW[k % 2], '#7d93a8');
      for (var j = k; j >= 1; j--) {
        disk(A.ring_r[j] * s, SNOW[(j - 1) % 2], '#9bb3c9');
      }
      // The arc picked up during this turn: from the contact line back by inTurn.
      if (inTurn > 0 && b > 0) {
        var rOut = (A.circular ? Math.max(r, rk + 1e-9) : rk + b) * s;
        ctx.save();
        ctx.rotate(-th);
        ctx.beginPath();
        ctx.arc(0, 0, rOut, Math.PI / 2, Math.PI / 2 + inTurn, false);
        ctx.arc(0, 0, rk * s, Math.PI / 2 + inTurn, Math.PI / 2, true);
        ctx.closePath();
        ctx.fillStyle = FRESH;
        ctx.fill();
        ctx.strokeStyle = '#4a90d9';
        ctx.stroke();
        ctx.restore();
      }
      disk(A.r0 * s, WOOD, WOOD_DARK);
      ctx.strokeStyle = WOOD_DARK;
      ctx.lineWidth = 1;
      for (var g = 1; g <= 3; g++) {
        ctx.beginPath(); ctx.arc(0, 0, A.r0 * s * g / 4, 0, TAU); ctx.stroke();
      }
      ctx.lineWidth = 3;
      ctx.beginPath(); ctx.moveTo(0, 0); ctx.lineTo(0, -A.r0 * s); ctx.stroke();
      ctx.restore();
      }
      ctx.restore();

      // Read-out, smaller on narrow screens.
      var fs = W < 600 ? 11 : 14;
      var lines = [
        A.model + ' (' + A.equation + '), slope ' + fmt(A.alpha_deg, 1) + '°, b = ' + A.snow_depth + ' m',
        't = ' + fmt(A.t[i], 3) + ' s    x = ' + fmt(x, 3) + ' m',
        'v = ' + fmt(A.v[i], 3) + ' m/s    r = ' + fmt(r, 4) + ' m',
        'turn ' + k + ', ' + fmt(inTurn * 180 / Math.PI, 0) + '° into it'
      ];
      ctx.font = fs + 'px sans-serif';
      var boxW = 0;
      for (var q = 0; q < lines.length; q++) { boxW = Math.max(boxW, ctx.measureText(lines[q]).width); }
      ctx.fillStyle = 'rgba(255,255,255,0.85)';
      ctx.fillRect(6, 6, boxW + 14, lines.length * (fs + 5) + 8);
      ctx.fillStyle = '#1d2329';
      ctx.textAlign = 'left';
      for (q = 0; q < lines.length; q++) { ctx.fillText(lines[q], 13, 8 + (q + 1) * (fs + 5)); }

      if (statusEl) {
        statusEl.setAttribute('data-frame', String(i));
        statusEl.setAttribute('data-max-frame', String(state.maxFrame));
        statusEl.setAttribute('data-ticks', String(state.ticks));
        statusEl.textContent = 'frame ' + i + ' / ' + n + ' · t = ' + fmt(A.t[i], 3) + ' s · ' +
          (state.playing ? 'playing' : 'paused') + ' at ' + speed() + '×';
      }
      if (scrub) { scrub.value = String(i); }
    }

    function speed() {
      var v = speedSel ? parseFloat(speedSel.value) : 1;
      return v > 0 ? v : 1;
    }

    function seek(i) {
      state.frame = Math.max(0, Math.min(n - 1, i));
      state.maxFrame = Math.max(state.maxFrame, state.frame);
      state.simT = A.t[state.frame];
    }

    function tick() {
      if (!state.playing) { return; }
      state.ticks += 1;
      if (state.frame >= n - 1) {
        state.hold += TICK_MS / 1000;
        if (state.hold >= HOLD_S) { state.hold = 0; seek(0); }
        draw();
        return;
      }
      state.simT += speed() * TICK_MS / 1000;
      var i = state.frame;
      while (i + 1 < n && A.t[i + 1] <= state.simT) { i += 1; }
      seek(i);
      state.simT = Math.max(state.simT, A.t[i]);
      draw();
    }

    function setPlaying(on) {
      state.playing = on;
      if (playBtn) {
        playBtn.textContent = on ? 'Pause' : 'Play';
        playBtn.setAttribute('aria-pressed', on ? 'true' : 'false');
      }
      draw();
    }

    if (playBtn) { playBtn.addEventListener('click', function () { setPlaying(!state.playing); }); }
    if (speedSel) { speedSel.addEventListener('change', draw); }
    if (scrub) {
      scrub.addEventListener('input', function () {
        seek(parseInt(scrub.value, 10) || 0);
        draw();
      });
    }
    window.addEventListener('resize', resize);
    resize();
    window.setInterval(tick, TICK_MS);
  }
  var all = document.querySelectorAll('script.anim-data');
  for (var i = 0; i < all.length; i++) { play(all[i]); }
})();
