#!/usr/bin/env bash
# Browser test of `snowroll serve` (the classroom explorer).
#
#   .ci/serve-browser-test.sh SNOWROLL OUT_DIR
#
# SNOWROLL is a snowroll binary built with the `serve` feature. Starts it on a
# free port, installs Debian's chromium if it is missing (.ci/install-chromium.sh),
# loads the page headless with its test hook (#selftest: the page records its
# readout and plots, moves the alpha slider to its middle by an input event
# as a hand would, and records them again once the new answers are drawn),
# and checks that
#   - the page wrote nothing to the browser console,
#   - the slider's move reached the server and the page redrew: the plots'
#     pixels and the readout's final speed both changed,
#   - the new readout is the API's number for the new alpha: the speed at the
#     stop of `GET /api/simulate` with the query the page sent, byte for
#     byte as the JSON has it, and that query holds the slider's new alpha.
# Screenshots at 1400 and 400 px wide are kept in OUT_DIR as
# serve-desktop.png and serve-phone.png. Exits non-zero on any failure.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
fail() { echo "serve-browser-test: FAIL: $*" >&2; exit 1; }

[ $# -eq 2 ] || fail "usage: .ci/serve-browser-test.sh SNOWROLL OUT_DIR"
snowroll=$1
mkdir -p "$2"
out=$(cd "$2" && pwd)
chromium=$("$here/install-chromium.sh") || fail "Chromium is not available"

work=$(mktemp -d)
server_pid=""
wrap_pid=""
cleanup() {
    if [ -n "$wrap_pid" ]; then kill "$wrap_pid" 2>/dev/null || true; wait "$wrap_pid" 2>/dev/null || true; fi
    if [ -n "$server_pid" ]; then kill -INT "$server_pid" 2>/dev/null || true; wait "$server_pid" 2>/dev/null || true; fi
    rm -rf "$work"
}
trap cleanup EXIT

"$snowroll" serve --port 0 >"$work/serve.out" 2>"$work/serve.err" &
server_pid=$!
# Waits (a minute at most: a busy machine may be slow to start a debug
# build) for the server's URL; it chose a free port itself (--port 0).
for _ in $(seq 300); do
    grep -q "http://" "$work/serve.out" 2>/dev/null && break
    kill -0 "$server_pid" 2>/dev/null || break
    sleep 0.2
done
url=$(grep -o 'http://[^ ]*' "$work/serve.out") || fail "the server printed no URL: $(cat "$work/serve.err")"
echo "serve-browser-test: $chromium on $url"

# Every Chromium run as in .ci/browser-test.sh: bounded tries, a try that
# wrote its output but does not exit ended, failed tries' logs kept and shown.
# No host name is looked up (the browser's own requests at start, the network
# time and the updaters, fail at once); the pages are on 127.0.0.1.
# shellcheck source=browser/chromium.sh
. "$here/browser/chromium.sh"
no_lookup="--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1"

run_chromium dom "$work/dom.html" "$no_lookup" --virtual-time-budget=4000 --window-size=1400,1000 --dump-dom \
    "${url}?models=torque-cm,loney#selftest" || fail "chromium failed (its log is above)"
run_chromium desktop "$out/serve-desktop.png" "$no_lookup" --virtual-time-budget=4000 --window-size=1400,1300 \
    --screenshot="$out/serve-desktop.png" "${url}?models=torque-cm,loney,turns&ball=1&alpha_deg=65" \
    || fail "desktop screenshot failed (its log is above)"
# At a phone's width: headless Chromium keeps a window at least 500 px wide,
# so the page is shown in a 400 px frame (as .ci/browser-test.sh does). The
# frame's page comes from a second local server: a file:// page's frame does
# not get its answers from 127.0.0.1.
mkdir -p "$work/wrap"
cat >"$work/wrap/phone.html" <<HTML
<!DOCTYPE html><html><body style="margin:0">
<iframe src="${url}?models=torque-cm,turns" style="width:400px;height:1800px;border:0"></iframe>
</body></html>
HTML
python3 -u -m http.server 0 --bind 127.0.0.1 --directory "$work/wrap" >"$work/wrap.out" 2>/dev/null &
wrap_pid=$!
for _ in $(seq 300); do
    grep -q "port" "$work/wrap.out" 2>/dev/null && break
    kill -0 "$wrap_pid" 2>/dev/null || break
    sleep 0.2
done
wrap_port=$(sed -n 's/.* port \([0-9]*\).*/\1/p' "$work/wrap.out" | head -1)
[ -n "$wrap_port" ] || fail "the frame's server did not start"
run_chromium phone "$out/serve-phone.png" "$no_lookup" --virtual-time-budget=4000 --window-size=400,1800 \
    --screenshot="$out/serve-phone.png" "http://127.0.0.1:$wrap_port/phone.html" \
    || fail "phone screenshot failed (its log is above)"
for shot in serve-desktop.png serve-phone.png; do
    [ -s "$out/$shot" ] || fail "no screenshot $shot"
done

console=$(grep -h "CONSOLE" "$work"/*.log || true)
[ -z "$console" ] || { echo "$console" >&2; fail "the page wrote to the browser console"; }
echo "ok   no console messages"

python3 - "$work/dom.html" "$url" <<'PY' || fail "the page's checks failed"
import html, json, re, sys, urllib.request
dom, url = open(sys.argv[1]).read(), sys.argv[2]
root = re.search(r"<html[^>]*>", dom).group(0)
data = {k: html.unescape(v) for k, v in re.findall(r'data-([a-z-]+)="([^"]*)"', root)}
def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        print("     page data:", data, file=sys.stderr)
        sys.exit(1)
check(data.get("selftest") == "done", "the page redrew after the slider moved")
check(data["before-sig"] != data["after-sig"], "the plots changed")
check(data["before-readout"] != data["after-readout"], "the readout changed: %s -> %s" % (data["before-readout"], data["after-readout"]))
query = data["after-query"]
check(("alpha_deg=" + data["after-alpha"]) in query, "the query sent holds the slider's alpha (%s)" % data["after-alpha"])
with urllib.request.urlopen(url + "api/simulate?" + query) as r:
    body = r.read().decode()
# The stop's speed as the JSON text has it (JavaScript prints a double's
# shortest round-trip form, as serde_json writes it).
api_v = json.loads(body)["stop"]["v_m_s"]
check(float(data["after-readout"]) == api_v and data["after-v"] == data["after-readout"],
      "the readout is the API's speed for the new alpha: %s == %r" % (data["after-readout"], api_v))
PY
echo "serve-browser-test: passed; screenshots in $out/serve-desktop.png, serve-phone.png"
