//! The load spectrum of a run — every impact's onset and peak force over the first 60° of crank
//! rotation — and its agreement with a converged run (explicit Dormand–Prince at rtol 1e-8).
//! Shared by the impact-accuracy test and `examples/impacts.rs`.
//!
//! An impact is a contact event (onset to separation); it counts if its converged peak exceeds
//! 5 % of the first impact's and it ends inside the window. Events are read from the peak-hold
//! outputs at 1 µs communication intervals (dense output: the step sequence does not change).

use flexible_slider_crank::integrator::Method;
use flexible_slider_crank::params::{BENCHMARK_SPEED, JointRole, RodFormulation};
use flexible_slider_crank::{ModelError, Parameters, Simulation};

/// Window: the first 60° of crank rotation.
pub const WINDOW_DEGREES: f64 = 60.0;
/// Communication interval \[s\].
const SAMPLE: f64 = 1e-6;
/// An impact counts if its converged peak exceeds this fraction of the first impact's.
const SIGNIFICANT: f64 = 0.05;

/// One contact event: onset time \[s\] and peak force \[N\].
#[derive(Clone, Copy, Debug)]
pub struct Impact {
    /// Start of the communication interval in which the contact began \[s\].
    pub onset: f64,
    /// Largest `joint.forcePeak` of the event \[N\].
    pub peak: f64,
}

/// The benchmarks of the load-spectrum check: A (rigid rod) and B with 4 and 8 modes and with the
/// full rod, each at the library's default settings.
pub fn benchmarks() -> [(&'static str, Parameters); 4] {
    let reduced = |n_modes| Parameters {
        rod_formulation: RodFormulation::CraigBampton,
        n_modes,
        ..Parameters::benchmark_b()
    };
    [
        ("rigid (A)", Parameters::benchmark_a()),
        ("4 modes (B)", reduced(4)),
        ("8 modes (B)", reduced(8)),
        ("full (B)", Parameters::benchmark_b()),
    ]
}

/// The converged reference of a run: the same model, explicit, rtol 1e-8.
pub fn converged(p: &Parameters) -> Parameters {
    Parameters {
        method: Method::DormandPrince,
        relative_tolerance: 1e-8,
        ..p.clone()
    }
}

/// The impacts of a run at its rod–slider joint that end inside the window, and the run's internal
/// steps.
pub fn impacts(p: Parameters) -> Result<(Vec<Impact>, u64), ModelError> {
    impacts_at(p, JointRole::RodSlider)
}

/// The impacts of a run at the clearance joint `role` (the rod–slider joint or the crank pin) that
/// end inside the window, and the run's internal steps.
pub fn impacts_at(p: Parameters, role: JointRole) -> Result<(Vec<Impact>, u64), ModelError> {
    let window = WINDOW_DEGREES.to_radians() / BENCHMARK_SPEED;
    let n = (window / SAMPLE).round() as usize;
    let mut sim = Simulation::new(p)?;
    let mut events = Vec::new();
    let mut current: Option<Impact> = None;
    for k in 1..=n {
        let t = k as f64 * SAMPLE;
        sim.advance_to(t)?;
        let o = sim.outputs()?;
        let (onsets, in_contact, peak) = match role {
            JointRole::CrankPin => (
                o.crank_pin_contact_onsets,
                o.crank_pin_in_contact,
                o.crank_pin_force_peak,
            ),
            JointRole::MainBearing => (
                o.main_bearing_contact_onsets,
                o.main_bearing_in_contact,
                o.main_bearing_force_peak,
            ),
            JointRole::RodSlider => (o.contact_onsets, o.in_contact, o.joint_force_peak),
        };
        if onsets > 0 {
            events.extend(current.take());
            current = Some(Impact {
                onset: t - SAMPLE,
                peak: 0.0,
            });
        }
        if let Some(c) = &mut current {
            c.peak = c.peak.max(peak);
            if !in_contact && onsets == 0 {
                events.push(*c);
                current = None;
            }
        }
    }
    Ok((events, sim.stats().steps))
}

/// One significant impact of the reference and the run's event nearest to it in onset time.
#[derive(Clone, Copy, Debug)]
pub struct Pair {
    /// The converged impact.
    pub reference: Impact,
    /// The run's impact.
    pub run: Impact,
}

impl Pair {
    /// |peak − converged peak| / converged peak.
    pub fn peak_error(&self) -> f64 {
        (self.run.peak - self.reference.peak).abs() / self.reference.peak
    }

    /// |onset − converged onset| in crank degrees.
    pub fn onset_error_degrees(&self) -> f64 {
        ((self.run.onset - self.reference.onset) * BENCHMARK_SPEED)
            .to_degrees()
            .abs()
    }
}

/// The significant impacts of `reference`, in order, each with the event of `run` nearest to it
/// in onset time (a run that misses an impact pairs it with a neighbour and scores its error).
pub fn pair(reference: &[Impact], run: &[Impact]) -> Vec<Pair> {
    let threshold = SIGNIFICANT * reference.first().map_or(0.0, |i| i.peak);
    reference
        .iter()
        .filter(|r| r.peak >= threshold)
        .filter_map(|r| {
            run.iter()
                .min_by(|a, b| {
                    (a.onset - r.onset)
                        .abs()
                        .total_cmp(&(b.onset - r.onset).abs())
                })
                .map(|e| Pair {
                    reference: *r,
                    run: *e,
                })
        })
        .collect()
}
