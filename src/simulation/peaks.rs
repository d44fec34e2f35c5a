//! Peak-hold outputs: the extremes of the joint loads, the slider acceleration, the rod's
//! deformation energy and stress over each communication interval, and the contact onsets in it.

use nalgebra::Vector2;

use super::cycle::{CycleHold, CycleStep};
use super::sample::{
    CRANK_PIN_FORCE, ECCENTRICITY_RATIO, FILM_PRESSURE, MAIN_BEARING_FORCE, SERIES, Sample,
};
use super::step::StepPoint;
use crate::integrator::dense;
use crate::joint::JointRole;
use crate::mechanism::{Conditions, Contacts, InputSignal, Loads, SliderCrank};

/// Extremes of the solution over a stretch of time, and the contact onsets in it (−∞ for an
/// extreme not yet seen: some are signed).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Peaks {
    /// Largest |joint force| \[N\].
    pub joint_force: f64,
    /// Largest |slider acceleration| \[m/s²\].
    pub slider_acceleration: f64,
    /// Largest rod deformation energy \[J\].
    pub deformation_energy: f64,
    /// Largest |crank-pin force| \[N\].
    pub crank_pin_force: f64,
    /// Largest |main-bearing force| \[N\].
    pub main_bearing_force: f64,
    /// Largest |guide force| \[N\].
    pub guide_force: f64,
    /// Largest rod stress \[Pa\].
    pub rod_stress: f64,
    /// Largest eccentricity ratio ε = |e|/c at each joint (the smallest film thickness
    /// c (1 − ε)), by [`crate::joint::JointRole`].
    pub eccentricity_ratio: [f64; 3],
    /// Largest film pressure at each joint \[Pa\].
    pub film_pressure: [f64; 3],
    /// The most tensile fibre stress over the rod (signed: negative when the whole rod is
    /// compressed) \[Pa\].
    pub rod_tension: f64,
    /// The most compressive fibre stress over the rod, as a compression (minus the signed
    /// stress) \[Pa\].
    pub rod_compression: f64,
    /// Number of contact onsets at each joint.
    pub contact_onsets: Onsets,
}

impl Default for Peaks {
    /// No extreme seen, no onset.
    fn default() -> Self {
        Self::from_sample([f64::NEG_INFINITY; SERIES], [0; 3])
    }
}

/// Contact onsets at each joint, indexed by [`crate::joint::JointRole`].
pub type Onsets = [u64; 3];

/// Positions in a [`Sample`] of the quantities whose peaks inside a step are refined always (the
/// joint force, the slider acceleration, the deformation energy); the crank pin's and the main
/// bearing's forces are refined when that joint is worn.
const ALWAYS_REFINED: usize = 3;

impl Peaks {
    /// Extends these extremes by `other`'s and adds its onsets.
    pub(super) fn absorb(&mut self, other: &Peaks) {
        let mut sample = self.sample();
        for (s, o) in sample.iter_mut().zip(other.sample()) {
            *s = s.max(o);
        }
        let onsets = std::array::from_fn(|i| self.contact_onsets[i] + other.contact_onsets[i]);
        *self = Self::from_sample(sample, onsets);
    }

    /// Peaks of one instant's magnitudes `sample` with `contact_onsets` onsets.
    pub(super) fn from_sample(sample: Sample, contact_onsets: Onsets) -> Self {
        let [
            joint_force,
            slider_acceleration,
            deformation_energy,
            crank_pin_force,
            main_bearing_force,
            guide_force,
            rod_stress,
            ..,
            rod_tension,
            rod_compression,
        ] = sample;
        Self {
            joint_force,
            slider_acceleration,
            deformation_energy,
            crank_pin_force,
            main_bearing_force,
            guide_force,
            rod_stress,
            eccentricity_ratio: std::array::from_fn(|i| sample[ECCENTRICITY_RATIO + i]),
            film_pressure: std::array::from_fn(|i| sample[FILM_PRESSURE + i]),
            rod_tension,
            rod_compression,
            contact_onsets,
        }
    }

