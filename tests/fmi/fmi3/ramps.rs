//! Inputs with derivatives, through FMI 2 (fmi2SetRealInputDerivatives) and FMI 3 (the inputs
//! `der(u)` and `der(u,2)`): every input ramped as a master that provides derivatives ramps it,
//! the outputs at every communication point against closed forms (rigid rod, ideal joints) and
//! against runs that set the input at every fine step without derivatives.

use super::*;
use flexible_slider_crank::fmi::FMI3_TOKEN;
use fmi_export::fmi3::description::input_derivative_vr;
use fmi_sys::fmi2::fmi2Status_fmi2OK;

/// A master's view of one instance of either version: set values, input derivatives and switches
/// by name, step, read Real values.
trait Master {
    fn set(&self, name: &str, value: f64);
    fn set_derivatives(&self, name: &str, derivatives: [f64; 2]);
    fn step(&self, t: f64, h: f64);
    fn get(&self, names: &[&str]) -> Vec<f64>;
}

impl Master for Instance {
    fn set(&self, name: &str, value: f64) {
        assert_eq!(self.set_real(vr(name), value), fmi2Status_fmi2OK);
    }
    fn set_derivatives(&self, name: &str, derivatives: [f64; 2]) {
        let vrs = [vr(name); 2];
        // SAFETY: a live instance and two values each.
        let status = unsafe {
            crate::harness::fmu().fmi2SetRealInputDerivatives(
                self.c,
                vrs.as_ptr(),
                2,
                [1, 2].as_ptr(),
                derivatives.as_ptr(),
            )
        };
        assert_eq!(status, fmi2Status_fmi2OK, "{:?}", self.messages());
    }
    fn step(&self, t: f64, h: f64) {
        assert_eq!(
            self.do_step(t, h),
            fmi2Status_fmi2OK,
            "{:?}",
            self.messages()
        );
    }
    fn get(&self, names: &[&str]) -> Vec<f64> {
        let vrs: Vec<u32> = names.iter().map(|n| vr(n)).collect();
        self.get_reals(&vrs)
    }
}

/// The index of the input `name` among the inputs.
fn input_index(name: &str) -> usize {
    VARIABLES
        .iter()
        .filter(|v| v.causality == Causality::Input)
        .position(|v| v.name == name)
        .unwrap()
}

impl Master for Instance3 {
    fn set(&self, name: &str, value: f64) {
        self.set_float64(&[vr(name)], &[value]);
    }
    fn set_derivatives(&self, name: &str, derivatives: [f64; 2]) {
        let k = input_index(name);
        let vrs = [input_derivative_vr(k, 1), input_derivative_vr(k, 2)];
        self.set_float64(&vrs, &derivatives);
    }
    fn step(&self, t: f64, h: f64) {
        assert_eq!(self.do_step(t, h).0, OK, "{:?}", self.messages());
    }
    fn get(&self, names: &[&str]) -> Vec<f64> {
        let vrs: Vec<u32> = names.iter().map(|n| vr(n)).collect();
        let (status, values) = self.get_float64(&vrs);
        assert_eq!(status, OK);
        values
    }
}

impl Instance3 {
    fn set_float64(&self, vrs: &[u32], values: &[f64]) {
        // SAFETY: a live instance and as many values as value references.
        let status = unsafe {
            fmu3().fmi3SetFloat64(
                self.c,
                vrs.as_ptr(),
                vrs.len(),
                values.as_ptr(),
                values.len(),
            )
        };
        assert_eq!(status, OK, "{:?}", self.messages());
    }
}

/// The rigid rod with ideal joints and `switches` (drive mode), integrated tightly (the runs
/// compared differ by their inputs, not by their integration errors), ready to step, through FMI
/// `version`; `inputs` set in initialization mode.
fn rigid(version: u32, switches: &[(&str, i32)], inputs: &[(&str, f64)]) -> Box<dyn Master> {
    let inputs = [("solver.relativeTolerance", 1e-9)]
        .iter()
        .chain(inputs)
        .copied()
        .collect::<Vec<_>>();
    let switches = [("rod.formulation", 1), ("joint.model", 1)]
        .iter()
        .chain(switches)
        .copied()
        .collect::<Vec<_>>();
    if version == 2 {
        let inst = Instance::new(&format!("ramp-{}", NAMES.fetch_add(1, Ordering::Relaxed)));
        assert_eq!(inst.setup(0.0, None), fmi2Status_fmi2OK);
        assert_eq!(inst.enter(), fmi2Status_fmi2OK);
        for (name, value) in switches {
            assert_eq!(inst.set_integer(vr(name), value), fmi2Status_fmi2OK);
        }
        inputs
            .iter()
            .for_each(|&(name, value)| inst.set(name, value));
        assert_eq!(inst.exit(), fmi2Status_fmi2OK, "{:?}", inst.messages());
        return Box::new(inst);
    }
    let (inst, id) = Instance3::try_new(FMI3_TOKEN, false, false);
    let inst = inst.unwrap_or_else(|| panic!("{:?}", messages(id)));
    // SAFETY: a live instance, one value per value reference.
    unsafe {
        assert_eq!(
            fmu3().fmi3EnterInitializationMode(inst.c, false, 0.0, 0.0, false, 0.0),
            OK
        );
        for (name, value) in switches {
            let value = i64::from(value);
            assert_eq!(fmu3().fmi3SetInt64(inst.c, &vr(name), 1, &value, 1), OK);
        }
    }
    inputs
        .iter()
        .for_each(|&(name, value)| inst.set(name, value));
    // SAFETY: a live instance.
    assert_eq!(unsafe { fmu3().fmi3ExitInitializationMode(inst.c) }, OK);
    Box::new(inst)
}

