//! `--plot FILE.svg|FILE.png` of `simulate` and `turns`: the run kept in
//! memory beside its output ([`Keep`], [`KeepTurns`]), drawn with the
//! report's figure code ([`snowroll_report::run_plot`]) and written whole,
//! then renamed into place, as every output.

use std::io::Write;
use std::path::Path;

use anyhow::{bail, Context, Result};
use snowroll::trajectory::{Collected, LedgerRow, Sample, SampleSink, TurnState};
use snowroll::{Given, ModelKind, SinkError, TurnRow, TurnSink};
use snowroll_io::VERSION;
use snowroll_report::plot::{render_panels_png, render_panels_svg, Chart, Provenance};

use crate::args::OutputArgs;
use crate::sink::Sink;

/// The two formats a figure is written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlotFormat {
    /// Scalable vector graphics.
    Svg,
    /// A bitmap.
    Png,
}

/// The format the name `path` asks for: `.svg` or `.png`, in any case;
/// any other name is refused with the two it may end in.
///
/// # Errors
/// A name with another ending, or none.
pub fn plot_format(path: &Path) -> Result<PlotFormat> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("svg") => Ok(PlotFormat::Svg),
        Some("png") => Ok(PlotFormat::Png),
        _ => bail!(
            "--plot {}: the figure is written as SVG or PNG, chosen by the name's ending; \
             give a name that ends in .svg or .png",
            path.display()
        ),
    }
}

/// The figure `out` asks for (`--plot`), with its format, checked before
/// the run; `None` without `--plot`.
///
/// # Errors
/// A name that does not end in `.svg` or `.png`.
pub fn planned(out: &OutputArgs) -> Result<Option<(&Path, PlotFormat)>> {
    out.plot
        .as_deref()
        .map(|p| plot_format(p).map(|f| (p, f)))
        .transpose()
}

/// Who drew the figure: the program, the models and every parameter flag
/// given (the rest are the defaults, which the run's output records).
pub fn provenance(models: &[ModelKind], given: &Given) -> Provenance {
    let ids = models.iter().map(|m| m.id()).collect::<Vec<_>>().join(",");
    let mut params = vec![("model".to_string(), ids)];
    params.extend(given.iter().map(|(p, v)| (p.key.to_string(), p.text(v))));
    Provenance {
        software: format!("snowroll {VERSION}"),
        params,
    }
}

/// Draws `panels` one above the other and writes them to `path` in
/// `format` (temporary file, renamed).
///
/// # Errors
/// When the figure cannot be drawn or written.
pub fn write(path: &Path, format: PlotFormat, panels: &[Chart], prov: &Provenance) -> Result<()> {
    let bytes = match format {
        PlotFormat::Svg => render_panels_svg(panels, prov)?.into_bytes(),
        PlotFormat::Png => render_panels_png(panels, prov)?,
    };
    let mut sink = Sink::open(&OutputArgs {
        output: Some(path.to_path_buf()),
        ..OutputArgs::default()
    })?;
    let name = sink.name();
    sink.write_all(&bytes)
        .with_context(|| format!("writing {name}"))?;
    sink.commit().with_context(|| format!("writing {name}"))?;
    Ok(())
}

/// A sample sink that hands every sample on to `inner` and, when asked to,
/// keeps a copy for the figure.
pub struct Keep<'a, S: SampleSink> {
    /// Where the samples go.
    pub inner: &'a mut S,
    /// The copies kept, `None` when no figure is drawn.
    pub kept: Option<Collected>,
}

impl<S: SampleSink> SampleSink for Keep<'_, S> {
    fn sample(&mut self, sample: &Sample, turn: Option<&TurnState>) -> Result<(), SinkError> {
        self.inner.sample(sample, turn)?;
        if let Some(k) = &mut self.kept {
            k.sample(sample, turn)?;
        }
        Ok(())
    }

    fn ledger(&mut self, row: &LedgerRow) -> Result<(), SinkError> {
        self.inner.ledger(row)?;
        if let Some(k) = &mut self.kept {
            k.ledger(row)?;
        }
        Ok(())
    }
}

/// A turn sink that hands every row on to `inner` and, when asked to,
/// keeps a copy for the figure.
pub struct KeepTurns<'a, S: TurnSink> {
    /// Where the rows go.
    pub inner: &'a mut S,
    /// The copies kept, `None` when no figure is drawn.
    pub kept: Option<Vec<TurnRow>>,
}

impl<S: TurnSink> TurnSink for KeepTurns<'_, S> {
    fn turn(&mut self, row: &TurnRow) -> Result<(), SinkError> {
        self.inner.turn(row)?;
        if let Some(k) = &mut self.kept {
            k.push(*row);
        }
        Ok(())
    }

    fn ledger(&mut self, row: &LedgerRow) -> Result<(), SinkError> {
        self.inner.ledger(row)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_name_chooses_the_format_and_others_are_refused() {
        assert_eq!(
            plot_format(Path::new("a/run.svg")).unwrap(),
            PlotFormat::Svg
        );
        assert_eq!(plot_format(Path::new("RUN.PNG")).unwrap(), PlotFormat::Png);
        for bad in ["run.pdf", "run", "-", "run.svg.txt"] {
            let e = plot_format(Path::new(bad)).unwrap_err().to_string();
            assert!(e.contains(bad) && e.contains(".svg or .png"), "{e}");
        }
    }
}
