//! The presentation layer: figures, animation data, and the report files.
//!
//! The animation's geometry is checked against eq. (8): a circular log that
//! rolls without slipping turns by `dθ = dx/r` while `π r² = π r0² + b x`, so
//! `θ = 2π (r − r0)/b` and turn k starts at radius `r0 + k b`. The files are
//! checked for what a reader relies on: every figure, the numbers behind it,
//! the version and parameters, no external resources.

use std::f64::consts::TAU;
use std::path::Path;

use snowroll::{ModelKind, Sampling, Scenario, ScenarioFile, SimOptions, Trajectory};
use snowroll_io::VERSION;
use snowroll_report::plot::{png_size, Axis, Chart, PlotError, Provenance, Series, Style, NO_DATA};
use snowroll_report::{
    figure_csv, Animation, Claim, ClaimId, ClaimResult, Criterion, Figure, Metadata, Report,
    ReportError, Tolerance, Verdict,
};

/// Trapezoid rule for θ = ∫ dx/r over steps of 5 ms: the error per step is
/// O(Δx³ r''), far below this with Δx ≲ 0.05 m and r ≥ 0.1 m.
const THETA_REL_TOL: f64 = 1e-5;
/// With no snow r is constant and the trapezoid rule is exact up to rounding.
const SNOWLESS_THETA_TOL: f64 = 1e-12;
/// Rows of pixels from the top of a PNG holding the title.
const TITLE_BAND_PX: u32 = 50;
/// A pixel this dark (sum of RGB) is ink, not background or grid.
const INK_MAX_RGB_SUM: u32 = 200;

fn scenario(b: f64) -> Scenario {
    Scenario::new(ScenarioFile {
        snow_depth: b,
        ..ScenarioFile::default()
    })
    .unwrap()
}

fn run(kind: ModelKind, s: &Scenario, t_end: f64, sampling: Sampling) -> Trajectory {
    let opts = SimOptions {
        t_end,
        sampling,
        ..SimOptions::default()
    };
    kind.build().simulate(s, &opts).unwrap()
}

#[test]
fn eq8_circular_log_has_rolled_two_pi_r_minus_r0_over_b() {
    let s = scenario(0.01);
    let traj = run(ModelKind::Energy, &s, 3.0, Sampling::Every(0.005));
    let anim = Animation::from_trajectory(&traj, &s, usize::MAX).unwrap();
    assert_eq!(anim.frames.len(), traj.samples.len());
    let (b, r0) = (s.snow_depth(), s.initial_radius());
    for f in &anim.frames[1..] {
        let exact = TAU * (f.r_m - r0) / b;
        approx::assert_relative_eq!(f.theta_rad, exact, max_relative = THETA_REL_TOL);
        assert_eq!(f.turn, (f.theta_rad / TAU).floor() as u64);
    }
    assert!(
        anim.frames.last().unwrap().turn >= 5,
        "3 s should roll several turns"
    );
}

#[test]
fn eq8_turn_k_starts_at_radius_r0_plus_k_b() {
    let s = scenario(0.01);
    let traj = run(ModelKind::TorqueCm, &s, 3.0, Sampling::Every(0.005));
    let anim = Animation::from_trajectory(&traj, &s, 200).unwrap();
    let (b, r0) = (s.snow_depth(), s.initial_radius());
    let last_turn = anim.frames.iter().map(|f| f.turn).max().unwrap();
    assert_eq!(anim.turn_start_radius_m.len() as u64, last_turn + 1);
    for (k, &r) in anim.turn_start_radius_m.iter().enumerate() {
        // r is linear in θ, so interpolating at θ = 2πk is exact up to the θ error.
        approx::assert_relative_eq!(r, r0 + k as f64 * b, max_relative = THETA_REL_TOL);
    }
}

#[test]
fn app_a_snowless_log_turns_x_over_r0() {
    let s = scenario(0.0);
    let traj = run(ModelKind::Snowless, &s, 2.0, Sampling::Steps);
    let anim = Animation::from_trajectory(&traj, &s, usize::MAX).unwrap();
    for f in &anim.frames[1..] {
        let exact = f.x_m / s.initial_radius();
        approx::assert_relative_eq!(f.theta_rad, exact, max_relative = SNOWLESS_THETA_TOL);
    }
}

