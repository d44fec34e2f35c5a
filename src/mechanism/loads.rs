//! The loads parts are sized from: the force at every joint, the guide's normal force, the rod's
//! axial force at its pins and its largest normal stress.
//!
//! ```text
//! crank pin     F_A = m_rod a_G,rod − F_B − m_rod g          (the rod's linear momentum)
//! main bearing  F_O = m_c a_G,crank + F_A − m_c g             (the crank's)
//! guide         N   = F_B,y − m_s g_y                         (the slider's y equation)
//! axial force   N_A = −F_A · t_A,   N_B = F_B · t_B           (tension positive)
//! ```
//! with F_B the joint force on the journal (on the rod's slider end), F_A the force of the crank on
//! the rod, t_A, t_B the rod's unit tangents at its ends (crank → slider), and m_rod a_G,rod =
//! Σ_j (M t)_j p̈_j for the rigid translations t of the rod's coordinates: the rod's internal forces
//! cancel in its momentum (they are invariant under translation), so the pin force follows from
//! the accelerations alone, without the constraint solve, and the same formula serves the
//! accelerations of an evaluation and those of the dense output inside a step. A worn crank pin or
//! main bearing gives its force by its joint law instead (F_A = −F, F_O = F, with F the force on
//! the journal), exact in every state, as the rod–slider joint's is.
//!
//! The stress: from the equilibrium of the rod's parts under the pin force (and a worn crank
//! pin's moment) and the distributed inertia and gravity (d'Alembert): for a flexible rod by
//! quadrature over its elements ([`crate::ancf::Rod::normal_stresses`]), for the rigid rod in
//! closed form ([`rigid_rod_stress`]).
//!
//! With masses lumped at the pins (the rod's eyes, m_A and m_B) the pin forces move them too: the
//! rod's shank receives F_A − m_A (a_A − g) at A and F_B − m_B (a_B − g) at B, which set the axial
//! forces at the pins and the rigid rod's stress (the eyes are not beam material).

use nalgebra::Vector2;

use super::layout::{CRANK_ANGLE, PIN_A, pair};
use super::rod_body::RodBody;
use super::slider_crank::SliderCrank;
use crate::ancf::RodLoad;
use crate::ancf::{NormalStresses, RodProperties, SectionResult, section_place};
use crate::joint::{Contacts, JointRole};
use crate::math;
use crate::reduction::Deformation;

/// Loads of one instant (SI units).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Loads {
    /// Force of the crank on the rod at the crank pin \[N\].
    pub crank_pin: Vector2<f64>,
    /// Force of the ground on the crank at the main bearing (the crank pivot) \[N\].
    pub main_bearing: Vector2<f64>,
    /// Normal force of the guide on the slider, along y \[N\].
    pub guide: f64,
    /// The rod's axial force at the crank pin and at the slider pin, tension positive \[N\].
    pub axial: [f64; 2],
    /// The rod's normal stresses: the largest magnitude |N|/A + |M| c/I, the most tensile and
    /// the most compressive fibre's, where the largest lies, and the mid-span section's axial
    /// force and bending moment.
    pub stress: NormalStresses,
    /// The rod's strain energy \[J\].
    pub deformation_energy: f64,
}

impl SliderCrank {
    /// The loads of state `y` whose time derivative is `dy` (only its accelerations are read),
    /// with `joint_force` the rod–slider joint's force on the journal and `contacts` the contact
    /// states.
    pub fn loads(
        &mut self,
        y: &[f64],
        dy: &[f64],
        joint_force: Vector2<f64>,
        contacts: &Contacts,
    ) -> Loads {
        let l = self.layout;
        let (crank_pin, pin_moment) = self.crank_pin_load(y, dy, joint_force, contacts);
        let crank_centre_acceleration = match l.crank_centre() {
            Some(g) => pair(dy, l.rate_of(g)),
            None => {
                let (theta, omega) = (y[CRANK_ANGLE], y[l.crank_speed()]);
                let alpha = dy[l.crank_speed()];
                let (sin, cos) = math::sin_cos(theta);
                self.crank.centre
                    * (alpha * Vector2::new(-sin, cos) - omega * omega * Vector2::new(cos, sin))
            }
        };
        let main_bearing = if self.has_clearance(JointRole::MainBearing) {
            self.joint_force(JointRole::MainBearing, y, contacts)
                .0
                .force
        } else {
            self.crank.mass * crank_centre_acceleration + crank_pin - self.crank.mass * self.gravity
        };
        let load = self.rod_load(dy, (crank_pin, pin_moment), joint_force);
        let deformation = match &mut self.rod {
            RodBody::Rigid { .. } => {
                let (r_a, r_b) = (pair(y, PIN_A), pair(y, l.pin_b()));
                let t = (r_b - r_a).normalize();
                let accelerations = [pair(dy, l.rate_of(PIN_A)), pair(dy, l.rate_of(l.pin_b()))];
                Deformation {
                    energy: 0.0,
                    stresses: rigid_rod_stress(&self.rod_data.section, t, accelerations, &load),
                    tangents: [t, t],
                }
            }
            RodBody::Flexible(model) => model.deformation(&y[l.rod()], &dy[l.rod_rates()], &load),
        };
        let [t_a, t_b] = deformation.tangents;
        let [shank_a, shank_b] = self.shank_forces(dy, crank_pin, joint_force);
        Loads {
            crank_pin,
            main_bearing,
            guide: joint_force.y - self.slider.mass * self.gravity.y,
            axial: [-shank_a.dot(&t_a), shank_b.dot(&t_b)],
            stress: deformation.stresses,
            deformation_energy: deformation.energy,
        }
    }
}

