//! Many instances: interleaved in one thread and spread over threads, each equal to its serial run
//! bit for bit; and the FMU equal to the library's `Simulation` with the same parameters.

use flexible_slider_crank::Simulation;
use flexible_slider_crank::params::{Parameters, RodFormulation};
use fmi_sys::fmi2::fmi2Status_fmi2OK;

use crate::harness::{Instance, vr};

const STEP: f64 = 1e-4;
const STEPS: usize = 20;

fn outputs() -> Vec<u32> {
    [
        "slider.position",
        "slider.acceleration",
        "joint.force",
        "rod.deformationEnergy",
        "crank.torque",
    ]
    .map(vr)
    .to_vec()
}

fn configured(name: &str, n_modes: i32) -> Instance {
    let inst = Instance::new(name);
    assert_eq!(
        inst.set_integer(vr("rod.nModes"), n_modes),
        fmi2Status_fmi2OK
    );
    inst.initialize();
    inst
}

fn serial(name: &str, n_modes: i32) -> Vec<Vec<f64>> {
    let inst = configured(name, n_modes);
    (0..STEPS)
        .map(|i| {
            assert_eq!(inst.do_step(i as f64 * STEP, STEP), fmi2Status_fmi2OK);
            inst.get_reals(&outputs())
        })
        .collect()
}

/// Two instances with different nModes, interleaved step by step, equal their serial
/// runs bit for bit.
#[test]
fn interleaved_instances_equal_serial_runs() {
    let (ra, rb) = (serial("serial-2", 2), serial("serial-6", 6));
    let (a, b) = (configured("inter-2", 2), configured("inter-6", 6));
    for i in 0..STEPS {
        assert_eq!(a.do_step(i as f64 * STEP, STEP), fmi2Status_fmi2OK);
        assert_eq!(b.do_step(i as f64 * STEP, STEP), fmi2Status_fmi2OK);
        assert_eq!(a.get_reals(&outputs()), ra[i]);
        assert_eq!(b.get_reals(&outputs()), rb[i]);
    }
}

/// 8 threads × 4 instances (different nModes) equal their serial runs bit for bit.
#[test]
fn threads_equal_serial_runs() {
    let modes = [0, 2, 4, 6];
    let reference: Vec<Vec<Vec<f64>>> = modes
        .iter()
        .map(|&m| serial(&format!("thread-ref-{m}"), m))
        .collect();
    let handles: Vec<_> = (0..8)
        .map(|t| {
            std::thread::spawn(move || {
                let instances: Vec<Instance> = modes
                    .iter()
                    .map(|&m| configured(&format!("thread-{t}-{m}"), m))
                    .collect();
                let mut results = vec![Vec::new(); modes.len()];
                for i in 0..STEPS {
                    for (k, inst) in instances.iter().enumerate() {
                        assert_eq!(inst.do_step(i as f64 * STEP, STEP), fmi2Status_fmi2OK);
                        results[k].push(inst.get_reals(&outputs()));
                    }
                }
                results
            })
        })
        .collect();
    for h in handles {
        assert_eq!(h.join().unwrap(), reference);
    }
}

/// The FMU equals the library's Simulation for the same parameters (bit for bit; the test
/// allows 1e-12).
#[test]
fn fmu_equals_library_simulation() {
    let inst = Instance::new("vs-library");
    assert_eq!(
        inst.set_integer(vr("rod.formulation"), 2),
        fmi2Status_fmi2OK
    );
    assert_eq!(inst.set_integer(vr("rod.nElements"), 4), fmi2Status_fmi2OK);
    inst.initialize();
    let mut sim = Simulation::new(Parameters {
        rod_formulation: RodFormulation::Ancf,
        n_elements: 4,
        ..Parameters::default()
    })
    .unwrap();
    for i in 0..STEPS {
        let t = i as f64 * STEP;
        assert_eq!(inst.do_step(t, STEP), fmi2Status_fmi2OK);
        sim.advance_to(t + STEP).unwrap();
        let o = sim.outputs().unwrap();
        let fmu = inst.get_reals(&outputs());
        let lib = [
            o.slider_position,
            o.slider_acceleration,
            o.joint_force,
            o.deformation_energy,
            o.crank_torque,
        ];
        for (a, b) in fmu.iter().zip(lib) {
            assert!((a - b).abs() <= 1e-12 * b.abs().max(1e-300), "{a} vs {b}");
        }
    }
}
