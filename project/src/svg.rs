//! An SVG timing diagram of a run in the style of the manual's figures: one row per signal
//! (BOOLs as high/low traces, integers as value bands, states as labelled boxes), a time
//! axis in ms, and the scenario's notes as numbered markers.

use crate::sim::{ColKind, Run, Val};
use std::fmt::Write;

const LEFT: f64 = 170.0;
const PLOT: f64 = 860.0;
const ROW: f64 = 30.0;
const TOP: f64 = 44.0;

fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn state_color(s: &str) -> &'static str {
    match s {
        "RUN" => "#c8e6c9",
        "ERROR" => "#ffcdd2",
        "STOP" | "SAFE" => "#e0e0e0",
        _ => "#fff3c4",
    }
}

/// A "nice" tick step for a span of `total` ms (about 10 ticks).
fn tick_step(total: u32) -> u32 {
    let raw = (total / 10).max(1);
    let mag = 10u32.pow(raw.ilog10());
    [1, 2, 5, 10]
        .iter()
        .map(|m| m * mag)
        .find(|s| *s >= raw)
        .unwrap_or(10 * mag)
}

/// Width of a text of `n` characters at `size` px (DejaVu Sans: about 0.65 em per character;
/// generous, so that a label judged to fit does fit).
fn text_width(n: usize, size: f64) -> f64 {
    0.65 * size * n as f64
}

/// Where the label of one or more consecutive segments of a row goes.
enum Label {
    /// The value itself, inside its box.
    Inside(f64, String),
    /// A key inside a box too narrow for the value (x of the box's middle).
    Key(f64, String),
    /// A key below a run of boxes too narrow even for a key (x of the run's middle).
    Below(f64, String),
}

/// The labels of a row of value boxes, and the legend lines for the keys it used. A value
/// that fits its box is written in it; a run of consecutive boxes too narrow for their
/// values gets one letter key (in the box when a letter fits, else just below the row),
/// and the legend names the values behind the key with their times. Keys below the row
/// never overlap: a run that would touch the previous one joins it.
fn row_labels(
    name: &str,
    segs: &[(u32, u32, &Val)],
    x: &dyn Fn(u32) -> f64,
    keys: &mut Vec<String>,
) -> Vec<Label> {
    const SIZE: f64 = 10.0;
    let fits =
        |a: u32, b: u32, text: &str| x(b) - x(a) >= text_width(text.chars().count(), SIZE) + 4.0;
    let mut out = Vec::new();
    // Runs of segments that do not fit: (first, last) indices.
    let mut runs: Vec<(usize, usize)> = Vec::new();
    for (i, (a, b, v)) in segs.iter().enumerate() {
        let text = v.to_string();
        if fits(*a, *b, &text) {
            out.push(Label::Inside(x(*a) + 3.0, text));
        } else {
            match runs.last_mut() {
                Some(r) if r.1 + 1 == i => r.1 = i,
                _ => runs.push((i, i)),
            }
        }
    }
    // Runs whose keys would sit below the row and touch: one run.
    let key_w = text_width(1, 8.0) + 4.0;
    let mut merged: Vec<(usize, usize)> = Vec::new();
    for r in runs {
        let narrow = |r: (usize, usize)| !fits(segs[r.0].0, segs[r.1].1, "m");
        if let Some(last) = merged.last_mut() {
            let gap = x(segs[r.0].0) - x(segs[last.1].1);
            if narrow(*last) && narrow(r) && gap < key_w {
                last.1 = r.1;
                continue;
            }
        }
        merged.push(r);
    }
    for (first, last) in merged {
        let (a, b) = (segs[first].0, segs[last].1);
        let key = key_name(keys.len());
        let values: Vec<String> = segs[first..=last].iter().map(|s| s.2.to_string()).collect();
        let when = if last == first {
            format!("{a} ms")
        } else {
            format!("{a}–{} ms", segs[last].0)
        };
        keys.push(format!("{name}: {key} = {} ({when})", values.join(", ")));
        let mid = (x(a) + x(b)) / 2.0;
        if fits(a, b, "m") && first == last {
            out.push(Label::Key(mid, key));
        } else {
            out.push(Label::Below(mid, key));
        }
    }
    out
}

