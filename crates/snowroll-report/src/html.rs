//! `report.html`: one self-contained page. CSS, the figures' SVG, the
//! animation's data (JSON) and its script are all inline; the page loads
//! nothing from the network and uses the reader's own sans-serif font.
//!
//! Hooks for the browser test (`.ci/browser-test.sh`): `body[data-figures]`
//! and `body[data-claims]` give the expected counts, each figure is a
//! `figure[data-figure=NAME]`, the claims table is `#claims-table`, each
//! animation is a `section[data-shape]` whose `#PREFIX-status` (`anim` for
//! the log, `ball-anim` for the snowball) carries `data-frame`,
//! `data-max-frame` and `data-ticks`, and script errors are counted in
//! `html[data-js-errors]`.

use std::fmt::Write as _;

use super::errata::{errata_section, link_citations};
use super::findings::{headline, method_text, short_measured, Group};
use super::intro::intro_section;
use super::markup::{esc, prose};
use super::CLAIMS_CSV;
use super::{ClaimId, ClaimResult, Figure, Report, ReportError, Tally, EXPECTATION_NOTE};

const CSS: &str = include_str!("../assets/report.css");
const SCRIPT: &str = include_str!("../assets/report.js");

/// Counts script errors on the root element before anything else runs.
const ERROR_TRAP: &str = "(function(){var n=0;function mark(){n+=1;document.documentElement.setAttribute('data-js-errors',String(n));}window.addEventListener('error',mark);window.addEventListener('unhandledrejection',mark);})();";

/// Records, once the page has laid out, what sticks out sideways: each
/// figure whose drawing (its scrolling frame, for a figure) is wider than
/// the figure or than the window, and
/// the page itself if it scrolls sideways. The browser test reads
/// `html[data-layout-overflow]` at a phone's width (empty: nothing overflows).
/// Records, once the page has laid out, for the browser test: every plotted
/// point (vertex of a curve, marker) of a figure that lies inside its legend
/// box (`html[data-legend-covers]`, `figure@x,y` of the first per figure;
/// empty when none), how many figures have a legend and how many points
/// were checked, and the smallest rendered size of figure text, px
/// (`data-figure-font-min`, at `data-figure-font-min-at`).
const FIGURE_PROBE: &str = "window.addEventListener('load',function(){var d=document.documentElement,covers=[],legends=0,points=0,fmin=1e9,fat='';document.querySelectorAll('figure.figure svg').forEach(function(svg){var name=svg.closest('figure').id;svg.querySelectorAll('text').forEach(function(t){var m=t.getScreenCTM(),f=parseFloat(t.getAttribute('font-size')||'0');if(m&&f>0&&t.textContent.trim()){var px=f*Math.sqrt(m.a*m.a+m.b*m.b);if(px<fmin){fmin=px;fat=name;}}});var g=svg.querySelector('g.legend');if(!g){return;}var frame=g.querySelector('rect');if(!frame){return;}legends+=1;var b=frame.getBoundingClientRect(),hit='';function at(x,y,m){var p=svg.createSVGPoint();p.x=x;p.y=y;p=p.matrixTransform(m);points+=1;if(!hit&&p.x>b.left&&p.x<b.right&&p.y>b.top&&p.y<b.bottom){hit=name+'@'+Math.round(p.x-b.left)+','+Math.round(p.y-b.top);}}svg.querySelectorAll('polyline,polygon,circle,rect').forEach(function(e){if(g.contains(e)){return;}var m=e.getScreenCTM();if(!m){return;}var k=e.tagName;if(k==='circle'){at(+e.getAttribute('cx'),+e.getAttribute('cy'),m);}else if(k==='rect'){var w=+e.getAttribute('width'),h=+e.getAttribute('height');if(w<100&&h<100){at(+e.getAttribute('x')+w/2,+e.getAttribute('y')+h/2,m);}}else{for(var i=0;i<e.points.numberOfItems;i++){var q=e.points.getItem(i);at(q.x,q.y,m);}}});if(hit){covers.push(hit);}});d.setAttribute('data-legend-covers',covers.join(' '));d.setAttribute('data-legend-figures',String(legends));d.setAttribute('data-legend-points',String(points));d.setAttribute('data-figure-font-min',fmin<1e9?fmin.toFixed(1):'');d.setAttribute('data-figure-font-min-at',fat);});";

