//! safelogic projects: a TOML file that describes TwinSAFE groups (members by name and type,
//! parameters by field name, links and process-image signals by name), its checks with
//! file:line:column errors, its CRC, the loader that builds the groups through the
//! registry, and the simulation of scenarios with a timeline, VCD and SVG output.

#![forbid(unsafe_code)]

pub mod error;
pub mod export_st;
pub mod plc;
pub mod project;
pub mod runtime;
pub mod sim;
pub mod svg;
pub mod vcd;

pub use error::Error;
pub use project::Project;
pub use runtime::Runtime;

/// Reads and checks a project file.
pub fn load_project(path: &str) -> Result<Project, Error> {
    let text = error::read_text(path)?;
    Project::parse(path, &text)
}
pub mod export_c;