#[test]
fn thinned_frames_are_real_samples_spread_in_time() {
    let s = scenario(0.01);
    let traj = run(ModelKind::Energy, &s, 3.0, Sampling::Every(0.001));
    let max = 100;
    let anim = Animation::from_trajectory(&traj, &s, max).unwrap();
    assert!(anim.frames.len() <= max && anim.frames.len() >= max - 1);
    let first = traj.samples.first().unwrap();
    let last = traj.samples.last().unwrap();
    assert_eq!(anim.frames[0].t_s.to_bits(), first.t_s.to_bits());
    assert_eq!(
        anim.frames.last().unwrap().t_s.to_bits(),
        last.t_s.to_bits()
    );
    for f in &anim.frames {
        assert!(traj
            .samples
            .iter()
            .any(|s| s.t_s.to_bits() == f.t_s.to_bits() && s.x_m.to_bits() == f.x_m.to_bits()));
    }
    // Evenly spread: no gap larger than two grid spacings of the thinning.
    let spacing = (last.t_s - first.t_s) / (max - 1) as f64;
    assert!(anim
        .frames
        .windows(2)
        .all(|w| w[1].t_s - w[0].t_s <= 2.0 * spacing));
}

fn provenance() -> Provenance {
    Provenance {
        software: format!("snowroll {VERSION}"),
        params: vec![
            ("alpha_deg".into(), "30".into()),
            ("snow_depth".into(), "0.01".into()),
        ],
    }
}

fn speed_chart(runs: &[Trajectory]) -> Chart {
    runs.iter().enumerate().fold(
        Chart::new(
            "speed",
            "Speed down the slope",
            Axis::linear("time t", "s").column("t_s"),
            Axis::linear("speed v", "m/s").column("v_m_s"),
        ),
        |c, (i, t)| {
            let style = if i % 2 == 0 {
                Style::Line
            } else {
                Style::Dashed
            };
            c.with_series(
                Series::from_samples(t.model.id(), &t.samples, |s| s.t_s, |s| s.v_m_s).style(style),
            )
        },
    )
}

fn circular_runs() -> Vec<Trajectory> {
    let s = scenario(0.01);
    [ModelKind::TorqueCm, ModelKind::Energy, ModelKind::Loney]
        .iter()
        .map(|&k| run(k, &s, 5.0, Sampling::Every(0.05)))
        .collect()
}

#[test]
fn png_is_drawn_with_the_embedded_font_and_records_provenance() {
    let chart = speed_chart(&circular_runs());
    let bytes = chart.render_png(&provenance()).unwrap();
    let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    let mut reader = decoder.read_info().unwrap();
    let info = reader.info();
    assert_eq!((info.width, info.height), png_size());
    let texts: Vec<String> = info
        .utf8_text
        .iter()
        .map(|t| t.get_text().unwrap())
        .collect();
    assert!(texts.iter().any(|t| t.contains(VERSION)), "{texts:?}");
    assert!(texts.iter().any(|t| t.contains("snow_depth = 0.01")));
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let frame = reader.next_frame(&mut buf).unwrap();
    assert_eq!(frame.color_type, png::ColorType::Rgb);
    let width = frame.width as usize;
    // The title band has ink only if the font rendered text (there is no
    // other drawing above the plot area).
    let ink = buf[..width * 3 * TITLE_BAND_PX as usize]
        .chunks(3)
        .filter(|p| u32::from(p[0]) + u32::from(p[1]) + u32::from(p[2]) <= INK_MAX_RGB_SUM)
        .count();
    assert!(ink > 100, "only {ink} dark pixels in the title band");
}

#[test]
fn svg_has_title_axis_units_legend_and_provenance() {
    let runs = circular_runs();
    let svg = speed_chart(&runs).render_svg(&provenance()).unwrap();
    assert!(svg.starts_with("<svg"));
    // Shown at 960 × 600, drawn on a canvas SVG_OVERSAMPLE times finer so
    // that nearly flat curves do not step; lines join round.
    let k = snowroll_report::plot::SVG_OVERSAMPLE;
    assert!(k >= 4, "a whole pixel of the canvas must be at most 1/4 px");
    assert!(svg.contains(&format!("viewBox=\"0 0 {} {}\"", 960 * k, 600 * k)));
    assert!(svg.contains("width=\"960\" height=\"600\""));
    assert!(svg.contains("stroke-linejoin=\"round\""));
    for text in ["Speed down the slope", "time t [s]", "speed v [m/s]"] {
        assert!(svg.contains(text), "missing {text:?}");
    }
    for t in &runs {
        // Legend entries are `<text …>\nNAME\n</text>`.
        assert!(
            svg.contains(&format!(">\n{}\n</text>", t.model.id())),
            "no legend entry for {}",
            t.model.id()
        );
    }
    assert!(svg.contains(&format!(
        "<!-- speed: Speed down the slope | snowroll {VERSION}"
    )));
}

