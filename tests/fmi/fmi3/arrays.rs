//! FMI 3's arrays and structural parameter, and the description without arrays.

use super::*;

/// The value reference of the FMI 3 array `name`.
fn array(name: &str) -> u32 {
    FMI3.arrays.iter().find(|a| a.name == name).unwrap().vr
}

/// rod.nSections is set in Configuration Mode only, inside its range, and sizes every rod.section
/// array: a get names scalars and arrays in one call with nValues their total size, the middle
/// of 21 sections has the mid-span results, the positions are evenly spaced over rod.length;
/// an array cannot be set, a wrong count is refused, and Configuration Mode is closed after
/// initialization.
#[test]
fn structural_parameters_size_the_arrays_in_configuration_mode() {
    let (inst, _) = Instance3::try_new(GUID, false, false);
    let inst = inst.unwrap();
    let last = |inst: &Instance3| inst.messages().last().cloned().unwrap_or_default();
    let get_sections = |inst: &Instance3| {
        let mut n = 0u64;
        // SAFETY: a live instance, one value.
        let status = unsafe { fmu3().fmi3GetUInt64(inst.c, &N_SECTIONS, 1, &mut n, 1) };
        (status, n)
    };
    // SAFETY: a live instance; every pointer is valid for the counts given.
    unsafe {
        assert_eq!(fmu3().fmi3SetUInt64(inst.c, &N_SECTIONS, 1, &21, 1), ERROR);
        assert!(last(&inst).contains("it is set in Configuration Mode only"));
        assert_eq!(fmu3().fmi3Reset(inst.c), OK);
        assert_eq!(fmu3().fmi3EnterConfigurationMode(inst.c), OK);
        // FMI 3.0 reads no variable in Configuration Mode.
        assert_eq!(get_sections(&inst).0, ERROR);
        assert!(last(&inst).contains("fmi3GetUInt64: Illegal call sequence."));
        assert_eq!(fmu3().fmi3Reset(inst.c), OK);
        assert_eq!(fmu3().fmi3EnterConfigurationMode(inst.c), OK);
        assert_eq!(fmu3().fmi3SetUInt64(inst.c, &N_SECTIONS, 1, &1, 1), ERROR);
        assert!(last(&inst).contains("rod.nSections = 1 is outside the allowed range [2, 1001]"));
        assert_eq!(fmu3().fmi3Reset(inst.c), OK);
        assert_eq!(fmu3().fmi3EnterConfigurationMode(inst.c), OK);
        assert_eq!(fmu3().fmi3SetUInt64(inst.c, &N_SECTIONS, 1, &21, 1), OK);
        assert_eq!(fmu3().fmi3Reset(inst.c), OK);
        assert_eq!(
            fmu3().fmi3EnterInitializationMode(inst.c, false, 0.0, 0.0, false, 0.0),
            OK
        );
        assert_eq!(
            get_sections(&inst),
            (OK, 11),
            "reset restores the start value"
        );
        assert_eq!(fmu3().fmi3Reset(inst.c), OK);
        assert_eq!(fmu3().fmi3EnterConfigurationMode(inst.c), OK);
        assert_eq!(fmu3().fmi3SetUInt64(inst.c, &N_SECTIONS, 1, &21, 1), OK);
        assert_eq!(fmu3().fmi3ExitConfigurationMode(inst.c), OK);
        assert_eq!(
            fmu3().fmi3EnterInitializationMode(inst.c, false, 0.0, 0.0, false, 0.0),
            OK
        );
        assert_eq!(fmu3().fmi3ExitInitializationMode(inst.c), OK);
    }
    assert_eq!(get_sections(&inst), (OK, 21));
    let mut t = 0.0;
    for _ in 0..20 {
        assert_eq!(inst.do_step(t, 1e-4).0, OK);
        t += 1e-4;
    }
    let moment = array("rod.section.bendingMoment");
    let position = array("rod.section.position");
    let refs = [
        TIME,
        vr("rod.bendingMomentMidspan"),
        moment,
        position,
        vr("rod.length"),
    ];
    let mut values = vec![f64::NAN; 1 + 1 + 21 + 21 + 1];
    // SAFETY: as above, nValues the total size.
    let status = unsafe {
        fmu3().fmi3GetFloat64(
            inst.c,
            refs.as_ptr(),
            refs.len(),
            values.as_mut_ptr(),
            values.len(),
        )
    };
    assert_eq!(status, OK, "{:?}", inst.messages());
    let (midspan, sections, positions) = (values[1], &values[2..23], &values[23..44]);
    assert!((values[0] - t).abs() < 1e-12);
    assert!(midspan.abs() > 1.0, "a loaded rod: {midspan}");
    assert!(
        (sections[10] - midspan).abs() < 1e-12 * midspan.abs(),
        "{sections:?} vs {midspan}"
    );
    let length = values[44];
    for (k, s) in positions.iter().enumerate() {
        assert!(
            (s - k as f64 * length / 20.0).abs() < 1e-15,
            "{positions:?}"
        );
    }
    // SAFETY: as above.
    unsafe {
        let status = fmu3().fmi3GetFloat64(inst.c, &moment, 1, values.as_mut_ptr(), 11);
        assert_eq!(status, ERROR);
        assert!(last(&inst).contains("nValues = 11 but the variables named have 21 elements"));
        assert_eq!(fmu3().fmi3Reset(inst.c), OK);
        assert_eq!(
            fmu3().fmi3SetFloat64(inst.c, &moment, 1, values.as_ptr(), 11),
            ERROR
        );
        assert!(last(&inst).contains("rod.section.bendingMoment is computed by the FMU"));
        assert_eq!(fmu3().fmi3Reset(inst.c), OK);
        assert_eq!(
            fmu3().fmi3EnterInitializationMode(inst.c, false, 0.0, 0.0, false, 0.0),
            OK
        );
        assert_eq!(fmu3().fmi3EnterConfigurationMode(inst.c), ERROR);
        assert!(last(&inst).contains("fmi3EnterConfigurationMode: Illegal call sequence."));
    }
}

