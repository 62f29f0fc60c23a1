"""Checks the DOM of report.html as Chromium left it after playing for a while.

Usage: check_dom.py DOM_FILE REPORT_DIR [PHONE_DOM_FILE]

DOM_FILE is the output of `chromium --dump-dom` after a virtual time budget;
PHONE_DOM_FILE the same at a phone's width (400 px), for the layout check.
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
        self.statuses = {}  # id of each animation's output.anim-status -> attrs
        self.anim_shapes = {}  # id of each animation section -> its data-shape
        self.ids = set()
        self.hrefs = []  # in-page links: (target id, id of the enclosing element with an id)
        self.model_rows = 0
        self.figure_supports = {}  # figure id -> claim ids it links to
        self.status_texts = {}
        self.claim_supports = {}  # claim id -> figure links and data files linked from its row
        self.latexisms = []  # text outside code with _{ ^{ ^( _(
        self.table_rows = []  # (id or None, texts of the cells) of every table row
        self.sections = []  # ids of the <section> elements, in order
        self.findings = []  # data-claim of each li of #findings
        self.claim_details = {}  # claim row id -> list of its <details>' open flags
        self._row = None
        self._status_id = None
        self._verdict_depth = None
        self._verdict_buf = []
        self._in_status = False

    def _inside(self, pred):
        return any(pred(tag, attrs) for tag, attrs in self.stack)

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a:
            self.ids.add(a["id"])
        href = a.get("href", "")
        if tag == "a" and href and not href.startswith("#"):
            row = next((x["id"] for t, x in reversed(self.stack) if t == "tr" and "id" in x), None)
            if row and row.startswith("claim-") and href.startswith("data/") and href.endswith(".csv"):
                self.claim_supports.setdefault(row[len("claim-"):], []).append(href)
        if tag == "tr":
            self._row = (a.get("id"), [])
            self.table_rows.append(self._row)
        if tag == "a" and href.startswith("#"):
            row = next((x["id"] for t, x in reversed(self.stack) if t == "tr" and "id" in x), None)
            if row and row.startswith("claim-") and href.startswith("#fig-"):
                self.claim_supports.setdefault(row[len("claim-"):], []).append(href)
            owner = next((x["id"] for t, x in reversed(self.stack) if "id" in x), None)
            self.hrefs.append((a["href"][1:], owner))
            if owner and owner.startswith("fig-") and a["href"].startswith("#claim-"):
                self.figure_supports.setdefault(owner, []).append(a["href"][len("#claim-"):])
        if tag == "section":
            self.sections.append(a.get("id"))
        if tag == "li" and "data-claim" in a and self._inside(lambda t, x: x.get("id") == "findings"):
            self.findings.append(a["data-claim"])
        if tag == "details":
            row = next((x["id"] for t, x in reversed(self.stack) if t == "tr" and "id" in x), None)
            if row and row.startswith("claim-"):
                self.claim_details.setdefault(row, []).append("open" in a)
        if tag == "tr" and a.get("id", "").startswith("model-"):
            self.model_rows += 1
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
        if tag == "section" and "data-shape" in a:
            self.anim_shapes[a.get("id", "")] = a["data-shape"]
        if tag == "output" and "anim-status" in a.get("class", "").split():
            self.statuses[a.get("id", "")] = a
            self._status_id = a.get("id", "")
            self.status_texts[self._status_id] = ""
            self._in_status = True
        if tag not in ("br", "meta", "img", "input", "hr", "link", "source", "path", "line",
                       "circle", "rect", "polyline", "polygon"):
            self.stack.append((tag, a))

    def handle_endtag(self, tag):
        if tag == "tr":
            self._row = None
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
        if self._row is not None and self._inside(lambda t, x: t in ("td", "th")):
            self._row[1].append(data)
        if not self._inside(lambda t, x: t in ("code", "pre", "script", "style")):
            for m in re.finditer(r"(_\{|\^\{|\^\(|_\()", data):
                self.latexisms.append(data[max(0, m.start() - 20):m.end() + 20])
        if self._verdict_depth is not None:
            self._verdict_buf.append(data)
        if self._in_status:
            self.status_texts[self._status_id] += data


# Smallest readable size of figure text on screen, px.
MIN_FIGURE_FONT_PX = 9.0


def main():
    dom_file, report_dir = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    phone_file = pathlib.Path(sys.argv[3]) if len(sys.argv) > 3 else None
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
    rows = [r.get("id", "") for r in dom.claim_rows]
    check(dom.sections[:2] == ["abstract", "findings"],
          f"the page opens with its abstract, then its findings (first sections: {dom.sections[:2]})")
    abstract = [t for t, owner in dom.hrefs if owner == "abstract" and t.startswith("claim-")]
    check(len(abstract) == 5 and len(set(abstract)) == 5 and set(abstract) <= set(rows),
          f"the abstract links its five results to their claims' rows ({abstract})")
    check(not dom.findings and len(set(rows)) == len(rows),
          f"each claim appears once in full: one row each, no second list ({len(dom.findings)} list lines)")
    folded = [r for r in rows if dom.claim_details.get(r) == [False]]
    check(len(folded) == len(rows),
          f"each claim's checking folds out of its row, closed at first ({len(folded)} of {len(rows)})")
    bad = [t for t in dom.verdict_texts if not any(t.endswith(w) or w + " (" in t for w in VERDICT_WORDS)]
    check(len(dom.verdict_texts) == len(dom.claim_rows) and not bad,
          f"every claim shows a verdict in words ({len(dom.verdict_texts)} found; unreadable: {bad})")

    want_figs = int(dom.body_attrs.get("data-figures", "-1"))
    with_svg = [n for n, f in dom.figures.items() if f["svg"]]
    check(want_figs >= 1 and len(with_svg) == want_figs,
          f"{len(with_svg)} figures with inline SVG, page declares {want_figs}")
    # figures/geometry.svg is the opening's drawing, written for report.md; the
    # page draws it inline in the problem section (checked below), not as a chart.
    on_disk = sorted(p.stem for p in (report_dir / "figures").glob("*.svg") if p.stem != "geometry")
    missing = [n for n in on_disk if n not in with_svg]
    check(on_disk and not missing, f"every figures/*.svg is shown in the page (missing: {missing})")

    # Each animation advances: the log's (anim-status) and the snowball's
    # (ball-anim-status, in the section whose data-shape is sphere).
    check(sorted(dom.anim_shapes.values()) == ["cylinder", "sphere"],
          f"the page has the log's and the snowball's animation (sections by shape: {dom.anim_shapes})")
    for prefix in ("anim", "ball-anim"):
        st = dom.statuses.get(prefix + "-status")
        ticks = int((st or {}).get("data-ticks", "0"))
        max_frame = int((st or {}).get("data-max-frame", "0"))
        text = dom.status_texts.get(prefix + "-status", "").strip()
        check(st is not None and ticks > 0 and max_frame > 0,
              f"animation {prefix} advanced: {ticks} ticks, reached frame {max_frame} ({text!r})")

    broken = sorted({t for t, _ in dom.hrefs if t not in dom.ids})
    check(dom.hrefs and not broken, f"every in-page link resolves ({len(dom.hrefs)} links; broken: {broken[:5]})")
    claim_ids = {r.get("id", "")[len("claim-"):] for r in dom.claim_rows}
    linked_from_claims = {t for t, owner in dom.hrefs if owner and owner.startswith("claim-") and t.startswith("fig-")}
    figure_ids = {"fig-" + n for n in dom.figures}
    check(figure_ids and figure_ids <= linked_from_claims,
          f"every figure is linked from a claim (not linked: {sorted(figure_ids - linked_from_claims)})")
    unsupported = sorted(f for f in figure_ids if not dom.figure_supports.get(f))
    bad_back = sorted({c for cs in dom.figure_supports.values() for c in cs if c not in claim_ids})
    check(not unsupported and not bad_back,
          f"every figure links back to the claims it supports (none: {unsupported}; unknown claims: {bad_back})")
    want_models = int(dom.body_attrs.get("data-models", "-1"))
    check(want_models >= 1 and dom.model_rows == want_models and "problem" in dom.ids and "geometry" in dom.ids
          and (report_dir / "figures" / "geometry.svg").is_file(),
          f"the problem section has the geometry drawing and {dom.model_rows} model rows (page declares {want_models})")
    results = sorted(i for i in dom.ids if i.startswith("result-"))
    check("snowball-and-losses" in dom.ids and "unwinding-roll" in dom.ids and len(results) == 7
          and "result-unwinding-textbook-speed" in results and "result-unwinding-hollow-roll" in results
          and all(("claim-" + r[len("result-"):], r) in dom.hrefs for r in results),
          "the snowball-and-losses section has its 5 results and the unwinding roll's its 2, "
          f"each linked to its claim ({results})")
    check("errata" in dom.ids and any(i.startswith("erratum-") for i in dom.ids),
          "the errata section is there, with a row per erratum")
    unlinked = sorted(c for c in claim_ids if not dom.claim_supports.get(c))
    files = sorted({h for hs in dom.claim_supports.values() for h in hs if h.startswith("data/")})
    missing_files = [h for h in files if not (report_dir / h).is_file()]
    check(claim_ids and not unlinked and not missing_files,
          f"every claim links to a figure or data file that supports it (none: {unlinked}; "
          f"missing files: {missing_files})")
    dashes = [r for r in dom.table_rows if r[1] and set("".join(r[1]).strip()) <= set("-|: ")]
    row_ids = [i for i, _ in dom.table_rows if i is not None]
    bad_ids = sorted({i for i in row_ids if not i or i.endswith("-") or row_ids.count(i) > 1})
    check(not dashes and not bad_ids,
          f"no table row is a Markdown separator and every row id is non-empty and unique "
          f"(separator rows: {len(dashes)}; bad ids: {bad_ids[:5]})")
    check(not dom.latexisms,
          f"no LaTeX or ASCII groups (_{{ ^{{ ^( _() in the page's text outside code ({dom.latexisms[:5]})")

    def label_gap_check(attrs, where):
        for prefix in ("anim", "ball-anim"):
            gap = attrs.get(f"data-{prefix}-label-gap")
            try:
                ok = gap == "none" or float(gap) >= 0.0
            except (TypeError, ValueError):
                ok = False
            check(ok, f"{where}: animation {prefix}'s distance labels do not overlap (narrowest gap: {gap} px)")

    label_gap_check(dom.root_attrs, "at 1400 px")

    def figure_checks(attrs, where):
        # Every figure drawn from a chart has a legend box (<g class="legend">
        # in its SVG); the page's probe lists each one whose box has a plotted
        # point (a curve's vertex, a marker) inside it.
        charts = sum(1 for p in (report_dir / "figures").glob("*.png"))
        covers = attrs.get("data-legend-covers")
        legends = attrs.get("data-legend-figures")
        points = attrs.get("data-legend-points")
        check(covers == "" and legends == str(charts) and int(points or 0) > 1000,
              f"{where}: no legend box covers a plotted point ({legends} legends of {charts} charts, "
              f"{points} points checked; covered: {covers!r})")
        # The smallest figure text as rendered: at least 9 px, readable
        # on a phone (the figures' 15-16 px text shown at 960 px).
        font = attrs.get("data-figure-font-min")
        try:
            ok = float(font) >= MIN_FIGURE_FONT_PX
        except (TypeError, ValueError):
            ok = False
        check(ok, f"{where}: figure text is at least {MIN_FIGURE_FONT_PX} px as rendered "
                  f"(smallest: {font} px, in {attrs.get('data-figure-font-min-at')})")

    figure_checks(dom.root_attrs, "at 1400 px")

    raw = (report_dir / "report.html").read_text(encoding="utf-8")
    external = re.findall(r"""(?:src|href)\s*=\s*["']?(?:https?:)?//[^"'\s>]+|url\(\s*["']?(?:https?:)?//[^)]+\)|@import|<link\b""", raw)
    check(not external, f"no external resources referenced ({external[:3]})")

    if phone_file is not None:
        phone = Dom()
        phone.feed(phone_file.read_text(encoding="utf-8"))
        overflow = phone.root_attrs.get("data-layout-overflow")
        width = phone.root_attrs.get("data-layout-width")
        check(overflow == "",
              f"at a phone's width ({width} px) no figure or animation overflows and the page does not scroll sideways "
              f"(overflowing: {overflow!r})")
        label_gap_check(phone.root_attrs, f"at a phone's width ({width} px)")
        figure_checks(phone.root_attrs, f"at a phone's width ({width} px)")

    if failures:
        print(f"browser-test: {len(failures)} check(s) failed", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