/// The numbers of attribute `key` in `text` (`key="N"`), in order.
fn attr_values(text: &str, key: &str) -> Vec<f64> {
    text.split(&format!(" {key}=\""))
        .skip(1)
        .filter_map(|s| s.split('"').next()?.parse().ok())
        .collect()
}

/// Issue 36, item 3: the page's figure is drawn for a phone's width. It is
/// PAGE_WIDTH wide in its viewBox (so it scales to any box), its legend is
/// a group under every plotted point and every axis label, no entry runs
/// past the figure's right edge, and its smallest text, shown 327 px wide
/// (a 360 px phone inside the page's margins), is at least 9 px.
#[test]
fn issue36_the_page_figure_has_its_legend_under_the_plot_and_fits_a_phone() {
    let runs = circular_runs();
    let mut chart = speed_chart(&runs);
    // A label longer than the figure is wide: broken into lines that fit.
    chart.series[0].name = "a very long legend entry that names a model, its equation and its terminal value, 0.3333 G".to_string();
    let svg = chart.render_svg_page(&provenance()).unwrap();
    let k = f64::from(snowroll_report::plot::SVG_OVERSAMPLE);
    let w = f64::from(snowroll_report::plot::PAGE_WIDTH);
    assert!(svg.contains(&format!("width=\"{w}\"")) && svg.contains("viewBox=\"0 0 "));
    let (body, legend) = svg
        .split_once("<g class=\"legend\">")
        .expect("no legend group");
    let legend_top = attr_values(legend, "y")
        .into_iter()
        .fold(f64::INFINITY, f64::min);
    let lowest_plot = attr_values(body, "y")
        .into_iter()
        .chain(attr_values(body, "cy"))
        .chain(
            body.split("points=\"")
                .skip(1)
                .flat_map(|p| p.split('"').next().unwrap_or("").split_whitespace())
                .filter_map(|xy| xy.split(',').nth(1)?.parse().ok()),
        )
        .fold(0.0, f64::max);
    assert!(
        lowest_plot < legend_top,
        "the plot reaches {lowest_plot}, the legend starts at {legend_top}"
    );
    // No title or footer: the page's caption has them.
    for t in body.split("<text").skip(1) {
        let t = t.split("</text>").next().unwrap_or("");
        assert!(
            !t.contains("Speed down the slope") && !t.contains(VERSION),
            "title or footer drawn: {t}"
        );
    }
    // Every legend line fits the figure's width (the font's advance is at
    // most 0.62 em for these labels in DejaVu Sans).
    let sizes = attr_values(&svg, "font-size");
    for line in legend.split("</text>").filter_map(|t| {
        let x: f64 = t.split(" x=\"").nth(1)?.split('"').next()?.parse().ok()?;
        let size: f64 = t
            .split("font-size=\"")
            .nth(1)?
            .split('"')
            .next()?
            .parse()
            .ok()?;
        let text = t.rsplit('>').next()?.trim().to_string();
        Some((x, size, text))
    }) {
        let (x, size, text) = line;
        let right = x + 0.62 * size * text.chars().count() as f64;
        assert!(
            right <= w * k,
            "legend line {text:?} reaches {right} of {}",
            w * k
        );
    }
    assert!(
        chart.series.len() < legend.matches("</text>").count(),
        "the long label was not broken"
    );
    let smallest = sizes.into_iter().fold(f64::INFINITY, f64::min) / k;
    let shown = smallest * 327.0 / w;
    assert!(
        shown >= 9.0,
        "smallest text {smallest} px is {shown:.2} px on a phone"
    );
}

#[test]
fn a_chart_missing_a_unit_or_data_is_refused() {
    let base = Chart::new("c", "T", Axis::linear("x", ""), Axis::linear("y", "m"))
        .with_series(Series::new("s", vec![(1.0, 1.0)]));
    assert!(matches!(
        base.render_svg(&provenance()),
        Err(PlotError::MissingText {
            field: "x-axis unit",
            ..
        })
    ));
}

