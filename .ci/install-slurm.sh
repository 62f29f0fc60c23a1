#!/usr/bin/env bash
# Installs Debian's Slurm (slurm-wlm: slurmctld, slurmd and the client
# commands) and munge if slurmctld, slurmd, sbatch or munged is missing.
# Used by scripts/test-slurm.sh; safe to run again (does nothing when
# installed). Needs root or sudo. The packages' own services are not used
# (the test starts its daemons with its own configuration), so any that
# the install started are stopped again.
set -euo pipefail

missing() {
    local cmd
    for cmd in slurmctld slurmd sbatch squeue scancel munged mungekey; do
        command -v "$cmd" >/dev/null 2>&1 || PATH=$PATH:/usr/sbin command -v "$cmd" >/dev/null 2>&1 || return 0
    done
    return 1
}

if missing; then
    echo "install-slurm: Slurm or munge not found, installing Debian's packages" >&2
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update -qq >&2
    # policy-rc.d 101: the packages' services are not started by the install
    # (on a machine without systemd they could not be stopped cleanly).
    had_policy=0
    [ -e /usr/sbin/policy-rc.d ] && had_policy=1
    if [ "$had_policy" = 0 ]; then
        printf '#!/bin/sh\nexit 101\n' | $sudo tee /usr/sbin/policy-rc.d >/dev/null
        $sudo chmod +x /usr/sbin/policy-rc.d
    fi
    status=0
    $sudo apt-get install -y -qq --no-install-recommends slurm-wlm munge >&2 || status=$?
    if [ "$had_policy" = 0 ]; then $sudo rm -f /usr/sbin/policy-rc.d; fi
    [ "$status" = 0 ] || exit "$status"
fi
if missing; then
    echo "install-slurm: FAIL: slurmctld, slurmd, sbatch or munged is still missing after apt-get install" >&2
    exit 1
fi
echo "install-slurm: $(PATH=$PATH:/usr/sbin slurmctld -V)" >&2
