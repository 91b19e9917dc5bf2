//! Expands the crate's `*_struct!` (and `*_variants!`) macros for cbindgen, which reads the
//! sources literally and does not expand macros: a family of blocks whose structs have one
//! shape declares it once as a `macro_rules!` whose name ends in `_struct` (`_variants`
//! for the tags and aliases of generic variants), and every invocation of it is written
//! out here as plain Rust for cbindgen (`Builder::with_src`), next to the crate.
//!
//! This is a small `macro_rules!` interpreter for what those macros use: one or more arms;
//! fragments `ident`, `literal`, `tt`, `ty` (one group or a path with generic arguments), `path`,
//! `expr` (up to the next `,` or `;`), `meta` (the rest of the group); repetitions `$(…)*`,
//! `$(…),*`, `+`, `?`; `$crate`; `concat!` of literals and `stringify!` of an ident (how a macro builds a doc string
//! such as `Offset 8.`). Doc comments become `#[doc = "…"]` attributes, as rustc reads
//! them. Anything else is a build failure with the macro's name, never a silent skip.

use std::collections::HashMap;

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Ident(String),
    Lit(String),
    /// A punctuation character; `true` when the next character belongs to the same
    /// operator (`::`, `=>`), so printing keeps them together.
    Punct(char, bool),
    Group(char, Vec<Tok>),
}

fn close_of(open: char) -> char {
    match open {
        '(' => ')',
        '[' => ']',
        _ => '}',
    }
}

/// Tokens of `s` from byte `pos` up to the closing `close` (or the end); returns them and
/// the byte after the closing delimiter.
fn tokenize(s: &str, mut pos: usize, close: Option<char>) -> (Vec<Tok>, usize) {
    let b = s.as_bytes();
    let mut out = Vec::new();
    while pos < b.len() {
        let c = s[pos..].chars().next().expect("char");
        if c.is_whitespace() {
            pos += c.len_utf8();
        } else if s[pos..].starts_with("///") && !s[pos..].starts_with("////") {
            let end = s[pos..].find('\n').map_or(s.len(), |e| pos + e);
            // Verbatim, leading space included: rustc and cbindgen keep it.
            let text = &s[pos + 3..end];
            out.push(Tok::Punct('#', false));
            out.push(Tok::Group(
                '[',
                vec![
                    Tok::Ident("doc".into()),
                    Tok::Punct('=', false),
                    Tok::Lit(quote(text)),
                ],
            ));
            pos = end;
        } else if s[pos..].starts_with("//") {
            pos = s[pos..].find('\n').map_or(s.len(), |e| pos + e);
        } else if s[pos..].starts_with("/*") {
            pos += s[pos..].find("*/").expect("end of block comment") + 2;
        } else if c == '"' {
            let mut i = pos + 1;
            while b[i] != b'"' {
                i += if b[i] == b'\\' { 2 } else { 1 };
            }
            out.push(Tok::Lit(s[pos..=i].to_string()));
            pos = i + 1;
        } else if c == '\'' && b.get(pos + 2) == Some(&b'\'') {
            out.push(Tok::Lit(s[pos..pos + 3].to_string()));
            pos += 3;
        } else if c.is_ascii_digit() {
            let mut i = pos;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                i += 1;
            }
            out.push(Tok::Lit(s[pos..i].to_string()));
            pos = i;
        } else if c.is_alphabetic() || c == '_' {
            let mut i = pos;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                i += 1;
            }
            out.push(Tok::Ident(s[pos..i].to_string()));
            pos = i;
        } else if matches!(c, '(' | '[' | '{') {
            let (inner, next) = tokenize(s, pos + 1, Some(close_of(c)));
            out.push(Tok::Group(c, inner));
            pos = next;
        } else if Some(c) == close {
            return (out, pos + 1);
        } else {
            assert!(
                !matches!(c, ')' | ']' | '}'),
                "unbalanced {c} at byte {pos}"
            );
            let joint = s[pos + 1..]
                .chars()
                .next()
                .is_some_and(|n| "!#$%&*+-./:;<=>?@^|~".contains(n));
            out.push(Tok::Punct(c, joint && c != ',' && c != ';'));
            pos += c.len_utf8();
        }
    }
    assert!(close.is_none(), "unclosed group");
    (out, pos)
}

