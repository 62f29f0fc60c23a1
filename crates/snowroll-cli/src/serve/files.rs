//! The page's files, built into the binary: the server needs no file and no
//! network. This table is the one list of what `GET` serves besides the API;
//! a file added to or removed from the page is added or removed here.

/// One file of the page.
#[derive(Debug)]
pub struct StaticFile {
    /// The path it is served at.
    pub path: &'static str,
    /// Its `Content-Type`.
    pub content_type: &'static str,
    /// Its bytes.
    pub body: &'static [u8],
}

const HTML: &str = "text/html; charset=utf-8";
const JS: &str = "text/javascript; charset=utf-8";
const CSS: &str = "text/css; charset=utf-8";

/// Every file served, by path (`/` is the page).
pub const FILES: &[StaticFile] = &[
    StaticFile {
        path: "/",
        content_type: HTML,
        body: include_bytes!("assets/index.html"),
    },
    StaticFile {
        path: "/index.html",
        content_type: HTML,
        body: include_bytes!("assets/index.html"),
    },
    StaticFile {
        path: "/app.js",
        content_type: JS,
        body: include_bytes!("assets/app.js"),
    },
    StaticFile {
        path: "/race.js",
        content_type: JS,
        body: include_bytes!("assets/race.js"),
    },
    StaticFile {
        path: "/plots.js",
        content_type: JS,
        body: include_bytes!("assets/plots.js"),
    },
    StaticFile {
        path: "/bodies.js",
        content_type: JS,
        body: include_bytes!("assets/bodies.js"),
    },
    StaticFile {
        path: "/style.css",
        content_type: CSS,
        body: include_bytes!("assets/style.css"),
    },
];

/// The file served at `path`, if any.
pub fn find(path: &str) -> Option<&'static StaticFile> {
    FILES.iter().find(|f| f.path == path)
}
