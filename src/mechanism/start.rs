//! The mechanism's initial state: the ideal mechanism's motion with a straight rod, and the
//! quasi-static start that deforms the rod by the inertial loads of that motion.

use nalgebra::Vector2;

use super::inputs::{Conditions, Inputs};
use super::layout::{CRANK_ANGLE, PIN_A, pair};
use super::slider_crank::SliderCrank;
use crate::error::{ModelError, Num};
use crate::joint::{ContactState, Contacts, JointRole, MIN_IMPACT_VELOCITY};
use crate::linalg::lu::Lu;
use crate::math;

/// A joint's reaction in the ideal mechanism's start, and the rotation speeds of its journal and
/// bearing ([`SliderCrank::start_reactions`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reaction {
    /// Force on the journal \[N\].
    pub force: Vector2<f64>,
    /// The journal's rotation speed \[rad/s\].
    pub omega_journal: f64,
    /// The bearing's rotation speed \[rad/s\].
    pub omega_bearing: f64,
    /// The unit axis of the body the joint's feed sits in (x̂ without a feed).
    pub feed_axis: Vector2<f64>,
}

impl SliderCrank {
    /// Initial state: crank at `angle` turning at `speed`, rod straight and unstressed, journals
    /// centred, every velocity that of the ideal mechanism (docs/model.md §7).
    pub fn initial_state(&self, angle: f64, speed: f64) -> Vec<f64> {
        self.initial_state_with_eccentricities(angle, speed, [Vector2::zeros(); 3])
    }

    /// As [`SliderCrank::initial_state`] with each joint's journal at its eccentricity in `e`
    /// (indexed by [`JointRole`]) and at rest in its bearing: the crank's pivot at e_O from the
    /// main bearing's centre, the rod's eye A at e_P from the crank pin, the rod's slider end at
    /// height e_y,B, moving along the guide with the slider.
    pub fn initial_state_with_eccentricities(
        &self,
        angle: f64,
        speed: f64,
        e: [Vector2<f64>; 3],
    ) -> Vec<f64> {
        let [pivot, crank_pin, rod_slider] = e;
        let (r_c, l) = (self.crank.length, self.rod_data.length);
        let (sin, cos) = math::sin_cos(angle);
        let a = r_c * Vector2::new(cos, sin) + (pivot - crank_pin);
        let sin_beta = (self.slider.offset + rod_slider.y - a.y) / l;
        let cos_beta = (1.0 - sin_beta * sin_beta).sqrt();
        let b = a + l * Vector2::new(cos_beta, sin_beta);
        let v_a = r_c * speed * Vector2::new(-sin, cos);
        let beta_dot = -r_c * speed * cos / (l * cos_beta);
        let v_b = v_a + l * beta_dot * Vector2::new(-sin_beta, cos_beta);
        let (p, p_dot) = (self.rod.straight(a, b), self.rod.straight(v_a, v_b));
        let l = self.layout;
        let mut y = vec![0.0; l.n_states()];
        y[CRANK_ANGLE] = angle;
        y[l.rod()].copy_from_slice(&p);
        y[l.slider()] = b.x - rod_slider.x;
        y[l.crank_speed()] = speed;
        y[l.rod_rates()].copy_from_slice(&p_dot);
        y[l.slider_velocity()] = v_b.x;
        if let Some(g) = l.crank_centre() {
            // A free crank turning about its pivot, at rest in the main bearing.
            let a = self.crank.centre;
            y[g] = pivot.x + a * cos;
            y[g + 1] = pivot.y + a * sin;
            y[l.rate_of(g)] = -a * speed * sin;
            y[l.rate_of(g) + 1] = a * speed * cos;
        }
        y[l.drive_angle()] = angle;
        for role in JointRole::ALL {
            if let Some(i) = self.temperature[role as usize] {
                y[i] = self.start_temperatures[role as usize];
            }
        }
        y
    }