fn quote(text: &str) -> String {
    format!("\"{}\"", text.replace('\\', "\\\\").replace('"', "\\\""))
}

/// The value of a string or number literal token, for `concat!`.
fn unquote(lit: &str) -> String {
    match lit.strip_prefix('"').and_then(|l| l.strip_suffix('"')) {
        Some(inner) => inner.replace("\\\"", "\"").replace("\\\\", "\\"),
        None => lit.to_string(),
    }
}

/// A pattern element of a macro arm.
#[derive(Debug)]
enum Pat {
    Tok(Tok),
    Group(char, Vec<Pat>),
    Var(String, String),
    Rep(Vec<Pat>, Option<Tok>, char),
}

fn pattern(toks: &[Tok]) -> Vec<Pat> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < toks.len() {
        match (&toks[i], toks.get(i + 1)) {
            (Tok::Punct('$', _), Some(Tok::Ident(name))) if name != "crate" => {
                let Some(Tok::Ident(frag)) = toks.get(i + 3) else {
                    panic!("${name} without a fragment");
                };
                out.push(Pat::Var(name.clone(), frag.clone()));
                i += 4;
            }
            (Tok::Punct('$', _), Some(Tok::Group('(', inner))) => {
                let (sep, op, used) = rep_tail(&toks[i + 2..]);
                out.push(Pat::Rep(pattern(inner), sep, op));
                i += 2 + used;
            }
            (Tok::Group(d, inner), _) => {
                out.push(Pat::Group(*d, pattern(inner)));
                i += 1;
            }
            (t, _) => {
                out.push(Pat::Tok(t.clone()));
                i += 1;
            }
        }
    }
    out
}

/// The separator and operator after `$(…)`, and how many tokens they take.
fn rep_tail(toks: &[Tok]) -> (Option<Tok>, char, usize) {
    let op = |t: Option<&Tok>| match t {
        Some(Tok::Punct(c @ ('*' | '+' | '?'), _)) => Some(*c),
        _ => None,
    };
    match op(toks.first()) {
        Some(c) => (None, c, 1),
        None => (
            Some(toks[0].clone()),
            op(toks.get(1)).expect("repetition operator"),
            2,
        ),
    }
}

/// What a variable matched: one fragment, or one entry per repetition.
#[derive(Clone, Debug)]
enum Bound {
    One(Vec<Tok>),
    Many(Vec<HashMap<String, Bound>>),
}

fn same(a: &Tok, b: &Tok) -> bool {
    match (a, b) {
        (Tok::Punct(x, _), Tok::Punct(y, _)) => x == y,
        _ => a == b,
    }
}

/// How many tokens of `input` the fragment takes, if it matches.
fn fragment(frag: &str, input: &[Tok]) -> Option<usize> {
    let first = input.first()?;
    match frag {
        "ident" => matches!(first, Tok::Ident(_)).then_some(1),
        "literal" => match (first, input.get(1)) {
            (Tok::Lit(_), _) => Some(1),
            (Tok::Punct('-', _), Some(Tok::Lit(_))) => Some(2),
            _ => None,
        },
        "tt" => Some(1),
        "meta" => Some(input.len()),
        "expr" => Some(
            input
                .iter()
                .position(|t| matches!(t, Tok::Punct(',' | ';', _)))
                .unwrap_or(input.len()),
        ),
        "ty" | "path" => {
            if matches!(first, Tok::Group(..)) {
                return (frag == "ty").then_some(1);
            }
            let mut n = 0;
            loop {
                if !matches!(input.get(n), Some(Tok::Ident(_))) {
                    return None;
                }
                n += 1;
                if matches!(input.get(n), Some(Tok::Punct('<', _))) {
                    let mut depth = 0;
                    while let Some(t) = input.get(n) {
                        n += 1;
                        match t {
                            Tok::Punct('<', _) => depth += 1,
                            Tok::Punct('>', _) => depth -= 1,
                            _ => {}
                        }
                        if depth == 0 {
                            break;
                        }
                    }
                }
                match (input.get(n), input.get(n + 1)) {
                    (Some(Tok::Punct(':', true)), Some(Tok::Punct(':', _))) => n += 2,
                    _ => return Some(n),
                }
            }
        }
        _ => panic!("fragment {frag} is not supported by build_support/expand.rs"),
    }
}

