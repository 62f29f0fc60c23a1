//! Writing a report's files: CSV data, `claims.json`, and the atomic
//! write-then-rename every file goes through.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

use serde::ser::{Serialize, SerializeMap, Serializer};
use thiserror::Error;

use crate::plot::{PlotError, Scale};

use super::{Figure, Metadata, RenderedFigure, Report, Tally, CLAIMS_CSV};

/// A report that could not be built or written.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum ReportError {
    /// Reading or writing a file failed. The message names the file; the
    /// cause is the error's `source`, so that a chain of messages names it once.
    #[error("{}", path.display())]
    Io {
        /// The file or folder.
        path: PathBuf,
        /// The underlying error.
        #[source]
        source: std::io::Error,
    },
    /// A figure could not be drawn.
    #[error(transparent)]
    Plot(#[from] PlotError),
    /// A simulation behind the report failed.
    #[error(transparent)]
    Simulation(#[from] snowroll::error::SimError),
    /// JSON serialisation failed.
    #[error("JSON: {0}")]
    Json(#[from] serde_json::Error),
    /// CSV serialisation failed.
    #[error("CSV: {0}")]
    Csv(#[from] csv::Error),
    /// A data file would carry NaN or infinity.
    #[error("{figure}: {source}")]
    NonFinite {
        /// The figure or data file.
        figure: String,
        /// The number and where it is.
        source: snowroll_io::NonFinite,
    },
    /// Two figures share a name, so their files would collide.
    #[error("two figures are named {name:?}")]
    DuplicateFigure {
        /// The shared name.
        name: String,
    },
    /// The animation data cannot be played.
    #[error("animation: {reason}")]
    InvalidAnimation {
        /// What is wrong.
        reason: &'static str,
    },
}

fn io_err(path: &Path) -> impl FnOnce(std::io::Error) -> ReportError + '_ {
    move |source| ReportError::Io {
        path: path.to_path_buf(),
        source,
    }
}

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

/// Writes `# key = value` comment lines: version, then parameters.
pub(super) fn comment_header(
    out: &mut Vec<u8>,
    software: &str,
    lines: &[(String, String)],
) -> Result<(), ReportError> {
    let io = io_err(Path::new("<memory>"));
    let mut text = format!("# {software}\n");
    for (k, v) in lines {
        text.push_str(&format!("# {k} = {}\n", v.replace('\n', " ")));
    }
    out.write_all(text.as_bytes()).map_err(io)
}

/// The CSV of a figure: `#` lines with version, title, axes and parameters,
/// then one row per point: `series,<x column>,<y column>`. Every point is
/// kept, including those a logarithmic axis cannot draw.
///
/// # Errors
/// [`ReportError::Csv`] if serialisation fails.
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
    let mut out = Vec::new();
    comment_header(&mut out, &prov.software, &lines)?;
    {
        let mut w = csv::Writer::from_writer(&mut out);
        w.write_record(["series", chart.x.column.as_str(), chart.y.column.as_str()])?;
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
                w.serialize((s.name.as_str(), x, y))?;
            }
        }
        w.flush().map_err(io_err(Path::new("<memory>")))?;
    }
    utf8(out)
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
    let mut text = serde_json::to_string_pretty(&doc)?;
    text.push('\n');
    Ok(text)
}

/// The file, under the report's `data/`, of every claim's measured numbers,
/// verdict and evidence: the data behind a claim that no figure plots.
/// `data/claims.csv`: `#` lines with version, title and parameters, then one
/// row per claim: `id,paper_ref,verdict,expected,as_expected,measured,evidence`.
///
/// # Errors
/// [`ReportError::Csv`] if serialisation fails.
pub(super) fn claims_csv(report: &Report) -> Result<String, ReportError> {
    let m = &report.metadata;
    let mut lines = vec![("title".to_string(), m.title.clone())];
    lines.extend(m.params.iter().cloned());
    let mut out = Vec::new();
    comment_header(&mut out, &m.software, &lines)?;
    {
        let mut w = csv::Writer::from_writer(&mut out);
        w.write_record([
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
            w.write_record([
                r.claim.id.as_str(),
                r.claim.paper_ref,
                &r.verdict.label(),
                &r.claim.expected.label(),
                &as_expected,
                &r.measured,
                &r.evidence,
            ])?;
        }
        w.flush().map_err(io_err(Path::new("<memory>")))?;
    }
    utf8(out)
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
    let svgs: Vec<String> = rendered.iter().map(|r| r.svg.clone()).collect();
    let page = super::html::render(report, &svgs)?;
    put(dir.join("report.html"), page.as_bytes())?;
    Ok(written)
}

/// Converts CSV bytes to text.
pub(super) fn utf8(out: Vec<u8>) -> Result<String, ReportError> {
    String::from_utf8(out).map_err(|e| ReportError::Io {
        path: PathBuf::from("<memory>"),
        source: std::io::Error::new(std::io::ErrorKind::InvalidData, e),
    })
}
