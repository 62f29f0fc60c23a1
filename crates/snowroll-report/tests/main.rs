//! Every integration test of `snowroll-report` in one binary (one link instead of
//! one per file); each file is a module, named as before.

mod claims;
mod report_render;