    /// The extremes as a sample (see [`Peaks::from_sample`]).
    pub(super) fn sample(&self) -> Sample {
        let [e0, e1, e2] = self.eccentricity_ratio;
        let [p0, p1, p2] = self.film_pressure;
        [
            self.joint_force,
            self.slider_acceleration,
            self.deformation_energy,
            self.crank_pin_force,
            self.main_bearing_force,
            self.guide_force,
            self.rod_stress,
            e0,
            e1,
            e2,
            p0,
            p1,
            p2,
            self.rod_tension,
            self.rod_compression,
        ]
    }
}

/// The peak-held magnitudes of one instant: the joint force on the journal, the slider
/// acceleration, the loads, and each joint's eccentricity ratio and film pressure
/// ([`SliderCrank::film_extremes`]).
pub(super) fn sample(
    joint_force: Vector2<f64>,
    slider_acceleration: f64,
    loads: &Loads,
    film: [(f64, f64); 3],
) -> Sample {
    Peaks {
        joint_force: joint_force.norm(),
        slider_acceleration: slider_acceleration.abs(),
        deformation_energy: loads.deformation_energy,
        crank_pin_force: loads.crank_pin.norm(),
        main_bearing_force: loads.main_bearing.norm(),
        guide_force: loads.guide.abs(),
        rod_stress: loads.stress.largest,
        eccentricity_ratio: film.map(|(ratio, _)| ratio),
        film_pressure: film.map(|(_, pressure)| pressure),
        rod_tension: loads.stress.max,
        rod_compression: -loads.stress.min,
        contact_onsets: [0; 3],
    }
    .sample()
}

/// The larger of two samples, quantity by quantity.
pub(super) fn larger(a: Sample, b: Sample) -> Sample {
    std::array::from_fn(|i| a[i].max(b[i]))
}

/// Interior points of an accepted step at which the peak-hold outputs sample the joint load while
/// the journal touches the bearing (see [`PeakHold`]).
const PEAK_SAMPLES: usize = 4;

/// Peak-hold bookkeeping: what a sampled output misses between communication points.
///
/// An impact lasts tens of microseconds, less than a typical communication step, so the joint
/// force and slider acceleration read at communication points alias their peaks. The peak-hold
/// outputs are the maxima over the communication interval (t_prev, t] of every accepted internal
/// step's end point and of the value at t itself and, for each step in which the journal touches
/// the bearing, of the joint load inside the step's part in the interval (a step across t is
/// sampled on each side of it, `Engine::divide_pending_step`, so that a peak counts in the
/// interval where it happens, also when the internal steps are longer than the communication
/// step); the contact onsets are counted at the accepted step in which the journal starts
/// touching. The internal steps follow the solution, not the master's grid.
///
/// Inside a step the load is read from the step's dense output: a stiff rod's impact lasts only a
/// few internal steps, whose ends alone can miss its peak by tens of percent (the rigid rod's
/// benchmark B at the default tolerance: 36.6 kN at step ends against 45.9 kN converged). The
/// load is sampled at four equally spaced interior points of the quintic Hermite interpolant
/// ([`dense::interpolate`]) and once more at the vertex of the parabola through the largest sample
/// and its neighbours. That interpolant uses the end
/// accelerations, which after a large implicit step carry amplified unresolved stiff content; on
/// benchmark B its peaks agree within 0.1 % with sampling the implicit method's own solution
/// (a partial step per sample, 3× the run's cost) at the default tolerance, for every rod, and
/// exceed them by at most 3.5 % at rtol 1e-1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PeakHold {
    /// Over the current communication interval, from the steps' parts inside it.
    pub interval: Peaks,
    /// Of the last accepted step: at its end, and inside it after the last communication point
    /// it crosses.
    pub step_end: Peaks,
    /// Whether `step_end` lies beyond the current time (it belongs to a later interval).
    pub pending: bool,
    /// Contact onsets up to the current time.
    pub total_onsets: Onsets,
    /// The extremes since the start, of every accepted step taken into an interval (the film's
    /// are output; the value at the current time is added when the outputs are read).
    pub since_start: Peaks,
    /// What the last accepted step brings to the cycle results, while it is pending.
    pub cycle_step: Option<CycleStep>,
    /// The cycle results, of every accepted step taken into an interval.
    pub cycles: CycleHold,
}

