#!/usr/bin/env bash
# Browser test of the HTML report.
#
#   .ci/browser-test.sh REPORT_DIR
#
# Installs Debian's chromium if it is missing, opens REPORT_DIR/report.html
# headless, lets it play for a few seconds of virtual time, and checks that
#   - the page logs nothing to the console and raises no script error,
#   - the claims table is there, with a verdict in words on every row,
#   - every figure (every REPORT_DIR/figures/*.svg) is shown as inline SVG,
#   - the animation advances,
#   - the page references no external resource.
# Screenshots (desktop and phone widths) are kept in REPORT_DIR as
# browser-desktop.png and browser-phone.png. Exits non-zero on any failure.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
fail() { echo "browser-test: FAIL: $*" >&2; exit 1; }

[ $# -eq 1 ] || fail "usage: .ci/browser-test.sh REPORT_DIR"
report_dir=$(cd "$1" 2>/dev/null && pwd) || fail "no such directory: $1"
page="$report_dir/report.html"
[ -f "$page" ] || fail "no report.html in $report_dir"

chromium=$("$here/install-chromium.sh") || fail "Chromium is not available"

# Virtual time the page plays before the DOM is read, ms.
budget_ms=3000
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# run_chromium NAME ARGS...: one headless run with a fresh, empty profile;
# stderr (with the page's console) goes to $work/NAME.log.
run_chromium() {
    local name=$1
    shift
    mkdir -p "$work/profile-$name"
    timeout 120 "$chromium" \
        --headless --no-sandbox --disable-gpu --no-first-run \
        --disable-background-networking --disable-component-update --disable-sync \
        --user-data-dir="$work/profile-$name" \
        --host-resolver-rules="MAP * ~NOTFOUND" \
        --enable-logging=stderr --v=0 \
        --hide-scrollbars \
        --virtual-time-budget="$budget_ms" \
        "$@" "file://$page" 2>"$work/$name.log"
}

echo "browser-test: $chromium on $page"
run_chromium dom --window-size=1280,900 --dump-dom >"$work/dom.html" \
    || fail "chromium exited with an error while loading the page (see below)
$(tail -20 "$work/dom.log")"
[ -s "$work/dom.html" ] || fail "chromium returned an empty DOM"

run_chromium desktop --window-size=1280,2400 --screenshot="$report_dir/browser-desktop.png" >/dev/null \
    || fail "desktop screenshot failed: $(tail -5 "$work/desktop.log")"
run_chromium phone --window-size=390,1800 --screenshot="$report_dir/browser-phone.png" >/dev/null \
    || fail "phone screenshot failed: $(tail -5 "$work/phone.log")"
for shot in browser-desktop.png browser-phone.png; do
    [ -s "$report_dir/$shot" ] || fail "no screenshot $shot"
done

# The page writes nothing to the console: any console line is a failure
# (uncaught exceptions and failed loads arrive here too).
console=$(grep -h "CONSOLE" "$work/dom.log" "$work/desktop.log" "$work/phone.log" || true)
if [ -n "$console" ]; then
    echo "$console" >&2
    fail "the page wrote to the browser console"
fi
echo "ok   no console messages"

python3 "$here/browser/check_dom.py" "$work/dom.html" "$report_dir" \
    || fail "DOM checks failed"
echo "browser-test: passed; screenshots in $report_dir/browser-desktop.png, browser-phone.png"
