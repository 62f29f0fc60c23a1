//! Every integration test of `snowroll-report` in one binary (one link instead of
//! one per file); each file is a module, named as before.

mod claims;
#[cfg(feature = "comment")]
mod comment;
mod report_render;
