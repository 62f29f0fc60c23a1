//! The report's sections of results beyond the note: the snowball and the
//! losses (issue 11, `docs/snowball-and-losses.md`) and the unwinding roll
//! (issue 35, `docs/unwinding.md`). Each lists the results its claims
//! established, one paragraph each, with the verdict and the measured
//! numbers of the claim that carries it and links to its row of the claims
//! table, its figures and the snowball's animation. It reads the report;
//! nothing is computed here.

use std::fmt::Write as _;

use super::markup::{esc, markdown_prose, prose};
use super::{ClaimId, ClaimResult, Report};

/// Id of the snowball's section in the page.
pub(super) const SECTION_ID: &str = "snowball-and-losses";
/// Its heading.
pub(super) const TITLE: &str = "The snowball and the losses";

/// One section: its id in the page, heading, opening paragraph and results.
pub(super) struct Section {
    id: &'static str,
    title: &'static str,
    intro: &'static str,
    results: &'static [Item],
}

/// The sections, in the order of the report.
const SECTIONS: [Section; 2] = [
    Section {
        id: SECTION_ID,
        title: TITLE,
        intro: "The note's title names a snowball but treats only the log, and fn. 5 sets the losses aside. \
             The program adds both on the same models, integrator and outputs (docs/snowball-and-losses.md): \
             the ball with I = (2/5) M r² in every circular model, and air drag, rolling resistance and the \
             work of compacting the snow picked up, each with its energy in a ledger. What the claims below found:",
        results: &RESULTS,
    },
    Section {
        id: "unwinding-roll",
        title: "The unwinding roll",
        intro: "Run backwards, the snow log is a roll of paper, tape or carpet that lays its layer down as it rolls \
             (b < 0 in eq. (8), down to the core radius; docs/unwinding.md): an experiment for a classroom. Every \
             circular model takes it; the turn models do not (their log climbs a step onto each layer). The laid \
             layer leaves at rest: the momentum balance of eq. (2) counts that, the torque balances of eqs. (3) \
             and (5) differ in the angular momentum it takes away, and the energy balances of eqs. (11), (14) and \
             (15) in the potential energy it keeps. What the claims below found:",
        results: &UNWINDING,
    },
];

/// The unwinding roll's results.
const UNWINDING: [Item; 2] = [
    Item {
        claim: ClaimId::UnwindingTextbookSpeed,
        lead: "On a level floor, from rest, only the energy balances move the roll: as it thins, its centre falls. Eq. (15) is then the textbook unrolling carpet (Serway, ch. 10), v² = 4g(R³ − r³)/(3r²) and √(14gR/3) at r = R/2, while the torque analyses of eqs. (4) and (6) have no term that starts it. Down a slope every model unwinds it, the torque balances fastest (docs/unwinding.md gives each model's speed at R/2 and time to unwind).",
    },
    Item {
        claim: ClaimId::UnwindingHollowRoll,
        lead: "The textbook's roll is of one material down to its centre; a real one is hollow, on a tube. With the tube's own mass (--core-mass) every balance runs with the roll's M(r) and I(r), and eq. (15) keeps its energy integral: a 5 g tube under 0.70 kg of paper makes the roll about a fifth faster at R/2 than the textbook says. A measurement should give the tube, or fit it.",
    },
];

/// One result: the claim that carries it and the sentence that says what it
/// means.
struct Item {
    claim: ClaimId,
    lead: &'static str,
}

