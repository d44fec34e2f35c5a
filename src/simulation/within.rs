//! The extremes inside an accepted step: its dense output sampled for the peak-hold outputs
//! ([`super::peaks::PeakHold`]), over the whole step or divided at a communication point.

use nalgebra::Vector2;

use super::peaks::{larger, sample};
use super::sample::{CRANK_PIN_FORCE, MAIN_BEARING_FORCE, SERIES, Sample};
use super::step::StepPoint;
use crate::integrator::dense;
use crate::joint::JointRole;
use crate::mechanism::{Conditions, Contacts, InputSignal, SliderCrank};

/// Positions in a [`Sample`] of the quantities whose peaks inside a step are refined always (the
/// joint force, the slider acceleration, the deformation energy); the crank pin's and the main
/// bearing's forces are refined when that joint is worn.
const ALWAYS_REFINED: usize = 3;

/// Interior points of an accepted step at which the peak-hold outputs sample the joint load while
/// the journal touches the bearing (see [`super::peaks::PeakHold`]).
const PEAK_SAMPLES: usize = 4;

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

/// The quantities whose largest sample is refined at the vertex of a parabola
/// ([`largest_loads`]): the joint force, the slider acceleration, the deformation energy, and a
/// worn crank pin's or main bearing's force as the rod–slider joint's.
fn refined_series(mechanism: &SliderCrank) -> [bool; SERIES] {
    std::array::from_fn(|i| match i {
        CRANK_PIN_FORCE => mechanism.has_clearance(JointRole::CrankPin),
        MAIN_BEARING_FORCE => mechanism.has_clearance(JointRole::MainBearing),
        _ => i < ALWAYS_REFINED,
    })
}

/// The largest peak-held magnitudes inside the step just accepted, under the contact states it
/// was integrated with (an onset inside it is latched at its end), if [`sampled_inside`] (no
/// extreme otherwise); see [`super::peaks::PeakHold`]. The samples at its ends are `known`'s
/// where it has them; `sample` and `acceleration` are scratch space of one state each.
pub(super) fn within_step(
    mechanism: &mut SliderCrank,
    step: &AcceptedStep<'_>,
    known: KnownEnds,
    sample: &mut [f64],
    acceleration: &mut [f64],
) -> Within {
    if !sampled_inside(mechanism, step) {
        return Within::default();
    }
    let refined = refined_series(mechanism);
    within_part(
        mechanism,
        step,
        (0.0, 1.0),
        known,
        refined,
        sample,
        acceleration,
    )
}

/// The extremes of the step just accepted divided at the fraction `at` of it, where a
/// communication interval ends: its part (`from`, `at`) in that interval and its part (`at`, 1)
/// after it, as [`within_step`] samples a whole step, each as densely
/// ([`sample_intervals`]) and sharing the sample at `at`.
pub(super) fn divided_step(
    mechanism: &mut SliderCrank,
    step: &AcceptedStep<'_>,
    (from, at): (f64, f64),
    known: KnownEnds,
    sample: &mut [f64],
    acceleration: &mut [f64],
) -> Division {
    if !sampled_inside(mechanism, step) {
        return Division::default();
    }
    let refined = refined_series(mechanism);
    let at_division = load_within(mechanism, step, sample, acceleration, at);
    let mut part = |range, start, end| {
        let known = KnownEnds { start, end };
        within_part(mechanism, step, range, known, refined, sample, acceleration)
    };
    let before = part((from, at), known.start, Some(at_division));
    let after = part((at, 1.0), Some(at_division), known.end);
    let later = |i: usize| after.largest[i] > before.largest[i];
    let largest = larger(before.largest, after.largest);
    let start = before.ends[0];
    let end = after.ends[1];
    let whole = Within {
        largest,
        rise: std::array::from_fn(|i| match refined[i] {
            true => largest[i] - start[i].max(end[i]),
            false => 0.0,
        }),
        place: std::array::from_fn(|i| match later(i) {
            true => after.place[i],
            false => before.place[i],
        }),
        ends: [start, end],
    };
    Division {
        before: before.largest,
        after: after.largest,
        whole,
    }
}

/// A step's extremes divided at a communication point ([`divided_step`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Division {
    /// The largest value of each quantity in the part before the point.
    pub(super) before: Sample,
    /// The largest value of each quantity in the part after it.
    pub(super) after: Sample,
    /// The extremes of both parts together.
    pub(super) whole: Within,
}

