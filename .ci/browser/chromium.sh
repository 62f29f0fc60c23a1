# Sourced by .ci/browser-test.sh and .ci/serve-browser-test.sh (needs
# $chromium, the browser, and $work, a scratch directory):
#
#   run_chromium NAME OUT ARGS...
#
# One headless Chromium run: a fresh, empty profile, ARGS (the flags of the
# run and the page), its stdout to OUT for --dump-dom (OUT is the
# screenshot's path for --screenshot), its stderr (with the page's console)
# to $work/NAME.log. Returns 0 when a try ends with status 0, or wrote its
# whole output (a PNG to its IEND chunk, a DOM to its </html>) and had not
# exited 5 s later: it is then ended, and the output kept. The new headless
# mode has been seen to write its screenshot and then not exit; such a try
# used to cost the whole timeout and a second try. A try is given 45 s
# ($CHROMIUM_TRY_SECONDS; 3.5 s on a quiet machine, about three times that
# beside the Python and Slurm tests); one that dies or hangs before its output is complete is
# tried again, up to three times, its log kept as $work/NAME-tryN.failed
# and its last lines shown, so that the next hang says where it stopped.
run_chromium() {
    local name=$1 out=$2
    shift 2
    local attempt pid start done_at status why dump=1 limit=${CHROMIUM_TRY_SECONDS:-45}
    # Extra flags for a diagnosis (e.g. --vmodule=...), from the environment.
    local extra=()
    read -r -a extra <<<"${CHROMIUM_EXTRA_FLAGS:-}"
    case " $* " in *" --screenshot="*) dump=0 ;; esac
    for attempt in 1 2 3; do
        rm -rf "$work/profile-$name" "$work/home-$name" "$out"
        mkdir -p "$work/profile-$name" "$work/home-$name"
        # A home of its own besides the profile: Chromium keeps its crash
        # database (~/.config/chromium/Crash Reports), certificate store
        # (~/.pki) and caches in the user's home whatever --user-data-dir
        # says, shared with every other Chromium of that user on the
        # machine (another checkout's tests, another user's browser).
        if [ "$dump" = 1 ]; then
            HOME=$work/home-$name XDG_CONFIG_HOME=$work/home-$name/.config \
                XDG_CACHE_HOME=$work/home-$name/.cache \
                "$chromium" --headless --no-sandbox --disable-gpu --no-first-run \
                --disable-background-networking --disable-component-update --disable-sync \
                --user-data-dir="$work/profile-$name" --enable-logging=stderr --v=0 \
                --hide-scrollbars "${extra[@]}" "$@" >"$out" 2>"$work/$name.try" &
        else
            HOME=$work/home-$name XDG_CONFIG_HOME=$work/home-$name/.config \
                XDG_CACHE_HOME=$work/home-$name/.cache \
                "$chromium" --headless --no-sandbox --disable-gpu --no-first-run \
                --disable-background-networking --disable-component-update --disable-sync \
                --user-data-dir="$work/profile-$name" --enable-logging=stderr --v=0 \
                --hide-scrollbars "${extra[@]}" "$@" >/dev/null 2>"$work/$name.try" &
        fi
        pid=$!
        start=$SECONDS done_at="" why=""
        while kill -0 "$pid" 2>/dev/null; do
            if [ -z "$done_at" ] && chromium_output_complete "$out" "$dump"; then
                done_at=$SECONDS
            fi
            if [ -n "$done_at" ] && [ $((SECONDS - done_at)) -ge 5 ]; then
                why="wrote its whole output but had not exited 5 s later"
                break
            fi
            if [ $((SECONDS - start)) -ge "$limit" ]; then
                why="did not finish within $limit s"
                break
            fi
            sleep 0.2
        done
        if [ -n "$why" ] && [ -z "$done_at" ]; then
            chromium_snapshot "$pid" >"$work/$name.snapshot" 2>&1
        fi
        if [ -n "$why" ]; then
            kill "$pid" 2>/dev/null
            for _ in $(seq 15); do kill -0 "$pid" 2>/dev/null || break; sleep 0.2; done
            kill -9 "$pid" 2>/dev/null
        fi
        status=0
        wait "$pid" 2>/dev/null || status=$?
        if [ -z "$why" ] && [ "$status" = 0 ]; then
            mv "$work/$name.try" "$work/$name.log"
            return 0
        fi
        if [ -n "$done_at" ] && chromium_output_complete "$out" "$dump"; then
            echo "chromium ($name): ${why:-exited with status $status after writing its whole output}, at $((SECONDS - start)) s; ended it and kept its output" >&2
            mv "$work/$name.try" "$work/$name.log"
            return 0
        fi
        echo "chromium ($name): ${why:-exited with status $status}, attempt $attempt of 3, after $((SECONDS - start)) s; the last lines of its log:" >&2
        tail -n 15 "$work/$name.try" | sed 's/^/    /' >&2
        if [ -s "$work/$name.snapshot" ]; then
            echo "  its processes when it was ended (CPU seconds over the last second, threads by state):" >&2
            sed 's/^/    /' "$work/$name.snapshot" >&2
            cat "$work/$name.snapshot" >>"$work/$name.try"
            rm -f "$work/$name.snapshot"
        fi
        mv "$work/$name.try" "$work/$name-try$attempt.failed"
        # Kept whole where the caller asks (scripts/test.sh: target/browser-test/).
        if [ -n "${CHROMIUM_FAILED_LOGS:-}" ]; then
            mkdir -p "$CHROMIUM_FAILED_LOGS"
            cp "$work/$name-try$attempt.failed" "$CHROMIUM_FAILED_LOGS/chromium-$name-$(date +%H%M%S)-try$attempt.log"
        fi
    done
    return 1
}

