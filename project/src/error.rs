//! Errors with file, line and column.

use std::fmt;
use std::ops::Range;

/// One mistake in a project or scenario file: where, and what was expected.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    /// The file as given.
    pub file: String,
    /// 1-based line (0: no position, e.g. the file could not be read).
    pub line: usize,
    /// 1-based column in characters.
    pub col: usize,
    /// What is wrong and what was expected.
    pub msg: String,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "{}: error: {}", self.file, self.msg)
        } else {
            write!(
                f,
                "{}:{}:{}: error: {}",
                self.file, self.line, self.col, self.msg
            )
        }
    }
}

impl std::error::Error for Error {}

/// A source text and its name, to turn byte spans into line:column.
#[derive(Clone, Copy, Debug)]
pub struct Source<'a> {
    /// The file name as given.
    pub file: &'a str,
    /// Its text.
    pub text: &'a str,
}

impl Source<'_> {
    /// An error at the start of `span`.
    pub fn error(&self, span: Range<usize>, msg: impl Into<String>) -> Error {
        let at = span.start.min(self.text.len());
        let before = &self.text[..at];
        let line = before.matches('\n').count() + 1;
        let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
        Error {
            file: self.file.to_string(),
            line,
            col,
            msg: msg.into(),
        }
    }

    /// The line and column of the start of `span`.
    pub fn pos(&self, span: Range<usize>) -> crate::project::Pos {
        let e = self.error(span, "");
        crate::project::Pos {
            line: e.line,
            col: e.col,
        }
    }

    /// A TOML syntax or shape error (toml reports its span). A duplicate key is named (toml
    /// says only "duplicate key"; its span is the key).
    pub fn toml_error(&self, e: &toml::de::Error) -> Error {
        let mut msg = e.message().trim().to_string();
        if let (true, Some(key)) = (
            msg == "duplicate key",
            e.span().and_then(|s| self.text.get(s)),
        ) {
            msg = format!("duplicate key `{}`", key.trim());
        }
        match e.span() {
            Some(span) => self.error(span, msg),
            None => Error {
                file: self.file.to_string(),
                line: 0,
                col: 0,
                msg,
            },
        }
    }
}

/// A file that could not be read.
pub fn read_error(file: &str, e: &std::io::Error) -> Error {
    Error {
        file: file.to_string(),
        line: 0,
        col: 0,
        msg: format!("cannot read the file: {e}"),
    }
}

/// A file that could not be written.
pub fn write_error(file: &str, e: &std::io::Error) -> Error {
    Error {
        file: file.to_string(),
        line: 0,
        col: 0,
        msg: format!("cannot write the file: {e}"),
    }
}

/// Reads a text file: a read error, or a file that is not UTF-8 with the line, column and
/// byte offset of its first invalid byte.
pub fn read_text(file: &str) -> Result<String, Error> {
    let bytes = std::fs::read(file).map_err(|e| read_error(file, &e))?;
    String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        // The valid prefix is text: its lines and characters give the position.
        let before = std::str::from_utf8(&bytes[..at]).unwrap_or("");
        let src = Source { file, text: before };
        let mut err = src.error(at..at, "");
        err.msg = format!(
            "the file is not UTF-8 text: byte 0x{:02X} at byte offset {at} is not valid UTF-8",
            bytes[at]
        );
        err
    })
}

/// Writes files all or nothing: each text goes to a temporary file in its target's
/// directory, and only when every one was written are they renamed into place (a rename
/// within a directory is atomic). On any failure the temporary files are removed and no
/// target is touched, so a failed run leaves nothing behind.
pub fn write_all(files: &[(&str, &str)]) -> Result<(), Error> {
    let mut temps: Vec<(std::path::PathBuf, &str)> = Vec::new();
    let cleanup = |temps: &[(std::path::PathBuf, &str)]| {
        for (t, _) in temps {
            // Best effort: the temporary file may not exist if its creation failed.
            std::fs::remove_file(t).ok();
        }
    };
    for (i, (path, text)) in files.iter().enumerate() {
        let target = std::path::Path::new(path);
        let name = target
            .file_name()
            .map_or_else(|| "out".into(), |n| n.to_string_lossy().into_owned());
        let tmp = target.with_file_name(format!(".{name}.{}.{i}.tmp", std::process::id()));
        if let Err(e) = std::fs::write(&tmp, text) {
            cleanup(&temps);
            std::fs::remove_file(&tmp).ok();
            return Err(write_error(path, &e));
        }
        temps.push((tmp, path));
    }
    for (k, (tmp, path)) in temps.iter().enumerate() {
        if let Err(e) = std::fs::rename(tmp, path) {
            cleanup(&temps[k..]);
            return Err(write_error(path, &e));
        }
    }
    Ok(())
}
