//! The timing diagram stays readable however short a state or close two notes are: every
//! state box shows its name, an abbreviation explained in the legend, or a key; marker
//! numbers never overlap each other; marker lines never cross a label.

use safelogic_project::sim::{ColKind, Column, Run, Val};
use safelogic_project::svg;

/// A TWOHAND-like run over 3 s: a 100 ms RELEASE, a 5 ms DELAYOUT, a 1 ms START, notes
/// 5 ms apart (the "2" and "3" that read as "23").
fn run() -> Run {
    let states = [
        (0, "STOP"),
        (100, "RUN"),
        (2000, "RELEASE"),
        (2100, "RUN"),
        (2400, "DELAYOUT"),
        (2405, "START"),
        (2406, "RESET"),
        (2407, "RUN"),
    ];
    Run {
        columns: vec![
            Column {
                name: "Button".into(),
                kind: ColKind::Bool,
                changes: vec![(0, Val::N(0)), (100, Val::N(1)), (2000, Val::N(0))],
            },
            Column {
                name: "th.state".into(),
                kind: ColKind::State,
                changes: states.iter().map(|(t, s)| (*t, Val::S(s))).collect(),
            },
        ],
        until: 3000,
        failures: 0,
        checked: 0,
        notes: vec![
            (0, "start".into()),
            (1000, "press".into()),
            (1005, "press again".into()),
            (1010, "and again".into()),
            (2400, "release".into()),
        ],
    }
}

/// Approximate box of a text (x from its anchor, 6.5 px per character at 10 px).
fn text_box(n: &roxmltree::Node) -> (f64, f64, f64, f64) {
    let x: f64 = n.attribute("x").unwrap().parse().unwrap();
    let y: f64 = n.attribute("y").unwrap().parse().unwrap();
    let size: f64 = n
        .attribute("font-size")
        .map_or(12.0, |s| s.parse().unwrap());
    let w = 0.65 * size * n.text().unwrap_or("").chars().count() as f64;
    let x0 = match n.attribute("text-anchor") {
        Some("middle") => x - w / 2.0,
        Some("end") => x - w,
        _ => x,
    };
    (x0, y - 0.8 * size, x0 + w, y + 0.2 * size)
}

fn overlap(a: (f64, f64, f64, f64), b: (f64, f64, f64, f64)) -> bool {
    a.0 < b.2 && b.0 < a.2 && a.1 < b.3 && b.1 < a.3
}

#[test]
fn short_states_and_close_notes_stay_readable() {
    let r = run();
    let text = svg::svg(&r, "TWOHAND");
    let doc = roxmltree::Document::parse(&text).unwrap();
    let class = |c: &'static str| {
        doc.descendants()
            .filter(move |n| n.attribute("class") == Some(c))
            .collect::<Vec<_>>()
    };
    // Every state segment has a label: its name in its box, or a key whose legend entry
    // ("<row>: <key> = <names> (<times>)") names it.
    let labels = class("state-label");
    let legend: Vec<String> = class("legend")
        .iter()
        .filter_map(|n| n.text().map(str::to_string))
        .collect();
    let shown: Vec<&str> = labels.iter().filter_map(|n| n.text()).collect();
    for (_, v) in &r.columns[1].changes {
        let Val::S(full) = v else { unreachable!() };
        let explained = legend.iter().any(|l| {
            l.split_once(" = ").is_some_and(|(k, names)| {
                shown.contains(&k.trim_start_matches("th.state: "))
                    && names
                        .split(" (")
                        .next()
                        .unwrap()
                        .split(", ")
                        .any(|n| n == *full)
            })
        });
        assert!(
            shown.contains(full) || explained,
            "{full}: labels {shown:?}, legend {legend:?}"
        );
    }
    assert!(
        legend
            .iter()
            .any(|l| l.starts_with("th.state: ") && l.contains("RELEASE (2000 ms)")),
        "{legend:?}"
    );
    // State labels do not overlap each other.
    for (i, a) in labels.iter().enumerate() {
        for b in &labels[i + 1..] {
            assert!(
                !overlap(text_box(a), text_box(b)),
                "{:?} / {:?}",
                a.text(),
                b.text()
            );
        }
    }
    // Marker numbers never overlap each other.
    let markers = class("marker");
    assert_eq!(markers.len(), 5);
    for (i, a) in markers.iter().enumerate() {
        for b in &markers[i + 1..] {
            assert!(
                !overlap(text_box(a), text_box(b)),
                "markers {:?} / {:?}",
                a.text(),
                b.text()
            );
        }
    }
    // Marker lines are painted before (under) every state box and label.
    let order: Vec<_> = doc
        .descendants()
        .filter_map(|n| n.attribute("class"))
        .collect();
    let last_line = order.iter().rposition(|c| *c == "marker-line").unwrap();
    let first_label = order.iter().position(|c| *c == "state-label").unwrap();
    let first_box = order.iter().position(|c| *c == "state-box").unwrap();
    assert!(last_line < first_box && last_line < first_label);
}