impl PeakHold {
    /// Nothing held yet, the load cycles of crank-angle period `period` \[rad\] counted from
    /// crank angle `angle` at time `time`.
    pub fn new(period: f64, time: f64, angle: f64) -> Self {
        Self {
            interval: Peaks::default(),
            step_end: Peaks::default(),
            pending: false,
            total_onsets: [0; 3],
            since_start: Peaks::default(),
            cycle_step: None,
            cycles: CycleHold::new(period, time, angle),
        }
    }

    /// Completes the cycle under way at the boundary the pending step crosses, if the crank angle
    /// reaches it by the time `t` (an interval that ends inside the step).
    pub(super) fn complete_cycle_before(&mut self, t: f64) {
        if let Some(step) = &mut self.cycle_step {
            step.from = self.cycles.complete_before(step, t);
        }
    }

    /// Moves the last step end's extremes into the current interval.
    pub(super) fn take_step_end(&mut self) {
        if let Some(step) = self.cycle_step.take() {
            self.cycles.absorb(&step);
        }
        self.since_start.absorb(&Peaks {
            contact_onsets: [0; 3],
            ..self.step_end
        });
        self.interval.absorb(&self.step_end);
        for (total, onsets) in self
            .total_onsets
            .iter_mut()
            .zip(self.step_end.contact_onsets)
        {
            *total += onsets;
        }
        self.pending = false;
    }
}

/// Abscissa (in sample units) of the vertex of the parabola through the largest of equally spaced
/// samples `f` and its two neighbours, if that sample is interior and the parabola is concave:
///
/// ```text
/// k* + ½ (f[k*−1] − f[k*+1]) / (f[k*−1] − 2 f[k*] + f[k*+1])
/// ```
fn parabola_vertex(f: &[f64]) -> Option<f64> {
    let k = (0..f.len()).max_by(|&i, &j| f[i].total_cmp(&f[j]))?;
    if k == 0 || k + 1 == f.len() {
        return None;
    }
    let curvature = f[k - 1] - 2.0 * f[k] + f[k + 1];
    (curvature < 0.0).then(|| k as f64 + 0.5 * (f[k - 1] - f[k + 1]) / curvature)
}

/// The step just accepted, whose dense output the peaks are sampled from: its start and end times,
/// states and derivatives, the contact states it was integrated with and those at its end.
pub(super) struct AcceptedStep<'a> {
    pub(super) start: &'a StepPoint,
    pub(super) end: &'a StepPoint,
    pub(super) contact_start: Contacts,
    pub(super) contact_end: Contacts,
    /// The inputs it was integrated with.
    pub(super) signal: &'a InputSignal,
}

/// The samples at a step's ends already taken (the last step's end and this one's), which the
/// samples inside it at its start and end would repeat.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct KnownEnds {
    pub(super) start: Option<Sample>,
    pub(super) end: Option<Sample>,
}

/// Whether the peak-hold outputs sample the inside of the step `step`: the journal touches the
/// bearing at either end of it, or a film carries the load.
pub(super) fn sampled_inside(mechanism: &SliderCrank, step: &AcceptedStep<'_>) -> bool {
    step.contact_start.any() || step.contact_end.any() || mechanism.has_film()
}

