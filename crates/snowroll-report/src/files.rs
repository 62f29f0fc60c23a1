//! Writing a report's files: CSV data, `claims.json`, and the atomic
//! write-then-rename every file goes through.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

use crate::plot::Scale;
use serde::ser::{Serialize, SerializeMap, Serializer};

use super::error::{io_err, ReportError};
use super::{html, markdown, Figure, Metadata, RenderedFigure, Report, Tally, CLAIMS_CSV};
use snowroll_io::CsvTable;

/// Writes `bytes` to a temporary file next to `path`, then renames it into place.
pub(crate) fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), ReportError> {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let tmp = path.with_file_name(format!(".{name}.tmp{}", std::process::id()));
    let result = fs::File::create(&tmp)
        .and_then(|mut f| {
            f.write_all(bytes)?;
            f.sync_all()
        })
        .and_then(|()| fs::rename(&tmp, path));
    if result.is_err() {
        // Best effort: the temporary file may not exist.
        let _ = fs::remove_file(&tmp);
    }
    result.map_err(io_err(path))
}

/// A report's outputs: the HTML page, the Markdown, `claims.json`, and
/// every file written into a folder (here, above the renderers they call,
/// rather than beside the report's types).
impl Report {
    /// The self-contained HTML page, with the figures' SVGs inline, each
    /// drawn for a page that may be a phone's
    /// ([`Chart::render_svg_page`](crate::plot::Chart::render_svg_page):
    /// narrower, the legend under the plot).
    ///
    /// # Errors
    /// [`ReportError`] when a figure cannot be drawn or the data not serialised.
    pub fn to_html(&self) -> Result<String, ReportError> {
        self.validate()?;
        html::render(self, &self.page_svgs()?)
    }

    /// Every figure drawn for the page, in order.
    ///
    /// # Errors
    /// [`ReportError::Plot`] when a figure cannot be drawn.
    pub(crate) fn page_svgs(&self) -> Result<Vec<String>, ReportError> {
        self.figures
            .iter()
            .map(|f| Ok(f.chart.render_svg_page(&f.provenance(&self.metadata))?))
            .collect()
    }

    /// The Markdown report (figures linked as `figures/NAME.svg`).
    pub fn to_markdown(&self) -> String {
        markdown::render(self)
    }

    /// `claims.json`: version, parameters, tally and every claim result.
    ///
    /// # Errors
    /// [`ReportError::Json`] if serialisation fails.
    pub fn claims_json(&self) -> Result<String, ReportError> {
        claims_json(self)
    }

    /// Writes the whole report into `dir` (created if missing) and returns
    /// the paths written, in order.
    ///
    /// # Errors
    /// [`ReportError`] when the report is invalid, a figure cannot be drawn
    /// or a file cannot be written.
    pub fn write_to(&self, dir: &Path) -> Result<Vec<PathBuf>, ReportError> {
        self.validate()?;
        let rendered = self.render_figures()?;
        write_all(self, &rendered, dir)
    }
}

/// The CSV of a figure: `#` lines with version, title, axes and parameters,
/// then one row per point: `series,<x column>,<y column>`. Every point is
/// kept, including those a logarithmic axis cannot draw.
///
/// # Errors
/// [`ReportError::Output`] if serialisation fails.
pub fn figure_csv(figure: &Figure, meta: &Metadata) -> Result<String, ReportError> {
    let chart = &figure.chart;
    let prov = figure.provenance(meta);
    let scale = |s: Scale| match s {
        Scale::Linear => "linear",
        Scale::Log => "log",
    };
    let mut lines = vec![
        ("figure".to_string(), chart.name.clone()),
        ("title".to_string(), chart.title.clone()),
        (
            "x".to_string(),
            format!("{} ({} axis)", chart.x.title(), scale(chart.x.scale)),
        ),
        (
            "y".to_string(),
            format!("{} ({} axis)", chart.y.title(), scale(chart.y.scale)),
        ),
        (
            "points_not_drawn".to_string(),
            chart.omitted_points().to_string(),
        ),
    ];
    lines.extend(prov.params.iter().cloned());
    let mut w = CsvTable::new(&prov.software, &lines);
    {
        w.text_record(["series", chart.x.column.as_str(), chart.y.column.as_str()])?;
        let non_finite = |source| ReportError::NonFinite {
            figure: chart.name.clone(),
            source,
        };
        let mut row = 0;
        for s in &chart.series {
            for &(x, y) in &s.points {
                row += 1;
                for (column, value) in [(&chart.x.column, x), (&chart.y.column, y)] {
                    snowroll_io::check_finite(&value, Some(row)).map_err(|mut e| {
                        e.field.clone_from(column);
                        non_finite(e)
                    })?;
                }
                w.row(&(s.name.as_str(), x, y))?;
            }
        }
    }
    Ok(w.finish()?)
}

