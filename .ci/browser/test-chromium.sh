#!/usr/bin/env bash
# Tests of run_chromium (.ci/browser/chromium.sh), the one way the browser
# tests start Chromium, with stand-in browsers (shell scripts) that behave as
# headless Chromium has been seen to: writing a screenshot and then not
# exiting, hanging before any output, dying in its setup once. About 15 s,
# mostly waiting; scripts/test.sh runs it beside the Rust tests.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# shellcheck source=chromium.sh
. "$here/chromium.sh"
fail() { echo "test-chromium: FAIL: $*" >&2; exit 1; }

# A stand-in browser: $1 is what it does, the rest Chromium's flags.
cat >"$work/browser" <<'SH'
#!/usr/bin/env bash
mode=$(cat "$MODE_FILE")
out=""
for a; do case $a in --screenshot=*) out=${a#--screenshot=} ;; esac; done
png() { printf '\211PNG\r\n\032\n0000IHDRxxxx0000IEND\256B`\202' >"$out"; }
case $mode in
    png-then-hang) png; exec sleep 600 ;;
    dom-then-hang) printf '<html><body>page</body></html>\n'; exec sleep 600 ;;
    hang) exec sleep 600 ;;
    die-once)
        if [ ! -e "$MODE_FILE.died" ]; then
            touch "$MODE_FILE.died"
            echo "zygote_host_impl_linux.cc: Connection reset by peer" >&2
            exit 1
        fi
        png; echo "written" >&2; exit 0 ;;
esac
SH
chmod +x "$work/browser"
chromium=$work/browser
export MODE_FILE=$work/mode

# 1. The screenshot written, then no exit: kept, the browser ended 5 s
# later (it used to cost the 45 s timeout and a second try).
echo png-then-hang >"$MODE_FILE"
t=$SECONDS
run_chromium shot "$work/shot.png" --screenshot="$work/shot.png" page 2>"$work/1.err" \
    || fail "a screenshot written before a hang was not kept: $(cat "$work/1.err")"
took=$((SECONDS - t))
[ "$took" -ge 5 ] && [ "$took" -le 10 ] || fail "ended after $took s, expected 5 to 10 s"
grep -q "wrote its whole output but had not exited 5 s later" "$work/1.err" || fail "no note: $(cat "$work/1.err")"
chromium_output_complete "$work/shot.png" 0 || fail "the screenshot is not whole"
echo "ok   a screenshot written before a hang is kept, the browser ended after $took s"

# 2. The same for a DOM dump.
echo dom-then-hang >"$MODE_FILE"
run_chromium dom "$work/dom.html" --dump-dom page 2>"$work/2.err" || fail "a DOM written before a hang was not kept"
grep -q '</html>' "$work/dom.html" || fail "the DOM is not whole"
echo "ok   a DOM written before a hang is kept"

# 3. A hang before any output: each try bounded, three tries, then a
# failure that shows each try's log.
echo hang >"$MODE_FILE"
t=$SECONDS
if CHROMIUM_TRY_SECONDS=2 run_chromium stuck "$work/stuck.png" --screenshot="$work/stuck.png" page 2>"$work/3.err"; then
    fail "a browser that wrote nothing passed"
fi
took=$((SECONDS - t))
[ "$took" -le 12 ] || fail "three tries of 2 s took $took s"
[ "$(grep -c 'did not finish within 2 s' "$work/3.err")" = 3 ] || fail "not three bounded tries: $(cat "$work/3.err")"
[ -e "$work/stuck-try3.failed" ] || fail "the failed tries' logs were not kept"
echo "ok   a browser that hangs before its output is tried three times, $took s in all"

# 4. A browser that dies in its setup once: tried again, its log kept and shown.
echo die-once >"$MODE_FILE"
run_chromium once "$work/once.png" --screenshot="$work/once.png" page 2>"$work/4.err" || fail "not tried again"
grep -q "Connection reset" "$work/4.err" || fail "the dead try's log was not shown"
grep -q written "$work/once.log" || fail "the passing try's log is not NAME.log"
echo "ok   a browser that dies once is tried again, the dead try's log shown"
echo "test-chromium: 4 passed, 0 failed"
