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

    /// A TOML syntax or shape error (toml reports its span).
    pub fn toml_error(&self, e: &toml::de::Error) -> Error {
        let msg = e.message().trim().to_string();
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
pub fn io_error(file: &str, e: &std::io::Error) -> Error {
    Error {
        file: file.to_string(),
        line: 0,
        col: 0,
        msg: format!("cannot read the file: {e}"),
    }
}