/// Serialises `(key, value)` pairs as one JSON object, in their order.
struct OrderedMap<'a>(&'a [(String, String)]);

impl Serialize for OrderedMap<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.0.len()))?;
        for (k, v) in self.0 {
            map.serialize_entry(k, v)?;
        }
        map.end()
    }
}

#[derive(serde::Serialize)]
struct ClaimRow<'a> {
    #[serde(flatten)]
    claim: &'a super::Claim,
    /// The headline the report prints for it ([`super::headline`]).
    headline: String,
    measured: &'a str,
    verdict: super::Verdict,
    evidence: &'a str,
    as_expected: bool,
}

#[derive(serde::Serialize)]
struct ClaimsDoc<'a> {
    software: &'a str,
    title: &'a str,
    params: OrderedMap<'a>,
    tally: Tally,
    claims: Vec<ClaimRow<'a>>,
}

/// `claims.json`.
pub(super) fn claims_json(report: &Report) -> Result<String, ReportError> {
    let m = &report.metadata;
    let doc = ClaimsDoc {
        software: &m.software,
        title: &m.title,
        params: OrderedMap(&m.params),
        tally: Tally::of(&report.claims),
        claims: report
            .claims
            .iter()
            .map(|r| ClaimRow {
                claim: r.claim,
                headline: super::headline(r),
                measured: &r.measured,
                verdict: r.verdict,
                evidence: &r.evidence,
                as_expected: r.as_expected(),
            })
            .collect(),
    };
    Ok(snowroll_io::json_document(&doc)?)
}

/// The file, under the report's `data/`, of every claim's measured numbers,
/// verdict and evidence: the data behind a claim that no figure plots.
/// `data/claims.csv`: `#` lines with version, title and parameters, then one
/// row per claim: `id,paper_ref,verdict,expected,as_expected,measured,evidence`.
///
/// # Errors
/// [`ReportError::Output`] if serialisation fails.
pub(super) fn claims_csv(report: &Report) -> Result<String, ReportError> {
    let m = &report.metadata;
    let mut lines = vec![("title".to_string(), m.title.clone())];
    lines.extend(m.params.iter().cloned());
    let mut w = CsvTable::new(&m.software, &lines);
    {
        w.text_record([
            "id",
            "paper_ref",
            "verdict",
            "expected",
            "as_expected",
            "measured",
            "evidence",
        ])?;
        for r in &report.claims {
            let as_expected = r.as_expected().to_string();
            w.text_record([
                r.claim.id.as_str(),
                r.claim.paper_ref,
                &r.verdict.label(),
                &r.claim.expected.label(),
                &as_expected,
                &r.measured,
                &r.evidence,
            ])?;
        }
    }
    Ok(w.finish()?)
}

/// Writes every file of the report into `dir`.
pub(super) fn write_all(
    report: &Report,
    rendered: &[RenderedFigure],
    dir: &Path,
) -> Result<Vec<PathBuf>, ReportError> {
    let figures_dir = dir.join("figures");
    let data_dir = dir.join("data");
    for d in [dir, &figures_dir, &data_dir] {
        fs::create_dir_all(d).map_err(io_err(d))?;
    }
    let mut written = Vec::new();
    let mut put = |path: PathBuf, bytes: &[u8]| -> Result<(), ReportError> {
        write_atomic(&path, bytes)?;
        written.push(path);
        Ok(())
    };
    // The opening's drawing, for report.md (report.html has it inline).
    put(
        figures_dir.join(format!("{}.svg", super::intro::GEOMETRY_FIGURE)),
        super::intro::geometry_svg().as_bytes(),
    )?;
    for (fig, r) in report.figures.iter().zip(rendered) {
        let name = &fig.chart.name;
        put(figures_dir.join(format!("{name}.svg")), r.svg.as_bytes())?;
        put(figures_dir.join(format!("{name}.png")), &r.png)?;
        let csv = figure_csv(fig, &report.metadata)?;
        put(data_dir.join(format!("{name}.csv")), csv.as_bytes())?;
    }
    for anim in &report.animations {
        let csv = anim.to_csv(&report.metadata.software)?;
        put(
            data_dir.join(format!("{}.csv", anim.name())),
            csv.as_bytes(),
        )?;
    }
    put(data_dir.join(CLAIMS_CSV), claims_csv(report)?.as_bytes())?;
    put(dir.join("claims.json"), report.claims_json()?.as_bytes())?;
    put(dir.join("report.md"), report.to_markdown().as_bytes())?;
    let page = super::html::render(report, &report.page_svgs()?)?;
    put(dir.join("report.html"), page.as_bytes())?;
    Ok(written)
}