/// Matches a prefix of `input`; returns how many tokens it took.
fn match_seq(pat: &[Pat], input: &[Tok], binds: &mut HashMap<String, Bound>) -> Option<usize> {
    let mut at = 0;
    for p in pat {
        match p {
            Pat::Tok(t) => {
                if !same(t, input.get(at)?) {
                    return None;
                }
                at += 1;
            }
            Pat::Group(d, inner) => {
                let Some(Tok::Group(e, toks)) = input.get(at) else {
                    return None;
                };
                if d != e || match_seq(inner, toks, binds)? != toks.len() {
                    return None;
                }
                at += 1;
            }
            Pat::Var(name, frag) => {
                let n = fragment(frag, &input[at..])?;
                binds.insert(name.clone(), Bound::One(input[at..at + n].to_vec()));
                at += n;
            }
            Pat::Rep(inner, sep, op) => {
                let mut runs = Vec::new();
                loop {
                    let mut start = at;
                    if !runs.is_empty() {
                        if let Some(s) = sep {
                            if !input.get(at).is_some_and(|t| same(s, t)) {
                                break;
                            }
                            start += 1;
                        }
                    }
                    let mut b = HashMap::new();
                    // A repetition that would leave the rest of the pattern nothing to
                    // match ends here (no backtracking beyond this one check).
                    let Some(n) = match_seq(inner, &input[start..], &mut b) else {
                        break;
                    };
                    if n == 0 {
                        break;
                    }
                    runs.push(b);
                    at = start + n;
                    if *op == '?' {
                        break;
                    }
                }
                if *op == '+' && runs.is_empty() {
                    return None;
                }
                for name in vars(inner) {
                    binds.insert(name, Bound::Many(runs.clone()));
                }
            }
        }
    }
    Some(at)
}

fn vars(pat: &[Pat]) -> Vec<String> {
    let mut out = Vec::new();
    for p in pat {
        match p {
            Pat::Var(n, _) => out.push(n.clone()),
            Pat::Group(_, inner) | Pat::Rep(inner, _, _) => out.extend(vars(inner)),
            Pat::Tok(_) => {}
        }
    }
    out
}

fn transcribe(toks: &[Tok], binds: &HashMap<String, Bound>, out: &mut Vec<Tok>) {
    let mut i = 0;
    while i < toks.len() {
        match (&toks[i], toks.get(i + 1)) {
            (Tok::Punct('$', _), Some(Tok::Ident(name))) if name == "crate" => {
                out.push(Tok::Ident("crate".into()));
                i += 2;
            }
            (Tok::Punct('$', _), Some(Tok::Ident(name))) => {
                match binds.get(name) {
                    Some(Bound::One(t)) => out.extend(t.iter().cloned()),
                    other => panic!("${name} used at the wrong depth: {other:?}"),
                }
                i += 2;
            }
            (Tok::Punct('$', _), Some(Tok::Group('(', inner))) => {
                let (sep, _, used) = rep_tail(&toks[i + 2..]);
                let runs = binds
                    .iter()
                    .filter(|(n, _)| used_in(n, inner))
                    .find_map(|(_, b)| match b {
                        Bound::Many(r) => Some(r.clone()),
                        Bound::One(_) => None,
                    })
                    .expect("a repetition names a repeated variable");
                for (k, run) in runs.iter().enumerate() {
                    if k > 0 {
                        out.extend(sep.clone());
                    }
                    let mut b = binds.clone();
                    b.extend(run.clone());
                    transcribe(inner, &b, out);
                }
                i += 2 + used;
            }
            (Tok::Group(d, inner), _) => {
                let mut g = Vec::new();
                transcribe(inner, binds, &mut g);
                out.push(Tok::Group(*d, g));
                i += 1;
            }
            (t, _) => {
                out.push(t.clone());
                i += 1;
            }
        }
    }
}

