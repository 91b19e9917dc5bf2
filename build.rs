//! Generates the C header with cbindgen and appends compile-time layout checks: each field's
//! offset and each struct's size, computed here from the generated declarations under the
//! ABI's rule "every member naturally aligned, no implicit padding". The build fails when a
//! struct would need implicit padding or when a Rust doc comment "Offset N." disagrees with
//! the computed offset. The header lands in OUT_DIR; with SAFELOGIC_WRITE_HEADER set it is
//! also written to include/safelogic.h (the committed copy a test compares against).

use std::collections::HashMap;
use std::env;
use std::fs;
use std::path::PathBuf;

fn main() {
    let dir = PathBuf::from(env::var("CARGO_MANIFEST_DIR").expect("CARGO_MANIFEST_DIR"));
    let out = PathBuf::from(env::var("OUT_DIR").expect("OUT_DIR"));
    println!("cargo:rerun-if-changed=src");
    println!("cargo:rerun-if-changed=cbindgen.toml");
    println!("cargo:rerun-if-env-changed=SAFELOGIC_WRITE_HEADER");
    // SONAME of the shared library (major version 0); tools/install.sh installs the versioned names.
    if env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("linux") {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libsafelogic.so.0");
    }

    let config = cbindgen::Config::from_file(dir.join("cbindgen.toml")).expect("cbindgen.toml");
    let bindings = cbindgen::Builder::new()
        .with_crate(&dir)
        .with_config(config)
        .generate()
        .expect("cbindgen could not generate the header");
    let mut raw = Vec::new();
    bindings.write(&mut raw);
    let text = String::from_utf8(raw).expect("header is UTF-8");
    let header = with_layout_checks(&parenthesize_negative_defines(&text));

    fs::write(out.join("safelogic.h"), &header).expect("write OUT_DIR/safelogic.h");
    if env::var_os("SAFELOGIC_WRITE_HEADER").is_some() {
        fs::write(dir.join("include/safelogic.h"), &header).expect("write include/safelogic.h");
    }
}

/// `#define X -1` becomes `#define X (-1)` so the macro is safe in any expression.
fn parenthesize_negative_defines(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 64);
    for line in text.lines() {
        match line
            .strip_prefix("#define ")
            .and_then(|r| r.split_once(" -"))
        {
            Some((name, num)) if num.chars().all(|c| c.is_ascii_digit()) => {
                out.push_str(&format!("#define {name} (-{num})"));
            }
            _ => out.push_str(line),
        }
        out.push('\n');
    }
    out
}

struct Field {
    name: String,
    offset: usize,
    doc_offset: Option<usize>,
}

/// Size and alignment of a scalar C type of the header.
fn scalar(ty: &str) -> Option<(usize, usize)> {
    match ty {
        "uint8_t" | "int8_t" | "SL_BOOL" => Some((1, 1)),
        "uint16_t" | "int16_t" => Some((2, 2)),
        "uint32_t" | "int32_t" => Some((4, 4)),
        _ => None,
    }
}

fn with_layout_checks(text: &str) -> String {
    let mut layouts: HashMap<String, (usize, usize)> = HashMap::new();
    let mut checks = Vec::new();
    let mut current: Option<(String, Vec<Field>, usize, usize)> = None;
    // Structs holding pointers (SL_MEMBER) differ between 32- and 64-bit targets: no
    // published offsets, and no block may embed them.
    let mut has_pointer = false;
    let mut doc_offset: Option<usize> = None;

    for line in text.lines() {
        let t = line.trim();
        if let Some(rest) = t.strip_prefix("typedef struct ") {
            let name = rest.trim_end_matches('{').trim().to_string();
            current = Some((name, Vec::new(), 0, 1));
            has_pointer = false;
            continue;
        }
        let Some((name, fields, offset, align)) = current.as_mut() else {
            continue;
        };
        if let Some(pos) = t.find("Offset ") {
            let digits: String = t[pos + 7..]
                .chars()
                .take_while(|c| c.is_ascii_digit())
                .collect();
            doc_offset = digits.parse().ok();
            continue;
        }
        if t.starts_with('}') && has_pointer {
            current = None;
            continue;
        }
        if t.starts_with('}') {
            assert!(
                *offset % *align == 0,
                "{name}: size {offset} is not a multiple of its alignment"
            );
            if name.starts_with("FB_") {
                assert!(
                    *offset % 8 == 0,
                    "{name}: size {offset} is not a multiple of 8"
                );
            }
            for f in fields.iter() {
                if let Some(d) = f.doc_offset {
                    assert_eq!(
                        d, f.offset,
                        "{name}.{}: doc comment says offset {d}, layout gives {}",
                        f.name, f.offset
                    );
                }
                checks.push(format!(
                    "SL_STATIC_ASSERT(offsetof({name}, {}) == {}, \"offset of {name}.{}\");",
                    f.name, f.offset, f.name
                ));
            }
            checks.push(format!(
                "SL_STATIC_ASSERT(sizeof({name}) == {offset}, \"size of {name}\");"
            ));
            layouts.insert(name.clone(), (*offset, *align));
            current = None;
            continue;
        }
        let Some(decl) = t.strip_suffix(';') else {
            continue;
        };
        if decl.starts_with("/*") || decl.starts_with('*') {
            continue;
        }
        if decl.contains('*') {
            has_pointer = true;
            continue;
        }
        let mut parts = decl.split_whitespace().filter(|w| *w != "struct");
        let (Some(ty), Some(var)) = (parts.next(), parts.next()) else {
            continue;
        };
        let (fname, count) = match var.split_once('[') {
            Some((n, c)) => (
                n,
                c.trim_end_matches(']')
                    .parse::<usize>()
                    .expect("array length"),
            ),
            None => (var, 1),
        };
        let (size, a) = scalar(ty)
            .or_else(|| layouts.get(ty).copied())
            .unwrap_or_else(|| panic!("{name}.{fname}: unknown type {ty}"));
        assert!(
            *offset % a == 0,
            "{name}.{fname}: would need implicit padding before offset {offset}"
        );
        fields.push(Field {
            name: fname.to_string(),
            offset: *offset,
            doc_offset: doc_offset.take(),
        });
        *offset += size * count;
        *align = (*align).max(a);
    }

    let block = format!(
        "\n/* Layout checks: every published offset and size (ABI.md section 3). */\n\
         #if defined(__cplusplus)\n#define SL_STATIC_ASSERT(c, m) static_assert(c, m)\n\
         #else\n#define SL_STATIC_ASSERT(c, m) _Static_assert(c, m)\n#endif\n{}\n\n",
        checks.join("\n")
    );
    let end = text.rfind("#endif").expect("include guard end");
    format!("{}{}{}", &text[..end], block, &text[end..])
}