# Whether OUT holds a whole output: a PNG ends with its IEND chunk (the
# chunk's type, then 4 bytes of CRC), a dumped DOM with </html>.
chromium_output_complete() {
    [ -s "$1" ] || return 1
    if [ "$2" = 1 ]; then
        tail -c 64 "$1" | grep -q '</html>'
    else
        [ "$(tail -c 8 "$1" | head -c 4)" = IEND ]
    fi
}

# What each process of a hung browser (PID $1 and its descendants) is
# doing: its kind (--type=), the CPU time it used over one second, and its
# threads by name and state, from /proc (no debugger needed). Says whether
# the browser waits (every process asleep) or works (one is busy).
chromium_snapshot() {
    local tree=("$1") pid kind
    local -A cpu
    while read -r pid ppid; do
        for k in "${tree[@]}"; do
            [ "$ppid" = "$k" ] && tree+=("$pid") && break
        done
    done < <(ps -e -o pid=,ppid= --sort=start_time)
    ticks() { awk '{print $14 + $15}' "/proc/$1/stat" 2>/dev/null || echo 0; }
    for pid in "${tree[@]}"; do cpu[$pid]=$(ticks "$pid"); done
    sleep 1
    for pid in "${tree[@]}"; do
        [ -d "/proc/$pid" ] || continue
        # (Chromium rewrites its children's command lines into one string.)
        kind=$(grep -ao -e '--type=[a-z-]*' -e '--utility-sub-type=[a-zA-Z.]*' "/proc/$pid/cmdline" 2>/dev/null \
            | sed 's/^--[a-z-]*=//' | paste -sd' ' -)
        printf '%s %s: %s s CPU in 1 s; threads: %s\n' "${kind:-browser}" "$pid" \
            "$(awk -v a="${cpu[$pid]}" -v b="$(ticks "$pid")" -v hz="$(getconf CLK_TCK)" 'BEGIN { printf "%.2f", (b - a) / hz }')" \
            "$(for t in /proc/"$pid"/task/*; do
                printf '%s:%s\n' "$(cat "$t/comm" 2>/dev/null)" "$(awk '{ sub(/.*\) /, ""); print $1 }' "$t/stat" 2>/dev/null)"
            done | sort | uniq -c | awk '{ printf "%s%s x%s", sep, $2, $1; sep = ", " }')"
    done
}
