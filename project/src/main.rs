//! The `safelogic` command-line tool: `check`, `sim`, `export-c`, `export-st`; without arguments it
//! simulates the embedded KL6904 example 5.1 and writes its timing diagram.

#![forbid(unsafe_code)]

use clap::{Parser, Subcommand};
use safelogic_project::error::{read_text, write_all, write_error};
use safelogic_project::export_st::{self, Dialect};
use safelogic_project::sim::{self, Scenario};
use safelogic_project::{load_project, svg, vcd, Error, Project};
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "safelogic",
    version,
    about = "Check, simulate and export safelogic projects (TOML). Without a command: simulates the embedded KL6904 example 5.1 and writes its timing diagram."
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Validates a project, prints its wiring and its CRC; with --dialect also what
    /// `export-st` needs (names, group sizes, process-image locations).
    Check {
        /// The project file.
        project: String,
        /// Check that this PLC dialect can express the project: iec, twincat or codesys.
        #[arg(long, value_parser = parse_dialect)]
        dialect: Option<Dialect>,
    },
    /// Runs a project against a scenario: prints the timeline, checks the expectations
    /// (exit status 1 when one fails), writes VCD and SVG.
    Sim {
        /// The project file.
        project: String,
        /// The scenario file.
        scenario: String,
        /// Write a VCD file (GTKWave).
        #[arg(long)]
        vcd: Option<String>,
        /// Write an SVG timing diagram.
        #[arg(long)]
        svg: Option<String>,
        /// Print every cycle (all signals and states) instead of the timeline.
        #[arg(long)]
        trace: bool,
    },
    /// Writes a C file that sets the project up through the C API (with a scenario: a
    /// main() that replays it and prints the same trace as `sim --trace`).
    ExportC {
        /// The project file.
        project: String,
        /// A scenario to replay.
        scenario: Option<String>,
        /// Output file (default: standard output).
        #[arg(short, long)]
        output: Option<String>,
    },
    /// Writes the project as a PLC program in Structured Text that runs its groups through
    /// the ST bindings (plc_bindings/): iec (matiec: OpenPLC v3, Beremiz; one self-contained
    /// file with located variables), twincat or codesys (a GVL and a PROGRAM).
    ExportSt {
        /// The project file.
        project: String,
        /// iec, twincat or codesys.
        #[arg(long, default_value = "iec", value_parser = parse_dialect)]
        dialect: Dialect,
        /// Output file (default: standard output).
        #[arg(short, long)]
        output: Option<String>,
        /// Also write the process image as JSON: every signal's IEC location and OpenPLC
        /// Modbus TCP address, the clock and the state words (with their value names).
        #[arg(long)]
        map: Option<String>,
    },
}

fn parse_dialect(s: &str) -> Result<Dialect, String> {
    Dialect::named(s)
        .ok_or_else(|| format!("`{s}` is not a dialect; expected iec, twincat or codesys"))
}

const DEFAULT_PROJECT: &str = include_str!("../../examples/projects/kl6904_5_1.toml");
const DEFAULT_SCENARIO: &str = include_str!("../../examples/projects/kl6904_5_1.scenario.toml");

fn read(path: &str) -> Result<String, Error> {
    read_text(path)
}

/// Runs a scenario; Ok(false) when an expectation failed.
fn simulate(
    p: &Project,
    sc: &Scenario,
    vcd_out: Option<&str>,
    svg_out: Option<&str>,
    trace: bool,
) -> Result<bool, Error> {
    let mut stdout = std::io::stdout().lock();
    let run = sim::run(p, sc, trace, &mut stdout).map_err(|msg| Error {
        file: p.name.clone(),
        line: 0,
        col: 0,
        msg,
    })?;
    // Both files or neither (a failed run leaves nothing behind).
    let vcd_text = vcd_out.map(|path| (path, vcd::vcd(&run, &p.name)));
    let svg_text = svg_out.map(|path| (path, svg::svg(&run, &format!("{} — {}", p.name, sc.name))));
    let files: Vec<(&str, &str)> = [&vcd_text, &svg_text]
        .into_iter()
        .flatten()
        .map(|(path, text)| (*path, text.as_str()))
        .collect();
    write_all(&files)?;
    if let Some(path) = vcd_out {
        eprintln!("VCD written to {path}");
    }
    if let Some(path) = svg_out {
        eprintln!("timing diagram (SVG) written to {path}");
    }
    Ok(run.failures == 0)
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Some(Command::Check { project, dialect }) => (|| {
            let p = load_project(&project)?;
            if let Some(d) = dialect {
                export_st::check(&p, d)?;
            }
            print!("{}", p.describe());
            if let Some(d) = dialect {
                println!("export-st --dialect {}: can be expressed", d.name());
            }
            Ok(true)
        })(),
        Some(Command::Sim {
            project,
            scenario,
            vcd,
            svg,
            trace,
        }) => (|| {
            let p = load_project(&project)?;
            let sc = Scenario::parse(&scenario, &read(&scenario)?, &p)?;
            simulate(&p, &sc, vcd.as_deref(), svg.as_deref(), trace)
        })(),
        Some(Command::ExportC {
            project,
            scenario,
            output,
        }) => (|| {
            let p = load_project(&project)?;
            let sc = match &scenario {
                Some(path) => Some(Scenario::parse(path, &read(path)?, &p)?),
                None => None,
            };
            let c = safelogic_project::export_c::export(&p, sc.as_ref());
            match output {
                Some(path) => write_all(&[(&path, &c)])?,
                None => print!("{c}"),
            }
            Ok(true)
        })(),
        Some(Command::ExportSt {
            project,
            dialect,
            output,
            map,
        }) => (|| {
            let p = load_project(&project)?;
            let st = export_st::export(&p, dialect)?;
            let map_text = map
                .as_ref()
                .map(|_| export_st::modbus_map(&p))
                .transpose()?;
            // both files or neither (atomic writes: nothing left from a failed run)
            let mut files: Vec<(&str, &str)> = Vec::new();
            if let Some(path) = &output {
                files.push((path, &st));
            }
            if let (Some(path), Some(text)) = (&map, &map_text) {
                files.push((path, text));
            }
            write_all(&files)?;
            if output.is_none() {
                print!("{st}");
            }
            Ok(true)
        })(),
        None => (|| {
            let p = Project::parse("<embedded kl6904_5_1.toml>", DEFAULT_PROJECT)?;
            let sc = Scenario::parse("<embedded kl6904_5_1.scenario.toml>", DEFAULT_SCENARIO, &p)?;
            print!("{}", p.describe());
            println!();
            let dir = std::env::temp_dir().join("safelogic");
            std::fs::create_dir_all(&dir)
                .map_err(|e| write_error(&dir.display().to_string(), &e))?;
            let svg_path = dir.join("kl6904_5_1.svg").display().to_string();
            let vcd_path = dir.join("kl6904_5_1.vcd").display().to_string();
            let ok = simulate(&p, &sc, Some(&vcd_path), Some(&svg_path), false)?;
            println!("\ntiming diagram: {svg_path} (waveform for GTKWave: {vcd_path})");
            println!("more: safelogic check|sim|export-c|export-st, projects in examples/projects/ (safelogic --help)");
            Ok(ok)
        })(),
    };
    match result {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("{e}");
            ExitCode::from(2)
        }
    }
}