/// A scenario in which a quantity never arises (no turn completed at 85°,
/// say) gives a chart with no series or no point an axis can show: it is
/// drawn as empty axes that say so, in both formats, not refused.
#[test]
fn a_chart_with_nothing_to_draw_says_so() {
    let empty = Chart::new("c", "T", Axis::linear("x", "m"), Axis::linear("y", "m"));
    let nothing_positive = Chart::new("c", "T", Axis::linear("x", "m"), Axis::log("y", "m"))
        .with_series(Series::new("s", vec![(1.0, 0.0), (2.0, -1.0)]));
    let nan = Chart::new("c", "T", Axis::linear("x", "m"), Axis::linear("y", "m")).with_series(
        Series::new("s", vec![(f64::NAN, 1.0), (1.0, f64::INFINITY)]),
    );
    for chart in [&empty, &nothing_positive, &nan] {
        assert!(chart.is_empty());
        let svg = chart.render_svg(&provenance()).unwrap();
        assert!(svg.contains(NO_DATA), "no note in {svg}");
        // Nothing plotted: no curve and no marker.
        // (The legend's keys are lines too: only the plot is searched.)
        let body = svg.split("<g class=\"legend\">").next().unwrap();
        let drawn = body
            .split("<polyline")
            .skip(1)
            .filter(|p| {
                // A curve is 2 px wide (8 in the 4× viewBox), an axis or tick 1.
                let attr = |k: &str| {
                    let from = p.find(&format!("{k}=\"")).unwrap() + k.len() + 2;
                    p[from..].split('"').next().unwrap().trim().to_string()
                };
                attr("stroke-width") == "8" && !attr("points").is_empty()
            })
            .count();
        assert_eq!(drawn, 0, "a curve in {svg}");
        assert!(!body.contains("<circle"));
        assert!(chart
            .render_png(&provenance())
            .unwrap()
            .starts_with(b"\x89PNG"));
    }
    // A chart with one drawable point is not empty, and carries no note.
    let one = Chart::new("c", "T", Axis::linear("x", "m"), Axis::log("y", "m"))
        .with_series(Series::new("s", vec![(1.0, 0.0), (2.0, 3.0)]));
    assert!(!one.is_empty());
    assert!(!one.render_svg(&provenance()).unwrap().contains(NO_DATA));
}

#[test]
fn a_chart_with_a_bad_name_is_refused() {
    let bad_name = Chart::new("A b", "T", Axis::linear("x", "m"), Axis::linear("y", "m"))
        .with_series(Series::new("s", vec![(1.0, 1.0)]));
    assert!(matches!(
        bad_name.validate(),
        Err(PlotError::InvalidName { .. })
    ));
}

#[test]
fn csv_keeps_every_point_even_those_a_log_axis_cannot_draw() {
    let pts = vec![(1.0, 0.5), (2.0, 0.0), (3.0, 1.0 / 3.0), (4.0, -2.5e-7)];
    let chart = Chart::new(
        "approach",
        "Approach",
        Axis::log("distance x", "m").column("x_m"),
        Axis::log("|a − a∞|", "m/s²").column("da_m_s2"),
    )
    .with_series(Series::new("eq. (4)", pts.clone()));
    assert_eq!(chart.omitted_points(), 2);
    let fig = Figure::new(chart, "caption");
    let meta = Metadata::new("t").param("alpha_deg", 30);
    let csv = figure_csv(&fig, &meta).unwrap();
    assert!(csv.starts_with(&format!("# snowroll {VERSION}\n")));
    assert!(csv.contains("# alpha_deg = 30\n"));
    assert!(csv.contains("# points_not_drawn = 2\n"));
    let body: String = csv
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| format!("{l}\n"))
        .collect();
    let mut rdr = csv::Reader::from_reader(body.as_bytes());
    assert_eq!(
        rdr.headers().unwrap().iter().collect::<Vec<_>>(),
        ["series", "x_m", "da_m_s2"]
    );
    let got: Vec<(String, f64, f64)> = rdr.deserialize().map(Result::unwrap).collect();
    assert_eq!(got.len(), pts.len());
    for ((name, x, y), (px, py)) in got.iter().zip(&pts) {
        assert_eq!(name, "eq. (4)");
        assert_eq!((x.to_bits(), y.to_bits()), (px.to_bits(), py.to_bits()));
    }
}

