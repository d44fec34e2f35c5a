//! The hot path allocates nothing: after initialisation, `advance_to` and `outputs` of every rod ×
//! joint model run without a single heap allocation, and so do fmi2DoStep and fmi2GetReal through
//! the FMI layer (counting global allocator, own test binary).

// Test code: a failed unwrap is a failed test, with its message.
#![allow(clippy::unwrap_used, clippy::expect_used)]
// A global allocator is an unsafe trait implementation; it only forwards to `System`.
#![allow(unsafe_code)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

use flexible_slider_crank::params::JointParameters;
use flexible_slider_crank::params::{FilmModel, JointModel, RodFormulation};
use flexible_slider_crank::{Parameters, Simulation};

/// Counts the allocations of each thread while its [`COUNT`] is `Some` (tests run in parallel).
struct Counting;

thread_local! {
    static COUNT: Cell<Option<usize>> = const { Cell::new(None) };
}

fn record() {
    COUNT.with(|c| c.set(c.get().map(|n| n + 1)));
}

/// Runs `f` and returns how many allocations this thread made meanwhile.
fn allocations_in(f: impl FnOnce()) -> usize {
    COUNT.with(|c| c.set(Some(0)));
    f();
    COUNT.with(|c| c.replace(None)).unwrap_or(0)
}

// SAFETY: forwards every call to the system allocator unchanged; only counts.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        record();
        // SAFETY: same contract as the caller's.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: same contract as the caller's.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        record();
        // SAFETY: same contract as the caller's.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// The counter sees allocations made while counting (so a zero below means something).
#[test]
fn counter_counts() {
    let n = allocations_in(|| drop(std::hint::black_box(vec![1.0f64; 16])));
    assert!(n >= 1);
}

#[test]
fn stepping_does_not_allocate() {
    for rod in [
        RodFormulation::Rigid,
        RodFormulation::Ancf,
        RodFormulation::CraigBampton,
    ] {
        for (joint, film) in [
            (JointModel::Ideal, FilmModel::Finite),
            (JointModel::Dry, FilmModel::Finite),
            (JointModel::Lubricated, FilmModel::Short),
            (JointModel::Lubricated, FilmModel::Finite),
        ] {
            let p = Parameters {
                joint: JointParameters {
                    model: joint,
                    film_model: film,
                    ..Parameters::default().joint
                },
                rod_formulation: rod,
                ..Parameters::default()
            };
            let mut sim = Simulation::new(p).unwrap();
            sim.advance_to(1e-4).unwrap();
            sim.outputs().unwrap();
            let mut inputs = *sim.inputs();
            let n = allocations_in(|| {
                for i in 1..=40 {
                    inputs.value.drive_speed = 520.0 + f64::from(i);
                    sim.advance_with(&inputs, 1e-4 + 5e-5 * f64::from(i))
                        .unwrap();
                    sim.outputs_seeing(&inputs).unwrap();
                }
            });
            assert_eq!(
                n, 0,
                "{rod:?} rod, {joint:?} joint ({film:?} film): {n} allocations in 40 steps"
            );
        }
    }
}

/// A machine of the user's own with every option on the hot path: all three joints worn (a
/// crank pin lubricated by the finite film, a dry main bearing with 0.1 mm clearance, a rod–slider
/// joint in line contact), a counterweight,
/// an offset cylinder, heavy rod eyes, a damped rod and a crank-angle load table: stepping still
/// allocates nothing.
#[test]
fn stepping_a_machine_with_every_option_does_not_allocate() {
    use flexible_slider_crank::params::ContactGeometry;
    let table = std::env::temp_dir().join(format!("alloc-free-{}.csv", std::process::id()));
    std::fs::write(&table, "0,0\n30,-2000\n90,-500\n180,0\n").unwrap();
    let base = Parameters::default();
    let worn = |model| JointParameters {
        model,
        ..base.joint
    };
    let mut p = Parameters {
        joint: JointParameters {
            contact_geometry: ContactGeometry::Cylinder,
            ..base.joint
        },
        crank_pin: worn(JointModel::Lubricated),
        main_bearing: JointParameters {
            clearance: 1e-4,
            ..worn(JointModel::Dry)
        },
        crank_centre_of_mass_ratio: -0.2,
        slider_offset: 0.005,
        slider_force_table: table.display().to_string(),
        ..base.clone()
    };
    p.rod.damping_ratio = 0.01;
    p.rod.crank_end_mass = 0.05;
    p.rod.slider_end_mass = 0.02;
    let mut sim = Simulation::new(p).unwrap();
    std::fs::remove_file(&table).unwrap();
    sim.advance_to(1e-4).unwrap();
    sim.outputs().unwrap();
    let mut inputs = *sim.inputs();
    let n = allocations_in(|| {
        for i in 1..=40 {
            inputs.value.slider_force = -10.0 * f64::from(i);
            sim.advance_with(&inputs, 1e-4 + 5e-5 * f64::from(i))
                .unwrap();
            sim.outputs_seeing(&inputs).unwrap();
        }
    });
    assert_eq!(n, 0, "{n} allocations in 40 steps");
}

