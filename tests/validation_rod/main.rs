//! Validation of the ANCF rod and its Craig–Bampton reduction against results no one here wrote:
//! rigid-body invariance, Euler–Bernoulli deflections and frequencies, the elastica, and the
//! exactness properties of component mode synthesis.

// Test code: a failed unwrap is a failed test, with its message.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod beam;
mod common;
mod reduction;