static HOLDS: Claim = Claim {
    // Real ids (the set of ids is closed); the rest of the row is made up.
    id: ClaimId::SnowlessLimit,
    paper_ref: "App. A",
    statement: "A <b>bold</b> claim & more | with a pipe.",
    method: "m",
    tolerances: &[Criterion {
        quantity: "q",
        tolerance: Tolerance::Relative { value: 1e-8 },
        reason: "why",
    }],
    expected: Verdict::Holds,
};

static CORRECTED: Claim = Claim {
    id: ClaimId::LagrangianDiffersFromEnergy,
    paper_ref: "eq. (21)",
    statement: "s",
    method: "m",
    tolerances: &[],
    expected: Verdict::HoldsAfterCorrection("docs/errata.md (21)"),
};

fn small_report() -> Report {
    let s = scenario(0.01);
    let runs = circular_runs();
    let anim_run = run(ModelKind::Energy, &s, 2.0, Sampling::Every(0.02));
    Report {
        metadata: Metadata::new("Test report").param("alpha_deg", 30),
        claims: vec![
            ClaimResult {
                claim: &HOLDS,
                headline: None,
                measured: "1.0e-12".into(),
                verdict: Verdict::Holds,
                evidence: "e".into(),
            },
            ClaimResult {
                claim: &CORRECTED,
                headline: None,
                measured: "2".into(),
                verdict: Verdict::Refuted,
                evidence: "differs".into(),
            },
        ],
        tables: vec![snowroll_report::Table {
            title: "Where | they part".into(),
            caption: "c".into(),
            header: vec!["a".into(), "b".into()],
            rows: vec![vec!["1".into(), "<2>".into()]],
        }],
        figures: vec![
            Figure::new(speed_chart(&runs), "Speeds."),
            Figure::new(
                Chart::new(
                    "radius",
                    "Radius",
                    Axis::log("time t", "s"),
                    Axis::linear("radius r", "m"),
                )
                .with_series(Series::from_samples(
                    "energy",
                    &runs[1].samples,
                    |s| s.t_s,
                    |s| s.r_m,
                )),
                "Radii.",
            )
            .param("snow_depth", 0.01),
        ],
        animations: vec![Animation::from_trajectory(&anim_run, &s, 300).unwrap()],
        explorer: false,
    }
}

fn read(dir: &Path, name: &str) -> String {
    std::fs::read_to_string(dir.join(name)).unwrap()
}

#[test]
fn write_to_produces_every_file_each_recording_version_and_parameters() {
    let dir = tempfile::tempdir().unwrap();
    let report = small_report();
    let written = report.write_to(dir.path()).unwrap();
    let expected = [
        "figures/geometry.svg",
        "figures/speed.svg",
        "figures/speed.png",
        "data/speed.csv",
        "figures/radius.svg",
        "figures/radius.png",
        "data/radius.csv",
        "data/animation.csv",
        "data/claims.csv",
        "claims.json",
        "report.md",
        "report.html",
    ];
    assert_eq!(written.len(), expected.len());
    for name in expected {
        assert!(dir.path().join(name).is_file(), "missing {name}");
    }
    // No temporary file is left behind by the write-then-rename.
    for sub in ["", "figures", "data"] {
        for e in std::fs::read_dir(dir.path().join(sub)).unwrap() {
            let name = e.unwrap().file_name().into_string().unwrap();
            assert!(!name.starts_with('.'), "left over {name}");
        }
    }
    let tag = format!("snowroll {VERSION}");
    for name in [
        "figures/speed.svg",
        "data/speed.csv",
        "data/animation.csv",
        "data/claims.csv",
        "claims.json",
        "report.md",
        "report.html",
    ] {
        let text = read(dir.path(), name);
        assert!(text.contains(&tag), "{name} lacks the version");
        assert!(text.contains("alpha_deg"), "{name} lacks the parameters");
    }
    // A figure's own parameters replace the report's in its files.
    assert!(read(dir.path(), "data/radius.csv").contains("# snow_depth = 0.01"));
    // data/claims.csv: one row per claim after the header, each claim row of
    // the page links it.
    let claims_csv = read(dir.path(), "data/claims.csv");
    let mut rows = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .from_reader(claims_csv.as_bytes());
    let ids: Vec<String> = rows.records().map(|r| r.unwrap()[0].to_string()).collect();
    let want: Vec<String> = report
        .claims
        .iter()
        .map(|r| r.claim.id.to_string())
        .collect();
    assert_eq!(ids, want);
    let html = read(dir.path(), "report.html");
    assert_eq!(
        html.matches("href=\"data/claims.csv\"").count(),
        report.claims.len()
    );
}

