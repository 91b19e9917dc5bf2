//! Prints the registry's field table of every block type as JSON (name, tag, struct, size,
//! and per field: name, offset, C type, direction), the one source the PLC generator
//! (`tools/plcgen.py`) reads for the direction and type of each field and checks against
//! the header. `cargo run --release --quiet --example field_table`.

use safelogic::registry::{Dir, BLOCKS};

fn main() {
    let mut out = String::from("{\"blocks\": [\n");
    for (i, b) in BLOCKS.iter().enumerate() {
        let fields: Vec<String> = b
            .fields
            .iter()
            .map(|f| {
                let dir = match f.dir {
                    Dir::Input => "input",
                    Dir::Control => "control",
                    Dir::Param => "param",
                    Dir::Output => "output",
                    Dir::Info => "info",
                };
                format!(
                    "{{\"name\": \"{}\", \"offset\": {}, \"ctype\": \"{}\", \"dir\": \"{}\"}}",
                    f.name,
                    f.offset,
                    f.kind.c_type(),
                    dir
                )
            })
            .collect();
        out += &format!(
            "  {{\"name\": \"{}\", \"struct\": \"{}{}\", \"tag\": {}, \"size\": {}, \"fields\": [\n    {}\n  ]}}{}\n",
            b.info.name,
            b.struct_prefix(),
            b.info.name,
            b.info.tag,
            b.size,
            fields.join(",\n    "),
            if i + 1 < BLOCKS.len() { "," } else { "" }
        );
    }
    out += "]}";
    println!("{out}");
}
