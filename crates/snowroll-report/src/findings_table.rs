//! The findings of `report.html`: one table with every claim once, grouped
//! as [`Group`] orders them (refuted first). A row states the finding (its
//! headline, [`headline`]), the number measured and the verdict, and where
//! in the note the claim stands; the note's statement, how it was checked,
//! the tolerances, the whole measurement and the evidence fold out of it.

use std::fmt::Write as _;

use super::errata::link_citations;
use super::findings::{headline, method_text, short_measured, Group};
use super::markup::{esc, prose};
use super::CLAIMS_CSV;
use super::{ClaimId, ClaimResult, Figure, Tally, EXPECTATION_NOTE};

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

/// The verdict's legend above the table.
const LEGEND: &str = "<p class=\"legend\"><span class=\"verdict holds\">✓ holds</span> \
     <span class=\"verdict corrected\">✎ holds after correction</span> \
     <span class=\"verdict refuted\">✗ refuted</span> \
     <span class=\"verdict inconclusive\">? inconclusive</span></p>\n";

/// The header row of each group's table.
const HEAD: &str = "<thead><tr><th scope=\"col\">Verdict</th><th scope=\"col\">Finding</th>\
     <th scope=\"col\">Measured</th><th scope=\"col\">In the note</th></tr></thead>\n";

/// "Findings": the tally, then every claim once, one table per [`Group`]
/// under its heading, each group folded out of it (`<details>`): open,
/// except the claims that hold as printed, which a reader opens.
pub(super) fn findings_section(h: &mut String, claims: &[ClaimResult], figures: &[Figure]) {
    h.push_str("<section id=\"findings\">\n<h2>Findings: every claim of the note</h2>\n");
    let _ = writeln!(
        h,
        "<p class=\"tally\">{}</p>",
        prose(&Tally::of(claims).sentence())
    );
    let _ = writeln!(
        h,
        "<p class=\"expectation\">{}</p>",
        prose(EXPECTATION_NOTE)
    );
    h.push_str(LEGEND);
    h.push_str("<div id=\"claims-table\" class=\"claims-groups\"><span id=\"claims\"></span>\n");
    for group in Group::ALL {
        let rows: Vec<&ClaimResult> = claims.iter().filter(|r| Group::of(r) == group).collect();
        if rows.is_empty() {
            continue;
        }
        let open = if group == Group::Holds { "" } else { " open" };
        let _ = writeln!(
            h,
            "<details class=\"group\" data-group=\"{}\"{open}><summary><h3>{} ({})</h3></summary>\n\
             <div class=\"table-wrap\"><table class=\"claims\">\n{HEAD}<tbody>",
            group.key(),
            group.title(),
            rows.len()
        );
        for r in rows {
            claim_row(h, r, figures);
        }
        h.push_str("</tbody></table></div>\n</details>\n");
    }
    h.push_str("</div>\n</section>\n");
}

/// One claim's row.
fn claim_row(h: &mut String, r: &ClaimResult, figures: &[Figure]) {
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
         <td data-label=\"Verdict\"><span class=\"verdict {class}\">{symbol} {label}</span>{expected}</td>\
         <td data-label=\"Finding\" class=\"finding\">{headline}<details><summary>How it was checked</summary>\
         <p><strong>The note:</strong> {statement}</p><p>{method}</p><p class=\"tol\">Tolerances: {tol}</p>\
         <p>Measured: {measured}</p><p>{evidence}{figures}</p></details></td>\
         <td data-label=\"Measured\" class=\"measured\">{short}</td>\
         <td data-label=\"In the note\" class=\"where\">{paper}</td></tr>",
        id = esc(c.id.as_str()),
        class = r.verdict.class(),
        ok = r.as_expected(),
        paper = prose(c.paper_ref),
        headline = prose(&headline(r)),
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