impl Default for Division {
    /// A step not sampled inside: no extreme.
    fn default() -> Self {
        Self {
            before: [f64::NEG_INFINITY; SERIES],
            after: [f64::NEG_INFINITY; SERIES],
            whole: Within::default(),
        }
    }
}

/// The extremes inside the part `range` = (s₀, s₁) of the step just accepted (fractions of it),
/// sampled at [`sample_intervals`] equal intervals, with the `refined` quantities refined
/// ([`largest_loads`]); the samples at the part's ends are `known`'s where it has them.
fn within_part(
    mechanism: &mut SliderCrank,
    step: &AcceptedStep<'_>,
    (from, to): (f64, f64),
    known: KnownEnds,
    refined: [bool; SERIES],
    sample: &mut [f64],
    acceleration: &mut [f64],
) -> Within {
    let n = sample_intervals(to - from);
    let fraction = |k: f64| from + (to - from) * k / n as f64;
    let mut at = |k: f64| match (k == 0.0, k == n as f64, known) {
        (true, _, KnownEnds { start: Some(s), .. }) => s,
        (_, true, KnownEnds { end: Some(s), .. }) => s,
        _ => load_within(mechanism, step, sample, acceleration, fraction(k)),
    };
    let mut within = largest_loads(&mut at, n, refined);
    if (from, to) != (0.0, 1.0) {
        for place in &mut within.place {
            *place = from + (to - from) * *place;
        }
    }
    within
}

/// The number of equal intervals between the samples of a part `length` (a fraction of the step)
/// of a step: [`PEAK_SAMPLES`] + 1 for the whole step, for a part as many as keep its samples at
/// least as dense, one at the least.
fn sample_intervals(length: f64) -> usize {
    let whole = PEAK_SAMPLES + 1;
    ((length * whole as f64).ceil() as usize).clamp(1, whole)
}

/// The largest of each quantity among the samples k = 0 … `n` (n ≤ [`PEAK_SAMPLES`] + 1) of a
/// step and at the vertex of the parabola through each `refined` quantity's largest sample and
/// its neighbours: the joint force, the slider acceleration, the deformation energy and the force
/// of a worn crank pin or main bearing. The other loads and the stress peak with the joint forces
/// at an impact: they take the largest of every evaluation made, those vertices included, without
/// evaluations of their own.
fn largest_loads(at: &mut impl FnMut(f64) -> Sample, n: usize, refined: [bool; SERIES]) -> Within {
    let mut samples = [[0.0; PEAK_SAMPLES + 2]; SERIES];
    for k in 0..=n {
        for (values, value) in samples.iter_mut().zip(at(k as f64)) {
            values[k] = value;
        }
    }
    let series = |i: usize| &samples[i][..=n];
    let mut largest: Sample =
        std::array::from_fn(|i| series(i).iter().copied().fold(f64::NEG_INFINITY, f64::max));
    // Where each quantity's largest sample lies, as a fraction of the step.
    let mut place: Sample = std::array::from_fn(|i| {
        let k = (0..=n)
            .max_by(|&a, &b| series(i)[a].total_cmp(&series(i)[b]))
            .unwrap_or(0);
        k as f64 / n as f64
    });
    let mut vertices: Sample = [f64::NEG_INFINITY; SERIES];
    for i in (0..SERIES).filter(|&i| refined[i]) {
        if let Some(k) = parabola_vertex(series(i)) {
            let sample = at(k);
            if sample[i] > largest[i] {
                largest[i] = sample[i];
                place[i] = k / n as f64;
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
        true => largest[i] - series(i)[0].max(series(i)[n]),
        false => 0.0,
    });
    Within {
        largest,
        rise,
        place,
        ends: [0, n].map(|k| std::array::from_fn(|i| series(i)[k])),
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
    /// The samples at the ends of the part sampled.
    pub(super) ends: [Sample; 2],
}

impl Default for Within {
    /// A step not sampled inside: no extreme, no rise.
    fn default() -> Self {
        Self {
            largest: [f64::NEG_INFINITY; SERIES],
            rise: [0.0; SERIES],
            place: [0.0; SERIES],
            ends: [[f64::NEG_INFINITY; SERIES]; 2],
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
        let within = largest_loads(&mut at, PEAK_SAMPLES + 1, refined);
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
