//! The points of the integrator's step sequence the simulation keeps: the start and the end of
//! the last accepted step; and the end of a step in which a joint came into contact, where an
//! early return stops ([`Onset`]).

use crate::integrator::dense::Span;
use crate::joint::JointRole;
use crate::math;

/// A point of the integrator's step sequence: its time, the state there and the state's
/// derivative (what the dense output between two points is made of).
#[derive(Clone, Debug, PartialEq)]
pub struct StepPoint {
    /// Time \[s\].
    pub time: f64,
    /// State.
    pub y: Vec<f64>,
    /// Its time derivative.
    pub f: Vec<f64>,
}

impl StepPoint {
    /// The point at `time` with state `y` and a zero derivative.
    pub fn at_rest(time: f64, y: &[f64]) -> Self {
        Self {
            time,
            y: y.to_vec(),
            f: vec![0.0; y.len()],
        }
    }

    /// Whether `other` has the same time, state and derivative, bit for bit.
    pub fn same_bits(&self, other: &StepPoint) -> bool {
        self.time.to_bits() == other.time.to_bits()
            && math::same_bits(&self.y, &other.y)
            && math::same_bits(&self.f, &other.f)
    }

    /// Whether time, state and derivative are finite numbers.
    pub fn is_finite(&self) -> bool {
        self.time.is_finite() && self.y.iter().chain(&self.f).all(|x| x.is_finite())
    }

    /// The step from this point to `end`, whose dense output they make.
    pub fn span_to<'a>(&'a self, end: &'a StepPoint) -> Span<'a> {
        Span {
            t0: self.time,
            h: end.time - self.time,
            y0: &self.y,
            f0: &self.f,
            y1: &end.y,
            f1: &end.f,
        }
    }

    /// Copies `other` into this point (of the same length).
    pub fn copy_from(&mut self, other: &StepPoint) {
        self.time = other.time;
        self.y.copy_from_slice(&other.y);
        self.f.copy_from_slice(&other.f);
    }
}

/// A contact onset an early return stopped at ([`super::Engine::advance`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Onset {
    /// The joint that came into contact.
    pub joint: JointRole,
    /// The time reached \[s\], on the clock grid.
    pub time: f64,
}

impl Onset {
    /// What happened, for a log: "contact onset in crankPin".
    pub fn event(&self) -> &'static str {
        match self.joint {
            JointRole::MainBearing => "contact onset in mainBearing",
            JointRole::CrankPin => "contact onset in crankPin",
            JointRole::RodSlider => "contact onset in joint",
        }
    }
}

/// An interval under way: where it started and ends, the step limit its inputs set, and the
/// integrator's work count at its start (its step budget).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct Interval {
    pub(super) t_start: f64,
    pub(super) t_end: f64,
    pub(super) limit: Option<f64>,
    pub(super) work_start: u64,
}

/// How an interval may end before its end: at a contact onset (an early return), or paused after
/// an accepted step for a master that reads the state inside the interval (FMI 3 intermediate
/// update). Neither: the interval runs to its end.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Mode {
    /// Stop at the end of the first internal step in which a joint comes into contact, if that is
    /// before the interval's end ([`Advance::Onset`]).
    pub stop_at_onset: bool,
    /// Pause after every accepted step that ends before the interval's end, by a clock tick at
    /// least ([`Advance::Paused`]).
    pub pause: bool,
}

/// Where an interval stopped ([`super::Engine::advance`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Advance {
    /// At the interval's end \[s\] (on the clock grid).
    Reached(f64),
    /// Early, at a contact onset: the interval ends there.
    Onset(Onset),
    /// After an accepted step before the interval's end, at its end \[s\] (not on the clock
    /// grid): the state there is the current one; the interval resumes at the next call.
    Paused(f64),
}