    /// The oil's viscosity at the film temperature the joint `role` starts at, where its heat
    /// balance sets it \[Pa s\].
    fn start_viscosity(&self, role: JointRole) -> Option<f64> {
        let balance = self.joint(role).heat_balance()?;
        Some(
            balance
                .oil
                .viscosity(self.start_temperatures[role as usize]),
        )
    }

    /// Sets the film temperature each joint with a heat balance starts at: that of the steady heat
    /// balance ([`crate::joint::Joint::settled_temperature`]) against the start reaction in
    /// `reactions` where one is given (the settled thermal start), else the oil's supply
    /// temperature, the oil supplied at `inputs`' temperature and pressure. Fails, naming the
    /// joint, where no steady balance exists.
    pub fn settle_temperatures(
        &mut self,
        reactions: [Option<Reaction>; 3],
        inputs: &Inputs,
    ) -> Result<(), ModelError> {
        let supply = inputs.oil_supply_temperature;
        for role in JointRole::ALL {
            let i = role as usize;
            self.start_temperatures[i] = match reactions[i] {
                Some(r) if self.temperature[i].is_some() => self
                    .joint(role)
                    .settled_temperature(
                        r.force,
                        (r.omega_journal, r.omega_bearing),
                        (supply, inputs.oil_supply_pressure),
                        r.feed_axis,
                    )
                    .ok_or_else(|| {
                        ModelError::Numerical(format!(
                            "{}: no steady heat balance at the start: no film temperature up to \
                             1000 K above the supply carries its friction power away (give it \
                             an oil flow or {}.heatTransferCoefficient, or start it at the \
                             supply temperature, {}.thermalStart = supply)",
                            role.prefix(),
                            role.prefix(),
                            role.prefix()
                        ))
                    })?,
                _ => supply,
            };
        }
        Ok(())
    }

    /// The start reactions of this mechanism, with every joint ideal: its state at `angle` and
    /// `speed` under the inputs `inputs` (equilibrated with `equilibrate`), and there the force
    /// on each journal, indexed by [`JointRole`] (the main bearing's and the crank pin's from the
    /// loads, the rod–slider joint's its reaction), with the journal's and the bearing's rotation
    /// speeds.
    pub fn start_reactions(
        &mut self,
        (angle, speed): (f64, f64),
        inputs: Inputs,
        equilibrate: bool,
    ) -> Result<[Reaction; 3], ModelError> {
        let mut y = self.initial_state(angle, speed);
        let contacts = Contacts::default();
        if equilibrate {
            self.equilibrate(&mut y, inputs, &contacts)?;
        }
        let mut dy = vec![0.0; y.len()];
        let c = Conditions::held(inputs, &contacts);
        let force = self.evaluate(&y, &c, &mut dy)?.joint_force;
        let loads = self.loads(&y, &dy, force, &contacts);
        let forces = [loads.main_bearing, -loads.crank_pin, force];
        Ok(JointRole::ALL.map(|role| {
            let kin = self.joint_kinematics(role, &y);
            Reaction {
                force: forces[role as usize],
                omega_journal: kin.omega_journal,
                omega_bearing: kin.omega_bearing,
                feed_axis: self.feed_axis(role, &y),
            }
        }))
    }