static NAMES: AtomicUsize = AtomicUsize::new(0);

/// An input over time: u(t) = u₀ + u̇₀ t + ü t²/2.
#[derive(Clone, Copy)]
struct Ramp {
    name: &'static str,
    start: f64,
    rate: f64,
    curvature: f64,
}

impl Ramp {
    fn at(&self, t: f64) -> f64 {
        self.start + t * (self.rate + 0.5 * t * self.curvature)
    }
    fn rate(&self, t: f64) -> f64 {
        self.rate + t * self.curvature
    }
}

/// Runs `master` to `stop` in steps of `h`, the input set at every point as `ramp` gives it, with
/// its derivatives there if `derivatives`; the values of `names` at every point after the start.
fn run(
    master: &dyn Master,
    ramp: Ramp,
    derivatives: bool,
    (h, stop): (f64, f64),
    names: &[&str],
) -> Vec<(f64, Vec<f64>)> {
    let n = (stop / h).round() as u32;
    let mut rows = Vec::new();
    for k in 0..n {
        let t = f64::from(k) * h;
        master.set(ramp.name, ramp.at(t));
        if derivatives {
            master.set_derivatives(ramp.name, [ramp.rate(t), ramp.curvature]);
        }
        master.step(t, h);
        rows.push((f64::from(k + 1) * h, master.get(names)));
    }
    rows
}

/// The slider's position x(θ) = r cos θ + √(l² − (r sin θ − e)²) of the rigid mechanism and its
/// acceleration ẍ = x′(θ) θ̈ + x″(θ) θ̇².
fn slider_acceleration(theta: f64, speed: f64, acceleration: f64) -> f64 {
    let start = |name: &str| crate::harness::real_start(VARIABLES, name);
    let (r, l, e) = (
        start("crank.length"),
        start("rod.length"),
        start("slider.offset"),
    );
    let (sin, cos) = flexible_slider_crank::math::sin_cos(theta);
    let (s, s1, s2) = (r * sin - e, r * cos, -r * sin);
    let q = (l * l - s * s).sqrt();
    let q1 = -s * s1 / q;
    let q2 = -(s1 * s1 + s * s2) / q - (s * s1).powi(2) / q.powi(3);
    (-r * sin + q1) * acceleration + (-r * cos + q2) * speed * speed
}

/// A prescribed speed ramped from 1500 to 3000 rpm in 50 ms (and the same run with a second
/// derivative), at communication steps of 1e-4 and 5e-4 s, through FMI 2 and FMI 3: at every
/// point the crank follows the speed and its rate, and the slider's acceleration is its closed
/// form with the crank's angular acceleration, within 1e-6 of its peak. Both versions give the
/// same values, bit for bit.
#[test]
fn a_ramped_speed_reaches_the_accelerations_at_every_point() {
    let rpm = std::f64::consts::PI / 30.0;
    let names = ["crank.angle", "crank.speed", "slider.acceleration"];
    for curvature in [0.0, -4e5] {
        let ramp = Ramp {
            name: "drive.speed",
            start: 1500.0 * rpm,
            rate: 1500.0 * rpm / 0.05 - 0.025 * curvature,
            curvature,
        };
        for h in [1e-4, 5e-4] {
            let runs = [2, 3].map(|version| {
                let master = rigid(version, &[], &[("drive.speed", ramp.start)]);
                run(&*master, ramp, true, (h, 0.05), &names)
            });
            assert_eq!(runs[0], runs[1], "FMI 2 and FMI 3 differ (h = {h} s)");
            let mut worst = 0.0_f64;
            let mut peak = 0.0_f64;
            for (t, values) in &runs[0] {
                let [theta, speed, acceleration] = values[..] else {
                    unreachable!()
                };
                let rate = ramp.rate(*t);
                assert!(
                    (speed - ramp.at(*t)).abs() < 1e-6 * speed,
                    "t = {t}: {speed}"
                );
                let exact = slider_acceleration(theta, speed, rate);
                worst = worst.max((acceleration - exact).abs());
                peak = peak.max(exact.abs());
            }
            assert!(
                worst < 1e-6 * peak,
                "h = {h} s, ω̈ = {curvature}: slider.acceleration off its closed form by {worst} \
                 m/s2 of {peak}"
            );
        }
    }
}