/// Through the FMI layer, in process: after a first step and read, fmi2SetReal of an input,
/// fmi2DoStep and fmi2GetReal of every Real output (the variables of each call resolved into the
/// buffer the instance keeps) allocate nothing, for the default model.
#[test]
fn fmi_stepping_and_reading_do_not_allocate() {
    use flexible_slider_crank::fmi::GUID;
    use flexible_slider_crank::fmi::instance::SliderCrankFmu as M;
    use flexible_slider_crank::variables::{Causality, Kind, VARIABLES, Vr};
    use fmi_export::fmi2::exports::sys::{fmi2CallbackFunctions, fmi2Type_fmi2CoSimulation};
    use fmi_export::fmi2::exports::{
        fmi2DoStep, fmi2EnterInitializationMode, fmi2ExitInitializationMode, fmi2FreeInstance,
        fmi2GetReal, fmi2Instantiate, fmi2SetReal, fmi2SetupExperiment,
    };
    use std::ffi::CString;

    let callbacks = fmi2CallbackFunctions {
        logger: Some(fmi_sys::fmi2::logger::callback_logger_handler),
        allocateMemory: None,
        freeMemory: None,
        stepFinished: None,
        componentEnvironment: std::ptr::null_mut(),
    };
    let (name, guid) = (CString::new("alloc").unwrap(), CString::new(GUID).unwrap());
    let outputs: Vec<u32> = VARIABLES
        .iter()
        .filter(|v| v.causality == Causality::Output && matches!(v.kind, Kind::Real { .. }))
        .map(|v| v.vr as u32)
        .collect();
    let mut values = vec![0.0; outputs.len()];
    let speed = Vr::DriveSpeed as u32;
    // SAFETY: valid strings, callbacks and buffers of the stated lengths for every call.
    unsafe {
        let c = fmi2Instantiate::<M>(
            name.as_ptr(),
            fmi2Type_fmi2CoSimulation,
            guid.as_ptr(),
            std::ptr::null(),
            &callbacks,
            0,
            0,
        );
        assert!(!c.is_null());
        assert_eq!(fmi2SetupExperiment::<M>(c, 0, 0.0, 0.0, 0, 0.0), 0);
        assert_eq!(fmi2EnterInitializationMode::<M>(c), 0);
        assert_eq!(fmi2ExitInitializationMode::<M>(c), 0);
        assert_eq!(fmi2DoStep::<M>(c, 0.0, 1e-4, 1), 0);
        let read = |values: &mut [f64]| {
            fmi2GetReal::<M>(c, outputs.as_ptr(), outputs.len(), values.as_mut_ptr())
        };
        assert_eq!(read(&mut values), 0);
        let n = allocations_in(|| {
            for i in 1..=40 {
                let t = 1e-4 * f64::from(i);
                let u = 520.0 + f64::from(i);
                assert_eq!(fmi2SetReal::<M>(c, &speed, 1, &u), 0);
                assert_eq!(fmi2DoStep::<M>(c, t, 1e-4, 1), 0);
                assert_eq!(read(&mut values), 0);
            }
        });
        fmi2FreeInstance::<M>(c);
        assert_eq!(n, 0, "{n} allocations in 40 steps through the FMI layer");
    }
}