impl SliderCrank {
    /// The rod's `result` at `out.len()` evenly spaced sections from the crank pin to the slider
    /// pin ([`section_place`]) in state `y` whose time derivative is `dy` (only its accelerations
    /// are read), with `joint_force` the rod–slider joint's force on the journal and `contacts`
    /// the contact states: the deflection from the flexible rod's shape, the resultants from the
    /// equilibrium of the rod's parts ([`crate::ancf::Rod::sections`], [`RigidRodResultants`];
    /// the rigid rod has no deflection).
    pub fn rod_sections(
        &mut self,
        y: &[f64],
        dy: &[f64],
        (joint_force, contacts): (Vector2<f64>, &Contacts),
        result: SectionResult,
        out: &mut [f64],
    ) {
        let l = self.layout;
        let crank_pin = self.crank_pin_load(y, dy, joint_force, contacts);
        let load = self.rod_load(dy, crank_pin, joint_force);
        if let RodBody::Flexible(model) = &mut self.rod {
            model.sections(&y[l.rod()], &dy[l.rod_rates()], &load, result, out);
            return;
        }
        if result == SectionResult::Deflection {
            out.fill(0.0);
            return;
        }
        let t = (pair(y, l.pin_b()) - pair(y, PIN_A)).normalize();
        let accelerations = [pair(dy, l.rate_of(PIN_A)), pair(dy, l.rate_of(l.pin_b()))];
        let section = &self.rod_data.section;
        let r = RigidRodResultants::new(section, t, accelerations, &load);
        let n = out.len();
        for (k, value) in out.iter_mut().enumerate() {
            let s = section_place(k, n) * section.length;
            *value = match result {
                SectionResult::AxialForce => r.axial(s),
                _ => r.moment(s),
            };
        }
    }

    /// The force of the crank on the rod at the crank pin in state `y` with time derivative `dy`,
    /// from the rod's momentum or from a worn crank pin's joint law, and the worn pin's moment on
    /// the rod's eye (its film's or contact's friction and the force's lever about the eye's
    /// centre; 0 for an ideal pin), from one evaluation of the joint law.
    fn crank_pin_load(
        &mut self,
        y: &[f64],
        dy: &[f64],
        joint_force: Vector2<f64>,
        contacts: &Contacts,
    ) -> (Vector2<f64>, f64) {
        if self.has_clearance(JointRole::CrankPin) {
            let (law, _) = self.joint_force(JointRole::CrankPin, y, contacts);
            return (-law.force, law.bearing_moment);
        }
        let p_ddot = &dy[self.layout.rod_rates()];
        let momentum = |d: usize| -> f64 {
            self.rod_data.translation[d]
                .iter()
                .zip(p_ddot)
                .map(|(u, a)| u * a)
                .sum()
        };
        let force = Vector2::new(momentum(0), momentum(1))
            - joint_force
            - self.rod_data.mass * self.gravity;
        (force, 0.0)
    }

    /// What the rod's section resultants balance besides its inertia and weight: the force on its
    /// shank at the crank pin ([`SliderCrank::shank_forces`]) and the crank pin's moment on its
    /// eye, from the crank pin's load `(force, moment)` ([`SliderCrank::crank_pin_load`]).
    fn rod_load(
        &self,
        dy: &[f64],
        (crank_pin, start_moment): (Vector2<f64>, f64),
        joint_force: Vector2<f64>,
    ) -> RodLoad {
        let [start_force, _] = self.shank_forces(dy, crank_pin, joint_force);
        RodLoad {
            start_force,
            start_moment,
            gravity: self.gravity,
        }
    }