/// The key of the `i`-th legend entry: a, b, …, z, a1, b1, …
fn key_name(i: usize) -> String {
    let letter = char::from(b'a' + (i % 26) as u8);
    if i < 26 {
        letter.to_string()
    } else {
        format!("{letter}{}", i / 26)
    }
}

/// The lane (0 = lowest) of each marker number so that no two overlap: a number takes the
/// lowest lane where it keeps 3 px from the number before it in that lane.
fn marker_lanes(xs: &[(f64, f64)]) -> Vec<usize> {
    let mut right: Vec<f64> = Vec::new();
    xs.iter()
        .map(|(x, w)| {
            let lane = right
                .iter()
                .position(|r| x - w / 2.0 > r + 3.0)
                .unwrap_or(right.len());
            if lane == right.len() {
                right.push(f64::MIN);
            }
            right[lane] = x + w / 2.0;
            lane
        })
        .collect()
}

/// The SVG text of a run.
pub fn svg(run: &Run, title: &str) -> String {
    let end = run.until.max(1) + run.until.max(1) / 50 + 1;
    let x = |t: u32| LEFT + f64::from(t) * PLOT / f64::from(end);
    // Marker numbers in lanes above the plot; the plot starts below the highest lane.
    let marks: Vec<(f64, f64)> = run
        .notes
        .iter()
        .enumerate()
        .map(|(i, (t, _))| (x(*t), text_width((i + 1).to_string().len(), 10.0)))
        .collect();
    let lanes = marker_lanes(&marks);
    let lane_count = lanes.iter().max().map_or(1, |m| m + 1);
    let top = TOP + 11.0 * (lane_count - 1) as f64;
    // Labels first: the legend's length sets the height.
    let mut keys = Vec::new();
    let rows: Vec<_> = run
        .columns
        .iter()
        .map(|c| {
            // Segments: (start, end, value).
            let segs: Vec<(u32, u32, &Val)> = c
                .changes
                .iter()
                .enumerate()
                .map(|(i, (t, v))| (*t, c.changes.get(i + 1).map_or(end, |n| n.0), v))
                .collect();
            let labels = match c.kind {
                ColKind::Bool => Vec::new(),
                ColKind::Int(_) | ColKind::State => row_labels(&c.name, &segs, &x, &mut keys),
            };
            (c, segs, labels)
        })
        .collect();
    let axis_y = top + rows.len() as f64 * ROW + 8.0;
    let legend_y = axis_y + 34.0;
    let height = legend_y + 16.0 * (run.notes.len() + keys.len()) as f64;
    let width = LEFT + PLOT + 20.0;
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}" font-family="DejaVu Sans, Arial, sans-serif" font-size="12">"#
    );
    let _ = writeln!(
        s,
        r#"<rect x="0" y="0" width="{width}" height="{height}" fill="white"/>"#
    );
    let _ = writeln!(
        s,
        r#"<text x="10" y="22" font-size="15" font-weight="bold">{}</text>"#,
        esc(title)
    );
    // Row backgrounds and names.
    for (r, (c, ..)) in rows.iter().enumerate() {
        let y0 = top + r as f64 * ROW;
        let fill = if r % 2 == 0 { "#fafafa" } else { "#ffffff" };
        let _ = writeln!(
            s,
            r#"<rect x="0" y="{y0}" width="{width}" height="{ROW}" fill="{fill}"/>"#
        );
        let _ = writeln!(
            s,
            r#"<text x="10" y="{}">{}</text>"#,
            y0 + ROW / 2.0 + 4.0,
            esc(&c.name)
        );
    }
    // Grid and marker lines under the traces and boxes: they never cross a label.
    let step = tick_step(end);
    let mut t = 0;
    while t <= end {
        let xt = x(t);
        let _ = writeln!(
            s,
            r##"<line x1="{xt:.1}" y1="{top}" x2="{xt:.1}" y2="{}" stroke="#ccc" stroke-dasharray="2,3"/>"##,
            axis_y + 4.0
        );
        t += step;
    }
    for (t, _) in &run.notes {
        let xt = x(*t);
        let _ = writeln!(
            s,
            r##"<line class="marker-line" x1="{xt:.1}" y1="{}" x2="{xt:.1}" y2="{axis_y}" stroke="#d32f2f" stroke-width="0.8"/>"##,
            top - 4.0
        );
    }
    for (r, (c, segs, labels)) in rows.iter().enumerate() {
        let y0 = top + r as f64 * ROW;
        let (hi, lo) = (y0 + 5.0, y0 + ROW - 7.0);
        match c.kind {
            ColKind::Bool => {
                let mut d = String::new();
                for (i, (a, b, v)) in segs.iter().enumerate() {
                    let y = if matches!(v, Val::N(n) if *n != 0) {
                        hi
                    } else {
                        lo
                    };
                    let _ = write!(
                        d,
                        "{}{:.1},{y} L{:.1},{y} ",
                        if i == 0 { "M" } else { "L" },
                        x(*a),
                        x(*b)
                    );
                    if matches!(v, Val::N(n) if *n != 0) {
                        // Translucent, so the marker lines under it stay visible.
                        let _ = writeln!(
                            s,
                            r##"<rect x="{:.1}" y="{hi}" width="{:.1}" height="{}" fill="#bbdefb" fill-opacity="0.75"/>"##,
                            x(*a),
                            x(*b) - x(*a),
                            lo - hi
                        );
                    }
                }
                let _ = writeln!(
                    s,
                    r##"<path d="{}" fill="none" stroke="#0d47a1" stroke-width="1.6"/>"##,
                    d.trim_end()
                );
            }
            ColKind::Int(_) | ColKind::State => {
                for (a, b, v) in segs {
                    let (xa, xb) = (x(*a), x(*b));
                    let color = match v {
                        Val::S(name) => state_color(name),
                        Val::N(_) => "#ede7f6",
                    };
                    let _ = writeln!(
                        s,
                        r##"<rect class="state-box" x="{xa:.1}" y="{hi}" width="{:.1}" height="{}" fill="{color}" stroke="#555" stroke-width="0.8"/>"##,
                        xb - xa,
                        lo - hi
                    );
                }
                for l in labels {
                    let _ = match l {
                        Label::Inside(xl, text) => writeln!(
                            s,
                            r#"<text class="state-label" x="{xl:.1}" y="{}" font-size="10">{}</text>"#,
                            lo - 5.0,
                            esc(text)
                        ),
                        Label::Key(xl, key) => writeln!(
                            s,
                            r##"<text class="state-label" x="{xl:.1}" y="{}" font-size="10" font-style="italic" fill="#6a1b9a" text-anchor="middle">{key}</text>"##,
                            lo - 5.0
                        ),
                        // Below the row a marker line may pass: a white halo keeps the key
                        // clear of it.
                        Label::Below(xl, key) => writeln!(
                            s,
                            r##"<text class="state-label" x="{xl:.1}" y="{}" font-size="8" font-style="italic" fill="#6a1b9a" text-anchor="middle" stroke="white" stroke-width="3" paint-order="stroke">{key}</text>"##,
                            lo + 6.5
                        ),
                    };
                }
            }
        }
    }
    // Time axis.
    let _ = writeln!(
        s,
        r##"<line x1="{LEFT}" y1="{axis_y}" x2="{}" y2="{axis_y}" stroke="#000"/>"##,
        LEFT + PLOT
    );
    let mut t = 0;
    while t <= end {
        let _ = writeln!(
            s,
            r#"<text x="{:.1}" y="{}" font-size="10" text-anchor="middle">{t} ms</text>"#,
            x(t),
            axis_y + 16.0
        );
        t += step;
    }
    // Notes: numbers in their lanes, then the list; then the keys of the abbreviated boxes.
    for (i, (t, n)) in run.notes.iter().enumerate() {
        let _ = writeln!(
            s,
            r##"<text class="marker" x="{:.1}" y="{}" font-size="10" fill="#d32f2f" text-anchor="middle">{}</text>"##,
            x(*t),
            top - 6.0 - 11.0 * lanes[i] as f64,
            i + 1
        );
        let _ = writeln!(
            s,
            r##"<text x="10" y="{}" font-size="11"><tspan fill="#d32f2f">{}</tspan> {t} ms: {}</text>"##,
            legend_y + 16.0 * i as f64,
            i + 1,
            esc(n)
        );
    }
    for (k, line) in keys.iter().enumerate() {
        let _ = writeln!(
            s,
            r##"<text class="legend" x="10" y="{}" font-size="11" fill="#6a1b9a">{}</text>"##,
            legend_y + 16.0 * (run.notes.len() + k) as f64,
            esc(line)
        );
    }
    s += "</svg>\n";
    s
}