const LAYOUT_PROBE: &str = "window.addEventListener('load',function(){var d=document.documentElement,w=d.clientWidth,bad=[];document.querySelectorAll('figure,.anim').forEach(function(f){var r=f.getBoundingClientRect(),s=f.querySelector('.svg-wrap,svg,canvas');var sr=s?s.getBoundingClientRect():r;if(r.right>w+1||sr.right>r.right+1||sr.width>r.width+1){bad.push(f.id||'figure');}});if(d.scrollWidth>w+1){bad.push('page('+d.scrollWidth+'>'+w+')');}d.setAttribute('data-layout-overflow',bad.join(' '));d.setAttribute('data-layout-width',String(w));});";

/// Makes text safe inside an HTML comment.
fn comment(s: &str) -> String {
    s.replace("--", "- -").replace('>', "&gt;")
}

/// The page.
pub(super) fn render(report: &Report, svgs: &[String]) -> Result<String, ReportError> {
    let mut h = String::with_capacity(64 * 1024 + svgs.iter().map(String::len).sum::<usize>());
    page_head(&mut h, report);
    page_top(&mut h, report);
    findings_section(&mut h, &report.claims);
    intro_section(&mut h);
    claims_section(&mut h, &report.claims, &report.figures);
    for (i, t) in report.tables.iter().enumerate() {
        table_section(&mut h, i, t);
    }
    super::losses_section::html(&mut h, report);
    for anim in &report.animations {
        animation_section(&mut h, anim);
    }
    figures_section(&mut h, report, svgs);
    errata_section(&mut h);
    params_section(&mut h, report);
    h.push_str("</main>\n");
    page_end(&mut h, report)?;
    Ok(h)
}

