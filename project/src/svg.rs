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

/// The SVG text of a run.
pub fn svg(run: &Run, title: &str) -> String {
    let end = run.until.max(1) + run.until.max(1) / 50 + 1;
    let x = |t: u32| LEFT + f64::from(t) * PLOT / f64::from(end);
    let rows = run.columns.len() as f64;
    let axis_y = TOP + rows * ROW + 8.0;
    let height = axis_y + 34.0 + 16.0 * run.notes.len() as f64;
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
    for (r, c) in run.columns.iter().enumerate() {
        let y0 = TOP + r as f64 * ROW;
        let (hi, lo) = (y0 + 5.0, y0 + ROW - 7.0);
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
        // Segments: (start, end, value).
        let segs: Vec<(u32, u32, &Val)> = c
            .changes
            .iter()
            .enumerate()
            .map(|(i, (t, v))| (*t, c.changes.get(i + 1).map_or(end, |n| n.0), v))
            .collect();
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
                        let _ = writeln!(
                            s,
                            r##"<rect x="{:.1}" y="{hi}" width="{:.1}" height="{}" fill="#bbdefb"/>"##,
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
                for (a, b, v) in &segs {
                    let (xa, xb) = (x(*a), x(*b));
                    let color = match v {
                        Val::S(name) => state_color(name),
                        Val::N(_) => "#ede7f6",
                    };
                    let _ = writeln!(
                        s,
                        r##"<rect x="{xa:.1}" y="{hi}" width="{:.1}" height="{}" fill="{color}" stroke="#555" stroke-width="0.8"/>"##,
                        xb - xa,
                        lo - hi
                    );
                    let text = v.to_string();
                    if (xb - xa) > 7.0 * text.len() as f64 + 4.0 {
                        let _ = writeln!(
                            s,
                            r#"<text x="{:.1}" y="{}" font-size="10">{}</text>"#,
                            xa + 3.0,
                            lo - 5.0,
                            esc(&text)
                        );
                    }
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
    let step = tick_step(end);
    let mut t = 0;
    while t <= end {
        let xt = x(t);
        let _ = writeln!(
            s,
            r##"<line x1="{xt:.1}" y1="{TOP}" x2="{xt:.1}" y2="{}" stroke="#ccc" stroke-dasharray="2,3"/>"##,
            axis_y + 4.0
        );
        let _ = writeln!(
            s,
            r#"<text x="{xt:.1}" y="{}" font-size="10" text-anchor="middle">{t} ms</text>"#,
            axis_y + 16.0
        );
        t += step;
    }
    // Notes.
    for (i, (t, n)) in run.notes.iter().enumerate() {
        let xt = x(*t);
        let _ = writeln!(
            s,
            r##"<line x1="{xt:.1}" y1="{}" x2="{xt:.1}" y2="{axis_y}" stroke="#d32f2f" stroke-width="0.8"/>"##,
            TOP - 4.0
        );
        let _ = writeln!(
            s,
            r##"<text x="{xt:.1}" y="{}" font-size="10" fill="#d32f2f" text-anchor="middle">{}</text>"##,
            TOP - 6.0,
            i + 1
        );
        let _ = writeln!(
            s,
            r##"<text x="10" y="{}" font-size="11"><tspan fill="#d32f2f">{}</tspan> {t} ms: {}</text>"##,
            axis_y + 34.0 + 16.0 * i as f64,
            i + 1,
            esc(n)
        );
    }
    s += "</svg>\n";
    s
}
