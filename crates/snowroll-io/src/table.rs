//! CSV tables that open with `#` comment lines (the software, then one
//! `# key = value` line per parameter): the report's data files (the
//! points of each figure, the claims, the frames of an animation). The one
//! place besides the trajectory, turn-table and sweep writers of this crate
//! where CSV is written.

use serde::Serialize;

use crate::OutputError;

/// A CSV table being written in memory ([`CsvTable::finish`] gives its text).
pub struct CsvTable {
    writer: csv::Writer<Vec<u8>>,
}

impl CsvTable {
    /// A table whose text starts with `# {software}` and one
    /// `# key = value` line per entry of `lines` (a value's newlines become
    /// spaces, so that each stays one comment line).
    pub fn new(software: &str, lines: &[(String, String)]) -> Self {
        let mut text = format!("# {software}\n");
        for (k, v) in lines {
            text.push_str(&format!("# {k} = {}\n", v.replace('\n', " ")));
        }
        CsvTable {
            writer: csv::Writer::from_writer(text.into_bytes()),
        }
    }

    /// Writes one record of text fields (the column names, or a row of
    /// text), quoted where CSV needs it.
    ///
    /// # Errors
    /// [`OutputError::Csv`].
    pub fn text_record<I, T>(&mut self, fields: I) -> Result<(), OutputError>
    where
        I: IntoIterator<Item = T>,
        T: AsRef<[u8]>,
    {
        Ok(self.writer.write_record(fields)?)
    }

    /// Serialises one row: a tuple is its fields in order; a struct's field
    /// names are written as the column names before its first row.
    ///
    /// # Errors
    /// [`OutputError::Csv`].
    pub fn row<T: Serialize>(&mut self, row: &T) -> Result<(), OutputError> {
        Ok(self.writer.serialize(row)?)
    }

    /// The table's text.
    ///
    /// # Errors
    /// [`OutputError::Csv`] (never from memory, kept for the writer's
    /// contract).
    pub fn finish(self) -> Result<String, OutputError> {
        let bytes = self.writer.into_inner().map_err(|e| e.into_error())?;
        String::from_utf8(bytes)
            .map_err(|e| OutputError::Io(std::io::Error::new(std::io::ErrorKind::InvalidData, e)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Serialize)]
    struct Frame {
        t: f64,
        label: &'static str,
    }

    /// The comment lines, the header from a struct's field names, quoting
    /// and `ryu`'s floats: the bytes written by hand here.
    #[test]
    fn comments_then_records() {
        let mut t = CsvTable::new("snowroll 1", &[("title".into(), "two\nlines".into())]);
        t.row(&Frame {
            t: 0.5,
            label: "a, b",
        })
        .unwrap();
        t.text_record(["x", "say \"hi\""]).unwrap();
        t.row(&(1e21, -0.0)).unwrap();
        assert_eq!(
            t.finish().unwrap(),
            "# snowroll 1\n# title = two lines\nt,label\n0.5,\"a, b\"\nx,\"say \"\"hi\"\"\"\n1e21,-0.0\n"
        );
    }
}