#[test]
fn claims_json_carries_verdicts_errata_and_mismatches() {
    let report = small_report();
    let v: serde_json::Value = serde_json::from_str(&report.claims_json().unwrap()).unwrap();
    assert_eq!(v["software"], format!("snowroll {VERSION}"));
    assert_eq!(v["params"]["alpha_deg"], "30");
    let claims = v["claims"].as_array().unwrap();
    assert_eq!(claims.len(), 2);
    assert_eq!(claims[0]["id"], "snowless-limit");
    assert_eq!(claims[0]["verdict"]["verdict"], "holds");
    assert_eq!(claims[0]["as_expected"], true);
    assert_eq!(claims[1]["expected"]["erratum"], "docs/errata.md (21)");
    assert_eq!(claims[1]["verdict"]["verdict"], "refuted");
    assert_eq!(claims[1]["as_expected"], false);
    assert_eq!(v["tally"]["unexpected"], 1);
    // The headline as the report prints it: the finding where the verdict
    // is the expected one, a sentence saying otherwise where it is not.
    assert!(
        claims[1]["headline"]
            .as_str()
            .unwrap()
            .contains("did not reach its finding: refuted where the claims table expects holds after correction"),
        "{}",
        claims[1]["headline"]
    );
    assert!(!claims[0]["headline"]
        .as_str()
        .unwrap()
        .contains("did not reach"));
}

#[test]
fn html_is_self_contained_and_holds_claims_figures_and_animation() {
    let report = small_report();
    let html = report.to_html().unwrap();
    // Nothing is fetched: no external scripts, styles, fonts or images.
    for needle in [
        "<link",
        "@import",
        "src=\"http",
        "href=\"http",
        "url(http",
        "@font-face",
    ] {
        assert!(!html.contains(needle), "found {needle}");
    }
    assert!(html.contains(&format!(
        "<body data-figures=\"2\" data-claims=\"2\" data-models=\"{}\">",
        snowroll::ModelKind::ALL.len()
    )));
    assert!(html.contains("id=\"claims-table\""));
    // Text is escaped, verdicts are in words as well as colour.
    assert!(html.contains("A &lt;b&gt;bold&lt;/b&gt; claim &amp; more"));
    assert!(html.contains("✓ holds</span>"));
    assert!(html.contains("✗ refuted</span>"));
    assert!(html.contains("class=\"expectation\""));
    assert!(html.contains("\">&lt;2&gt;</td>"));
    assert!(html.contains("expected: holds after correction (docs/errata.md (21))"));
    for name in ["speed", "radius"] {
        let start = html
            .find(&format!("<figure id=\"fig-{name}\""))
            .unwrap_or_else(|| panic!("no figure {name}"));
        let end = start + html[start..].find("</figure>").unwrap();
        assert!(
            html[start..end].contains("<svg"),
            "figure {name} has no SVG"
        );
    }
    // The embedded animation data parse back to the frames.
    let start = html
        .find("<script type=\"application/json\" class=\"anim-data\" id=\"anim-data\" data-prefix=\"anim\">")
        .unwrap();
    let body = &html[start..];
    let json = &body[body.find('>').unwrap() + 1..body.find("</script>").unwrap()];
    let v: serde_json::Value = serde_json::from_str(json).unwrap();
    let anim = &report.animations[0];
    assert_eq!(v["t"].as_array().unwrap().len(), anim.frames.len());
    assert_eq!(
        v["ring_r"].as_array().unwrap().len(),
        anim.turn_start_radius_m.len()
    );
    let last = anim.frames.last().unwrap();
    let x_last = v["x"].as_array().unwrap().last().unwrap().as_f64().unwrap();
    approx::assert_relative_eq!(x_last, last.x_m, max_relative = 1e-5);
    assert!(html.contains("id=\"anim-play\"") && html.contains("id=\"anim-speed\""));
}

