//! C export.
use crate::project::Project;
use crate::sim::Scenario;
/// x
pub fn export(_p: &Project, _s: Option<&Scenario>) -> String {
    String::new()
}
