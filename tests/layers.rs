//! The library's layers, checked on its module graph (docs/architecture.md).
//!
//! Every file of `src/` is a node; every path it names (`crate::…`, `$crate::…`,
//! `super::…`, an exported macro `crate::name!`, grouped imports included) is an edge to the
//! file that defines the longest module prefix of the path. Comments are not read, and
//! neither are unit-test modules (`#[cfg(test)] mod tests { … }` at the end of a file: they
//! may test a layer against the registry above it). The check fails on an edge into a
//! higher layer (a back edge) and on any circle of files, including one inside a layer.
//! It also writes the picture of the graph that docs/architecture.md shows, and fails when
//! the committed one is stale (`SAFELOGIC_WRITE_GRAPH=1` rewrites it).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The layers from the bottom; a module is in the layer of its first path segment.
const LAYERS: &[(&str, &[&str])] = &[
    ("core", &["base"]),
    ("blocks", &["blocks"]),
    ("registry", &["registry"]),
    ("fsoe", &["fsoe"]),
    ("group", &["group"]),
    ("API", &["any", "ffi"]),
    ("crate root", &[""]),
];

fn layer_of(module: &str) -> usize {
    let first = module.split("::").next().unwrap_or("");
    LAYERS
        .iter()
        .position(|(_, mods)| mods.contains(&first))
        .unwrap_or_else(|| panic!("module {module} is in no layer: add it to LAYERS"))
}

/// A source tree: module path ("" for the crate root, "blocks::boolean::estop") → text.
type Tree = BTreeMap<String, String>;

fn read_tree(root: &Path) -> Tree {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(p);
            }
        }
    }
    let mut files = Vec::new();
    walk(root, &mut files);
    files
        .into_iter()
        .map(|p| {
            let rel = p.strip_prefix(root).unwrap().with_extension("");
            let mut segs: Vec<String> = rel.iter().map(|s| s.to_string_lossy().into()).collect();
            if matches!(segs.last().map(String::as_str), Some("mod" | "lib")) {
                segs.pop();
            }
            let mut text = std::fs::read_to_string(&p).unwrap();
            // The declarations build.rs generates from the file's `.abi.toml` are part of it,
            // where it includes them (`include!(concat!(env!("OUT_DIR"), "/abi/…"))`).
            if let Some(start) = text.find("include!(concat!(") {
                let end = start + text[start..].find("));").unwrap() + 3;
                if text[start..end].contains("\"/abi/") {
                    let generated = Path::new(env!("OUT_DIR"))
                        .join("abi")
                        .join(p.strip_prefix(root).unwrap());
                    text.replace_range(start..end, &std::fs::read_to_string(generated).unwrap());
                }
            }
            (segs.join("::"), text)
        })
        .collect()
}

/// The text without comments, string literals and a trailing unit-test module.
fn code_of(text: &str) -> String {
    let text = match text.find("#[cfg(test)]\nmod tests") {
        Some(i) => &text[..i],
        None => text,
    };
    let mut out = String::with_capacity(text.len());
    let b = text.as_bytes();
    let mut i = 0;
    while i < b.len() {
        if b[i..].starts_with(b"//") {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if b[i..].starts_with(b"/*") {
            i += text[i..].find("*/").map_or(b.len() - i, |n| n + 2);
        } else if b[i] == b'"' && !(i > 0 && b[i - 1] == b'\'') {
            i += 1;
            while i < b.len() && b[i] != b'"' {
                i += if b[i] == b'\\' { 2 } else { 1 };
            }
            i += 1;
            out.push_str("\"\"");
        } else {
            out.push(b[i] as char);
            i += 1;
        }
    }
    out
}

fn is_ident(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_'
}

/// Every path that starts with `crate`, `$crate` or `super` in `code`, braces expanded;
/// a path to an exported macro ends in `name!`.
fn paths_in(code: &str) -> Vec<Vec<String>> {
    let b = code.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let start_ok = i == 0 || !(is_ident(b[i - 1]) || b[i - 1] == b':');
        let head = ["$crate::", "crate::", "super::"]
            .into_iter()
            .find(|h| code[i..].starts_with(h));
        match head {
            Some(h) if start_ok => {
                let first = h.trim_start_matches('$').trim_end_matches("::").to_string();
                let mut j = i + h.len();
                parse_tail(code, &mut j, vec![first], &mut out);
                i = j.max(i + 1);
            }
            _ => i += 1,
        }
    }
    out
}

