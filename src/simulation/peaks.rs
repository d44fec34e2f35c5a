//! Peak-hold outputs: the extremes of the joint loads, the slider acceleration, the rod's
//! deformation energy and stress over each communication interval, and the contact onsets in it.

use nalgebra::Vector2;

use super::cycle::{CycleHold, CycleStep};
use super::sample::{ECCENTRICITY_RATIO, FILM_PRESSURE, SERIES, Sample};
use crate::mechanism::Loads;

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
/// ([`crate::mechanism::SliderCrank::film_extremes`]).
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

/// Peak-hold bookkeeping: what a sampled output misses between communication points.
///
/// An impact lasts tens of microseconds, less than a typical communication step, so the joint
/// force and slider acceleration read at communication points alias their peaks. The peak-hold
/// outputs are the maxima over the communication interval (t_prev, t] of every accepted internal
/// step's end point and of the value at t itself and, for each step in which the journal touches
/// the bearing, of the joint load inside the step's part in the interval (a step across t is
/// sampled on each side of it, `within::divided_step`, so that a peak counts in the interval
/// where it happens, also when the internal steps are longer than the communication step; each
/// side as densely as a whole step, sharing the sample at t); the contact onsets are counted at
/// the accepted step in which the journal starts touching. The internal steps follow the
/// solution, not the master's grid.
///
/// Inside a step the load is read from the step's dense output: a stiff rod's impact lasts only a
/// few internal steps, whose ends alone can miss its peak by tens of percent (the rigid rod's
/// benchmark B at the default tolerance: 36.6 kN at step ends against 45.9 kN converged). The
/// load is sampled at four equally spaced interior points of the quintic Hermite interpolant
/// ([`crate::integrator::dense::interpolate`]) and once more at the vertex of the parabola through
/// the largest sample and its neighbours. That interpolant uses the end accelerations, which
/// after a large implicit step carry amplified unresolved stiff content; on benchmark B its peaks
/// agree within 0.1 % with sampling the implicit method's own solution (a partial step per
/// sample, 3× the run's cost) at the default tolerance, for every rod, and exceed them by at most
/// 3.5 % at rtol 1e-1.
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

    /// Takes the extremes `before` of the pending step's part before the end of the current
    /// interval into the interval (and the extremes since the start).
    pub(super) fn take_before(&mut self, before: Sample) {
        let before = Peaks::from_sample(before, [0; 3]);
        self.interval.absorb(&before);
        self.since_start.absorb(&before);
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
