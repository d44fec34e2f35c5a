//! Validity monitors: limits beyond which the model has left the domain its laws were made for.
//! Each cause is reported once per simulation, as a message for the FMU's logger
//! ([`super::Simulation::take_warnings`]).

use crate::error::Num;
use crate::joint::{Elastic, Joint, JointField, JointRole};
use crate::mechanism::SliderCrank;
use crate::params::{JointModel, Parameters, RodFormulation};

/// Largest contact penetration, as a fraction of the journal radius: Hertz theory assumes a
/// contact zone small against the radii.
pub const PENETRATION_PER_RADIUS: f64 = 0.01;
/// Largest rod mid-span deflection, as a fraction of the rod length: beyond it a reduced
/// (Craig–Bampton) rod leaves the small-deformation range of its modes.
pub const DEFLECTION_PER_LENGTH: f64 = 0.05;
/// Largest crank speed \[rad/s\]: 1 % beyond the range of `drive.speed` (±1e4 rad/s), so that
/// a speed drive at its limit stays silent.
pub const CRANK_SPEED: f64 = 1.01e4;
/// Largest excursion of the slider beyond its rigid-mechanism stroke
/// [√((l − r)² − e²) − c, √((l + r)² − e²) + c] (e: the slider offset), as a fraction of the crank
/// length.
pub const STROKE_EXCESS_PER_CRANK: f64 = 0.01;
/// Shortest time constant of a film temperature, C/(2 ρ c_p Q + k), in units of
/// `solver.maxStepSize`: the heat balance is integrated with the motion's steps, as a slow state
/// (its rate taken at each stage, not solved for), and wants many steps per time constant.
pub const THERMAL_STEPS: f64 = 10.0;

/// The warnings of a simulation: which validity limits were already crossed, the messages not
/// yet taken, and the count since the start.
#[derive(Clone, Debug, Default)]
pub(super) struct Monitor {
    fired: [bool; 6],
    /// Whether a joint's force peak was reported as resting on the interpolant, by role.
    doubted: [bool; 3],
    /// Such a report not yet taken (time, interpolated peak, integrated value), by role: the
    /// message is written when it is taken, so that stepping allocates nothing.
    doubts: [Option<(f64, f64, f64)>; 3],
    /// A lubricated joint's dry-contact onsets not yet reported (the first one's time and how
    /// many), by role: written when taken, as the doubts are.
    metal: [Option<(f64, u64)>; 3],
    messages: Vec<String>,
    /// Warnings raised since the start.
    pub(super) total: u64,
}

impl Monitor {
    /// Records a warning.
    pub(super) fn warn(&mut self, message: String) {
        self.messages.push(message);
        self.total += 1;
    }

    /// Warns, once per joint, that a force peak `value` at the joint `role` inside a step, at
    /// time `t`, differs from the integrator's own solution there, `integrated`, by more than the
    /// accuracy its peaks are held to.
    pub(super) fn doubt_peak(&mut self, role: JointRole, t: f64, value: f64, integrated: f64) {
        if !std::mem::replace(&mut self.doubted[role as usize], true) {
            self.doubts[role as usize] = Some((t, value, integrated));
            self.total += 1;
        }
    }

    /// Warns that the lubricated joint `role` went into dry metal contact at time `t` (every
    /// onset counts).
    pub(super) fn metal_contact(&mut self, role: JointRole, t: f64) {
        let pending = &mut self.metal[role as usize];
        *pending = Some(pending.map_or((t, 1), |(first, n)| (first, n + 1)));
        self.total += 1;
    }

    /// The warnings raised since the last call.
    pub(super) fn take(&mut self) -> Vec<String> {
        for (role, pending) in JointRole::ALL.into_iter().zip(&mut self.metal) {
            let Some((t, onsets)) = pending.take() else {
                continue;
            };
            let more = match onsets {
                1 => String::new(),
                n => format!(" ({n} onsets since the last report)"),
            };
            self.messages.push(format!(
                "t = {} s: the lubricated joint {} went into dry metal contact{more}: neither the \
                 film nor the asperities carried its load there ({}.penetration > 0; see \
                 {}.metalContactFractionCycle)",
                Num(t),
                role.prefix(),
                role.prefix(),
                role.prefix(),
            ));
        }
        for (role, doubt) in JointRole::ALL.into_iter().zip(&mut self.doubts) {
            let Some((t, value, integrated)) = doubt.take() else {
                continue;
            };
            self.messages.push(format!(
                "t = {} s: {}.forcePeak holds {} N from the interpolant between two internal \
                 steps, where the integrator's own solution gives {} N: that peak is {} % off, \
                 and others of the run may be; a smaller solver.relativeTolerance or \
                 solver.maxStepSize resolves them",
                Num(t),
                role.prefix(),
                Num(value),
                Num(integrated),
                Num((1000.0 * (value - integrated).abs() / value).round() / 10.0),
            ));
        }
        std::mem::take(&mut self.messages)
    }