/// The largest peak-held magnitudes inside the part `range` = (s₀, s₁) of the step just accepted
/// (fractions of it: (0, 1) the whole step), under the contact states it was integrated with (an
/// onset inside it is latched at its end), if [`sampled_inside`] (no extreme otherwise); see
/// [`PeakHold`]. The samples at the range's ends are `known`'s where it has them; `sample` and
/// `acceleration` are scratch space of one state each.
pub(super) fn within_step(
    mechanism: &mut SliderCrank,
    step: &AcceptedStep<'_>,
    range: (f64, f64),
    known: KnownEnds,
    sample: &mut [f64],
    acceleration: &mut [f64],
) -> Within {
    if !sampled_inside(mechanism, step) {
        return Within::default();
    }
    let (from, to) = range;
    let fraction = |k: f64| from + (to - from) * k / (PEAK_SAMPLES + 1) as f64;
    // The worn crank joints' forces are refined as the rod–slider joint's is.
    let refined = std::array::from_fn(|i| match i {
        CRANK_PIN_FORCE => mechanism.has_clearance(JointRole::CrankPin),
        MAIN_BEARING_FORCE => mechanism.has_clearance(JointRole::MainBearing),
        _ => i < ALWAYS_REFINED,
    });
    let mut at = |k: f64| {
        let end = k == (PEAK_SAMPLES + 1) as f64;
        match (k == 0.0, end, known) {
            (true, _, KnownEnds { start: Some(s), .. }) => s,
            (_, true, KnownEnds { end: Some(s), .. }) => s,
            _ => load_within(mechanism, step, sample, acceleration, fraction(k)),
        }
    };
    let mut within = largest_loads(&mut at, refined);
    if range != (0.0, 1.0) {
        for place in &mut within.place {
            *place = from + (to - from) * *place;
        }
    }
    within
}

/// The largest of each quantity among the samples k = 0 … [`PEAK_SAMPLES`] + 1 of a step and at
/// the vertex of the parabola through each `refined` quantity's largest sample and its neighbours:
/// the joint force, the slider acceleration, the deformation energy and the force of a worn crank
/// pin or main bearing. The other loads and the stress peak with the joint forces at an impact:
/// they take the largest of every evaluation made, those vertices included, without evaluations of
/// their own.
fn largest_loads(at: &mut impl FnMut(f64) -> Sample, refined: [bool; SERIES]) -> Within {
    let mut series = [[0.0; PEAK_SAMPLES + 2]; SERIES];
    for k in 0..PEAK_SAMPLES + 2 {
        for (values, value) in series.iter_mut().zip(at(k as f64)) {
            values[k] = value;
        }
    }
    let mut largest: Sample =
        std::array::from_fn(|i| series[i].iter().copied().fold(f64::NEG_INFINITY, f64::max));
    // Where each quantity's largest sample lies, as a fraction of the step.
    let mut place: Sample = std::array::from_fn(|i| {
        let k = (0..PEAK_SAMPLES + 2)
            .max_by(|&a, &b| series[i][a].total_cmp(&series[i][b]))
            .unwrap_or(0);
        k as f64 / (PEAK_SAMPLES + 1) as f64
    });
    let mut vertices: Sample = [f64::NEG_INFINITY; SERIES];
    for (i, values) in series.iter().enumerate() {
        if !refined[i] {
            continue;
        }
        if let Some(k) = parabola_vertex(values) {
            let sample = at(k);
            if sample[i] > largest[i] {
                largest[i] = sample[i];
                place[i] = k / (PEAK_SAMPLES + 1) as f64;
            }
            for (v, s) in vertices.iter_mut().zip(sample) {
                *v = v.max(s);
            }
        }
    }
    for i in (0..SERIES).filter(|&i| !refined[i]) {
        largest[i] = largest[i].max(vertices[i]);
    }
    let rise = std::array::from_fn(|i| match refined[i] {
        true => largest[i] - series[i][0].max(series[i][PEAK_SAMPLES + 1]),
        false => 0.0,
    });
    Within {
        largest,
        rise,
        place,
    }
}

/// The extremes inside an accepted step ([`within_step`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Within {
    /// The largest value of each quantity inside the step.
    pub(super) largest: Sample,
    /// For each refined quantity, how far its largest value rose above the larger of the step's
    /// ends: the part of an in-step peak that the interpolant, not the integration, decides.
    pub(super) rise: Sample,
    /// Where each largest value lies, as a fraction s ∈ [0, 1] of the step.
    pub(super) place: Sample,
}

impl Default for Within {
    /// A step not sampled inside: no extreme, no rise.
    fn default() -> Self {
        Self {
            largest: [f64::NEG_INFINITY; SERIES],
            rise: [0.0; SERIES],
            place: [0.0; SERIES],
        }
    }
}

