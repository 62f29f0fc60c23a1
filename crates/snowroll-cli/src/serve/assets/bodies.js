// The bodies the explorer offers: the note's snow log, the snowball and the
// unwinding roll. Choosing one sets every parameter to the table's default,
// then to the body's `values` (text, as typed into the form), and ticks its
// `models`; `note` is the page's line on what it is. A key or a model the
// table does not have is an error (a preset gone stale says so instead of
// quietly running something else). Loaded before app.js, whose state and
// form's fields it uses once the page has built them.
'use strict';

const BODIES = {
  log: {
    models: ['torque-cm', 'loney', 'turns'],
    values: {},
    note: 'The note\'s snow log rolling down a snowy slope, picking up snow as it goes.',
  },
  ball: {
    // The turn models take the log only: the circular analyses that
    // disagree most, eq. (4) and the energy balance eq. (14).
    models: ['torque-cm', 'energy'],
    values: { shape: 'sphere' },
    note: 'A snowball rolling down a snowy slope, picking up snow as it goes.',
  },
  roll: {
    // A roll of toilet tissue, its free end held on a level floor
    // (docs/unwinding.md): R = 6 cm on a 2 cm tube, 10 cm long. About 25 m
    // of tissue (200 sheets of 12.5 cm), so the layer it lays per unit
    // length is pi (R^2 - r_c^2)/25 m = 4.0e-4 m: the loosely wound
    // two-ply's thickness in the roll, more than the sheet's own. Density:
    // about 100 g of tissue in pi (R^2 - r_c^2) 0.1 m = 1.0e-3 m^3, so
    // 100 kg/m^3 (a roll of printing paper is nearer 700; tissue is mostly
    // air). The tube: a cardboard wall about 0.5 mm thick, 4 cm across and
    // 10 cm long, of board near 700 kg/m^3: pi 0.04 m 0.1 m 0.5e-3 m 700
    // kg/m^3 = 4.4 g, so core_mass = 4 g (the roll is then hollow inside
    // it). On the level floor the energy balances unwind it in about 40 s,
    // within the default t_end of 100 s; the torque balances and eq. (32)
    // do not start it. The turn models refuse a roll (their log climbs a
    // step onto each new layer), so none is ticked.
    models: ['energy-thin', 'energy', 'torque-cm', 'quasi-circular'],
    values: {
      alpha_deg: '0', snow_depth: '-0.0004', r0: '0.06', core_radius: '0.02', core_mass: '0.004', density: '100', length: '0.1',
    },
    note: 'A roll of paper on a level floor or a gentle board, its free end held: it lays its paper down as it ' +
      'rolls, shrinking to its tube. The energy balances start it on a level floor, the torque balances do not ' +
      '(why: "The unwinding roll" in snowroll\'s documentation).',
  },
};

// A field back at the table's default.
function resetField(key) {
  const input = state.inputs[key];
  const p = input.p;
  if (input.check) input.check.checked = p.default === true;
  else if (input.select) input.select.value = p.default;
  else { input.text.value = p.default === null ? '' : p.default_text; syncSlider(input); }
}

// Fills the form with body `id`'s defaults and ticks its models.
function applyBody(id) {
  const body = BODIES[id];
  for (const key of Object.keys(body.values)) if (!state.inputs[key]) throw new Error('body ' + id + ': the parameter table has no ' + key);
  const ids = state.models.map((m) => m.id);
  for (const m of body.models) if (!ids.includes(m)) throw new Error('body ' + id + ': no model ' + m);
  for (const key of Object.keys(state.inputs)) resetField(key);
  for (const [key, value] of Object.entries(body.values)) setGiven(key, value);
  for (const c of $('models').querySelectorAll('input')) c.checked = body.models.includes(c.value);
  $('ball-too').checked = false;
  showBody(id);
}

function showBody(id) {
  state.body = id;
  $('body-choice').value = id;
  $('body-note').textContent = BODIES[id].note;
}

// The body an address without `body=` shows: its snow depth and shape say.
function bodyOf(q) {
  if (parseFloat(q.get('snow_depth')) < 0) return 'roll';
  return q.get('shape') === 'sphere' ? 'ball' : 'log';
}
