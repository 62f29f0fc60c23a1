//! The typst compiler's view of the comment: one source, the figures it
//! includes, and the fonts compiled into the program. Nothing is read from
//! the disk or the network, and the date is never asked for, so the same
//! source gives the same PDF on any machine.

use std::collections::BTreeMap;

use typst::diag::{FileError, FileResult, Severity, SourceDiagnostic};
use typst::foundations::{Bytes, Datetime};
use typst::layout::PagedDocument;
use typst::syntax::{FileId, Source, VirtualPath};
use typst::text::{Font, FontBook};
use typst::utils::LazyHash;
use typst::{Library, World};
use typst_pdf::PdfOptions;

use super::CommentError;

/// The name of the source inside the compiler's virtual file system (and
/// beside the PDF).
pub(super) const MAIN: &str = "comment.typ";

/// The source and its files, all in memory.
pub(super) struct CommentWorld {
    library: LazyHash<Library>,
    book: LazyHash<FontBook>,
    fonts: Vec<Font>,
    main: Source,
    /// Files the source includes (the figures), by their path relative to it.
    files: BTreeMap<String, Bytes>,
}

impl CommentWorld {
    /// A world of `source` and `files` (`(relative path, bytes)`), with
    /// the fonts of typst's own assets (New Computer Modern for the text
    /// and the equations) and the report's DejaVu Sans (the figures' text).
    pub(super) fn new(source: String, files: Vec<(String, Vec<u8>)>) -> Self {
        let fonts: Vec<Font> = typst_assets::fonts()
            .chain([crate::plot::FONT])
            .flat_map(|data| Font::iter(Bytes::new(data)))
            .collect();
        let book = FontBook::from_fonts(&fonts);
        let id = FileId::new(None, VirtualPath::new(MAIN));
        Self {
            library: LazyHash::new(Library::builder().build()),
            book: LazyHash::new(book),
            fonts,
            main: Source::new(id, source),
            files: files
                .into_iter()
                .map(|(path, bytes)| (path, Bytes::new(bytes)))
                .collect(),
        }
    }

    /// The PDF: compiled, then exported with a fixed identifier and no
    /// creation date, so that the same source gives the same bytes.
    ///
    /// # Errors
    /// [`CommentError::Typeset`] for an error or a warning of the compiler
    /// (a warning is an error here: the source must compile cleanly), with
    /// the line of the source it points at.
    pub(super) fn pdf(&self) -> Result<Vec<u8>, CommentError> {
        let compiled = typst::compile::<PagedDocument>(self);
        if !compiled.warnings.is_empty() {
            return Err(self.error(&compiled.warnings));
        }
        let document = compiled.output.map_err(|e| self.error(&e))?;
        let options = PdfOptions {
            ident: typst::foundations::Smart::Custom("snowroll-comment"),
            timestamp: None,
            ..PdfOptions::default()
        };
        typst_pdf::pdf(&document, &options).map_err(|e| self.error(&e))
    }

    /// The diagnostics as one error, each with its line in the source.
    fn error(&self, diagnostics: &[SourceDiagnostic]) -> CommentError {
        let messages = diagnostics
            .iter()
            .map(|d| {
                let kind = match d.severity {
                    Severity::Error => "error",
                    Severity::Warning => "warning",
                };
                let line = self
                    .main
                    .range(d.span)
                    .and_then(|r| self.main.byte_to_line(r.start))
                    .map_or_else(String::new, |l| format!(" (line {})", l + 1));
                let hints: String = d.hints.iter().map(|h| format!("; hint: {h}")).collect();
                format!("{kind}{line}: {}{hints}", d.message)
            })
            .collect();
        CommentError::Typeset { messages }
    }
}

impl World for CommentWorld {
    fn library(&self) -> &LazyHash<Library> {
        &self.library
    }

    fn book(&self) -> &LazyHash<FontBook> {
        &self.book
    }

    fn main(&self) -> FileId {
        self.main.id()
    }

    fn source(&self, id: FileId) -> FileResult<Source> {
        if id == self.main.id() {
            Ok(self.main.clone())
        } else {
            Err(FileError::NotFound(id.vpath().as_rootless_path().into()))
        }
    }

    fn file(&self, id: FileId) -> FileResult<Bytes> {
        let path = id.vpath().as_rootless_path();
        path.to_str()
            .and_then(|p| self.files.get(p))
            .cloned()
            .ok_or_else(|| FileError::NotFound(path.into()))
    }

    fn font(&self, index: usize) -> Option<Font> {
        self.fonts.get(index).cloned()
    }

    /// No date: the comment never prints one, and a PDF that did would
    /// differ from day to day.
    fn today(&self, _offset: Option<i64>) -> Option<Datetime> {
        None
    }
}