/// Largest relative error of the peak of a lubricated joint's force inside a step: the 2 % its
/// peaks are held to at the default tolerance.
pub(super) const PEAK_TOLERANCE: f64 = 0.02;

/// Whether a peak `value` inside a step that rose `rise` above the step's ends may rest on the
/// interpolant and matters: it rose more than [`PEAK_TOLERANCE`] of itself above both ends
/// (below that, the ends, which the integration sets, bound its error), and it is at least half
/// the largest value so far, `largest` (the lesser peaks of a cycle set no design load). Such a
/// peak is then checked against the integrator's own solution at its place
/// (`Simulation::doubt_film_peaks`).
pub(super) fn interpolated_peak(value: f64, rise: f64, largest: f64) -> bool {
    rise > PEAK_TOLERANCE * value && value >= 0.5 * largest
}

/// The peak-held magnitudes at the fraction `theta` of the step just accepted, from the dense
/// output's state and accelerations.
fn load_within(
    mechanism: &mut SliderCrank,
    step: &AcceptedStep<'_>,
    sample: &mut [f64],
    acceleration: &mut [f64],
    theta: f64,
) -> Sample {
    let span = step.start.span_to(step.end);
    let c = Conditions::at(step.signal, span.t0 + theta * span.h, &step.contact_start);
    let n_q = mechanism.n_coordinates();
    dense::interpolate(n_q, &span, theta, sample);
    dense::acceleration(n_q, &span, theta, acceleration);
    if mechanism.has_film() {
        dense::cubic_velocities(n_q, span.h, span.y0, span.y1, theta, sample);
    }
    let (force, slider_acceleration) = mechanism
        .clearance_joint_load(sample, &c)
        .unwrap_or((Vector2::zeros(), 0.0));
    let loads = mechanism.loads(sample, acceleration, force, c.contacts);
    let film = mechanism.film_extremes(sample);
    self::sample(force, slider_acceleration, &loads, film)
}
#[cfg(test)]
mod tests {
    use super::*;

    /// The rise above a step's ends of each refined series, and where its largest value lies:
    /// a sampled bump between flat ends rises by its height, at its vertex; an unrefined series
    /// does not rise. A rise of more than 2 % of a peak at least half the largest so far may rest
    /// on the interpolant.
    #[test]
    fn largest_loads_report_the_rise_above_the_ends() {
        let mut at = |k: f64| -> Sample {
            let mut s = [1.0; SERIES];
            s[0] = 1.0 + 0.5 * (1.0 - ((k - 2.5) / 2.5).powi(2));
            s[5] = s[0];
            s
        };
        let mut refined = [false; SERIES];
        refined[0] = true;
        let within = largest_loads(&mut at, refined);
        assert!(
            (within.largest[0] - 1.5).abs() < 1e-12,
            "{:?}",
            within.largest
        );
        assert!((within.rise[0] - 0.5).abs() < 1e-12);
        assert!((within.place[0] - 0.5).abs() < 1e-12);
        assert_eq!(within.rise[5], 0.0);
        assert!(interpolated_peak(within.largest[0], within.rise[0], 2.0));
        assert!(!interpolated_peak(1000.0, 20.0, 0.0));
        assert!(!interpolated_peak(1000.0, 300.0, 2500.0));
    }

    /// Samples of a concave parabola give its vertex; a maximum at either end of the samples, or
    /// a flat top, gives none.
    #[test]
    fn parabola_vertex_locates_the_maximum_between_samples() {
        let f: Vec<f64> = (0..6).map(|k| 7.0 - (k as f64 - 2.3).powi(2)).collect();
        let vertex = parabola_vertex(&f).expect("interior maximum");
        assert!((vertex - 2.3).abs() < 1e-12, "{vertex}");
        assert_eq!(parabola_vertex(&[3.0, 2.0, 1.0]), None);
        assert_eq!(parabola_vertex(&[1.0, 2.0, 3.0]), None);
        assert_eq!(parabola_vertex(&[1.0, 2.0, 2.0, 2.0]), None);
        assert_eq!(parabola_vertex(&[]), None);
    }
}
