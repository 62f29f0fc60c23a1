#!/usr/bin/env bash
# Runs every derivation script; exits non-zero if any formula fails. Needs python3 + sympy only.
# Takes a few minutes on one core (turn_numerics.py bisects the hop angle over 2000 turns).
set -euo pipefail
cd "$(dirname "$0")"
status=0
for script in contact_forces.py collisions.py sphere.py losses.py circular_numerics.py turn_numerics.py near_stall_times.py unwinding.py; do
    echo "### $script"
    python3 "$script" || status=1
done
exit $status