/// The results, in the order of the derivation.
const RESULTS: [Item; 5] = [
    Item {
        claim: ClaimId::SnowballFiveSevenths,
        lead: "A uniform ball (I = (2/5) M r²) rolling on a bare slope accelerates at (5/7) g sin α, the ball's counterpart of the log's 2/3 (App. A).",
    },
    Item {
        claim: ClaimId::TptLetterClosedForm,
        lead: "The letter in The Physics Teacher 57, p. 436 (2019), on S. Rubin's rolling snowball, gives a closed form whose acceleration starts at (5/7) g sin α and tends to (1/6) g sin α. It is the ball's torque-about-the-centre model (eq. (4)'s balance, Loney's fn. 4 for a ball) with the swath 2r: the claim is reproduced, by that model only.",
    },
    Item {
        claim: ClaimId::SnowballTerminalFractions,
        lead: "Picking up the layer over its diameter (π r² = π r₀² + b x, as for the log), the always-round ball tends to a terminal fraction of g sin α set by its balance: 1/6 (torque about the centre), 1/7 (contact line), 2/7 (energy), 5/28 (eq. (21) as printed), each below the log's 1/5, 1/6, 1/3 and 2/9. These fractions, and the letter's 1/6 with them, hold for the swath 2r only: a fixed width gives 15/67 (torque about the centre), the contact chord 2√(2rb − b²) of a ball pressed through the layer 25/127, approached only like b/r (docs/snowball-and-losses.md §1.3); the snowless 5/7 holds for any swath.",
    },
    Item {
        claim: ClaimId::SnowlessDragTerminalVelocity,
        lead: "fn. 5 sets dissipation aside. With air drag and no snow the log reaches the terminal velocity v_t² = M g sin α/(½ ρ_a C_d A) of the closed form; with snow it has none, since the mass grows faster than the frontal area and the speed keeps growing.",
    },
    Item {
        claim: ClaimId::EnergyLedgerBalances,
        lead: "With drag, rolling resistance and compaction the energy is accounted for at every sample: the kinetic energy, the work of each loss and what the model's own equation destroys (the inelastic pick-up of the torque models) add up to the potential energy released. The physics library's own tests check the same sum on 2700 random runs.",
    },
];

/// The claim result of `id`, if the report has it.
fn result(report: &Report, id: ClaimId) -> Option<&ClaimResult> {
    report.claims.iter().find(|r| r.claim.id == id)
}

/// `(number, name)` of each figure of `report` that supports claim `id`,
/// numbered as in the report.
fn figures_of(report: &Report, id: ClaimId) -> Vec<(usize, &str)> {
    report
        .figures
        .iter()
        .enumerate()
        .filter(|(_, f)| f.supports.contains(&id))
        .map(|(i, f)| (i + 1, f.chart.name.as_str()))
        .collect()
}

/// Whether the report animates the snowball.
fn has_ball(report: &Report) -> bool {
    report
        .animations
        .iter()
        .any(|a| a.shape == snowroll::scenario::Shape::Sphere)
}

/// Whether the report holds any of the section's claims (a report without
/// them has no section).
fn applies(section: &Section, report: &Report) -> bool {
    section
        .results
        .iter()
        .any(|r| result(report, r.claim).is_some())
}

/// The links of the navigation bar to the sections the report has.
pub(super) fn nav(h: &mut String, report: &Report) {
    for section in SECTIONS.iter().filter(|s| applies(s, report)) {
        let _ = write!(
            h,
            "<a class=\"minor\" href=\"#{}\">{}</a>",
            section.id, section.title
        );
    }
}

/// The sections in the page.
pub(super) fn html(h: &mut String, report: &Report) {
    for section in &SECTIONS {
        section_html(h, section, report);
    }
}

/// One section in the page, folded (below the first screen; its title shows,
/// its results open on a click).
fn section_html(h: &mut String, section: &Section, report: &Report) {
    if !applies(section, report) {
        return;
    }
    let _ = writeln!(
        h,
        "<section id=\"{}\">\n<details class=\"fold\"><summary><h2>{}</h2></summary>\n<p>{}</p>",
        section.id,
        section.title,
        prose(section.intro)
    );
    h.push_str("<ul class=\"results\">\n");
    for r in section.results {
        let Some(found) = result(report, r.claim) else {
            continue;
        };
        let mut links = vec![format!(
            "<a href=\"#claim-{0}\">claim <code>{0}</code></a>",
            esc(r.claim.as_str())
        )];
        links.extend(
            figures_of(report, r.claim)
                .into_iter()
                .map(|(n, name)| format!("<a href=\"#fig-{}\">Figure {n}</a>", esc(name))),
        );
        if r.claim == ClaimId::TptLetterClosedForm && has_ball(report) {
            links.push("<a href=\"#ball-animation\">the snowball's animation</a>".to_string());
        }
        let _ = writeln!(
            h,
            "<li id=\"result-{id}\">{lead} <span class=\"verdict {class}\">{symbol} {label}</span>: {measured}. \
             <span class=\"figlinks\">See {links}.</span></li>",
            id = esc(r.claim.as_str()),
            lead = prose(r.lead),
            class = found.verdict.class(),
            symbol = found.verdict.symbol(),
            label = esc(&found.verdict.label()),
            measured = prose(&found.measured),
            links = links.join(", "),
        );
    }
    h.push_str("</ul>\n</details>\n</section>\n");
}