#[test]
fn markdown_has_the_claims_table_and_links_every_figure() {
    let md = small_report().to_markdown();
    assert!(md.contains(&format!("snowroll {VERSION}")));
    assert!(md.contains(
        "| <a id=\"claim-snowless-limit\"></a>`snowless-limit` | App. A | A &lt;b&gt;bold&lt;/b&gt; claim &amp; more \\| with a pipe."
    ));
    assert!(md.contains("**✗ refuted (expected: holds after correction (docs/errata.md (21)))**"));
    // The tolerances shown are the checks' own, with their reasons, and the
    // report says what "as expected" means, in the report's one notation.
    assert!(md.contains("Tolerances: q: relative 10⁻⁸ (why)"));
    // The findings open the report, one line per claim linked to its row;
    // how each was checked folds out in the appendix.
    let findings = md.find("## Findings").unwrap();
    assert!(findings < md.find("## The problem").unwrap());
    assert!(md.contains("](#claim-snowless-limit)"));
    assert!(md.contains("<details><summary><code>snowless-limit</code>"));
    assert!(md.contains(snowroll_report::EXPECTATION_NOTE));
    // Extra tables, escaped like the claims.
    assert!(md.contains("| 1 | &lt;2&gt; |"));
    for name in ["speed", "radius"] {
        assert!(md.contains(&format!("](figures/{name}.svg)")));
        assert!(md.contains(&format!("(data/{name}.csv)")));
    }
    // The opening has the geometry drawing and the models' assumptions, as
    // report.html has (issue 9).
    assert!(md.contains("![The geometry](figures/geometry.svg)"));
    assert!(md.contains("| Model (alias) | Note | Equation of motion | Assumptions | a∞/G |"));
}

#[test]
fn two_figures_with_one_name_are_refused() {
    let mut report = small_report();
    let dup = report.figures[0].clone();
    report.figures.push(dup);
    let dir = tempfile::tempdir().unwrap();
    assert!(matches!(
        report.write_to(dir.path()),
        Err(ReportError::DuplicateFigure { name }) if name == "speed"
    ));
}

#[test]
fn a_figure_named_like_the_geometry_drawing_is_refused() {
    // figures/geometry.svg holds the opening's drawing; a chart of that name
    // would overwrite it.
    let mut report = small_report();
    report.figures[0].chart.name = "geometry".to_string();
    let dir = tempfile::tempdir().unwrap();
    assert!(matches!(
        report.write_to(dir.path()),
        Err(ReportError::DuplicateFigure { name }) if name == "geometry"
    ));
}

/// A trajectory laid out as the turn model of `docs/turn-model.md` records it:
/// turn k has nominal radius r_k = r0 + k b and starts at X_k = Σ_{j<k} 2π r_j;
/// within it x = X_k + r_k θ. (No turn model exists yet, so the samples are
/// built from these formulae; the model tag is only a label.)
fn turn_shaped_trajectory(s: &Scenario, turns: u64, per_turn: usize) -> Trajectory {
    use snowroll::{Sample, Stop, StopReason, TurnState};
    let (r0, b) = (s.initial_radius(), s.snow_depth());
    let mut samples = Vec::new();
    let mut states = Vec::new();
    let mut start_x = 0.0;
    for k in 0..turns {
        let rk = r0 + k as f64 * b;
        for q in 0..per_turn {
            let theta = TAU * q as f64 / per_turn as f64;
            samples.push(Sample {
                t_s: samples.len() as f64 * 0.01,
                x_m: start_x + rk * theta,
                v_m_s: 1.0,
                a_m_s2: 0.0,
                r_m: rk,
                mass_kg: 1.0,
                normal_n: 1.0,
                friction_n: 0.0,
                friction_ratio: Some(0.0),
            });
            states.push(TurnState {
                turn: k,
                theta_rad: theta,
                omega_rad_s: 1.0 / rk,
            });
        }
        start_x += TAU * rk;
    }
    let end = *samples.last().unwrap();
    Trajectory {
        model: ModelKind::QuasiCircular,
        samples,
        turn_states: states,
        stop: Stop {
            reason: StopReason::Turns,
            t_s: end.t_s,
            x_m: end.x_m,
            v_m_s: end.v_m_s,
            turn: None,
        },
        stats: Default::default(),
        ledger: Vec::new(),
    }
}