/// Parses `a::b::{c, d::e}` or `name!` after a prefix, pushing the full paths.
fn parse_tail(code: &str, j: &mut usize, prefix: Vec<String>, out: &mut Vec<Vec<String>>) {
    let b = code.as_bytes();
    let mut path = prefix;
    loop {
        while *j < b.len() && b[*j].is_ascii_whitespace() {
            *j += 1;
        }
        if *j < b.len() && b[*j] == b'{' {
            *j += 1;
            loop {
                while *j < b.len() && (b[*j].is_ascii_whitespace() || b[*j] == b',') {
                    *j += 1;
                }
                if *j >= b.len() || b[*j] == b'}' {
                    *j += 1;
                    return;
                }
                let before = *j;
                parse_tail(code, j, path.clone(), out);
                if *j == before {
                    *j += 1;
                }
            }
        }
        let s = *j;
        while *j < b.len() && is_ident(b[*j]) {
            *j += 1;
        }
        if *j == s {
            out.push(path);
            return;
        }
        let mut seg = code[s..*j].to_string();
        if *j < b.len() && b[*j] == b'!' {
            seg.push('!');
        }
        path.push(seg);
        if code[*j..].starts_with("::") {
            *j += 2;
        } else {
            out.push(path);
            return;
        }
    }
}

/// The exported macros (`#[macro_export] macro_rules! name`) and their modules.
fn exported_macros(tree: &Tree) -> BTreeMap<String, String> {
    let mut out = BTreeMap::new();
    for (module, text) in tree {
        let code = code_of(text);
        for (i, _) in code.match_indices("#[macro_export]") {
            if let Some(k) = code[i..].find("macro_rules!") {
                let rest = code[i + k + "macro_rules!".len()..].trim_start();
                let name: String = rest.chars().take_while(|c| is_ident(*c as u8)).collect();
                out.insert(name, module.clone());
            }
        }
    }
    out
}

/// The module a path reaches: the longest prefix that is a file of the tree.
fn target(
    tree: &Tree,
    macros: &BTreeMap<String, String>,
    from: &str,
    path: &[String],
) -> Option<String> {
    let mut segs: Vec<String> = Vec::new();
    let mut rest = path;
    match path.first().map(String::as_str) {
        Some("crate") => rest = &path[1..],
        Some("super") => {
            // a file's module is its path; `super` is its parent (a mod.rs is its folder)
            segs = from
                .split("::")
                .filter(|s| !s.is_empty())
                .map(String::from)
                .collect();
            while rest.first().map(String::as_str) == Some("super") {
                segs.pop();
                rest = &rest[1..];
            }
        }
        _ => return None,
    }
    if let Some(m) = rest.first().and_then(|s| s.strip_suffix('!')) {
        if segs.is_empty() {
            return macros.get(m).cloned();
        }
    }
    let mut best = segs.join("::");
    for s in rest {
        segs.push(s.trim_end_matches('!').to_string());
        let candidate = segs.join("::");
        if tree.contains_key(&candidate) {
            best = candidate;
        }
    }
    tree.contains_key(&best).then_some(best)
}

/// The child modules a file names by a relative path (`arith::Foo`, `self::arith::Foo`).
fn children_named(tree: &Tree, module: &str, text: &str) -> Vec<String> {
    let code = code_of(text).replace("self::", "");
    let prefix = if module.is_empty() {
        String::new()
    } else {
        format!("{module}::")
    };
    tree.keys()
        .filter_map(|k| {
            k.strip_prefix(prefix.as_str())
                .filter(|c| !c.is_empty() && !c.contains("::"))
                .map(|c| (k, c))
        })
        .filter(|(_, child)| {
            code.match_indices(&format!("{child}::")).any(|(i, _)| {
                i == 0 || !(is_ident(code.as_bytes()[i - 1]) || code.as_bytes()[i - 1] == b':')
            })
        })
        .map(|(k, _)| k.clone())
        .collect()
}

/// The graph: module → the modules it names.
fn graph(tree: &Tree) -> BTreeMap<String, BTreeSet<String>> {
    let macros = exported_macros(tree);
    tree.iter()
        .map(|(module, text)| {
            let edges = paths_in(&code_of(text))
                .iter()
                .filter_map(|p| target(tree, &macros, module, p))
                .chain(children_named(tree, module, text))
                .filter(|t| t != module)
                .collect();
            (module.clone(), edges)
        })
        .collect()
}

/// What is wrong with the graph: back edges and circles.
fn violations(g: &BTreeMap<String, BTreeSet<String>>) -> Vec<String> {
    let mut out = Vec::new();
    for (from, tos) in g {
        for to in tos {
            if layer_of(to) > layer_of(from) {
                out.push(format!(
                    "back edge: {from} ({}) imports {to} ({})",
                    LAYERS[layer_of(from)].0,
                    LAYERS[layer_of(to)].0
                ));
            }
        }
    }
    for scc in circles(g) {
        out.push(format!("circle: {}", scc.join(" -> ")));
    }
    out
}