    /// Settled start: places the journal of each clearance joint whose reaction is given in
    /// `reactions` (from [`SliderCrank::start_reactions`] of the ideal mechanism) at its
    /// quasi-static equilibrium against it ([`crate::joint::Joint::eccentricity_carrying`]), at rest relative to
    /// the bearing, the others centred, and equilibrates a flexible rod with the joints' own
    /// forces (with `equilibrate`; the rod stays straight otherwise): the mechanism then starts
    /// carrying its load, without the start-up impact of a centred journal. A journal in contact
    /// starts a contact event whose impact velocity is that of a journal crossing the clearance
    /// from the centre under the load (docs/model.md §8). The state, under the inputs `inputs`,
    /// and the joints' contact states.
    pub fn settle_journals(
        &mut self,
        (angle, speed): (f64, f64),
        inputs: Inputs,
        reactions: [Option<Reaction>; 3],
        equilibrate: bool,
    ) -> Result<(Vec<f64>, Contacts), ModelError> {
        let e = JointRole::ALL.map(|role| match reactions[role as usize] {
            Some(r) => self.joint(role).eccentricity_carrying(
                r.force,
                (r.omega_journal, r.omega_bearing),
                self.start_viscosity(role),
            ),
            None => Vector2::zeros(),
        });
        let mut y = self.initial_state_with_eccentricities(angle, speed, e);
        let mut contacts = Contacts::default();
        for role in JointRole::ALL {
            let (Some(reaction), Some(dry)) =
                (reactions[role as usize], self.joint(role).dry_contact())
            else {
                continue;
            };
            // The contact event's impact velocity: the speed of a journal crossing the clearance
            // from the centre under the load, √(2 |F₀| c / m), m the mass the joint's load moves
            // (the slider, the rod, the crank). The contact is then damped as after the centred
            // start's first impact; the floor instead would make its hysteresis damping some
            // fifty times critical and the force hypersensitive to the normal velocity.
            let mass = match role {
                JointRole::RodSlider => self.slider.mass,
                JointRole::CrankPin => self.rod_data.mass,
                JointRole::MainBearing => self.crank.mass,
            };
            let crossing = (2.0 * reaction.force.norm() * dry.clearance / mass).sqrt();
            contacts[role] = ContactState {
                in_contact: self.penetration(role, &y) > 0.0,
                impact_velocity: crossing.max(MIN_IMPACT_VELOCITY),
            };
        }
        if equilibrate {
            self.equilibrate(&mut y, inputs, &contacts)?;
        }
        Ok((y, contacts))
    }

