//! The peak-hold's sample at the end of the last accepted step, kept for the next step's first sample
//! inside ([`super::peaks::within_step`]), which it is wherever nothing it depends on changed.

use super::sample::{SERIES, Sample};
use super::step::StepPoint;
use crate::joint::Contacts;
use crate::math;
use crate::mechanism::{Conditions, InputSignal, Inputs};

/// The peak-hold sample at the end of the last accepted step with everything it is a function
/// of: the point (time, state, derivative), the inputs there (their values and the drive's
/// acceleration, what an evaluation reads of them: [`crate::mechanism::Conditions::at`]) and the
/// contact state it was taken with. The next step's first sample inside
/// ([`super::peaks::within_step`]) is this one wherever these are the same, bit for bit: the dense
/// output's first sample is the step's start exactly. (The next step's inputs are another
/// polynomial, written from its start, even where they are the same function of time.)
#[derive(Clone, Debug)]
pub(super) struct EndSample {
    point: StepPoint,
    inputs: Option<[f64; 6]>,
    contacts: Contacts,
    sample: Sample,
}

/// What an evaluation at `t` reads of the inputs `signal` ([`Conditions::at`]): their values and
/// the drive's acceleration.
fn read_at(signal: &InputSignal, t: f64) -> [f64; 6] {
    let contacts = Contacts::default();
    let c = Conditions::at(signal, t, &contacts);
    // (exhaustive: a new input is a compile error here)
    let Inputs {
        drive_speed,
        drive_torque,
        slider_force,
        oil_supply_temperature,
        oil_supply_pressure,
    } = c.inputs;
    [
        drive_speed,
        drive_torque,
        slider_force,
        oil_supply_temperature,
        oil_supply_pressure,
        c.drive_acceleration,
    ]
}

impl EndSample {
    /// No sample yet, for states of length `n`.
    pub(super) fn new(n: usize) -> Self {
        Self {
            point: StepPoint::at_rest(f64::NAN, &vec![0.0; n]),
            inputs: None,
            contacts: Contacts::default(),
            sample: [0.0; SERIES],
        }
    }

    /// The sample if it was taken at `point` with `signal` and `contacts`.
    pub(super) fn at(
        &self,
        point: &StepPoint,
        signal: &InputSignal,
        contacts: Contacts,
    ) -> Option<Sample> {
        let same_inputs = self
            .inputs
            .is_some_and(|u| math::same_bits(&u, &read_at(signal, point.time)));
        (same_inputs && self.contacts.same_bits(&contacts) && self.point.same_bits(point))
            .then_some(self.sample)
    }

    /// Keeps `sample`, taken at `point` with `signal` and `contacts` (None: a sample that a
    /// step's inside would not reproduce).
    pub(super) fn store(
        &mut self,
        point: &StepPoint,
        signal: &InputSignal,
        contacts: Contacts,
        sample: Option<Sample>,
    ) {
        self.inputs = sample.map(|_| read_at(signal, point.time));
        if let Some(sample) = sample {
            self.point.copy_from(point);
            self.contacts = contacts;
            self.sample = sample;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::joint::ContactState;

    /// The kept end sample is given back only for the point, inputs and contact state it was
    /// taken with, each bit for bit (a zero's sign included), the inputs as an evaluation there
    /// reads them (a polynomial written from another start gives the same), and not after a sample
    /// that a step's inside would not reproduce was stored in its place.
    #[test]
    fn the_end_sample_is_reused_only_where_it_was_taken() {
        let point = StepPoint {
            time: 1e-3,
            y: vec![0.1, -0.2, 0.3],
            f: vec![1.0, 2.0, 3.0],
        };
        let signal = InputSignal::held(Inputs {
            drive_speed: 523.6,
            ..Inputs::default()
        });
        let contacts = Contacts::default();
        let sample = [1.5; SERIES];
        let mut kept = EndSample::new(3);
        assert_eq!(kept.at(&point, &signal, contacts), None);
        kept.store(&point, &signal, contacts, Some(sample));
        assert_eq!(kept.at(&point, &signal, contacts), Some(sample));
        let mut moved = point.clone();
        moved.y[2] = f64::from_bits(0.3f64.to_bits() + 1);
        assert_eq!(kept.at(&moved, &signal, contacts), None);
        let mut later = point.clone();
        later.f[0] = 1.0 + f64::EPSILON;
        assert_eq!(kept.at(&later, &signal, contacts), None);
        let mut faster = signal;
        faster.value.drive_speed += 1e-9;
        assert_eq!(kept.at(&point, &faster, contacts), None);
        // The same inputs written from the point (the next step's polynomial) are the same there;
        // a drive speed that starts to ramp there is not.
        let rewritten = signal.continued_at(point.time);
        assert_ne!(rewritten.start, signal.start);
        assert_eq!(kept.at(&point, &rewritten, contacts), Some(sample));
        let mut ramped = rewritten;
        ramped.derivatives[0].drive_speed = 100.0;
        assert_eq!(kept.at(&point, &ramped, contacts), None);
        let mut touching = contacts;
        touching.0[2] = ContactState {
            in_contact: true,
            ..touching.0[2]
        };
        assert_eq!(kept.at(&point, &signal, touching), None);
        // A zero's sign tells apart what == holds equal.
        let mut at_zero = point.clone();
        at_zero.y[0] = 0.0;
        kept.store(&at_zero, &signal, contacts, Some(sample));
        assert_eq!(kept.at(&at_zero, &signal, contacts), Some(sample));
        let mut negative_zero = at_zero.clone();
        negative_zero.y[0] = -0.0;
        assert_eq!(kept.at(&negative_zero, &signal, contacts), None);
        // An input held at −0 reads +0 there (u + u̇τ), as the evaluation reads it.
        let mut reversed = signal;
        reversed.value.slider_force = -0.0;
        assert_eq!(kept.at(&at_zero, &reversed, contacts), Some(sample));
        kept.store(&point, &signal, contacts, None);
        assert_eq!(kept.at(&point, &signal, contacts), None);
    }
}