/// A ramp with the switches it runs with (the drive mode), the output that shows its value at
/// each point and how closely, relative.
type Case = (&'static [(&'static str, i32)], Ramp, &'static str, f64);

/// Each input ramped with first and second derivatives (the speed with the speed drive, the
/// torque with the torque drive, the slider force) reaches every output that depends on it: at
/// the communication points of 1e-4 s, the outputs of the run with derivatives are the limit of
/// runs that set the input at every fine step without them (their difference halves with the
/// fine step, first order), and the inputs' own outputs are their closed forms (the crank's speed,
/// the applied torque and force at each point). Through FMI 2 and FMI 3 alike, bit for bit.
#[test]
fn every_input_ramped_is_the_limit_of_fine_steps() {
    let outputs = [
        "crank.angle",
        "crank.speed",
        "crank.torque",
        "slider.position",
        "slider.velocity",
        "slider.acceleration",
        "slider.appliedForce",
        "joint.force",
        "energy.driveWork",
        "energy.sliderWork",
    ];
    // Each ramp with its drive mode, the output that shows it and how closely, relative (the
    // crank's speed follows the prescribed one through the stabilised drive constraint, to 1e-6;
    // the applied torque and force are the input at the point on the clock grid, which the
    // master's point is within a clock tick of).
    let cases: [Case; 3] = [
        (
            &[],
            Ramp {
                name: "drive.speed",
                start: 157.0,
                rate: 4000.0,
                curvature: -2e5,
            },
            "crank.speed",
            1e-6,
        ),
        (
            &[("drive.mode", 2)],
            Ramp {
                name: "drive.torque",
                start: 1.0,
                rate: 400.0,
                curvature: -2e4,
            },
            "crank.torque",
            1e-12,
        ),
        (
            &[],
            Ramp {
                name: "slider.force",
                start: -100.0,
                rate: 1e5,
                curvature: -5e6,
            },
            "slider.appliedForce",
            1e-12,
        ),
    ];
    let (h, stop) = (1e-4, 0.01);
    for (switches, ramp, own, tolerance) in cases {
        let inputs = [(ramp.name, ramp.start)];
        let with = [2, 3].map(|version| {
            let master = rigid(version, switches, &inputs);
            run(&*master, ramp, true, (h, stop), &outputs)
        });
        assert_eq!(with[0], with[1], "{}: FMI 2 and FMI 3 differ", ramp.name);
        let own = outputs.iter().position(|n| *n == own).unwrap();
        for (t, values) in &with[0] {
            let exact = ramp.at(*t);
            let on_grid = 2.0 * CLOCK_RESOLUTION * ramp.rate(*t).abs();
            let close = (values[own] - exact).abs() <= tolerance * exact.abs() + on_grid;
            assert!(
                close,
                "{} at t = {t}: {} for {exact}",
                ramp.name, values[own]
            );
        }
        let fine = [h / 25.0, h / 50.0].map(|fine| {
            let master = rigid(2, switches, &inputs);
            let rows = run(&*master, ramp, false, (fine, stop), &outputs);
            let every = (h / fine).round() as usize;
            rows.into_iter()
                .skip(every - 1)
                .step_by(every)
                .collect::<Vec<_>>()
        });
        for (i, name) in outputs.iter().enumerate() {
            // A fine run holds the prescribed speed over each fine step: at a point it reads no
            // rate, so the accelerations and the forces of the speed drive are checked against
            // their closed form instead (the test above).
            let reads_rate = ["crank.torque", "slider.acceleration", "joint.force"];
            if ramp.name == "drive.speed" && reads_rate.contains(name) {
                continue;
            }
            // The largest difference from the run with derivatives, over the points, of each
            // fine run, relative to the output's range.
            let range = with[0]
                .iter()
                .map(|(_, v)| v[i].abs())
                .fold(0.0, f64::max)
                .max(1e-9);
            let error = fine.each_ref().map(|rows| {
                rows.iter()
                    .zip(&with[0])
                    .map(|((_, f), (_, w))| (f[i] - w[i]).abs() / range)
                    .fold(0.0, f64::max)
            });
            let ratio = error[0] / error[1];
            assert!(
                error[1] < 1e-9 || (1.6..2.5).contains(&ratio),
                "{}: {name} does not converge to the run with derivatives at first order: \
                 errors {error:?} (ratio {ratio})",
                ramp.name
            );
            assert!(error[1] < 2e-2, "{}: {name} {error:?}", ramp.name);
        }
    }
}
