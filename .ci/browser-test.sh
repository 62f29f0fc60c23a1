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
#   - both animations (the log's and the snowball's) advance,
#   - the page references no external resource,
#   - every in-page link resolves; every claim links to a figure or data
#     file that supports it; each figure links to the claims it
#     supports and each is linked from a claim; the opening section has the
#     geometry drawing and one row per model; the errata are there,
#   - no table row is a Markdown separator, table row ids are unique, and
#     the text outside code has no LaTeX/ASCII groups (_{ ^{ ^( _(),
#   - at a phone's width (400 px) no figure or animation overflows and the
#     page does not scroll sideways,
#   - at both widths neither animation's distance labels run together,
#     no figure's legend box (<g class="legend">) covers a plotted point,
#     and the smallest figure text is at least 9 px as rendered,
#   - and, in viewports 1400, 400 and 360 px wide (playwright-core driving
#     the same Chromium, .ci/browser/report-layout.js): no horizontal
#     overflow, every element and figure inside the viewport's width, the
#     legends under the plots on the phones, the page at most 15,000 px
#     tall at 1400 px and 25,000 px on the phones, and the abstract's five
#     results and the scenario on the first screen.
# Screenshots (desktop and phone widths) are kept in REPORT_DIR as
# browser-desktop.png and browser-phone.png (whole windows), and
# browser-report.png and browser-report-phone.png (the first screens at
# 1400 and 400 px). Exits non-zero on any failure.
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

# Every Chromium run of this test is started by run_chromium (below, from
# .ci/browser/chromium.sh, shared with .ci/serve-browser-test.sh): a fresh
# profile, each try bounded, a try that wrote its whole output but does not
# exit ended 5 s later, a try that hangs or dies run again (three tries),
# and each failed try's log kept and shown. What the page shows is checked
# after the run, never by the exit status, so a retry cannot hide a failing
# check.
# shellcheck source=browser/chromium.sh
. "$here/browser/chromium.sh"
chromium_flags=(--host-resolver-rules="MAP * ~NOTFOUND" --virtual-time-budget="$budget_ms")

echo "browser-test: $chromium on $page"
run_chromium dom "$work/dom.html" "${chromium_flags[@]}" --window-size=1400,900 --dump-dom "file://$page" \
    || fail "chromium failed while loading the page (its log is above)"
[ -s "$work/dom.html" ] || fail "chromium returned an empty DOM"

# At a phone's width: headless Chromium keeps a window at least 500 px wide,
# so the page is loaded into a 400 px frame, whose layout probe
# (html[data-layout-overflow]) the wrapper copies out for --dump-dom.
cat >"$work/phone.html" <<EOF
<!DOCTYPE html><html><body style="margin:0">
<iframe id="f" src="file://$page" style="width:400px;height:1800px;border:0"></iframe>
<script>
var f = document.getElementById('f');
function copy() {
  var d = f.contentDocument && f.contentDocument.documentElement;
  if (d && d.hasAttribute('data-layout-overflow')) {
    for (var i = 0; i < d.attributes.length; i++) {
      var a = d.attributes[i];
      if (a.name.indexOf('data-') === 0) { document.documentElement.setAttribute(a.name, a.value); }
    }
  } else { setTimeout(copy, 100); }
}
f.addEventListener('load', copy);
</script></body></html>
EOF
run_chromium phonedom "$work/phone-dom.html" "${chromium_flags[@]}" --allow-file-access-from-files \
    --window-size=1280,1900 --dump-dom "file://$work/phone.html" \
    || fail "chromium failed while loading the page in a phone-wide frame (its log is above)"

run_chromium desktop "$report_dir/browser-desktop.png" "${chromium_flags[@]}" --window-size=1400,2400 \
    --screenshot="$report_dir/browser-desktop.png" "file://$page" \
    || fail "desktop screenshot failed (its log is above)"
run_chromium phone "$report_dir/browser-phone.png" "${chromium_flags[@]}" --window-size=400,1800 \
    --screenshot="$report_dir/browser-phone.png" "file://$page" \
    || fail "phone screenshot failed (its log is above)"
for shot in browser-desktop.png browser-phone.png; do
    [ -s "$report_dir/$shot" ] || fail "no screenshot $shot"
done

# The page writes nothing to the console: any console line is a failure
# (uncaught exceptions and failed loads arrive here too).
console=$(grep -h "CONSOLE" "$work/dom.log" "$work/phonedom.log" "$work/desktop.log" "$work/phone.log" || true)
if [ -n "$console" ]; then
    echo "$console" >&2
    fail "the page wrote to the browser console"
fi
echo "ok   no console messages"

python3 "$here/browser/check_dom.py" "$work/dom.html" "$report_dir" "$work/phone-dom.html" \
    || fail "DOM checks failed"

# The layout at a desktop's and two phones' widths, in real viewports (a
# window narrower than 500 px needs the DevTools protocol): playwright-core
# 1.57.0 from npm, no browser download, in the directory the explorer's
# browser test uses.
root=$(cd "$here/.." && pwd)
node=$("$here/install-node.sh") || fail "node is not available"
node_dir=${CARGO_TARGET_DIR:-$root/target}/explorer-node
case $node_dir in /*) ;; *) node_dir=$root/$node_dir ;; esac
if [ ! -f "$node_dir/node_modules/playwright-core/package.json" ]; then
    mkdir -p "$node_dir"
    npm install --prefix "$node_dir" --no-audit --no-fund --silent playwright-core@1.57.0 >&2 \
        || fail "npm could not install playwright-core"
fi
# A home of its own, as in .ci/explorer-browser-test.sh.
mkdir -p "$work/home"
HOME=$work/home XDG_CONFIG_HOME=$work/home/.config XDG_CACHE_HOME=$work/home/.cache \
    PLAYWRIGHT_CORE=$node_dir/node_modules/playwright-core \
    timeout 300 "$node" "$here/browser/report-layout.js" --chromium "$chromium" --page "$page" \
    --shots "$report_dir" || fail "layout checks failed"
echo "browser-test: passed; screenshots in $report_dir/browser-desktop.png, browser-phone.png"
