"""Checks the DOM of report.html as Chromium left it after playing for a while.

Usage: check_dom.py DOM_FILE REPORT_DIR

DOM_FILE is the output of `chromium --dump-dom` after a virtual time budget.
Prints one line per check and exits 1 if any fails.
"""

import html.parser
import pathlib
import re
import sys

VERDICT_WORDS = ("holds", "holds after correction", "refuted", "inconclusive")


class Dom(html.parser.HTMLParser):
    """Collects the elements the checks need, with their attributes and text."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.root_attrs = {}
        self.body_attrs = {}
        self.stack = []  # open elements: (tag, attrs)
        self.claim_rows = []  # attrs of tr inside #claims-table tbody
        self.verdict_texts = []
        self.figures = {}  # data-figure -> {"svg": bool}
        self.status = None
        self.status_text = ""
        self._verdict_depth = None
        self._verdict_buf = []
        self._in_status = False

    def _inside(self, pred):
        return any(pred(tag, attrs) for tag, attrs in self.stack)

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "html":
            self.root_attrs = a
        elif tag == "body":
            self.body_attrs = a
        in_claims = self._inside(lambda t, x: x.get("id") == "claims-table")
        if tag == "tr" and in_claims and self._inside(lambda t, x: t == "tbody"):
            self.claim_rows.append(a)
        if tag == "span" and in_claims and "verdict" in a.get("class", "").split():
            self._verdict_depth = len(self.stack)
            self._verdict_buf = []
        if tag == "figure" and "data-figure" in a:
            self.figures[a["data-figure"]] = {"svg": False}
        if tag == "svg":
            for t, x in reversed(self.stack):
                if t == "figure" and "data-figure" in x:
                    self.figures[x["data-figure"]]["svg"] = True
                    break
        if tag == "output" and a.get("id") == "anim-status":
            self.status = a
            self._in_status = True
        if tag not in ("br", "meta", "img", "input", "hr", "link", "source", "path", "line",
                       "circle", "rect", "polyline", "polygon"):
            self.stack.append((tag, a))

    def handle_endtag(self, tag):
        if tag == "span" and self._verdict_depth is not None and len(self.stack) - 1 == self._verdict_depth:
            self.verdict_texts.append("".join(self._verdict_buf).strip())
            self._verdict_depth = None
        if tag == "output":
            self._in_status = False
        for i in range(len(self.stack) - 1, -1, -1):
            if self.stack[i][0] == tag:
                del self.stack[i:]
                break

    def handle_data(self, data):
        if self._verdict_depth is not None:
            self._verdict_buf.append(data)
        if self._in_status:
            self.status_text += data


def main():
    dom_file, report_dir = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    dom = Dom()
    dom.feed(dom_file.read_text(encoding="utf-8"))
    failures = []

    def check(ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            failures.append(what)

    errors = dom.root_attrs.get("data-js-errors")
    check(errors is None, f"no script errors in the page (data-js-errors = {errors or 0})")

    want_claims = int(dom.body_attrs.get("data-claims", "-1"))
    check(want_claims >= 1 and len(dom.claim_rows) == want_claims,
          f"claims table has {len(dom.claim_rows)} rows, page declares {want_claims}")
    bad = [t for t in dom.verdict_texts if not any(t.endswith(w) or w + " (" in t for w in VERDICT_WORDS)]
    check(len(dom.verdict_texts) == len(dom.claim_rows) and not bad,
          f"every claim shows a verdict in words ({len(dom.verdict_texts)} found; unreadable: {bad})")

    want_figs = int(dom.body_attrs.get("data-figures", "-1"))
    with_svg = [n for n, f in dom.figures.items() if f["svg"]]
    check(want_figs >= 1 and len(with_svg) == want_figs,
          f"{len(with_svg)} figures with inline SVG, page declares {want_figs}")
    on_disk = sorted(p.stem for p in (report_dir / "figures").glob("*.svg"))
    missing = [n for n in on_disk if n not in with_svg]
    check(on_disk and not missing, f"every figures/*.svg is shown in the page (missing: {missing})")

    st = dom.status or {}
    ticks = int(st.get("data-ticks", "0"))
    max_frame = int(st.get("data-max-frame", "0"))
    check(dom.status is not None and ticks > 0 and max_frame > 0,
          f"animation advanced: {ticks} ticks, reached frame {max_frame} ({dom.status_text.strip()!r})")

    raw = (report_dir / "report.html").read_text(encoding="utf-8")
    external = re.findall(r"""(?:src|href)\s*=\s*["']?(?:https?:)?//[^"'\s>]+|url\(\s*["']?(?:https?:)?//[^)]+\)|@import|<link\b""", raw)
    check(not external, f"no external resources referenced ({external[:3]})")

    if failures:
        print(f"browser-test: {len(failures)} check(s) failed", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