fn used_in(name: &str, toks: &[Tok]) -> bool {
    toks.windows(2)
        .any(|w| matches!((&w[0], &w[1]), (Tok::Punct('$', _), Tok::Ident(n)) if n == name))
        || toks
            .iter()
            .any(|t| matches!(t, Tok::Group(_, g) if used_in(name, g)))
}

/// `concat!(literals)` becomes one string literal, `stringify!(ident)` the ident's name.
fn fold_concat(toks: Vec<Tok>) -> Vec<Tok> {
    let mut out: Vec<Tok> = Vec::new();
    let mut it = toks.into_iter().peekable();
    while let Some(t) = it.next() {
        match t {
            Tok::Ident(ref n)
                if n == "stringify" && matches!(it.peek(), Some(Tok::Punct('!', _))) =>
            {
                it.next();
                let Some(Tok::Group(_, args)) = it.next() else {
                    panic!("stringify! without arguments");
                };
                let [Tok::Ident(name)] = &args[..] else {
                    panic!("stringify! of more than one ident: {args:?}");
                };
                out.push(Tok::Lit(quote(name)));
            }
            Tok::Ident(ref n) if n == "concat" && matches!(it.peek(), Some(Tok::Punct('!', _))) => {
                it.next();
                let Some(Tok::Group(_, args)) = it.next() else {
                    panic!("concat! without arguments");
                };
                let mut s = String::new();
                for a in fold_concat(args) {
                    match a {
                        Tok::Lit(l) => s.push_str(&unquote(&l)),
                        Tok::Punct(',', _) => {}
                        other => panic!("concat! of a non-literal: {other:?}"),
                    }
                }
                out.push(Tok::Lit(quote(&s)));
            }
            Tok::Group(d, inner) => out.push(Tok::Group(d, fold_concat(inner))),
            t => out.push(t),
        }
    }
    out
}

fn print(toks: &[Tok], out: &mut String) {
    for t in toks {
        match t {
            Tok::Ident(s) | Tok::Lit(s) => {
                out.push_str(s);
                out.push(' ');
            }
            Tok::Punct(c, joint) => {
                out.push(*c);
                if !joint {
                    out.push(if matches!(c, ';' | ']') { '\n' } else { ' ' });
                }
            }
            Tok::Group(d, inner) => {
                out.push(*d);
                print(inner, out);
                out.push(close_of(*d));
                out.push(if *d == '{' { '\n' } else { ' ' });
            }
        }
    }
}

/// The macros written out for cbindgen, by the end of their names: `*_struct` declare
/// structs, `*_variants` the type tags and type aliases of a generic block's variants.
const EXPANDED: [&str; 2] = ["_struct", "_variants"];

/// The arms of every `macro_rules! *_struct` (or `*_variants`) in `sources`.
type Arms = Vec<(Vec<Pat>, Vec<Tok>)>;

fn definitions(sources: &[String]) -> HashMap<String, Arms> {
    let mut defs = HashMap::new();
    for text in sources {
        let mut rest = text.as_str();
        while let Some(p) = rest.find("macro_rules!") {
            let after = &rest[p + "macro_rules!".len()..];
            let name: String = after
                .trim_start()
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            rest = after;
            if !EXPANDED.iter().any(|s| name.ends_with(s)) {
                continue;
            }
            let brace = after.find('{').expect("macro body");
            let (body, end) = tokenize(after, brace + 1, Some('}'));
            rest = &after[end..];
            let mut arms = Vec::new();
            let mut i = 0;
            while i < body.len() {
                let (Tok::Group(_, m), Tok::Group(_, t)) = (&body[i], &body[i + 3]) else {
                    panic!("{name}: arm is not (matcher) => {{transcriber}}");
                };
                arms.push((pattern(m), t.clone()));
                i += 4;
                if matches!(body.get(i), Some(Tok::Punct(';', _))) {
                    i += 1;
                }
            }
            defs.insert(name, arms);
        }
    }
    defs
}