/// The sections in `report.md`.
pub(super) fn markdown(md: &mut String, report: &Report) {
    for section in &SECTIONS {
        section_markdown(md, section, report);
    }
}

/// One section in `report.md`.
fn section_markdown(md: &mut String, section: &Section, report: &Report) {
    if !applies(section, report) {
        return;
    }
    let _ = writeln!(md, "\n## {}\n", section.title);
    for r in section.results {
        let Some(found) = result(report, r.claim) else {
            continue;
        };
        let figures: Vec<String> = figures_of(report, r.claim)
            .into_iter()
            .map(|(n, _)| format!("Figure {n}"))
            .collect();
        let see = if figures.is_empty() {
            String::new()
        } else {
            format!(" See {}.", figures.join(", "))
        };
        let _ = writeln!(
            md,
            "* {} **{} {}** (`{}`): {}.{see}",
            markdown_prose(r.lead),
            found.verdict.symbol(),
            found.verdict.label(),
            r.claim,
            markdown_prose(&found.measured),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::{Axis, Chart, Series};
    use crate::{Figure, Metadata, Verdict, CLAIMS};

    /// A report holding the section's claims (with made-up findings) and
    /// one figure that supports the drag claim.
    fn report() -> Report {
        let mut report = Report::new(Metadata::new("t"));
        report.claims = RESULTS
            .iter()
            .map(|r| ClaimResult {
                headline: None,
                claim: &CLAIMS
                    .iter()
                    .find(|c| c.claim.id == r.claim)
                    .expect("every result names a claim of the table")
                    .claim,
                measured: format!("measured {}", r.claim),
                verdict: Verdict::Holds,
                evidence: String::new(),
            })
            .collect();
        let chart = Chart::new(
            "speed",
            "s",
            Axis::linear("t", "s"),
            Axis::linear("v", "m/s"),
        )
        .with_series(Series::new("v", vec![(0.0, 0.0), (1.0, 1.0)]));
        report.figures =
            vec![Figure::new(chart, "c").supports(&[ClaimId::SnowlessDragTerminalVelocity])];
        report
    }

    #[test]
    fn each_result_links_its_claim_and_the_figures_that_support_it() {
        let report = report();
        let mut h = String::new();
        html(&mut h, &report);
        assert!(h.starts_with(&format!("<section id=\"{SECTION_ID}\">")));
        for r in &RESULTS {
            assert!(
                h.contains(&format!("<li id=\"result-{}\">", r.claim)),
                "{}",
                r.claim
            );
            assert!(
                h.contains(&format!("href=\"#claim-{}\"", r.claim)),
                "{}",
                r.claim
            );
            assert!(h.contains(&format!("measured {}", r.claim)), "{}", r.claim);
        }
        // Figure 1 supports the drag claim only: one link to it.
        assert_eq!(h.matches("href=\"#fig-speed\">Figure 1</a>").count(), 1);
        let mut md = String::new();
        markdown(&mut md, &report);
        assert_eq!(md.matches("\n* ").count(), RESULTS.len());
        // Without the claims there is no section.
        let mut empty = Report::new(Metadata::new("t"));
        empty.figures = report.figures.clone();
        let mut h = String::new();
        html(&mut h, &empty);
        assert!(h.is_empty());
        // The unwinding roll's section comes with its claim, and its link.
        assert!(!report_has("unwinding-roll", &report));
        let mut with = report.clone();
        let mut found = with.claims[0].clone();
        found.claim = &CLAIMS
            .iter()
            .find(|c| c.claim.id == ClaimId::UnwindingTextbookSpeed)
            .unwrap()
            .claim;
        with.claims.push(found);
        assert!(report_has("unwinding-roll", &with));
    }

    /// Whether the page and the navigation of `report` have section `id`.
    fn report_has(id: &str, report: &Report) -> bool {
        let (mut h, mut n) = (String::new(), String::new());
        html(&mut h, report);
        nav(&mut n, report);
        let page = h.contains(&format!("<section id=\"{id}\">"));
        assert_eq!(page, n.contains(&format!("href=\"#{id}\"")), "{id}");
        page
    }
}