/// The document's head: metadata, a comment with the version and the
/// parameters, the title, the error trap and the inline CSS.
fn page_head(h: &mut String, report: &Report) {
    let m = &report.metadata;
    let params_line = m
        .params
        .iter()
        .map(|(k, v)| format!("{k} = {v}"))
        .collect::<Vec<_>>()
        .join("; ");
    h.push_str("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
    h.push_str("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n");
    let _ = writeln!(
        h,
        "<meta name=\"generator\" content=\"{}\">",
        esc(&m.software)
    );
    let _ = writeln!(
        h,
        "<!-- {} | {} -->",
        comment(&m.software),
        comment(&params_line)
    );
    let _ = writeln!(h, "<title>{}</title>", esc(&m.title));
    let _ = writeln!(h, "<script>{ERROR_TRAP}</script>");
    let _ = writeln!(h, "<style>\n{CSS}</style>\n</head>");
}

/// The opening of the body (with the counts the browser test reads), the
/// page's header and its navigation bar.
fn page_top(h: &mut String, report: &Report) {
    let m = &report.metadata;
    let _ = writeln!(
        h,
        "<body data-figures=\"{}\" data-claims=\"{}\" data-models=\"{}\">",
        report.figures.len(),
        report.claims.len(),
        snowroll::models::ModelKind::ALL.len()
    );
    let _ = writeln!(
        h,
        "<header class=\"top\"><h1>{}</h1><p class=\"sub\">{} · every number below was computed by this program</p>",
        esc(&m.title),
        esc(&m.software)
    );
    h.push_str(
        "<nav><a href=\"#findings\">Findings</a><a href=\"#problem\">The problem</a><a href=\"#claims\">Claims</a>",
    );
    for (i, t) in report.tables.iter().enumerate() {
        let _ = write!(h, "<a href=\"#table-{i}\">{}</a>", esc(&t.title));
    }
    super::losses_section::nav(h, report);
    for anim in &report.animations {
        let _ = write!(
            h,
            "<a href=\"#{}\">{}</a>",
            anim.name(),
            match anim.shape {
                snowroll::scenario::Shape::Cylinder => "Animation",
                snowroll::scenario::Shape::Sphere => "The snowball",
            }
        );
    }
    h.push_str(
        "<a href=\"#figures\">Figures</a><a href=\"#errata\">Errata</a><a href=\"#parameters\">Parameters</a></nav></header>\n<main>\n",
    );
}

/// The footer, each animation's data as JSON, and the scripts.
///
/// # Errors
/// [`ReportError`] when an animation cannot be written as JSON.
fn page_end(h: &mut String, report: &Report) -> Result<(), ReportError> {
    let m = &report.metadata;
    let _ = writeln!(
        h,
        "<footer>Generated by {} · self-contained page: no network, no external fonts.<br>{}</footer>",
        esc(&m.software),
        explorer_sentence(report.explorer, true)
    );
    for anim in &report.animations {
        // `</` cannot end the script element early once escaped.
        let json = anim.to_json()?.replace("</", "<\\/");
        let _ = writeln!(
            h,
            "<script type=\"application/json\" class=\"anim-data\" id=\"{p}-data\" data-prefix=\"{p}\">{json}</script>",
            p = anim.prefix()
        );
    }
    if !report.animations.is_empty() {
        let _ = writeln!(h, "<script>\n{SCRIPT}</script>");
    }
    let _ = writeln!(h, "<script>{FIGURE_PROBE}</script>");
    let _ = writeln!(h, "<script>{LAYOUT_PROBE}</script>");
    h.push_str("</body>\n</html>\n");
    Ok(())
}

/// Links to the figures that support claim `id`, numbered as in the report,
/// each with its data file, and to the claim's row of `data/claims.csv`.
fn figure_links(id: ClaimId, figures: &[Figure]) -> String {
    let links: Vec<String> = figures
        .iter()
        .enumerate()
        .filter(|(_, f)| f.supports.contains(&id))
        .map(|(i, f)| {
            let name = esc(&f.chart.name);
            format!(
                "<a href=\"#fig-{name}\">Figure {}</a> (<a href=\"data/{name}.csv\">data</a>)",
                i + 1
            )
        })
        .collect();
    let see = if links.is_empty() {
        String::new()
    } else {
        format!("See {}. ", links.join(", "))
    };
    format!(
        "<br><span class=\"figlinks\">{see}Measured values: row <code>{}</code> of \
         <a href=\"data/{CLAIMS_CSV}\">the claims' data (CSV)</a>.</span>",
        esc(id.as_str())
    )
}

/// "Findings": the tally, then one line per claim (its verdict, its
/// headline linked to its row of the claims table, the measured value),
/// grouped: refuted, corrected (naming the erratum), beyond the note, holds.
fn findings_section(h: &mut String, claims: &[ClaimResult]) {
    h.push_str("<section id=\"findings\">\n<h2>Findings</h2>\n");
    let _ = writeln!(
        h,
        "<p class=\"tally\">{}</p>",
        prose(&Tally::of(claims).sentence())
    );
    for group in Group::ALL {
        let rows: Vec<&ClaimResult> = claims.iter().filter(|r| Group::of(r) == group).collect();
        if rows.is_empty() {
            continue;
        }
        let _ = writeln!(h, "<h3>{}</h3>\n<ul class=\"findings\">", group.title());
        for r in rows {
            let erratum = match r.verdict {
                super::Verdict::HoldsAfterCorrection(e) => {
                    format!(
                        " <span class=\"erratum\">({})</span>",
                        link_citations(&prose(e))
                    )
                }
                _ => String::new(),
            };
            let _ = writeln!(
                h,
                "<li data-claim=\"{id}\"><span class=\"verdict {class}\" title=\"{label}\">{symbol}</span> \
                 <a href=\"#claim-{id}\">{headline}</a>{erratum}: <span class=\"measured\">{measured}</span></li>",
                id = esc(r.claim.id.as_str()),
                class = r.verdict.class(),
                label = esc(r.verdict.class()),
                symbol = r.verdict.symbol(),
                headline = prose(&headline(r)),
                measured = prose(&short_measured(&r.measured)),
            );
        }
        h.push_str("</ul>\n");
    }
    h.push_str("</section>\n");
}

/// "Claims of the note": one line per claim (where in the note, statement,
/// the measured value, verdict); how it was checked, the tolerances, the
/// whole measurement and the evidence fold out of the statement.
fn claims_section(h: &mut String, claims: &[ClaimResult], figures: &[Figure]) {
    let tally = Tally::of(claims);
    h.push_str("<section id=\"claims\">\n<h2>Claims of the note</h2>\n");
    let _ = writeln!(h, "<p class=\"tally\">{}</p>", prose(&tally.sentence()));
    let _ = writeln!(
        h,
        "<p class=\"expectation\">{}</p>",
        prose(EXPECTATION_NOTE)
    );
    h.push_str(
        "<p class=\"legend\"><span class=\"verdict holds\">✓ holds</span> \
         <span class=\"verdict corrected\">✎ holds after correction</span> \
         <span class=\"verdict refuted\">✗ refuted</span> \
         <span class=\"verdict inconclusive\">? inconclusive</span></p>\n",
    );
    h.push_str(
        "<div class=\"table-wrap\"><table id=\"claims-table\" class=\"claims\">\n<thead><tr>\
         <th scope=\"col\">Claim</th><th scope=\"col\">Statement</th>\
         <th scope=\"col\">Measured</th><th scope=\"col\">Verdict</th>\
         </tr></thead>\n<tbody>\n",
    );
    for r in claims {
        let c = r.claim;
        let expected = if r.as_expected() {
            String::new()
        } else {
            format!(
                "<br><span class=\"unexpected\">expected: {}</span>",
                esc(&c.expected.label())
            )
        };
        let _ = writeln!(
            h,
            "<tr id=\"claim-{id}\" data-verdict=\"{class}\" data-as-expected=\"{ok}\">\
             <td data-label=\"Claim\"><strong>{paper}</strong><br><code>{id}</code></td>\
             <td data-label=\"Statement\">{statement}<details><summary>How it was checked</summary>\
             <p>{method}</p><p class=\"tol\">Tolerances: {tol}</p><p>Measured: {measured}</p>\
             <p>{evidence}{figures}</p></details></td>\
             <td data-label=\"Measured\">{short}</td>\
             <td data-label=\"Verdict\"><span class=\"verdict {class}\">{symbol} {label}</span>{expected}</td></tr>",
            id = esc(c.id.as_str()),
            class = r.verdict.class(),
            ok = r.as_expected(),
            paper = prose(c.paper_ref),
            statement = prose(c.statement),
            method = prose(&method_text(c)),
            tol = prose(&c.tolerances_text()),
            measured = prose(&r.measured),
            short = prose(&short_measured(&r.measured)),
            symbol = r.verdict.symbol(),
            label = link_citations(&prose(&r.verdict.label())),
            evidence = link_citations(&prose(&r.evidence)),
            figures = figure_links(c.id, figures),
        );
    }
    h.push_str("</tbody></table></div>\n</section>\n");
}

fn table_section(h: &mut String, index: usize, t: &super::Table) {
    let _ = writeln!(
        h,
        "<section id=\"table-{index}\">\n<h2>{}</h2>\n<p>{}</p>",
        esc(&t.title),
        prose(&t.caption)
    );
    h.push_str("<div class=\"table-wrap\"><table class=\"parting\">\n<thead><tr>");
    for c in &t.header {
        let _ = write!(h, "<th scope=\"col\">{}</th>", prose(c));
    }
    h.push_str("</tr></thead>\n<tbody>\n");
    for row in &t.rows {
        h.push_str("<tr>");
        for c in row {
            let _ = write!(h, "<td>{}</td>", prose(c));
        }
        h.push_str("</tr>\n");
    }
    h.push_str("</tbody></table></div>\n</section>\n");
}

fn animation_section(h: &mut String, anim: &super::Animation) {
    let n = anim.frames.len();
    let p = anim.prefix();
    let _ = writeln!(
        h,
        "<section id=\"{}\" data-shape=\"{}\">\n<h2>{}</h2>\n<p>{}</p>",
        anim.name(),
        anim.shape,
        esc(&anim.title),
        prose(&anim.caption)
    );
    let _ = writeln!(
        h,
        "<div class=\"anim\" id=\"{p}-box\"><canvas id=\"{p}-canvas\" width=\"960\" height=\"540\" role=\"img\" \
         aria-label=\"{}\"></canvas>",
        esc(&anim.title)
    );
    let _ = write!(
        h,
        "<div class=\"controls\"><button id=\"{p}-play\" type=\"button\" aria-pressed=\"true\">Pause</button>\
         <label>Speed <select id=\"{p}-speed\">\
         <option value=\"0.1\">0.1×</option><option value=\"0.25\">0.25×</option>\
         <option value=\"0.5\">0.5×</option><option value=\"1\" selected>1×</option>\
         <option value=\"2\">2×</option><option value=\"4\">4×</option></select></label>"
    );
    let _ = write!(
        h,
        "<label class=\"scrub\">Time <input id=\"{p}-scrub\" type=\"range\" min=\"0\" max=\"{}\" value=\"0\" step=\"1\"></label>",
        n.saturating_sub(1)
    );
    let _ = writeln!(
        h,
        "</div>\n<output id=\"{p}-status\" class=\"anim-status\" data-frame=\"0\" data-max-frame=\"0\" data-ticks=\"0\" \
         data-frames=\"{n}\">frame 0 / {n}</output></div>\n</section>"
    );
}

fn figures_section(h: &mut String, report: &Report, svgs: &[String]) {
    h.push_str("<section id=\"figures\">\n<h2>Figures</h2>\n");
    for (i, (fig, svg)) in report.figures.iter().zip(svgs).enumerate() {
        let name = esc(&fig.chart.name);
        let prov = fig.provenance(&report.metadata).line();
        let supports = if fig.supports.is_empty() {
            String::new()
        } else {
            let links: Vec<String> = fig
                .supports
                .iter()
                .map(|id| {
                    format!(
                        "<a href=\"#claim-{0}\"><code>{0}</code></a>",
                        esc(id.as_str())
                    )
                })
                .collect();
            format!(
                " <span class=\"supports\">Evidence for: {}.</span>",
                links.join(", ")
            )
        };
        let _ = writeln!(
            h,
            "<figure id=\"fig-{name}\" class=\"figure\" data-figure=\"{name}\">\n<div class=\"svg-wrap\">{svg}</div>\n\
             <figcaption><strong>Figure {num}. {title}.</strong> {caption}{supports} \
             <span class=\"files\">Files: <a href=\"figures/{name}.svg\">SVG</a>, \
             <a href=\"figures/{name}.png\">PNG</a>, <a href=\"data/{name}.csv\">data (CSV)</a>. \
             {prov}</span></figcaption>\n</figure>",
            num = i + 1,
            title = prose(&fig.chart.title),
            caption = prose(&fig.caption),
            prov = esc(&prov),
        );
    }
    h.push_str("</section>\n");
}

fn params_section(h: &mut String, report: &Report) {
    let m = &report.metadata;
    h.push_str("<section id=\"parameters\">\n<h2>Parameters and version</h2>\n");
    h.push_str("<table class=\"params\"><tbody>\n");
    let _ = writeln!(
        h,
        "<tr><th scope=\"row\">program</th><td>{}</td></tr>",
        esc(&m.software)
    );
    for (k, v) in &m.params {
        let _ = writeln!(
            h,
            "<tr><th scope=\"row\">{}</th><td>{}</td></tr>",
            esc(k),
            esc(v)
        );
    }
    h.push_str("</tbody></table>\n</section>\n");
}

/// Where to explore the models interactively: the explorer written beside
/// the report (`paper --explorer`), linked; else how to make or serve it.
/// `html`: with a link and code elements, else Markdown.
pub(super) fn explorer_sentence(beside: bool, html: bool) -> String {
    let code = |c: &str| {
        if html {
            format!("<code>{}</code>", esc(c))
        } else {
            format!("`{c}`")
        }
    };
    if beside {
        let link = if html {
            "<a href=\"explorer.html\">explorer.html</a>".to_string()
        } else {
            "[explorer.html](explorer.html)".to_string()
        };
        format!(
            "Explore these models with sliders: {link}, beside this report (one page, the same library \
             compiled to WebAssembly, no network)."
        )
    } else {
        format!(
            "Explore these models with sliders: the explorer, one HTML file built from a checkout by {}, \
             or served by {}; {} puts it beside this report and links it here.",
            code("bash scripts/build-explorer.sh explorer.html"),
            code("snowroll serve"),
            code("snowroll paper --explorer explorer.html")
        )
    }
}
