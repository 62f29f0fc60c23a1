//! Several models' outputs in one (`simulate --model eq4,eq6,eq14`), each
//! model's written by its own single-model writer through [`Stack`], model
//! by model, so memory stays that of one row.
//!
//! * CSV: each model's block as a single run writes it (its `#` lines, its
//!   rows, its `# stop` line), with a leading `model` column: the column
//!   header once, before the first model's rows, and every row led by its
//!   model's id.
//! * JSON: one object `{"models": [...], "runs": [...]}`, each run the
//!   object a single run of that model writes.

use std::io::{self, Write};

use snowroll::ModelKind;
use snowroll_io::Format;

/// The name of the leading column: as `snowroll.Results.to_pandas`.
pub const MODEL_COLUMN: &str = "model";

/// What happens to the rest of the line being written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Line {
    /// At the start of a line: its first byte decides.
    Start,
    /// A `#` line, a row already led by its model, or JSON: passed on.
    Pass,
    /// The column header of a later model: dropped.
    Drop,
}

/// A writer that stacks the outputs of several models into `inner`: use
/// one [`Stack::model`] per model, in order, then [`Stack::end`].
pub struct Stack<W: Write> {
    inner: W,
    format: Format,
    /// Set when this model's output is to be stacked (several models).
    id: Option<&'static str>,
    /// Models begun so far.
    begun: usize,
    /// Whether the current model's column header has gone by.
    header_seen: bool,
    line: Line,
}

impl<W: Write> Stack<W> {
    /// Stacks into `inner`; with one of `models`, writes through unchanged.
    ///
    /// # Errors
    /// When `inner` fails (the JSON opening of several models).
    pub fn new(mut inner: W, format: Format, models: &[ModelKind]) -> io::Result<Self> {
        let several = models.len() > 1;
        if several && format == Format::Json {
            let ids: Vec<&str> = models.iter().map(|m| m.id()).collect();
            write!(
                inner,
                "{{\"{MODEL_COLUMN}s\": {},\n\"runs\": [\n",
                serde_json::to_string(&ids).map_err(io::Error::other)?
            )?;
        }
        Ok(Self {
            inner,
            format,
            id: None,
            begun: 0,
            header_seen: false,
            line: Line::Start,
        })
    }

    /// Starts the output of `model`, the next of the list (`several`:
    /// whether the list has more than one).
    ///
    /// # Errors
    /// When `inner` fails.
    pub fn model(&mut self, model: ModelKind, several: bool) -> io::Result<()> {
        if several && self.format == Format::Json && self.begun > 0 {
            self.inner.write_all(b",\n")?;
        }
        self.id = several.then(|| model.id());
        self.begun += 1;
        self.header_seen = false;
        self.line = Line::Start;
        Ok(())
    }

    /// Ends the output (closes the JSON object of several models).
    ///
    /// # Errors
    /// When `inner` fails.
    pub fn end(mut self, several: bool) -> io::Result<W> {
        if several && self.format == Format::Json {
            self.inner.write_all(b"]}\n")?;
        }
        self.inner.flush()?;
        Ok(self.inner)
    }

    /// Writes `line` (part of one line, up to and with its `\n` if any),
    /// first deciding at a line's start what the line is.
    fn put(&mut self, id: &str, part: &[u8]) -> io::Result<()> {
        if self.line == Line::Start {
            self.line = if part[0] == b'#' {
                Line::Pass
            } else if !self.header_seen {
                self.header_seen = true;
                if self.begun == 1 {
                    write!(self.inner, "{MODEL_COLUMN},")?;
                    Line::Pass
                } else {
                    Line::Drop
                }
            } else {
                write!(self.inner, "{id},")?;
                Line::Pass
            };
        }
        if self.line == Line::Pass {
            self.inner.write_all(part)?;
        }
        if part.ends_with(b"\n") {
            self.line = Line::Start;
        }
        Ok(())
    }
}

impl<W: Write> Write for Stack<W> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let Some(id) = self.id.filter(|_| self.format == Format::Csv) else {
            return self.inner.write(buf);
        };
        for part in buf.split_inclusive(|&b| b == b'\n') {
            self.put(id, part)?;
        }
        Ok(buf.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        self.inner.flush()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two models' CSV, written in odd pieces, stack as one table.
    #[test]
    fn csv_blocks_stack_under_one_header() {
        let models = [ModelKind::TorqueCm, ModelKind::Energy];
        let mut s = Stack::new(Vec::new(), Format::Csv, &models).unwrap();
        for (m, text) in models
            .iter()
            .zip(["# a\nt,v\n1,2\n3,4\n# stop\n", "# b\nt,v\n5,6\n# stop\n"])
        {
            s.model(*m, true).unwrap();
            for piece in text.as_bytes().chunks(3) {
                s.write_all(piece).unwrap();
            }
        }
        let out = String::from_utf8(s.end(true).unwrap()).unwrap();
        let (a, b) = (models[0].id(), models[1].id());
        assert_eq!(
            out,
            format!("# a\nmodel,t,v\n{a},1,2\n{a},3,4\n# stop\n# b\n{b},5,6\n# stop\n")
        );
    }
}
