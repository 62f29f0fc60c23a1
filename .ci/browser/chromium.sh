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
    case " $* " in *" --screenshot="*) dump=0 ;; esac
    for attempt in 1 2 3; do
        rm -rf "$work/profile-$name" "$out"
        mkdir -p "$work/profile-$name"
        if [ "$dump" = 1 ]; then
            "$chromium" --headless --no-sandbox --disable-gpu --no-first-run \
                --disable-background-networking --disable-component-update --disable-sync \
                --user-data-dir="$work/profile-$name" --enable-logging=stderr --v=0 \
                --hide-scrollbars "$@" >"$out" 2>"$work/$name.try" &
        else
            "$chromium" --headless --no-sandbox --disable-gpu --no-first-run \
                --disable-background-networking --disable-component-update --disable-sync \
                --user-data-dir="$work/profile-$name" --enable-logging=stderr --v=0 \
                --hide-scrollbars "$@" >/dev/null 2>"$work/$name.try" &
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
        mv "$work/$name.try" "$work/$name-try$attempt.failed"
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
