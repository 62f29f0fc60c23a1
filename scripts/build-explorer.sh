#!/usr/bin/env bash
# Builds the explorer as one self-contained HTML file: the snowroll library
# compiled to WebAssembly (crates/snowroll-wasm, inlined as base64) with the
# page's script and style (crates/snowroll-cli/src/serve/assets/, the same
# files `snowroll serve` serves). The file needs no server and no network:
# open it from file://, put it on any static host, or mail it.
#
#   bash scripts/build-explorer.sh OUT.html
#
# Installs the wasm32-unknown-unknown target with rustup when it is missing.
# Refuses to write a page over 1.5 MB. The page is written to a temporary
# file beside OUT and renamed into place: never half-written.
set -euo pipefail
cd "$(dirname "$0")/.."

fail() { echo "build-explorer: $*" >&2; exit 1; }
[ $# -eq 1 ] || fail "usage: bash scripts/build-explorer.sh OUT.html"
out=$1

target=wasm32-unknown-unknown
if ! rustup target list --installed 2>/dev/null | grep -qx "$target"; then
    echo "build-explorer: installing the Rust target $target (rustup target add)" >&2
    rustup target add "$target" >&2 || fail "cannot install the Rust target $target"
fi

# Symbols stripped: the module's function names are not needed by the page
# (about a fifth of its size).
CARGO_PROFILE_RELEASE_STRIP=symbols cargo build --quiet --release --locked \
    -p snowroll-wasm --target "$target"
dir=${CARGO_TARGET_DIR:-target}
wasm=$dir/$target/release/snowroll_wasm.wasm
[ -s "$wasm" ] || fail "the build wrote no $wasm"

python3 - "$wasm" "$out" <<'PY'
import base64, os, sys, tempfile
wasm, out = sys.argv[1], sys.argv[2]
assets = "crates/snowroll-cli/src/serve/assets"
def read(name):
    with open(os.path.join(assets, name), encoding="utf-8") as f:
        return f.read()
page = read("index.html")
def inline(tag, body, kind):
    if "</" + kind in body.lower():
        sys.exit("build-explorer: %s holds </%s>, which would end the inlined element" % (tag, kind))
    return body
with open(wasm, "rb") as f:
    b64 = base64.b64encode(f.read()).decode("ascii")
parts = {
    '<link rel="stylesheet" href="style.css">': "<style>\n" + inline("style.css", read("style.css"), "style") + "</style>",
    '<script src="race.js"></script>':
        "<script>\n// The snowroll library in WebAssembly (crates/snowroll-wasm), base64.\n"
        "const SNOWROLL_WASM = '" + b64 + "';\n</script>\n"
        "<script>\n" + inline("race.js", read("race.js"), "script") + "</script>",
    '<script src="plots.js"></script>': "<script>\n" + inline("plots.js", read("plots.js"), "script") + "</script>",
    '<script src="bodies.js"></script>': "<script>\n" + inline("bodies.js", read("bodies.js"), "script") + "</script>",
    '<script src="app.js"></script>': "<script>\n" + inline("app.js", read("app.js"), "script") + "</script>",
}
for old, new in parts.items():
    if page.count(old) != 1:
        sys.exit("build-explorer: index.html does not hold %s once" % old)
    page = page.replace(old, new)
data = page.encode("utf-8")
limit = 1536 * 1024
if len(data) > limit:
    sys.exit("build-explorer: the page is %d bytes, over the %d allowed (1.5 MB)" % (len(data), limit))
target = os.path.abspath(out)
fd, tmp = tempfile.mkstemp(dir=os.path.dirname(target), prefix=".explorer-", suffix=".tmp")
try:
    with os.fdopen(fd, "wb") as f:
        f.write(data)
    os.chmod(tmp, 0o644)
    os.replace(tmp, target)
except BaseException:
    os.unlink(tmp)
    raise
print("build-explorer: wrote %s (%d bytes; the module %d bytes)" % (out, len(data), os.path.getsize(wasm)))
PY