/// The FMU without arrays and input derivatives (its own token): no Configuration Mode, an array's
/// and an input derivative's value reference are unknown, the scalars read as with arrays; a token
/// of neither description is refused, naming both.
#[test]
fn the_description_without_arrays_serves_scalars_only() {
    use flexible_slider_crank::fmi::FMI3_SCALAR_TOKEN;
    let (inst, _) = Instance3::try_new(FMI3_SCALAR_TOKEN, false, false);
    let inst = inst.unwrap();
    let last = |inst: &Instance3| inst.messages().last().cloned().unwrap_or_default();
    // SAFETY: a live instance.
    unsafe {
        assert_eq!(fmu3().fmi3EnterConfigurationMode(inst.c), ERROR);
        assert!(
            last(&inst).contains("no structural parameters"),
            "{}",
            last(&inst)
        );
        assert_eq!(fmu3().fmi3Reset(inst.c), OK);
        assert_eq!(
            fmu3().fmi3EnterInitializationMode(inst.c, false, 0.0, 0.0, false, 0.0),
            OK
        );
        assert_eq!(fmu3().fmi3ExitInitializationMode(inst.c), OK);
    }
    let moment = N_SECTIONS + 4;
    assert_eq!(inst.get_float64(&[moment]).0, ERROR);
    assert!(last(&inst).contains("1000005"), "{}", last(&inst));
    let with_arrays = Instance3::initialized(false);
    let outputs = real_outputs();
    assert_eq!(with_arrays.do_step(0.0, 1e-3).0, OK);
    // (the refused get put the first instance in the Error state: a fresh one steps)
    let (fresh, _) = Instance3::try_new(FMI3_SCALAR_TOKEN, false, false);
    let fresh = fresh.unwrap();
    // SAFETY: a live instance.
    unsafe {
        assert_eq!(
            fmu3().fmi3EnterInitializationMode(fresh.c, false, 0.0, 0.0, false, 0.0),
            OK
        );
        assert_eq!(fmu3().fmi3ExitInitializationMode(fresh.c), OK);
    }
    assert_eq!(fresh.do_step(0.0, 1e-3).0, OK);
    assert_eq!(
        fresh.get_float64(&outputs).1,
        with_arrays.get_float64(&outputs).1
    );
    let derivative = fmi_export::fmi3::description::input_derivative_vr(0, 1);
    assert_eq!(with_arrays.get_float64(&[derivative]).0, OK);
    assert_eq!(fresh.get_float64(&[derivative]).0, ERROR);
    let message = fresh.messages().last().cloned().unwrap_or_default();
    assert!(message.contains("1001000"), "{message}");
    let (refused, id) = Instance3::try_new("{not-this-fmu}", false, false);
    assert!(refused.is_none());
    let message = messages(id).join("\n");
    assert!(
        message.contains(GUID) && message.contains(FMI3_SCALAR_TOKEN),
        "{message}"
    );
}