    /// The forces on the rod's shank at its ends, the pin forces `crank_pin` (of the crank on the
    /// rod at A) and `joint_force` (on the rod's journal at B) less what accelerates the end masses:
    /// F − m (a − g) at each pin, with the accelerations of `dy`.
    fn shank_forces(
        &self,
        dy: &[f64],
        crank_pin: Vector2<f64>,
        joint_force: Vector2<f64>,
    ) -> [Vector2<f64>; 2] {
        let l = self.layout;
        let [m_a, m_b] = self.rod_data.section.end_masses();
        let (a_a, a_b) = (pair(dy, l.rate_of(PIN_A)), pair(dy, l.rate_of(l.pin_b())));
        [
            crank_pin - m_a * (a_a - self.gravity),
            joint_force - m_b * (a_b - self.gravity),
        ]
    }
}

/// The section resultants of a rigid uniform rod with unit direction `t` (crank → slider), pin
/// accelerations `accelerations` = [a_A, a_B], loaded by the force F_A and the moment M_A at pin
/// A and by gravity g ([`RodLoad`]), and by its inertia (the slider pin's force and moment close
/// the balance).
///
/// The rod's acceleration field is linear along it, a(u) = a_A + (a_B − a_A) u/l, so the load per
/// length q(u) = ρA (g − a(u)) is linear too, with axial part q·t = p₀ + p₁u and transverse part
/// t × q = α + βu. The equilibrium of the part [0, s] gives the axial force (tension positive) and
/// the bending moment (positive where the rod turns left)
/// ```text
/// N(s) = −F_A·t − p₀ s − p₁ s²/2,      M(s) = −M_A + (t × F_A) s + α s²/2 + β s³/6.
/// ```
#[derive(Clone, Copy, Debug)]
pub struct RigidRodResultants {
    m0: f64,
    n0: f64,
    p0: f64,
    p1: f64,
    f_perp: f64,
    alpha: f64,
    beta: f64,
}

impl RigidRodResultants {
    /// The resultants of the rod `section` in the motion and under the loads described above.
    pub fn new(
        section: &RodProperties,
        t: Vector2<f64>,
        accelerations: [Vector2<f64>; 2],
        load: &RodLoad,
    ) -> Self {
        let cross = |a: Vector2<f64>, b: Vector2<f64>| a.x * b.y - a.y * b.x;
        let rho_a = section.density * section.area;
        let [a_a, a_b] = accelerations;
        let (f_a, g) = (load.start_force, load.gravity);
        let (q0, q1) = (rho_a * (g - a_a), -rho_a * (a_b - a_a) / section.length);
        Self {
            m0: -load.start_moment,
            n0: -f_a.dot(&t),
            p0: q0.dot(&t),
            p1: q1.dot(&t),
            f_perp: cross(t, f_a),
            alpha: cross(t, q0),
            beta: cross(t, q1),
        }
    }

    /// N(s) \[N\] at arc length `s` from pin A.
    pub fn axial(&self, s: f64) -> f64 {
        self.n0 - self.p0 * s - 0.5 * self.p1 * s * s
    }

    /// M(s) \[N m\] at arc length `s` from pin A.
    pub fn moment(&self, s: f64) -> f64 {
        self.m0 + self.f_perp * s + 0.5 * self.alpha * s * s + self.beta * s * s * s / 6.0
    }
}

/// The normal stresses of the rigid rod of [`RigidRodResultants`]: the fibres' stresses
/// N/A ± |M| c/I. On each stretch where N and M keep their signs each is a cubic, so its extremes
/// over [0, l] lie at an end or where ±N'/A ± M' c/I = 0: the roots of four quadratics are the
/// only candidates besides the ends (exact, no sampling).
pub fn rigid_rod_stress(
    section: &RodProperties,
    t: Vector2<f64>,
    accelerations: [Vector2<f64>; 2],
    load: &RodLoad,
) -> NormalStresses {
    let (length, area) = (section.length, section.area);
    let bending = section.outer_fibre_distance / section.second_moment_of_area;
    let r = RigidRodResultants::new(section, t, accelerations, load);
    let (axial, moment) = (|s| r.axial(s), |s| r.moment(s));
    let RigidRodResultants {
        p0,
        p1,
        f_perp,
        alpha,
        beta,
        ..
    } = r;
    let mut stresses = NormalStresses {
        largest: 0.0,
        max: f64::NEG_INFINITY,
        min: f64::INFINITY,
        location: 0.0,
        midspan_axial_force: axial(0.5 * length),
        midspan_moment: moment(0.5 * length),
    };
    let mut take = |s: f64| {
        let (direct, flexural) = (axial(s) / area, moment(s).abs() * bending);
        let magnitude = direct.abs() + flexural;
        if magnitude > stresses.largest {
            stresses.largest = magnitude;
            stresses.location = s / length;
        }
        stresses.max = stresses.max.max(direct + flexural);
        stresses.min = stresses.min.min(direct - flexural);
    };
    take(0.0);
    take(length);
    for sign_n in [-1.0, 1.0] {
        for sign_m in [-1.0, 1.0] {
            // sign_n N'/A + sign_m M' c/I = a s² + b s + c = 0.
            let (n, m) = (sign_n / area, sign_m * bending);
            let (a, b, c) = (0.5 * beta * m, alpha * m - p1 * n, f_perp * m - p0 * n);
            for s in quadratic_roots(a, b, c).into_iter().flatten() {
                if s > 0.0 && s < length {
                    take(s);
                }
            }
        }
    }
    stresses
}

