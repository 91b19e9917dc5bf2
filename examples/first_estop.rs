use safelogic::{EstopState, FunctionBlock, Status, FB_ESTOP};

fn main() -> Result<(), Status> {
    // One two-channel pair, discrepancy time 100 ms; the falling edge of Restart enables.
    let mut estop = FB_ESTOP::default();
    (estop.wInputActive, estop.tDiscTime12) = (0b11, 100);
    estop.try_init()?; // Err(Status::Config): the parameters are outside the manual's limits
    estop.set("bRun", 1)?; // a field by its name (the field table), or: estop.bRun = 1
    for (t, s1_pressed, restart) in [(0, 0, 0), (10, 0, 1), (20, 0, 0), (30, 1, 0)] {
        estop.bEStopIn1 = 1 - s1_pressed; // TRUE: no demand
        estop.bEStopIn2 = 1 - s1_pressed;
        estop.bRestart = restart;
        estop.try_cycle(t)?;
        let (state, out) = (estop.state_name(), estop.bEStopOut);
        println!("{t:>3} ms  S1 pressed {s1_pressed}  {state:<8} EStopOut {out}");
    }
    assert_eq!(estop.current_state()?, EstopState::Safe); // S1 pressed: SAFE, output FALSE
    Ok(())
}