/// The byte ranges of the bodies of every `macro_rules!` in `text`: an invocation written
/// there is part of a definition (its caller's expansion reaches it), not an item.
fn definition_spans(text: &str) -> Vec<(usize, usize)> {
    let mut spans = Vec::new();
    let mut from = 0;
    while let Some(p) = text[from..].find("macro_rules!") {
        let start = from + p;
        let brace = start + text[start..].find('{').expect("macro body");
        let (_, end) = tokenize(text, brace + 1, Some('}'));
        spans.push((start, end));
        from = end;
    }
    spans
}

/// `name!` applied to `args`, with every `*_struct!` invocation its expansion makes expanded
/// in turn (a family's macro may declare its struct through the core's).
fn expand_call(defs: &HashMap<String, Arms>, name: &str, args: &[Tok]) -> Vec<Tok> {
    let expanded = defs[name]
        .iter()
        .find_map(|(pat, body)| {
            let mut binds = HashMap::new();
            (match_seq(pat, args, &mut binds)? == args.len()).then(|| {
                let mut toks = Vec::new();
                transcribe(body, &binds, &mut toks);
                toks
            })
        })
        .unwrap_or_else(|| {
            let mut text = String::new();
            print(&args[..args.len().min(40)], &mut text);
            panic!("{name}!: no arm matches the invocation {text}…")
        });
    expand_nested(defs, expanded)
}

/// Replaces each `path::name!(…)` of a `*_struct` macro in `toks` by its expansion; any
/// other macro call is left for cbindgen (which reads only items).
fn expand_nested(defs: &HashMap<String, Arms>, toks: Vec<Tok>) -> Vec<Tok> {
    let mut out: Vec<Tok> = Vec::new();
    let mut it = toks.into_iter().peekable();
    while let Some(t) = it.next() {
        match t {
            Tok::Ident(ref n)
                if defs.contains_key(n) && matches!(it.peek(), Some(Tok::Punct('!', _))) =>
            {
                it.next();
                let Some(Tok::Group(_, args)) = it.next() else {
                    panic!("{n}! without arguments");
                };
                // The call's path (`crate::base::block::`) goes with it.
                while let [.., Tok::Ident(_), Tok::Punct(':', _), Tok::Punct(':', _)] = &out[..] {
                    out.truncate(out.len() - 3);
                }
                out.extend(expand_call(defs, n, &args));
                // A call in item position ends with `;` after `(…)` or `[…]`.
                if matches!(it.peek(), Some(Tok::Punct(';', _))) {
                    it.next();
                }
            }
            Tok::Group(d, inner) => out.push(Tok::Group(d, expand_nested(defs, inner))),
            t => out.push(t),
        }
    }
    out
}

/// Every invocation of a `*_struct!` macro in `sources`, expanded, as one Rust file.
pub fn expand_struct_macros(sources: &[String]) -> String {
    let defs = definitions(sources);
    let mut out =
        String::from("// Generated by build.rs (build_support/expand.rs) for cbindgen.\n");
    for text in sources {
        let spans = definition_spans(text);
        let mut calls = Vec::new();
        for name in defs.keys() {
            let call = format!("{name}!");
            for (pos, _) in text.match_indices(&call) {
                let line_start = text[..pos].rfind('\n').map_or(0, |n| n + 1);
                let before = text[..pos].chars().next_back();
                if text[line_start..pos].trim_start().starts_with("//")
                    || before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == '`')
                    || spans.iter().any(|&(s, e)| s <= pos && pos < e)
                {
                    continue;
                }
                let after = pos + call.len();
                let open = after + text[after..].len() - text[after..].trim_start().len();
                let Some(d @ ('(' | '[' | '{')) = text[open..].chars().next() else {
                    continue;
                };
                calls.push((pos, name, open, d));
            }
        }
        // In the order of the file (a stable output).
        calls.sort();
        for (_, name, open, d) in calls {
            let (args, _) = tokenize(text, open + 1, Some(close_of(d)));
            print(&fold_concat(expand_call(&defs, name, &args)), &mut out);
            out.push('\n');
        }
    }
    out
}