    /// Quasi-static start: changes the rod's deformation in a state from
    /// [`SliderCrank::initial_state`] so that the deformation has no acceleration.
    ///
    /// Unknowns: the rod's deviation d = p_o − Π_o(r_A, r_B) of its coordinates other than the pin
    /// positions from the straight rod through its pins (Π, [`super::rod_body::RodBody::straight`], linear), and
    /// a shift Δ of the slider end along the guide (r_B and x_s together: the journal stays
    /// centred, an ideal joint stays closed). Equations, with every velocity unchanged:
    /// ```text
    /// d̈ = p̈_o − Π_o(r̈_A, r̈_B) = 0                 (the rod accelerates as a straight rod)
    /// σ̈ = (r̈_B − r̈_A)·t + |ṙ_B − ṙ_A|²/|r_B − r_A| − ((ṙ_B − ṙ_A)·t)²/|r_B − r_A| = 0
    /// ```
    /// (σ = |r_B − r_A|, t its direction: no stretching acceleration). Solved by Newton with a
    /// finite-difference Jacobian. The rod then starts loaded by the inertial forces of the motion
    /// (and gravity) instead of unstressed, and does not ring at its axial and bending frequencies
    /// from t = 0. The rigid rod has no deformation: the state is left as it is.
    pub fn equilibrate(
        &mut self,
        y: &mut [f64],
        inputs: Inputs,
        contacts: &Contacts,
    ) -> Result<(), ModelError> {
        let c = Conditions::held(inputs, contacts);
        if self.rod.rigid_length().is_some() {
            return Ok(());
        }
        let l = self.layout;
        let e = self.rod.end_offset();
        let others: Vec<usize> = (0..l.rod().len())
            .filter(|&i| ![0, 1, e, e + 1].contains(&i))
            .collect();
        let m = others.len() + 1;
        let base = y.to_vec();
        let scales = self.error_scales().absolute;
        // The error-control unit of unknown j: its rod coordinate's, or the slider's for Δ.
        let unit = |j: usize| match others.get(j) {
            Some(&i) => scales[l.rod_coordinate(i)],
            None => scales[l.slider()],
        };
        let mut u = vec![0.0; m];
        let mut residual = vec![0.0; m];
        let mut shifted = vec![0.0; m];
        let mut jacobian = Lu::new(m);
        let mut dy = vec![0.0; y.len()];
        let mut first_norm = f64::NAN;
        for _ in 0..30 {
            self.quasi_static_residual((&base, &others), &u, &c, y, &mut dy, &mut residual)?;
            let norm = residual.iter().map(|r| r * r).sum::<f64>().sqrt();
            if first_norm.is_nan() {
                first_norm = norm;
            }
            // 1e-7 of the initial residual: below the round-off of the finite-difference Jacobian
            // of a 64-element rod, far below any acceleration the start could excite.
            if norm <= 1e-7 * first_norm || norm == 0.0 {
                return Ok(());
            }
            for j in 0..m {
                let scale = unit(j);
                // At least 1e-4 of the rod's own scale: a tiny clearance (joint length scale
                // below 1e-4 of the rod length) must not shrink the differences to round-off.
                let floor =
                    (1e-4 * self.rod_data.length / self.error_control.position_scale).max(1.0);
                let delta = 1e-7 * (u[j].abs() + scale * floor);
                let mut perturbed = u.clone();
                perturbed[j] += delta;
                self.quasi_static_residual(
                    (&base, &others),
                    &perturbed,
                    &c,
                    y,
                    &mut dy,
                    &mut shifted,
                )?;
                for i in 0..m {
                    jacobian.matrix_mut()[j * m + i] = (shifted[i] - residual[i]) / delta;
                }
            }
            jacobian.factorize()?;
            jacobian.solve(&mut residual);
            let mut largest_update = 0.0f64;
            for (j, (ui, ri)) in u.iter_mut().zip(&residual).enumerate() {
                *ui -= ri;
                largest_update = largest_update.max(ri.abs() / unit(j));
            }
            // An update of 1e-9 of the error-control unit: the residual is at its round-off floor
            // (a start from rest, whose straight rod is already in equilibrium).
            if largest_update <= 1e-9 {
                self.quasi_static_residual((&base, &others), &u, &c, y, &mut dy, &mut residual)?;
                return Ok(());
            }
        }
        self.quasi_static_residual((&base, &others), &u, &c, y, &mut dy, &mut residual)?;
        Err(ModelError::Numerical(format!(
            "Newton did not converge (residual {} of {})",
            Num(residual.iter().map(|r| r * r).sum::<f64>().sqrt()),
            Num(first_norm)
        )))
    }

    /// Writes the state of the quasi-static unknowns `u` = [d, Δ] (on the straight state `base`)
    /// to `y` and the residual [d̈, σ̈] under the conditions `c` to `out`.
    fn quasi_static_residual(
        &mut self,
        (base, others): (&[f64], &[usize]),
        u: &[f64],
        c: &Conditions,
        y: &mut [f64],
        dy: &mut [f64],
        out: &mut [f64],
    ) -> Result<(), ModelError> {
        let l = self.layout;
        let pin_b = l.pin_b();
        let shift = u[others.len()];
        y.copy_from_slice(base);
        y[pin_b] += shift;
        y[l.slider()] += shift;
        let (a, b) = (pair(y, PIN_A), pair(y, pin_b));
        let straight = self.rod.straight(a, b);
        for (k, &i) in others.iter().enumerate() {
            y[l.rod_coordinate(i)] = straight[i] + u[k];
        }
        self.evaluate(y, c, dy)?;
        let (acc_a, acc_b) = (pair(dy, l.rate_of(PIN_A)), pair(dy, l.rate_of(pin_b)));
        let straight_acc = self.rod.straight(acc_a, acc_b);
        for (k, &i) in others.iter().enumerate() {
            out[k] = dy[l.rod_rate(i)] - straight_acc[i];
        }
        let chord = b - a;
        let t = chord / chord.norm();
        let rate = pair(y, l.rate_of(pin_b)) - pair(y, l.rate_of(PIN_A));
        out[others.len()] =
            (acc_b - acc_a).dot(&t) + (rate.norm_squared() - rate.dot(&t).powi(2)) / chord.norm();
        Ok(())
    }
}
