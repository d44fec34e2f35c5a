//! Cycle results: what a bearing designer reads over one load cycle at each joint — the smallest
//! film thickness, the largest film pressure and the largest force, each with the crank angle
//! where it occurred, and the mean friction power and oil flow.
//!
//! A load cycle is a crank-angle period P (`slider.forceTablePeriod`, 360° without a load table):
//! the cycles are bounded by the multiples of P of the crank angle, whichever way the crank
//! turns, and the angle within a cycle is θ mod P ∈ [0, P). The extremes are caught as the peak
//! holds catch theirs ([`super::PeakHold`]): at every accepted step's end and inside the steps in
//! contact or with a film, each sample assigned to the cycle its crank angle lies in (linear in
//! time within a step). The means are the energy and the volume over the cycle, ∫ P dt and
//! ∫ Q dt by the trapezoidal rule over the internal steps (split where a boundary falls inside a
//! step), divided by the cycle's duration.
//!
//! The results are those of the last complete cycle, one that ran through a whole period from one
//! boundary to the next: cycle number `completed` (`cycle.number`); until the first completes
//! (`cycle.number` = 0), those of the cycle under way (from the start, or from the last boundary
//! crossed). A cycle completes at the communication point at or after the crank angle reaches its
//! boundary: an interval that ends inside the step that crosses it takes the step in up to the
//! boundary ([`CycleHold::complete_before`]). A boundary counts as reached within
//! [`BOUNDARY_TOLERANCE`] of the period, so that a run of exactly N periods reports cycle N
//! whatever the last bits of its crank angle.

use super::sample::{ECCENTRICITY_RATIO, FILM_PRESSURE, Sample, force_series};
use crate::joint::JointRole;

/// The fraction of the period within which a crank angle counts as on a cycle boundary: a
/// boundary is reached that much early turning forwards (late turning backwards), 1e-9 of a
/// revolution (3.6e-7°), well above the crank angle's round-off and far below any cycle result's
/// resolution.
pub const BOUNDARY_TOLERANCE: f64 = 1e-9;

/// An extreme value and the crank angle where it occurred \[rad, absolute\].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Extreme {
    /// The value.
    pub value: f64,
    /// The crank angle \[rad\].
    pub angle: f64,
}

impl Extreme {
    const NONE: Self = Self {
        value: f64::NEG_INFINITY,
        angle: 0.0,
    };

    fn absorb(&mut self, value: f64, angle: f64) {
        if value > self.value {
            *self = Self { value, angle };
        }
    }
}

/// One joint over a cycle (or part of one).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointCycle {
    /// The largest eccentricity ratio (the smallest film).
    pub eccentricity_ratio: Extreme,
    /// The largest film pressure \[Pa\].
    pub film_pressure: Extreme,
    /// The largest force \[N\].
    pub force: Extreme,
    /// ∫ friction power dt \[J\].
    pub friction_energy: f64,
    /// ∫ oil flow dt \[m³\].
    pub oil_volume: f64,
    /// The largest asperity force \[N\].
    pub asperity_force: Extreme,
    /// The time in dry metal contact \[s\].
    pub metal_contact_time: f64,
    /// The largest film temperature \[K\].
    pub film_temperature: Extreme,
}

impl JointCycle {
    const EMPTY: Self = Self {
        eccentricity_ratio: Extreme::NONE,
        film_pressure: Extreme::NONE,
        force: Extreme::NONE,
        friction_energy: 0.0,
        oil_volume: 0.0,
        asperity_force: Extreme::NONE,
        metal_contact_time: 0.0,
        film_temperature: Extreme::NONE,
    };
}

/// A cycle: the times and crank angles where it started and (so far) ends, and each joint's
/// results, by [`JointRole`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cycle {
    /// Start time \[s\].
    pub start: f64,
    /// End time \[s\].
    pub end: f64,
    /// Crank angle at the start \[rad\].
    pub start_angle: f64,
    /// Each joint's results.
    pub joints: [JointCycle; 3],
}

impl Cycle {
    fn empty(time: f64, angle: f64) -> Self {
        Self {
            start: time,
            end: time,
            start_angle: angle,
            joints: [JointCycle::EMPTY; 3],
        }
    }