/// The real roots of a s² + b s + c = 0 (a linear or constant equation when a vanishes).
fn quadratic_roots(a: f64, b: f64, c: f64) -> [Option<f64>; 2] {
    if a == 0.0 {
        return [(b != 0.0).then(|| -c / b), None];
    }
    let discriminant = b * b - 4.0 * a * c;
    if discriminant < 0.0 {
        return [None, None];
    }
    // The numerically stable pair: q = −(b + sign(b) √D)/2, roots q/a and c/q.
    let q = -0.5 * (b + b.signum() * discriminant.sqrt());
    [Some(q / a), (q != 0.0).then(|| c / q)]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed form against a dense sampling of the fibres' stresses N/A ± |M| c/I from the
    /// parts' equilibrium summed numerically: a rod with a pin force and moment, inertia and
    /// oblique gravity. The largest magnitude, the most tensile and the most compressive stress within
    /// 1e-6, the largest's place within 1e-3 of the length, the mid-span section's axial force and
    /// moment within 1e-6.
    #[test]
    fn rigid_rod_stress_is_the_extremes_over_the_rod() {
        let section = RodProperties::benchmark_b();
        let t = Vector2::new(0.8, 0.6);
        let accelerations = [Vector2::new(-900.0, 4000.0), Vector2::new(2500.0, -300.0)];
        let f_a = Vector2::new(700.0, -1500.0);
        let g = Vector2::new(3.0, -9.81);
        let m_a = 35.0;
        let load = RodLoad {
            start_force: f_a,
            start_moment: m_a,
            gravity: g,
        };
        let stress = rigid_rod_stress(&section, t, accelerations, &load);
        let (l, n) = (section.length, 20_000);
        let rho_a = section.density * section.area;
        let bending = section.outer_fibre_distance / section.second_moment_of_area;
        let ds = l / n as f64;
        let (mut largest, mut max, mut min) = (0.0f64, f64::NEG_INFINITY, f64::INFINITY);
        let (mut location, mut midspan) = (0.0, (0.0, 0.0));
        // March along the rod: the internal force T and moment M of the part [0, s].
        let (mut force, mut moment) = (-f_a, m_a);
        let cross = |a: Vector2<f64>, b: Vector2<f64>| a.x * b.y - a.y * b.x;
        for k in 0..=n {
            let s = k as f64 * ds;
            // (−M, by the sign convention of this sum.)
            let (axial, flexural) = (force.dot(&t) / section.area, moment.abs() * bending);
            if axial.abs() + flexural > largest {
                (largest, location) = (axial.abs() + flexural, s / l);
            }
            max = max.max(axial + flexural);
            min = min.min(axial - flexural);
            if k == n / 2 {
                midspan = (force.dot(&t), -moment);
            }
            // Midpoint rule for the load on [s, s + ds].
            let u = s + 0.5 * ds;
            let a = accelerations[0] + (accelerations[1] - accelerations[0]) * (u / l);
            let q = rho_a * (g - a) * ds;
            moment += cross(t, force) * ds - cross(t, q) * 0.5 * ds;
            force -= q;
        }
        let close = |a: f64, b: f64, scale: f64| (a - b).abs() < 1e-6 * scale;
        assert!(
            close(stress.largest, largest, largest),
            "{stress:?} vs {largest}"
        );
        assert!(close(stress.max, max, largest), "{stress:?} vs {max}");
        assert!(close(stress.min, min, largest), "{stress:?} vs {min}");
        assert!(
            (stress.location - location).abs() < 1e-3,
            "{stress:?} vs {location}"
        );
        assert!(close(stress.midspan_axial_force, midspan.0, f_a.norm()));
        assert!(
            close(stress.midspan_moment, midspan.1, f_a.norm() * l),
            "{stress:?} vs {midspan:?}"
        );
    }

    /// Quadratic roots, also with a vanishing leading coefficient.
    #[test]
    fn quadratic_roots_are_the_roots() {
        let mut roots: Vec<f64> = quadratic_roots(2.0, -6.0, 4.0)
            .into_iter()
            .flatten()
            .collect();
        roots.sort_by(f64::total_cmp);
        assert_eq!(roots, vec![1.0, 2.0]);
        assert_eq!(quadratic_roots(0.0, 2.0, -1.0), [Some(0.5), None]);
        assert_eq!(quadratic_roots(1.0, 0.0, 1.0), [None, None]);
    }
}
