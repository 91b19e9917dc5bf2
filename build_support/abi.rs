//! The ABI declarations kept as data: a source file `src/…/x.rs` keeps its C ABI constants,
//! its `block_struct!` / `private_struct!` / `zeroed_struct!` declarations and its `block_states!` /
//! `sf_states!` list in `src/…/x.abi.toml` beside it. build.rs writes them as Rust to
//! `OUT_DIR/abi/…/x.rs`, which the source file includes where the declarations belong:
//!
//! ```text
//! include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/muting.rs"));
//! ```
//!
//! The data file holds `[[variants]]` tables (an analog block's `analog_variants!`:
//! `name` and the `variant` array), `[[const]]` tables (`name`, `type`, `value`, `doc`, an optional plain
//! `comment` above), `[[struct]]` tables (`macro`, `name`, optional `generics`, `doc`,
//! optional `tail` — the macro's words after the fields — and `[[struct.field]]` tables with
//! `name`, `type` and `doc`; a field without `type` is a marker such as `stHeader`) and
//! `[[states]]` tables (`macro`, `name`, `doc`, `init` for `sf_states`, and the `state`
//! array). Docs are the doc comment's lines without `/// `. Variants come out first, then the
//! constants, the structs and the states, each kind in the file's order. A malformed file stops the
//! build naming the file, the declaration and the field or state.

use serde::Deserialize;
use std::collections::BTreeMap;
use std::fs;
use std::path::Path;

/// The integer types a C ABI constant may have.
const CONST_TYPES: [&str; 6] = ["u8", "u16", "u32", "i8", "i16", "i32"];

