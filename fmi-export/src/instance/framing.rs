//! The framing of an instance's serialized state: magic, format version, the state machine's
//! state, the clock, the inputs, the model's own bytes, and a checksum of all of them.

use super::Instance;
use crate::codec::{ByteReader, ByteWriter};
use crate::error::FmuError;
use crate::experiment::Clock;
use crate::model::{Context, Model};
use crate::signal::{InputRecord, InputValues};
use crate::state::State;

/// The states in the order of their byte in a serialized state.
const STATES: [State; 7] = [
    State::Instantiated,
    State::InitializationMode,
    State::StepComplete,
    State::StepFailed,
    State::Terminated,
    State::Error,
    State::EventMode,
];

/// The checksum that ends a serialized state: FNV-1a 64 of every byte before it.
pub fn state_checksum(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3)
    })
}

impl<M: Model> Instance<M> {
    /// The serialized state: magic, version, state machine, clock, inputs, the model's bytes,
    /// and an FNV-1a 64 checksum of everything before it (a corrupted byte is rejected, never
    /// restored).
    pub fn serialize(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(1024);
        out.extend_from_slice(&M::STATE_MAGIC);
        out.extend_from_slice(&M::STATE_VERSION.to_le_bytes());
        out.push(
            STATES
                .iter()
                .position(|s| *s == self.machine.state())
                .unwrap_or(0) as u8,
        );
        self.clock.write(&mut ByteWriter(&mut out));
        self.inputs.write(&mut ByteWriter(&mut out));
        self.model.save(&mut out);
        let checksum = state_checksum(&out);
        out.extend_from_slice(&checksum.to_le_bytes());
        out
    }

    /// Checks a serialized state and, if `apply`, resumes from it (state machine included).
    pub fn deserialize(&mut self, bytes: &[u8], apply: bool) -> Result<(), FmuError> {
        let bad = |what: String| FmuError::Invalid(format!("FMU state rejected: {what}"));
        if bytes.len() < 4 + 4 + 1 + 8 {
            return Err(bad(format!("{} bytes is too short", bytes.len())));
        }
        let (body, tail) = bytes.split_at(bytes.len() - 8);
        let mut sum = [0; 8];
        sum.copy_from_slice(tail);
        if state_checksum(body) != u64::from_le_bytes(sum) {
            return Err(bad("checksum mismatch (corrupted bytes)".into()));
        }
        if body[..4] != M::STATE_MAGIC {
            return Err(bad("wrong magic (not a state of this FMU)".into()));
        }
        let mut version = [0; 4];
        version.copy_from_slice(&body[4..8]);
        let version = u32::from_le_bytes(version);
        if version != M::STATE_VERSION {
            return Err(bad(format!(
                "format version {version}, expected {}",
                M::STATE_VERSION
            )));
        }
        let saved = *STATES
            .get(usize::from(body[8]))
            .ok_or_else(|| bad("invalid state".into()))?;
        let mut reader = ByteReader::new(&body[9..]);
        let clock = Clock::read(&mut reader)?;
        let inputs = InputRecord::<M::Inputs>::read(&mut reader)?;
        if !inputs.is_finite() {
            return Err(bad("a non-finite input or input derivative".into()));
        }
        for (k, v) in Self::input_variables().enumerate().take(M::Inputs::LEN) {
            crate::checks::check_real(v, inputs.stepping().value.value(k))
                .map_err(|e| bad(e.to_string()))?;
        }
        let model = &body[body.len() - reader.remaining()..];
        let cx = Context {
            log: &self.logger,
            inputs: &inputs,
            experiment: clock.experiment,
            time: clock.now(),
        };
        self.model.load(&cx, model, apply)?;
        if apply {
            self.machine.restore(saved);
            self.clock = clock;
            self.inputs = inputs;
        }
        Ok(())
    }
}
