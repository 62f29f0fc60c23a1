//! The [`Report`] value and its parts: [`Metadata`], [`Figure`].

use std::path::{Path, PathBuf};

use crate::plot::{Chart, Provenance};
use snowroll_io::{RunParams, VERSION};

use super::{files, html, markdown, Animation, ClaimId, ClaimResult, ReportError};

/// Title, version and parameters of a report.
#[derive(Debug, Clone, PartialEq)]
pub struct Metadata {
    /// The report's title.
    pub title: String,
    /// Program and version, e.g. `snowroll 0.1.0`.
    pub software: String,
    /// Parameters shared by the report, `(key, value)` with unit-suffixed keys, in display order.
    pub params: Vec<(String, String)>,
}

impl Metadata {
    /// Metadata with this program's version and no parameters yet.
    pub fn new(title: &str) -> Self {
        Self {
            title: title.to_string(),
            software: format!("snowroll {VERSION}"),
            params: Vec::new(),
        }
    }

    /// Adds one parameter.
    pub fn param(mut self, key: &str, value: impl ToString) -> Self {
        self.params.push((key.to_string(), value.to_string()));
        self
    }
}

/// Every parameter of a run as `(key, value)` pairs, keys sorted.
///
/// # Errors
/// [`ReportError::Json`] if the parameters cannot be serialised.
pub fn params_of(run: &RunParams) -> Result<Vec<(String, String)>, ReportError> {
    let value = serde_json::to_value(run)?;
    let Some(map) = value.as_object() else {
        return Ok(Vec::new());
    };
    Ok(map
        .iter()
        .map(|(k, v)| {
            let text = match v {
                serde_json::Value::Null => "none".to_string(),
                serde_json::Value::String(s) => s.clone(),
                serde_json::Value::Number(n) if n.is_f64() => {
                    n.as_f64().map_or_else(|| n.to_string(), short_number)
                }
                other => other.to_string(),
            };
            (k.clone(), text)
        })
        .collect())
}

/// Significant digits of parameter values in reports: enough for any input,
/// few enough to hide the rounding of a degree → radian → degree round trip.
const PARAM_DIGITS: usize = 12;

/// `v` rounded to [`PARAM_DIGITS`] significant digits, printed shortest:
/// plain decimals from 1e-4 to 1e9, else in exponent form (`1e-12`).
fn short_number(v: f64) -> String {
    let r = format!("{v:.prec$e}", prec = PARAM_DIGITS - 1)
        .parse::<f64>()
        .unwrap_or(v);
    if r == 0.0 || (1e-4..1e9).contains(&r.abs()) {
        r.to_string()
    } else {
        format!("{r:e}")
    }
}

/// A chart with its caption and the parameters that produced it.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// The chart (its `name` is the file stem).
    pub chart: Chart,
    /// One or two sentences under the figure: what it shows, what to look for.
    pub caption: String,
    /// The parameters of this figure; when empty, the report's parameters apply.
    pub params: Vec<(String, String)>,
    /// Ids of the claims this figure is evidence for ([`super::CLAIMS`]); the
    /// report links each way.
    pub supports: Vec<ClaimId>,
}

impl Figure {
    /// A figure drawn with the report's parameters.
    pub fn new(chart: Chart, caption: &str) -> Self {
        Self {
            chart,
            caption: caption.to_string(),
            params: Vec::new(),
            supports: Vec::new(),
        }
    }

    /// Names the claims this figure is evidence for.
    pub fn supports(mut self, claims: &[ClaimId]) -> Self {
        self.supports.extend_from_slice(claims);
        self
    }

    /// Adds a parameter specific to this figure.
    pub fn param(mut self, key: &str, value: impl ToString) -> Self {
        self.params.push((key.to_string(), value.to_string()));
        self
    }

    /// The version and parameters recorded in this figure's files.
    pub fn provenance(&self, meta: &Metadata) -> Provenance {
        Provenance {
            software: meta.software.clone(),
            params: if self.params.is_empty() {
                meta.params.clone()
            } else {
                self.params.clone()
            },
        }
    }
}

/// A small table of text cells shown after the claims (e.g. where the turn
/// models part ways).
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// Section title.
    pub title: String,
    /// One or two sentences under the title: what the table shows.
    pub caption: String,
    /// Column headers.
    pub header: Vec<String>,
    /// Rows of cells, as many as headers each.
    pub rows: Vec<Vec<String>>,
}

/// Everything `snowroll paper` shows: metadata, claim results, tables, figures, animation.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// Title, version, parameters.
    pub metadata: Metadata,
    /// One result per claim, in table order.
    pub claims: Vec<ClaimResult>,
    /// Tables shown after the claims.
    pub tables: Vec<Table>,
    /// Figures, in display order.
    pub figures: Vec<Figure>,
    /// The animations: at most one of the log and one of the snowball
    /// ([`Animation::name`] tells them apart).
    pub animations: Vec<Animation>,
    /// Whether the explorer (`scripts/build-explorer.sh`) is written beside
    /// the report as `explorer.html` (`snowroll paper --explorer`): the
    /// report links it; otherwise it says how to build or serve it.
    pub explorer: bool,
}

/// A figure drawn in both formats.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderedFigure {
    /// The SVG document.
    pub svg: String,
    /// The PNG image.
    pub png: Vec<u8>,
}

impl Report {
    /// An empty report.
    pub fn new(metadata: Metadata) -> Self {
        Self {
            metadata,
            claims: Vec::new(),
            tables: Vec::new(),
            figures: Vec::new(),
            animations: Vec::new(),
            explorer: false,
        }
    }

    /// Checks that figure names are unique and every chart can be drawn.
    ///
    /// # Errors
    /// [`ReportError`] naming the first problem.
    pub fn validate(&self) -> Result<(), ReportError> {
        // The geometry drawing is written as figures/geometry.svg beside the charts.
        let mut names: Vec<&str> = self.figures.iter().map(|f| f.chart.name.as_str()).collect();
        names.push(super::intro::GEOMETRY_FIGURE);
        names.sort_unstable();
        if let Some(w) = names.windows(2).find(|w| w[0] == w[1]) {
            return Err(ReportError::DuplicateFigure {
                name: w[0].to_string(),
            });
        }
        for f in &self.figures {
            f.chart.validate()?;
        }
        for (i, a) in self.animations.iter().enumerate() {
            a.validate()?;
            if self.animations[..i].iter().any(|b| b.name() == a.name()) {
                return Err(ReportError::InvalidAnimation {
                    reason: "two animations of one shape",
                });
            }
        }
        Ok(())
    }

    /// Draws every figure as SVG and PNG, in order.
    ///
    /// # Errors
    /// [`ReportError::Plot`] when a figure cannot be drawn.
    pub fn render_figures(&self) -> Result<Vec<RenderedFigure>, ReportError> {
        self.figures
            .iter()
            .map(|f| {
                let prov = f.provenance(&self.metadata);
                Ok(RenderedFigure {
                    svg: f.chart.render_svg(&prov)?,
                    png: f.chart.render_png(&prov)?,
                })
            })
            .collect()
    }

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
        files::claims_json(self)
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
        files::write_all(self, &rendered, dir)
    }
}