/// The strongly connected components with more than one module (Tarjan).
fn circles(g: &BTreeMap<String, BTreeSet<String>>) -> Vec<Vec<String>> {
    struct T<'a> {
        g: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on: BTreeSet<&'a str>,
        out: Vec<Vec<String>>,
    }
    fn visit<'a>(t: &mut T<'a>, v: &'a str) {
        let n = t.index.len();
        t.index.insert(v, n);
        t.low.insert(v, n);
        t.stack.push(v);
        t.on.insert(v);
        for w in t.g.get(v).into_iter().flatten() {
            let w = w.as_str();
            if !t.index.contains_key(w) {
                visit(t, w);
                let lw = t.low[w];
                let lv = t.low.get_mut(v).unwrap();
                *lv = (*lv).min(lw);
            } else if t.on.contains(w) {
                let iw = t.index[w];
                let lv = t.low.get_mut(v).unwrap();
                *lv = (*lv).min(iw);
            }
        }
        if t.low[v] == t.index[v] {
            let mut scc = Vec::new();
            while let Some(w) = t.stack.pop() {
                t.on.remove(w);
                scc.push(w.to_string());
                if w == v {
                    break;
                }
            }
            if scc.len() > 1 {
                scc.sort();
                t.out.push(scc);
            }
        }
    }
    let mut t = T {
        g,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on: BTreeSet::new(),
        out: Vec::new(),
    };
    for v in g.keys() {
        if !t.index.contains_key(v.as_str()) {
            visit(&mut t, v);
        }
    }
    t.out
}

