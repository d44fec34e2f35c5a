//! Coverage-guided fuzzing of FMU-state deserialization: the bytes a master hands to
//! fmi2DeSerializeFMUstate. Whatever they are, the FMU must answer with a status (never crash,
//! hang or abort); bytes it accepts must serialize back to themselves, restore with
//! fmi2SetFMUstate, and leave an instance that steps, answers every getter and frees cleanly.
//!
//! The fuzzer's input is a state without its closing checksum, which the target appends: every
//! mutation then reaches the parser behind the checksum instead of stopping at it. (A corrupted
//! checksum itself is covered by the unit and conformance tests.)

#![no_main]

use flexible_slider_crank_fuzz::{Instance, variable_count};
use fmi_export::instance::framing::state_checksum;
use fmi_sys::fmi2::fmi2Status_fmi2OK as OK;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some(mut fmu) = Instance::new("state", true, false) else {
        panic!("fmi2Instantiate refused a well-formed call");
    };
    assert_eq!(fmu.setup(None, 0.0, None), OK);
    assert_eq!(fmu.enter_initialization(), OK);
    assert_eq!(fmu.exit_initialization(), OK);
    let mut bytes = data.to_vec();
    bytes.extend_from_slice(&state_checksum(data).to_le_bytes());
    if fmu.deserialize(&bytes) != OK {
        return;
    }
    let restored = fmu.state_count() - 1;
    let again = fmu.serialize(restored);
    assert_eq!(
        again.as_deref(),
        Some(&bytes[..]),
        "accepted bytes do not serialize back to themselves"
    );
    if fmu.set_state(restored) != OK {
        return;
    }
    let vrs: Vec<u32> = (0..variable_count()).collect();
    fmu.get_all(&vrs);
    for vr in 0..variable_count() {
        fmu.get_output_derivative(vr, 1);
    }
    fmu.statuses();
    if let Some(t) = fmu.time() {
        fmu.do_step(t, 1e-5, false);
        fmu.get_all(&vrs);
    }
});