    /// Takes in the samples at step fractions s ∈ [from, to) of a step whose crank angle runs
    /// linearly from θ₀ to θ₁.
    fn absorb(&mut self, step: &CycleStep, (from, to): (f64, f64)) {
        let angle = |s: f64| step.angle[0] + s * (step.angle[1] - step.angle[0]);
        for role in JointRole::ALL {
            let i = role as usize;
            let joint = &mut self.joints[i];
            let series = [
                (&mut joint.eccentricity_ratio, ECCENTRICITY_RATIO + i),
                (&mut joint.film_pressure, FILM_PRESSURE + i),
                (&mut joint.force, force_series(role)),
            ];
            for (extreme, k) in series {
                if step.place[k] >= from && step.place[k] < to {
                    extreme.absorb(step.inside[k], angle(step.place[k]));
                }
                if to >= 1.0 {
                    extreme.absorb(step.at_end[k], step.angle[1]);
                }
            }
            // the trapezoidal rule over [from, to] of the linear rates
            let h = (to - from) * (step.time[1] - step.time[0]);
            let rate = |r: [f64; 2], s: f64| r[0] + s * (r[1] - r[0]);
            joint.friction_energy +=
                0.5 * h * (rate(step.friction_power[i], from) + rate(step.friction_power[i], to));
            joint.oil_volume +=
                0.5 * h * (rate(step.oil_flow[i], from) + rate(step.oil_flow[i], to));
            let contact = step.in_contact[i].map(f64::from);
            joint.metal_contact_time += 0.5 * h * (rate(contact, from) + rate(contact, to));
            for s in [from, to] {
                joint
                    .asperity_force
                    .absorb(rate(step.asperity_force[i], s), angle(s));
                joint
                    .film_temperature
                    .absorb(rate(step.film_temperature[i], s), angle(s));
            }
        }
        self.end = step.time[0] + to * (step.time[1] - step.time[0]);
    }

    /// The mean of a rate whose integral over the cycle is `integral` (0 for a cycle of no
    /// duration).
    pub fn mean(&self, integral: f64) -> f64 {
        let duration = self.end - self.start;
        if duration > 0.0 {
            integral / duration
        } else {
            0.0
        }
    }
}

/// What one accepted step brings to the cycle results: its ends' times and crank angles, the
/// peak-held samples at its end and the largest inside it with where they lie (fractions of
/// the step), and each joint's friction power and oil flow at both ends; and how much of it is
/// already taken in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CycleStep {
    /// The fraction of the step already taken into the cycle results (up to the boundary an
    /// interval ended past; 0 for a step not yet taken in).
    pub from: f64,
    /// Times of the step's ends \[s\].
    pub time: [f64; 2],
    /// Crank angles at the step's ends \[rad\].
    pub angle: [f64; 2],
    /// The samples at the step's end.
    pub at_end: Sample,
    /// The largest samples inside the step (−∞ where not sampled).
    pub inside: Sample,
    /// Where each largest sample lies, as a fraction of the step.
    pub place: Sample,
    /// Each joint's friction power at the step's ends \[W\].
    pub friction_power: [[f64; 2]; 3],
    /// Each joint's oil flow at the step's ends \[m³/s\].
    pub oil_flow: [[f64; 2]; 3],
    /// Each joint's asperity force at the step's ends \[N\].
    pub asperity_force: [[f64; 2]; 3],
    /// Whether each joint is in dry contact at the step's ends.
    pub in_contact: [[bool; 2]; 3],
    /// Each joint's film temperature at the step's ends (0 without a heat balance) \[K\].
    pub film_temperature: [[f64; 2]; 3],
}

/// The cycle under way and the last complete one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CycleHold {
    /// The load cycle's crank-angle period P \[rad\].
    pub period: f64,
    /// The cycle under way.
    pub current: Cycle,
    /// The last complete cycle, if one has completed.
    pub last: Option<Cycle>,
    /// The number of cycles completed (the number of the last complete one).
    pub completed: u64,
}