fn src() -> Tree {
    read_tree(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"))
}

/// The violations of src/ with `code` put at the top of the file of module `module`.
fn injected(module: &str, code: &str) -> Vec<String> {
    let mut tree = src();
    tree.get_mut(module).unwrap().insert_str(0, code);
    violations(&graph(&tree))
}

#[test]
fn every_import_goes_down_and_no_file_is_in_a_circle() {
    let tree = src();
    let g = graph(&tree);
    // the check reaches the tree: every layer has files and the blocks name the core
    for (name, _) in LAYERS {
        assert!(
            g.keys().any(|m| LAYERS[layer_of(m)].0 == *name),
            "layer {name} has no file"
        );
    }
    assert!(
        g["blocks::boolean::estop"].contains("base::member"),
        "{:?}",
        g["blocks::boolean::estop"]
    );
    assert!(g["registry"]
        .iter()
        .any(|t| t.starts_with("blocks::plcopen::")));
    let edges: usize = g.values().map(BTreeSet::len).sum();
    let found = violations(&g);
    assert!(
        found.is_empty(),
        "{} files, {edges} edges:\n{}",
        g.len(),
        found.join("\n")
    );
    println!("{} files, {edges} edges, 0 back edges, 0 circles", g.len());
}

#[test]
fn a_back_edge_or_a_circle_is_found() {
    // the core naming the registry: a back edge
    let found = injected("base::types", "use crate::registry::BLOCKS;\n");
    assert_eq!(
        found[0], "back edge: base::types (core) imports registry (registry)",
        "{found:?}"
    );
    // and, since the registry lists every block and every block names the core, a circle
    assert!(
        found[1..].iter().all(|c| c.starts_with("circle: ")
            && c.contains("base::types")
            && c.contains("registry")),
        "{found:?}"
    );
    // through a grouped import and a macro: the same
    let found = injected(
        "base::bools",
        "use crate::{group::{self, SL_LINK}};\nfn f() { crate::for_each_block!(x); }\n",
    );
    for wanted in [
        "base::bools (core) imports group",
        "base::bools (core) imports registry",
    ] {
        assert!(
            found.iter().any(|v| v.contains(wanted)),
            "{wanted} not in {found:?}"
        );
    }
    // two blocks of one family naming each other: a circle inside a layer
    let found = injected("blocks::boolean::guard", "use super::estop::FB_ESTOP;\n");
    assert_eq!(
        found,
        ["circle: blocks::boolean::estop -> blocks::boolean::guard"],
        "{found:?}"
    );
}

// (each injected at the top of a file: a unit-test module at the end is not read)

/// The picture of docs/architecture.md: the layers from the bottom up, a box per folder or
/// top-level module, an arrow per pair of boxes with at least one import, the count on it.
fn picture(g: &BTreeMap<String, BTreeSet<String>>) -> String {
    let boxed = |m: &str| -> String {
        let segs: Vec<&str> = m.split("::").collect();
        match segs.as_slice() {
            ["blocks", fam, ..] => format!("blocks::{fam}"),
            [first, ..] => first.to_string(),
            [] => String::new(),
        }
    };
    let mut boxes: BTreeMap<usize, BTreeSet<String>> = BTreeMap::new();
    let mut files: BTreeMap<String, usize> = BTreeMap::new();
    // a file that only declares its submodules (blocks/mod.rs) names nothing and is named by
    // nothing: it has no box
    let named: BTreeSet<&String> = g.values().flatten().collect();
    for m in g.keys().filter(|m| !g[*m].is_empty() || named.contains(m)) {
        let name = if m.is_empty() {
            "lib".to_string()
        } else {
            boxed(m)
        };
        boxes.entry(layer_of(m)).or_default().insert(name.clone());
        *files.entry(name).or_default() += 1;
    }
    let mut links: BTreeMap<(String, String), usize> = BTreeMap::new();
    for (from, tos) in g {
        let a = if from.is_empty() {
            "lib".to_string()
        } else {
            boxed(from)
        };
        for to in tos {
            let b = boxed(to);
            if a != b {
                *links.entry((a.clone(), b)).or_default() += 1;
            }
        }
    }
    let (h, bw, bh, gap) = (90.0f64, 150.0f64, 40.0f64, 14.0f64);
    let widest = boxes.values().map(BTreeSet::len).max().unwrap_or(1) as f64;
    let w = (130.0 + widest * bw + (widest - 1.0) * gap).max(960.0);
    let rows = LAYERS.len() as f64;
    let height = rows * h + 20.0;
    let mut pos: BTreeMap<String, (f64, f64)> = BTreeMap::new();
    let mut svg = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{height}\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<defs><marker id=\"a\" viewBox=\"0 0 10 10\" refX=\"10\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\" orient=\"auto\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"#555\"/></marker></defs>\n"
    );
    for (layer, names) in &boxes {
        let y = height - 10.0 - (*layer as f64 + 1.0) * h + (h - bh) / 2.0;
        svg += &format!(
            "<text x=\"8\" y=\"{:.0}\" fill=\"#777\">{}</text>\n",
            y + bh / 2.0 + 4.0,
            LAYERS[*layer].0
        );
        let n = names.len() as f64;
        let x0 = 110.0 + (w - 110.0 - n * bw - (n - 1.0) * gap) / 2.0;
        for (k, name) in names.iter().enumerate() {
            let x = x0 + k as f64 * (bw + gap);
            pos.insert(name.clone(), (x + bw / 2.0, y));
            svg += &format!(
                "<rect x=\"{x:.0}\" y=\"{y:.0}\" width=\"{bw:.0}\" height=\"{bh:.0}\" rx=\"5\" fill=\"#eef3fb\" stroke=\"#36c\"/>\n<text x=\"{:.0}\" y=\"{:.0}\" text-anchor=\"middle\">{name}</text>\n<text x=\"{:.0}\" y=\"{:.0}\" text-anchor=\"middle\" font-size=\"10\" fill=\"#555\">{} file{}</text>\n",
                x + bw / 2.0,
                y + 17.0,
                x + bw / 2.0,
                y + 32.0,
                files[name],
                if files[name] == 1 { "" } else { "s" }
            );
        }
    }
    for ((a, b), n) in &links {
        let (ax, ay) = pos[a];
        let (bx, by) = pos[b];
        // down to the box below; within a layer, a curve under the boxes
        let d = if by == ay {
            format!(
                "M{ax:.0},{:.0} Q{:.0},{:.0} {bx:.0},{:.0}",
                ay + bh,
                (ax + bx) / 2.0,
                ay + bh + 28.0,
                by + bh
            )
        } else {
            format!("M{ax:.0},{:.0} L{bx:.0},{by:.0}", ay + bh)
        };
        svg += &format!(
            "<path d=\"{d}\" fill=\"none\" stroke=\"#555\" stroke-opacity=\"0.45\" marker-end=\"url(#a)\"><title>{a} imports {b} ({n} files)</title></path>\n"
        );
    }
    svg += "</svg>\n";
    svg
}

#[test]
fn the_committed_picture_is_fresh() {
    let g = graph(&src());
    let svg = picture(&g);
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/architecture.svg");
    if std::env::var_os("SAFELOGIC_WRITE_GRAPH").is_some() {
        std::fs::write(&path, &svg).unwrap();
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(committed == svg, "docs/architecture.svg is stale: SAFELOGIC_WRITE_GRAPH=1 cargo test --release --test layers");
}