#[test]
fn turn_model_frames_count_whole_turns_and_start_each_at_r0_plus_k_b() {
    let s = scenario(0.02);
    let traj = turn_shaped_trajectory(&s, 4, 36);
    let anim = Animation::from_trajectory(&traj, &s, usize::MAX).unwrap();
    assert!(!anim.circular);
    for (f, k) in anim.frames.iter().zip(&traj.turn_states) {
        approx::assert_relative_eq!(
            f.theta_rad,
            TAU * k.turn as f64 + k.theta_rad,
            max_relative = SNOWLESS_THETA_TOL
        );
        assert_eq!(f.turn, k.turn);
    }
    let (r0, b) = (s.initial_radius(), s.snow_depth());
    assert_eq!(anim.turn_start_radius_m.len(), 4);
    for (k, &r) in anim.turn_start_radius_m.iter().enumerate() {
        approx::assert_relative_eq!(r, r0 + k as f64 * b, max_relative = SNOWLESS_THETA_TOL);
    }
    // Mismatched turn states are refused rather than drawn wrongly.
    let mut broken = traj.clone();
    broken.turn_states.pop();
    assert!(matches!(
        Animation::from_trajectory(&broken, &s, 100),
        Err(ReportError::InvalidAnimation { .. })
    ));
}

#[test]
fn a_snowball_animation_is_a_growing_shaded_ball() {
    // issue 11: the ball on its natural swath follows eq. (8) too, so it has
    // turned by 2π (r − r0)/b; the animation says it is a ball, and grows.
    let s = Scenario::new(ScenarioFile {
        shape: snowroll::Shape::Sphere,
        ..ScenarioFile::default()
    })
    .unwrap();
    let traj = run(ModelKind::TorqueCm, &s, 3.0, Sampling::Every(0.005));
    let anim = Animation::from_trajectory(&traj, &s, usize::MAX).unwrap();
    assert_eq!(anim.shape, snowroll::Shape::Sphere);
    assert!(anim.title.contains("snowball"), "{}", anim.title);
    assert!(anim.caption.contains("shaded"), "{}", anim.caption);
    let (b, r0) = (s.snow_depth(), s.initial_radius());
    for f in &anim.frames[1..] {
        approx::assert_relative_eq!(
            f.theta_rad,
            TAU * (f.r_m - r0) / b,
            max_relative = THETA_REL_TOL
        );
    }
    assert!(anim.frames.last().unwrap().r_m > 1.5 * r0);
    assert!(anim.to_json().unwrap().contains("\"shape\":\"sphere\""));
    let log = run(
        ModelKind::TorqueCm,
        &scenario(0.01),
        1.0,
        Sampling::Every(0.01),
    );
    let log_anim = Animation::from_trajectory(&log, &scenario(0.01), 50).unwrap();
    assert!(log_anim
        .to_json()
        .unwrap()
        .contains("\"shape\":\"cylinder\""));
}

/// The log and the snowball each get their own section, elements and
/// frames file; two animations of one shape are refused (their elements
/// would share ids).
#[test]
fn a_log_and_a_ball_animate_side_by_side_and_one_shape_twice_is_refused() {
    let mut report = small_report();
    let ball = Scenario::new(ScenarioFile {
        shape: snowroll::Shape::Sphere,
        ..ScenarioFile::from(scenario(0.01))
    })
    .unwrap();
    let traj = run(ModelKind::TorqueCm, &ball, 2.0, Sampling::Every(0.02));
    let anim = Animation::from_trajectory(&traj, &ball, 100).unwrap();
    // The ball's radius grows from r0 as it rolls (π r² = π r0² + b x).
    let (first, last) = (anim.frames[0], *anim.frames.last().unwrap());
    approx::assert_relative_eq!(first.r_m, 0.1, max_relative = 1e-12);
    approx::assert_relative_eq!(
        last.r_m,
        (0.01 + 0.01 * last.x_m / std::f64::consts::PI).sqrt(),
        max_relative = 1e-9
    );
    report.animations.push(anim);
    let html = report.to_html().unwrap();
    for id in ["animation", "ball-animation"] {
        assert!(html.contains(&format!("<section id=\"{id}\"")), "{id}");
    }
    for id in [
        "anim-canvas",
        "ball-anim-canvas",
        "anim-status",
        "ball-anim-status",
    ] {
        assert_eq!(html.matches(&format!("id=\"{id}\"")).count(), 1, "{id}");
    }
    assert!(html.contains("data-prefix=\"ball-anim\""));
    let dir = tempfile::tempdir().unwrap();
    report.write_to(dir.path()).unwrap();
    assert!(read(dir.path(), "data/ball-animation.csv").contains("# shape = sphere"));
    let md = report.to_markdown();
    assert!(md.contains("data/ball-animation.csv"));
    // Twice the log: refused.
    let log = report.animations[0].clone();
    report.animations.push(log);
    assert!(matches!(
        report.validate(),
        Err(ReportError::InvalidAnimation { .. })
    ));
}