    /// Checks the state `y` at time `t` (the end of an accepted step, or the state at a
    /// communication point, which the outputs show) against the limits; each cause warns once.
    pub(super) fn check(&mut self, p: &Parameters, mechanism: &mut SliderCrank, t: f64, y: &[f64]) {
        let layout = mechanism.layout();
        let elastic = |role: JointRole| mechanism.joint(role).dry_contact().map(|d| d.elastic);
        // The point contact deepest into its wall, relative to its journal's radius.
        let (role, penetration) = JointRole::ALL
            .into_iter()
            .filter(|&role| matches!(elastic(role), Some(Elastic::Point(_))))
            .map(|role| (role, mechanism.penetration(role, y)))
            .max_by(|a, b| {
                let ratio = |(role, d): (JointRole, f64)| d / p.joint(role).journal_radius;
                ratio(*a).total_cmp(&ratio(*b))
            })
            .unwrap_or((JointRole::RodSlider, f64::NEG_INFINITY));
        let radius = p.joint(role).journal_radius;
        // A line contact beyond the range of Johnson's law.
        let beyond = JointRole::ALL
            .into_iter()
            .find_map(|role| match elastic(role) {
                Some(Elastic::Cylinder(line)) => {
                    let (limit, _) = line.limit();
                    let depth = mechanism.penetration(role, y);
                    (depth > limit).then_some((role, depth, limit))
                }
                _ => None,
            });
        // The crank's joints widen the stroke by their clearances.
        let crank_gaps: f64 = [JointRole::MainBearing, JointRole::CrankPin]
            .map(|role| match p.joint(role).model {
                JointModel::Ideal => 0.0,
                _ => p.joint(role).clearance,
            })
            .iter()
            .sum();
        let (r_c, l, c) = (p.crank_length, p.rod.length, p.joint.clearance + crank_gaps);
        // The rigid mechanism's stroke: its dead centres at √((l ∓ r)² − e²).
        let e = p.slider_offset;
        let (inner, outer) = (
            ((l - r_c) * (l - r_c) - e * e).sqrt() - c,
            ((l + r_c) * (l + r_c) - e * e).sqrt() + c,
        );
        let x = y[layout.slider()];
        let excess = (inner - x).max(x - outer);
        let speed = y[layout.crank_speed()];
        let deflection = if p.rod_formulation == RodFormulation::Rigid {
            0.0
        } else {
            mechanism.midspan_deflection(y)
        };
        // The film temperature with the shortest time constant, against the step.
        let thermal = JointRole::ALL
            .into_iter()
            .filter_map(|role| {
                let Joint::Lubricated(bearing) = mechanism.joint(role) else {
                    return None;
                };
                let balance = bearing.heat_balance.as_ref()?;
                let flow = bearing.side_flow(&mechanism.joint_kinematics(role, y));
                let conductance = 2.0 * balance.oil.volumetric_heat() * flow + balance.conductance;
                Some((role, balance.capacity / conductance))
            })
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .filter(|(_, tau)| *tau < THERMAL_STEPS * p.max_step_size);
        let left = [
            penetration > PENETRATION_PER_RADIUS * radius,
            deflection.abs() > DEFLECTION_PER_LENGTH * l,
            speed.abs() > CRANK_SPEED,
            excess > STROKE_EXCESS_PER_CRANK * r_c,
            beyond.is_some(),
            thermal.is_some(),
        ];
        for (i, &left) in left.iter().enumerate() {
            if !left || self.fired[i] {
                continue;
            }
            self.fired[i] = true;
            let message = match i {
                0 => format!(
                    "{} penetration {} m exceeds {} % of {} = {} m (Hertz contact assumes a \
                     small contact zone)",
                    role.prefix(),
                    Num(penetration),
                    Num(100.0 * PENETRATION_PER_RADIUS),
                    role.parameter(JointField::JournalRadius),
                    Num(radius)
                ),
                1 => format!(
                    "rod mid-span deflection {} m exceeds {} % of rod.length = {} m",
                    Num(deflection),
                    Num(100.0 * DEFLECTION_PER_LENGTH),
                    Num(l)
                ),
                2 => format!(
                    "crank speed {} rad/s is more than 1 % beyond the drive's range ±1e4 rad/s",
                    Num(speed)
                ),
                3 => format!(
                    "slider position {} m is {} m beyond its kinematic stroke [{}, {}] m",
                    Num(x),
                    Num(excess),
                    Num(inner),
                    Num(outer)
                ),
                5 => {
                    let (role, tau) = thermal.unwrap_or((role, 0.0));
                    format!(
                        "{}'s film temperature follows its heat balance with a time constant of \
                         {} s, shorter than {} solver.maxStepSize = {} s: the heat balance is \
                         integrated as a slow state, and its temperature is then unreliable; \
                         raise {}.heatCapacity (a film with the near-surface metal of journal and \
                         shell holds 1-100 J/K)",
                        role.prefix(),
                        Num(tau),
                        Num(THERMAL_STEPS),
                        Num(p.max_step_size),
                        role.prefix(),
                    )
                }
                _ => {
                    let (role, depth, limit) = beyond.unwrap_or((role, 0.0, 0.0));
                    format!(
                        "{} penetration {} m is beyond the line contact's range {} m (0.40 {}): \
                         the force continues along the law's tangent there",
                        role.prefix(),
                        Num(depth),
                        Num(limit),
                        role.parameter(JointField::Clearance)
                    )
                }
            };
            self.warn(format!(
                "t = {} s: the model left its domain: {message}",
                Num(t)
            ));
        }
    }
}
