//! The PLCopen Safety blocks (`SF_<Name>`), run in the PLCopen envelope (`crate::base::sf`).
//! SF_EmergencyStop, SF_ESPE and SF_PSE share the restart-interlock machine of `restart`,
//! SF_Equivalent and SF_Antivalent the two-channel machine of `pair`, the two-hand types II
//! and III the machine of `twohand`; SF_Guard, SF_SafetyRequest, SF_OutControl,
//! SF_ResetButton, SF_EDM, SF_TestableSafetySensor, SF_EnableSwitch and SF_ModeSelector have
//! machines of their own.

pub mod antivalent;
pub mod edm;
pub mod emergencystop;
pub mod enableswitch;
pub mod equivalent;
pub mod espe;
pub mod guard;
pub mod modeselector;
pub mod outcontrol;
pub mod pair;
pub mod pse;
pub mod resetbutton;
pub mod restart;
pub mod safetyrequest;
pub mod testablesafetysensor;
pub mod twohand;
pub mod twohandcontroltypeii;
pub mod twohandcontroltypeiii;