/// The declaration macros of the core (`src/base/layout.rs`) a `[[struct]]` may name.
const MACROS: [&str; 3] = ["block_struct", "private_struct", "zeroed_struct"];

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Const {
    comment: Option<String>,
    name: String,
    #[serde(rename = "type")]
    ty: String,
    value: String,
    doc: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Struct {
    #[serde(rename = "macro")]
    mac: String,
    name: String,
    #[serde(default)]
    generics: String,
    doc: String,
    #[serde(default)]
    tail: String,
    // Read one by one below, so that an error names the field.
    field: Vec<toml::Value>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Variants {
    name: String,
    // Read one by one below, so that an error names the variant.
    variant: Vec<toml::Value>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Variant {
    #[serde(rename = "type")]
    ty: String,
    tag: String,
    value: u16,
    alias: String,
    args: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct States {
    #[serde(rename = "macro")]
    mac: String,
    name: String,
    init: Option<String>,
    #[serde(default)]
    doc: String,
    // Read one by one below, so that an error names the state.
    state: Vec<toml::Value>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct State {
    name: String,
    value: Option<String>,
    text: Option<String>,
    code: Option<String>,
    v1: Option<String>,
    description: Option<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Field {
    name: String,
    #[serde(rename = "type")]
    ty: Option<String>,
    doc: Option<String>,
}

/// Every `*.abi.toml` below `src`, written out as Rust below `out`: the generated text by
/// the path of the including file relative to `src` (`blocks/boolean/muting.rs`).
pub fn generate(src: &Path, out: &Path) -> BTreeMap<String, String> {
    // The text of a removed data file must not linger where a test reads the declarations.
    if out.exists() {
        fs::remove_dir_all(out).expect("clear OUT_DIR/abi");
    }
    let mut texts = BTreeMap::new();
    let mut todo = vec![src.to_path_buf()];
    while let Some(d) = todo.pop() {
        for entry in fs::read_dir(&d).expect("read src") {
            let p = entry.expect("dir entry").path();
            let name = p.file_name().and_then(|n| n.to_str()).unwrap_or_default();
            if p.is_dir() {
                todo.push(p);
            } else if let Some(stem) = name.strip_suffix(".abi.toml") {
                println!("cargo:rerun-if-changed={}", p.display());
                let rs = p.with_file_name(format!("{stem}.rs"));
                assert!(
                    rs.exists(),
                    "{}: no {} beside it",
                    p.display(),
                    rs.display()
                );
                let rel = rs
                    .strip_prefix(src)
                    .expect("below src")
                    .to_str()
                    .expect("UTF-8 path")
                    .replace('\\', "/");
                let file = format!("src/{}{stem}.abi.toml", &rel[..rel.len() - stem.len() - 3]);
                let text = rust_of(&file, &fs::read_to_string(&p).expect("read"));
                let target = out.join(&rel);
                fs::create_dir_all(target.parent().expect("parent")).expect("create OUT_DIR/abi");
                fs::write(&target, &text).expect("write OUT_DIR/abi");
                texts.insert(rel, text);
            }
        }
    }
    texts
}

/// The line that includes the generated declarations of `rel`.
fn include_line(rel: &str) -> String {
    format!("include!(concat!(env!(\"OUT_DIR\"), \"/abi/{rel}\"));")
}

/// `text` (the source file `rel`) with its include line replaced by the generated
/// declarations: what cbindgen and the macro expander read.
pub fn substitute(rel: &str, text: &str, texts: &BTreeMap<String, String>) -> String {
    let Some(generated) = texts.get(rel) else {
        assert!(
            !text.contains("\"/abi/"),
            "src/{rel} includes generated declarations but has no data file {}",
            rel.trim_end_matches(".rs").to_string() + ".abi.toml"
        );
        return text.to_string();
    };
    // The include as rustfmt may wrap it: compared without white space.
    let line = include_line(rel);
    let wanted: String = line.split_whitespace().collect();
    let span = text.match_indices("include!(").find_map(|(start, _)| {
        let end = start + text[start..].find("));")? + 3;
        let found: String = text[start..end].split_whitespace().collect();
        (found == wanted).then_some((start, end))
    });
    let (start, end) =
        span.unwrap_or_else(|| panic!("src/{rel} does not include its declarations: `{line}`"));
    format!("{}{}{}", &text[..start], generated, &text[end..])
}

fn is_ident(s: &str) -> bool {
    s.chars()
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// One line free of anything that would end the generated item early.
fn one_line(s: &str) -> bool {
    !s.is_empty() && !s.contains(['\n', ';', '{', '}'])
}

/// The `name` of a table, for messages.
fn name_of(v: &toml::Value) -> String {
    v.get("name")
        .and_then(|n| n.as_str())
        .unwrap_or("(no name)")
        .to_string()
}

/// `doc` as `///` lines at `indent`.
fn doc_lines(out: &mut String, indent: &str, doc: &str) {
    for line in doc.lines() {
        if line.is_empty() {
            out.push_str(&format!("{indent}///\n"));
        } else {
            out.push_str(&format!("{indent}/// {line}\n"));
        }
    }
}

/// The Rust declarations of the data file `file` (for messages) with the text `data`.
fn rust_of(file: &str, data: &str) -> String {
    let table: toml::Table = toml::from_str(data).unwrap_or_else(|e| panic!("{file}: {e}"));
    let mut out = format!("// Generated by build.rs from {file}: edit that file.\n\n");
    for key in table.keys() {
        assert!(
            ["variants", "const", "struct", "states"].contains(&key.as_str()),
            "{file}: unknown table `{key}` (expected [[variants]], [[const]], [[struct]] or [[states]])"
        );
    }
    let list = |key: &str| -> Vec<toml::Value> {
        match table.get(key) {
            None => Vec::new(),
            Some(toml::Value::Array(a)) => a.clone(),
            Some(_) => panic!("{file}: `{key}` must be an array of tables ([[{key}]])"),
        }
    };
    for (k, v) in list("variants").into_iter().enumerate() {
        let name = name_of(&v);
        let s: Variants = v
            .try_into()
            .unwrap_or_else(|e| panic!("{file}: variants {name} (number {}): {e}", k + 1));
        out.push_str(&variants(file, s));
    }
    for (k, v) in list("const").into_iter().enumerate() {
        let name = name_of(&v);
        let c: Const = v
            .try_into()
            .unwrap_or_else(|e| panic!("{file}: constant {name} (number {}): {e}", k + 1));
        assert!(is_ident(&c.name), "{file}: constant {name}: bad name");
        assert!(
            CONST_TYPES.contains(&c.ty.as_str()),
            "{file}: constant {name}: type `{}` is not one of {CONST_TYPES:?}",
            c.ty
        );
        assert!(
            one_line(&c.value),
            "{file}: constant {name}: bad value `{}`",
            c.value
        );
        assert!(!c.doc.is_empty(), "{file}: constant {name}: empty doc");
        for line in c.comment.iter().flat_map(|c| c.lines()) {
            out.push_str(&format!("// {line}\n"));
        }
        doc_lines(&mut out, "", &c.doc);
        out.push_str(&format!(
            "pub const {}: {} = {};\n\n",
            c.name, c.ty, c.value
        ));
    }
    for (k, v) in list("struct").into_iter().enumerate() {
        let name = name_of(&v);
        let s: Struct = v
            .try_into()
            .unwrap_or_else(|e| panic!("{file}: struct {name} (number {}): {e}", k + 1));
        assert!(is_ident(&s.name), "{file}: struct {name}: bad name");
        assert!(
            MACROS.contains(&s.mac.as_str()),
            "{file}: struct {name}: macro `{}` is not one of {MACROS:?}",
            s.mac
        );
        assert!(
            !s.generics.contains(['{', '}', ';']) || s.generics.starts_with('['),
            "{file}: struct {name}: bad generics `{}`",
            s.generics
        );
        assert!(!s.doc.is_empty(), "{file}: struct {name}: empty doc");
        assert!(
            !s.field.is_empty(),
            "{file}: struct {name}: no [[struct.field]]"
        );
        out.push_str(&format!("crate::base::layout::{}! {{\n", s.mac));
        doc_lines(&mut out, "    ", &s.doc);
        out.push_str(&format!("    {}{} {{\n", s.name, s.generics));
        for (j, f) in s.field.into_iter().enumerate() {
            let fname = name_of(&f);
            let f: Field = f.try_into().unwrap_or_else(|e| {
                panic!(
                    "{file}: struct {name}, field {fname} (number {}): {e}",
                    j + 1
                )
            });
            assert!(
                is_ident(&f.name),
                "{file}: struct {name}, field {fname} (number {}): bad name",
                j + 1
            );
            doc_lines(&mut out, "        ", f.doc.as_deref().unwrap_or_default());
            match f.ty {
                Some(ty) => {
                    assert!(
                        !ty.is_empty()
                            && !ty.contains(['\n', '{', '}', ','])
                            && (!ty.contains(';') || ty.starts_with('[')),
                        "{file}: struct {name}, field {fname}: bad type `{ty}`"
                    );
                    out.push_str(&format!("        pub {}: {ty},\n", f.name));
                }
                None => out.push_str(&format!("        {};\n", f.name)),
            }
        }
        out.push_str("    }");
        for (j, line) in s.tail.lines().enumerate() {
            out.push_str(if j == 0 { " " } else { "\n        " });
            out.push_str(line);
        }
        out.push_str("\n}\n\n");
    }
    for (k, v) in list("states").into_iter().enumerate() {
        let name = name_of(&v);
        let s: States = v
            .try_into()
            .unwrap_or_else(|e| panic!("{file}: states {name} (number {}): {e}", k + 1));
        out.push_str(&states(file, s));
    }
    out
}

/// The `analog_variants!` invocation of a `[[variants]]` table: the type tag and type alias
/// of each integer variant of a generic analog block (`src/blocks/analog/mod.rs`).
fn variants(file: &str, s: Variants) -> String {
    let name = &s.name;
    assert!(is_ident(name), "{file}: variants {name}: bad name");
    assert!(!s.variant.is_empty(), "{file}: variants {name}: no variant");
    let mut lines = Vec::new();
    for (j, v) in s.variant.into_iter().enumerate() {
        let alias = v
            .get("alias")
            .and_then(|a| a.as_str())
            .unwrap_or("(no alias)")
            .to_string();
        let at = format!(
            "{file}: variants {name}, variant {alias} (number {})",
            j + 1
        );
        let v: Variant = v.try_into().unwrap_or_else(|e| panic!("{at}: {e}"));
        assert!(
            ["INT", "UINT", "DINT", "UDINT"].contains(&v.ty.as_str()),
            "{at}: type `{}` is not INT, UINT, DINT or UDINT",
            v.ty
        );
        assert!(
            is_ident(&v.tag) && is_ident(&v.alias),
            "{at}: bad tag or alias"
        );
        assert!(
            !v.args.is_empty() && !v.args.contains(['[', ']', '{', '}', ';', '\n']),
            "{at}: bad args `{}`",
            v.args
        );
        lines.push(format!(
            "        {} {} = {} => {}[{}]",
            v.ty, v.tag, v.value, v.alias, v.args
        ));
    }
    format!(
        "crate::blocks::analog::analog_variants! {{\n    {name}:\n{}\n}}\n\n",
        lines.join(",\n")
    )
}

/// A Rust string literal of `text`.
fn quoted(text: &str) -> String {
    format!("\"{}\"", text.replace('\\', "\\\\").replace('"', "\\\""))
}

/// The `block_states!` (TwinSAFE: a common state by its name, a block's own with `value`, a
/// `SL_STATE_…` constant, and `text`) or `sf_states!` (PLCopen: `code`, `v1`, `text`,
/// `description`; `init` the state entered from IDLE) invocation of a `[[states]]` table.
fn states(file: &str, s: States) -> String {
    let name = &s.name;
    assert!(is_ident(name), "{file}: states {name}: bad name");
    assert!(!s.state.is_empty(), "{file}: states {name}: no state");
    let sf = match s.mac.as_str() {
        "block_states" => false,
        "sf_states" => true,
        m => panic!("{file}: states {name}: macro `{m}` is not block_states or sf_states"),
    };
    assert!(
        sf == s.init.is_some(),
        "{file}: states {name}: `init` belongs to sf_states, and sf_states needs it"
    );
    let path = if sf { "crate" } else { "crate::base::block" };
    let mut out = format!("{path}::{}!(\n", s.mac);
    doc_lines(&mut out, "    ", &s.doc);
    let count = s.state.len();
    let mut lines = Vec::new();
    for (j, v) in s.state.into_iter().enumerate() {
        let vname = name_of(&v);
        let st: State = v.try_into().unwrap_or_else(|e| {
            panic!(
                "{file}: states {name}, state {vname} (number {}): {e}",
                j + 1
            )
        });
        let at = format!("{file}: states {name}, state {vname}");
        assert!(is_ident(&st.name), "{at}: bad name");
        let text = st.text.as_deref().map(quoted);
        let line = if sf {
            let (Some(code), Some(v1), Some(text), Some(d), None) =
                (&st.code, &st.v1, &text, &st.description, &st.value)
            else {
                panic!("{at}: an sf_states state has code, v1, text and description, no value");
            };
            for c in [code, v1] {
                assert!(
                    c.strip_prefix("0x")
                        .is_some_and(|h| u16::from_str_radix(h, 16).is_ok()),
                    "{at}: `{c}` is not a 16-bit hex code"
                );
            }
            format!("{} = {code}, {v1}, {text}, {};", st.name, quoted(d))
        } else {
            assert!(
                st.code.is_none() && st.v1.is_none() && st.description.is_none(),
                "{at}: a block_states state has only name, value and text"
            );
            let sep = if j + 1 < count { "," } else { "" };
            match (&st.value, &text) {
                (None, None) => format!("{}{sep}", st.name),
                (Some(value), Some(text)) if is_ident(value) => {
                    format!("{} = {value}, {text}{sep}", st.name)
                }
                _ => panic!("{at}: `value` (a constant) and `text` go together"),
            }
        };
        lines.push(line);
    }
    if sf {
        out.push_str(&format!(
            "    {name}, init: {} {{\n",
            s.init.as_deref().unwrap_or_default()
        ));
        for l in lines {
            out.push_str(&format!("        {l}\n"));
        }
        out.push_str("    }\n);\n\n");
    } else {
        out.push_str(&format!("    {name}:\n"));
        for l in lines {
            out.push_str(&format!("        {l}\n"));
        }
        out.push_str(");\n\n");
    }
    out
}