impl CycleHold {
    /// No cycle yet, at time `time` and crank angle `angle`, with the period `period` \[rad\].
    pub fn new(period: f64, time: f64, angle: f64) -> Self {
        Self {
            period,
            current: Cycle::empty(time, angle),
            last: None,
            completed: 0,
        }
    }

    /// The cycle the results are read from: the last complete one, else the one under way.
    pub fn reported(&self) -> &Cycle {
        self.last.as_ref().unwrap_or(&self.current)
    }

    /// The angle within the cycle of a crank angle, θ mod P \[rad\].
    pub fn within(&self, angle: f64) -> f64 {
        angle.rem_euclid(self.period)
    }

    /// The cycle index of a crank angle: k where it lies in [kP, (k + 1) P), a boundary counting
    /// as reached [`BOUNDARY_TOLERANCE`] early.
    fn index(&self, angle: f64) -> f64 {
        (angle / self.period + BOUNDARY_TOLERANCE).floor()
    }

    /// Where the step crosses a cycle boundary, if it does: the fraction of the step where its
    /// crank angle (linear within it) reaches it (its end, for an angle that reaches the boundary
    /// only within the tolerance), and the boundary's angle.
    fn boundary(&self, step: &CycleStep) -> Option<(f64, f64)> {
        let [a0, a1] = step.angle;
        let (k0, k1) = (self.index(a0), self.index(a1));
        (k0 != k1).then(|| {
            let boundary = self.period * k0.max(k1);
            (((boundary - a0) / (a1 - a0)).clamp(0.0, 1.0), boundary)
        })
    }

    /// Takes in the rest of an accepted step (from `step.from`): where the crank angle crosses a
    /// multiple of the period inside it, the samples before go to the cycle under way, which ends
    /// there (and becomes the last complete one if it ran through a whole period), and those after
    /// to the next.
    pub fn absorb(&mut self, step: &CycleStep) {
        let from = self.complete_before(step, f64::INFINITY);
        self.current.absorb(step, (from, 1.0));
    }

