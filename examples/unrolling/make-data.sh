#!/usr/bin/env bash
# Writes examples/unrolling/track.txt: SYNTHETIC data in the form Tracker
# exports, made by snowroll (crates/snowroll/examples/synthetic_track.rs):
# the unwinding roll of eq. (15) with b < 0 (the textbook energy balance),
# a roll of 2 mm craft foam, R = 8 cm, on a cardboard core of 2 cm radius,
# let go at t = 0.4 s from x = 0.15 m on a board at 3 degrees, filmed at
# 30 frames/s for 3.5 s, Gaussian noise of 3 mm (fixed seed 35). Not a
# measurement: the first line says so.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
cargo run --release -q -p snowroll --example synthetic_track -- \
    --model energy-thin --alpha-deg 3 --snow-depth -0.002 --r0 0.08 --core-radius 0.02 \
    --fps 30 --t-end 3.5 --t0 0.4 --x0 0.15 --sigma 0.003 --seed 35 \
    > examples/unrolling/track.txt