    /// Takes in the step up to the cycle boundary it crosses, if that is reached by the time `t`
    /// and not taken in yet (from `step.from`): the cycle under way ends there. The fraction of
    /// the step taken in so far.
    pub fn complete_before(&mut self, step: &CycleStep, t: f64) -> f64 {
        let Some((s, boundary)) = self.boundary(step) else {
            return step.from;
        };
        let at = step.time[0] + s * (step.time[1] - step.time[0]);
        // (a cycle that starts at the boundary has taken the step in up to it)
        if self.current.start_angle == boundary || at > t {
            return step.from;
        }
        self.current.absorb(step, (step.from, s));
        let swept = (boundary - self.current.start_angle).abs();
        if swept >= self.period * (1.0 - 1e-12) {
            self.last = Some(self.current);
            self.completed += 1;
        }
        self.current = Cycle::empty(at, boundary);
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A step of constant rates, the eccentricity of joint 0 peaking inside it at `place`.
    fn step(t: [f64; 2], angle: [f64; 2], peak: f64, place: f64) -> CycleStep {
        let mut inside = [f64::NEG_INFINITY; 15];
        let mut places = [0.0; 15];
        inside[ECCENTRICITY_RATIO] = peak;
        places[ECCENTRICITY_RATIO] = place;
        CycleStep {
            from: 0.0,
            time: t,
            angle,
            at_end: [0.0; 15],
            inside,
            place: places,
            friction_power: [[2.0, 2.0]; 3],
            oil_flow: [[1e-6, 3e-6]; 3],
            asperity_force: [[0.0, 0.0]; 3],
            in_contact: [[false, false]; 3],
            film_temperature: [[0.0, 0.0]; 3],
        }
    }

    /// Over steps of 10° at 100 rad/s: a cycle completes at 360°, its extreme keeps its angle
    /// within the cycle, its means are the rates' means; a peak past the boundary inside the
    /// step that crosses it belongs to the next cycle.
    #[test]
    fn a_cycle_completes_at_the_period_and_keeps_its_angles() {
        let deg = std::f64::consts::PI / 180.0;
        let mut hold = CycleHold::new(360.0 * deg, 0.0, 0.0);
        let dt = 10.0 * deg / 100.0;
        for k in 0..40 {
            let (a0, a1) = (f64::from(k) * 10.0 * deg, f64::from(k + 1) * 10.0 * deg);
            // a peak at 95° in the first cycle, 0.3 at 365° in the second
            let (peak, place) = match k {
                9 => (0.9, 0.5),
                36 => (0.3, 0.5),
                _ => (0.1, 0.5),
            };
            hold.absorb(&step(
                [f64::from(k) * dt, f64::from(k + 1) * dt],
                [a0, a1],
                peak,
                place,
            ));
            if k < 35 {
                assert!(hold.last.is_none());
            }
        }
        let last = hold.last.expect("a complete cycle");
        assert!((last.end - last.start - 36.0 * dt).abs() < 1e-12);
        let joint = last.joints[0];
        assert_eq!(joint.eccentricity_ratio.value, 0.9);
        assert!((hold.within(joint.eccentricity_ratio.angle) / deg - 95.0).abs() < 1e-9);
        assert!((last.mean(joint.friction_energy) - 2.0).abs() < 1e-12);
        assert!((last.mean(joint.oil_volume) - 2e-6).abs() < 1e-18);
        assert_eq!(hold.current.joints[0].eccentricity_ratio.value, 0.3);
    }

    /// An interval that ends inside the step crossing a boundary completes the cycle there if
    /// the boundary lies before its end, and the step's end then goes to the next cycle only; a
    /// crank angle within the tolerance of a boundary has reached it (a run of exactly one
    /// period completes it).
    #[test]
    fn a_cycle_completes_at_the_first_point_past_its_boundary() {
        let mut hold = CycleHold::new(1.0, 0.0, 0.0);
        hold.absorb(&step([0.0, 1.0], [0.0, 0.9], 0.5, 0.5));
        let mut crossing = step([1.0, 2.0], [0.9, 1.1], 0.8, 0.25);
        // the boundary at s = 0.5, t = 1.5: not reached at t = 1.4
        assert_eq!(hold.complete_before(&crossing, 1.4), 0.0);
        assert_eq!(hold.completed, 0);
        crossing.from = hold.complete_before(&crossing, 1.6);
        assert!((crossing.from - 0.5).abs() < 1e-12);
        assert_eq!(hold.completed, 1);
        let last = hold.last.unwrap();
        assert_eq!(last.joints[0].eccentricity_ratio.value, 0.8);
        assert!((last.end - 1.5).abs() < 1e-12);
        hold.absorb(&crossing);
        assert_eq!(hold.completed, 1);
        // (its end sample only: the peak inside lay before the boundary)
        assert_eq!(hold.current.joints[0].eccentricity_ratio.value, 0.0);
        assert!((hold.current.end - 2.0).abs() < 1e-12);
        let mut exact = CycleHold::new(1.0, 0.0, 0.0);
        exact.absorb(&step([0.0, 1.0], [0.0, 1.0 - 1e-12], 0.1, 0.5));
        assert_eq!(exact.completed, 1);
    }

    /// Turning backwards from a boundary the first cycle runs from 0 down to −360°; a boundary
    /// inside a step splits it: the crossing step's peak before the boundary stays in the
    /// finishing cycle.
    #[test]
    fn cycles_are_bounded_by_multiples_of_the_period_either_way() {
        let period = 2.0;
        let mut hold = CycleHold::new(period, 0.0, 0.0);
        for k in 0..5 {
            let a = [-0.5 * f64::from(k), -0.5 * f64::from(k + 1)];
            let (peak, place) = if k == 3 { (0.7, 0.4) } else { (0.2, 0.5) };
            hold.absorb(&step([f64::from(k), f64::from(k + 1)], a, peak, place));
        }
        // the crossing at −2 happens at the end of step 3 (from −1.5 to −2): its peak at s = 0.4
        let last = hold.last.expect("complete");
        assert_eq!(last.joints[0].eccentricity_ratio.value, 0.7);
        assert!((last.start_angle - 0.0).abs() < 1e-15);
        assert!((hold.current.start_angle + 2.0).abs() < 1e-15);
    }
}
