//! Lubricated journal bearing: an oil film — the infinitely short bearing ([`super::short_film`])
//! or the finite bearing ([`super::finite_film`]) — with dry contact taking over near metal
//! contact, and the film's shear.
//!
//! ```text
//! force on the journal F = F_r n + F_t t (the film model's), on the bearing −F
//! shear moments  M_J = −T − |e| F_t/2   on the journal,   M_B = T − |e| F_t/2   on the bearing
//!                T = 2π μ R³ L (ω_J − ω_B) / (c √(1 − ε²))
//! loss           T (ω_J − ω_B) − F · v_s,   v_s = c (ε̇, −ε w/2) in (n, t)   (≥ 0)
//! ```
//! The film shear: T is the Couette shear of the relative rotation taken over the whole
//! circumference (engineering practice: the oil fills the cavitated zone in streamers), which
//! tends to Petroff's 2π μ R³ L (ω_J − ω_B)/c for a centred journal; −|e| F_t/2 on each surface is
//! the pressure-driven (Poiseuille) part, for any pressure field that vanishes at the film's edges
//! (integration by parts of the Poiseuille shear h/2 ∂p/∂x). Together they balance the couple
//! |e| F_t of the force pair at the two centres, M_J + M_B + |e| F_t = 0, so the massless film
//! transmits no net moment (the journal bearing's friction torque with its pressure part
//! e W sin φ / 2: Pinkus & Sternlicht 1961; Hamrock, Schmid & Jacobson 2004). With them the film's
//! power on journal and bearing, F·ė + M_J ω_J + M_B ω_B = c ε̇ F_r − |e| F_t w/2 − T (ω_J − ω_B),
//! is F · v_s − T (ω_J − ω_B) ≤ 0 for ε ≤ ε_b: v_s is the pure-squeeze velocity of the journal in
//! the frame turning at (ω_J + ω_B)/2, against which the film pushes back (for the short film,
//! −F · v_s = (c K_h/2) ∫_Θ (ε w sin θ − 2ε̇ cos θ)²/(1 + ε cos θ)³ dθ). The film never adds
//! energy, also in a whirl (where its force alone, through the journal centre, can). Above ε_b
//! the clamped film's force is no pressure field's; its moments keep the actual |e| (the moment
//! balance) and T the clamped ε.
//!
//! Hand-over (docs/model.md §4, continuous rule): for ε ≥ ε_b the film force is evaluated with ε
//! clamped to ε_b (actual ε̇ and w), and the dry contact force of [`DryContact`] is added whenever
//! δ = |e| − c > 0. Both pieces are continuous, so the total force is continuous in e.
//!
//! # References
//! - P. Flores, J. Ambrósio, J. C. P. Claro, H. M. Lankarani, C. S. Koshy (2006), A study on
//!   dynamics of mechanical systems including joints with clearance and lubrication, Mech. Mach.
//!   Theory 41, 247–261.
//! - O. Pinkus, B. Sternlicht (1961), Theory of Hydrodynamic Lubrication, McGraw-Hill.
//! - B. J. Hamrock, S. R. Schmid, B. O. Jacobson (2004), Fundamentals of Fluid Film Lubrication,
//!   2nd ed., Marcel Dekker (short journal bearings: pressure, friction torque, Petroff).
//! - docs/model.md §4 (pressure, sign convention verified against direct integration).

use nalgebra::Vector2;

use super::asperity::{Asperity, AsperityState};
use super::contact::DryContact;
use super::feed::Feed;
use super::finite_film::FiniteFilm;
use super::kinematics::{JointForce, JointKinematics, JointRates};
use super::short_film::FilmField;
use super::thermal::HeatBalance;

/// The oil film's model.
#[derive(Clone, Debug, PartialEq)]
pub enum Film {
    /// Ocvirk's infinitely short bearing ([`super::short_film`]).
    Short,
    /// The finite bearing of the Reynolds equation over its length ([`super::finite_film`]).
    Finite(FiniteFilm),
}

/// Constants of the lubricated joint.
#[derive(Clone, Debug, PartialEq)]
pub struct JournalBearing {
    /// Dynamic viscosity μ \[Pa s\].
    pub viscosity: f64,
    /// The length of each of the film's lands \[m\]: the bearing's length L, or (L − w)/2 beside
    /// a circumferential groove of width w.
    pub length: f64,
    /// How many lands carry the film side by side: 1, or 2 beside a circumferential groove
    /// ([`Feed::lands`]).
    pub lands: f64,
    /// The oil feed, None for an unfed film (boxed: most joints have none).
    pub feed: Option<Box<Feed>>,
    /// Eccentricity ratio ε_b above which the film model is clamped and dry contact may act.
    pub switch_eccentricity: f64,
    /// The film's model.
    pub film: Film,
    /// The rough surfaces' asperity contact, None for smooth surfaces.
    pub asperity: Option<Asperity>,
    /// The film's heat balance, None for an isoviscous oil (of `viscosity`).
    pub heat_balance: Option<HeatBalance>,
    /// Dry contact law (clearance, journal radius, friction, stiffness).
    pub dry: DryContact,
}

impl JournalBearing {
    /// Film coefficient K_h = μ R L³ / (2c²) \[N s\], summed over the lands.
    pub fn film_coefficient(&self) -> f64 {
        let c = self.dry.clearance;
        self.lands * self.viscosity * self.dry.journal_radius * self.length.powi(3) / (2.0 * c * c)
    }

    /// The oil's viscosity in the state `k` over the joint's own: μ(T)/μ where a heat balance sets
    /// it, exactly 1 for the isoviscous oil (every film force, pressure and loss is linear in μ).
    fn viscosity_ratio(&self, k: &JointKinematics) -> f64 {
        k.viscosity.map_or(1.0, |mu| mu / self.viscosity)
    }

    /// The oil's viscosity in the state `k` \[Pa s\]: the heat balance's, or the joint's own.
    pub fn viscosity_at(&self, k: &JointKinematics) -> f64 {
        k.viscosity.unwrap_or(self.viscosity)
    }

    /// Film force on the journal over the positive-pressure region, ε clamped to ε_b.
    pub fn film_force(&self, k: &JointKinematics) -> Vector2<f64> {
        self.film(k).0
    }

    /// The short film's field in a state, `None` where it vanishes (a centred journal, or no
    /// wedge and no squeeze).
    fn field(&self, k: &JointKinematics) -> Option<FilmField> {
        FilmField::of(k, self.dry.clearance, self.switch_eccentricity)
    }

    /// The finite film's ratios to the short one in the field's state (None for the short film).
    fn ratios(&self, field: &FilmField) -> Option<[f64; 4]> {
        match &self.film {
            Film::Short => None,
            Film::Finite(finite) => Some(finite.ratios_at(field.eps, field.squeeze_direction())),
        }
    }

    /// The film in the state `k` from one evaluation of its field and table: its force on the
    /// journal, F_t = F · t, and with `with_flow` the finite film's flow ratio T_q; None where the
    /// film vanishes.
    fn film_state(&self, k: &JointKinematics, with_flow: bool) -> Option<FilmState> {
        let field = self.field(k)?;
        let (f_r, f_t) = field.force();
        let scale = self.film_coefficient() * self.viscosity_ratio(k);
        let t = field.tangent();
        let (force, f_t, t_q) = match &self.film {
            Film::Short => (scale * (f_r * field.n + f_t * t), scale * f_t, None),
            Film::Finite(finite) => {
                let direction = field.squeeze_direction();
                let (t_r, t_t, t_q) = if with_flow {
                    let [t_r, t_t, _, t_q] = finite.ratios_at(field.eps, direction);
                    (t_r, t_t, Some(t_q))
                } else {
                    let [t_r, t_t] = finite.force_ratios_at(field.eps, direction);
                    (t_r, t_t, None)
                };
                let magnitude = scale * crate::math::hypot(f_r, f_t);
                (magnitude * (t_r * field.n + t_t * t), magnitude * t_t, t_q)
            }
        };
        Some(FilmState {
            field,
            force,
            f_t,
            t_q,
        })
    }

    /// Film force on the journal and its tangential component F_t = F · t.
    fn film(&self, k: &JointKinematics) -> (Vector2<f64>, f64) {
        self.film_state(k, false)
            .map_or((Vector2::zeros(), 0.0), |s| (s.force, s.f_t))
    }

    /// The largest film pressure \[Pa\], at mid-length: the short bearing's field
    /// p(θ, z) = (3μ/c²) (L²/4 − z²) A sin(θ − θ₁)/(1 + ε cos θ)³ at its maximum
    /// ([`FilmField::peak_shape`]), times the finite film's ratio T_p for the finite bearing;
    /// 0 without a film.
    pub fn peak_pressure(&self, k: &JointKinematics) -> f64 {
        let Some(field) = self.field(k) else {
            return 0.0;
        };
        let c = self.dry.clearance;
        let short = 3.0 * self.viscosity_at(k) * self.length * self.length / (4.0 * c * c)
            * field.amplitude
            * field.peak_shape();
        match self.ratios(&field) {
            None => short,
            Some([_, _, t_p, _]) => t_p * short,
        }
    }

    /// The oil flow out of both ends of the pressurised film \[m³/s\]: the short film's c R L A
    /// (A = √((εw)² + (2ε̇)²), ε clamped to ε_b), times the finite film's ratio T_q for the finite
    /// bearing, summed over the lands; 0 without a film.
    pub fn side_flow(&self, k: &JointKinematics) -> f64 {
        self.film_state(k, true)
            .map_or(0.0, |state| self.flow_of(&state))
    }

    /// The side flow of the film state `state` (one evaluated with its flow ratio).
    fn flow_of(&self, state: &FilmState) -> f64 {
        let short = self.lands
            * self.dry.clearance
            * self.dry.journal_radius
            * self.length
            * state.field.amplitude;
        match state.t_q {
            None => short,
            Some(t_q) => t_q * short,
        }
    }

    /// The rate at which the film dissipates energy \[W\], ≥ 0: its Couette shear
    /// T (ω_J − ω_B) and its pressure flow −F · v_s (module documentation), which equal
    /// −(F·ė + M_J ω_J + M_B ω_B) for ε ≤ ε_b; above ε_b, those of the film clamped there.
    pub fn film_loss(&self, k: &JointKinematics) -> f64 {
        self.loss_of(k, self.film_state(k, false).as_ref())
    }

    /// [`JournalBearing::film_loss`] with the film state `state` in `k` already evaluated.
    fn loss_of(&self, k: &JointKinematics, state: Option<&FilmState>) -> f64 {
        let relative = k.omega_journal - k.omega_bearing;
        let eps = (k.e.norm() / self.dry.clearance).min(self.switch_eccentricity);
        let ratio = self.viscosity_ratio(k);
        let shear =
            self.petroff_coefficient() * ratio * relative * relative / (1.0 - eps * eps).sqrt();
        let Some(FilmState { field, force, .. }) = state else {
            return shear;
        };
        if matches!(self.film, Film::Short) {
            return shear
                + 0.5 * self.dry.clearance * self.film_coefficient() * ratio * field.flow_loss();
        }
        // v_s = (c A/2) (cos ψ, sin ψ) in (n, t)
        let (cos, sin) = field.squeeze_direction();
        let half = 0.5 * self.dry.clearance * field.amplitude;
        let v_s = half * (cos * field.n + sin * field.tangent());
        shear - force.dot(&v_s)
    }

    /// Petroff's coefficient 2π μ R³ L / c \[N m s\]: the Couette shear torque of a centred
    /// journal per unit of relative speed ω_J − ω_B, over the lands (a groove carries no shear).
    pub fn petroff_coefficient(&self) -> f64 {
        let r = self.dry.journal_radius;
        std::f64::consts::TAU * self.viscosity * r * r * r * self.lands * self.length
            / self.dry.clearance
    }

    /// The feed's pressure flow in the state `k` \[m³/s\] ([`Feed::flow`]) for the supply
    /// pressure `pressure` \[Pa\], the feed's body's axis along `axis`; 0 without a feed.
    pub fn feed_flow(&self, k: &JointKinematics, axis: Vector2<f64>, pressure: f64) -> f64 {
        self.feed.as_ref().map_or(0.0, |feed| {
            feed.flow(
                self.dry.clearance,
                k.e,
                axis,
                self.viscosity_at(k),
                pressure,
            )
        })
    }

    /// The film's shear moments (M_J on the journal, M_B on the bearing) for its tangential
    /// force `f_t` on the journal: the Couette part ∓T with ε clamped to ε_b, and the pressure
    /// part −|e| F_t/2 on each (see the module documentation).
    fn shear_moments(&self, k: &JointKinematics, f_t: f64) -> (f64, f64) {
        let e_norm = k.e.norm();
        let eps = (e_norm / self.dry.clearance).min(self.switch_eccentricity);
        let couette = self.petroff_coefficient()
            * self.viscosity_ratio(k)
            * (k.omega_journal - k.omega_bearing)
            / (1.0 - eps * eps).sqrt();
        let pressure = 0.5 * e_norm * f_t;
        (-couette - pressure, couette - pressure)
    }

    /// The asperity contact's force and what it carries in the state `k` (zeros for smooth
    /// surfaces).
    pub fn asperity_force(&self, k: &JointKinematics) -> (JointForce, AsperityState) {
        self.asperity
            .as_ref()
            .map_or_else(Default::default, |a| a.force(k, &self.dry))
    }

    /// Film force and shear moments, plus the asperities' force where the film is thin on rough
    /// surfaces and dry contact when the journal touches the bearing.
    pub fn force(&self, k: &JointKinematics, impact_velocity: f64) -> JointForce {
        self.assemble(k, impact_velocity, self.film_state(k, false).as_ref())
            .0
    }

    /// [`JournalBearing::force`] and the joint's friction power, oil flow and asperity force in
    /// the same state, from one evaluation of the film (what a heat balance reads at every
    /// right-hand side).
    pub fn force_and_rates(
        &self,
        k: &JointKinematics,
        impact_velocity: f64,
    ) -> (JointForce, JointRates) {
        let state = self.film_state(k, true);
        let (force, asperity) = self.assemble(k, impact_velocity, state.as_ref());
        let rates = JointRates {
            friction_power: self.loss_of(k, state.as_ref())
                + self.dry.friction_power(k, impact_velocity)
                + asperity.friction_power,
            oil_flow: state.as_ref().map_or(0.0, |state| self.flow_of(state)),
            asperity_force: asperity.force,
        };
        (force, rates)
    }

    /// The joint's force of the film state `state`, with the shear, the asperities and the dry
    /// contact, and what the asperities carry.
    fn assemble(
        &self,
        k: &JointKinematics,
        impact_velocity: f64,
        state: Option<&FilmState>,
    ) -> (JointForce, AsperityState) {
        let dry = self.dry.force(k, impact_velocity);
        let (film, f_t) = state.map_or((Vector2::zeros(), 0.0), |s| (s.force, s.f_t));
        let (journal, bearing) = self.shear_moments(k, f_t);
        let mut total = JointForce {
            force: film + dry.force,
            moment: dry.moment + journal,
            bearing_moment: dry.bearing_moment + bearing,
            ..dry
        };
        let Some(asperity) = &self.asperity else {
            return (total, AsperityState::default());
        };
        let (force, carried) = asperity.force(k, &self.dry);
        total.force += force.force;
        total.moment += force.moment;
        total.bearing_moment += force.bearing_moment;
        total.potential += force.potential;
        (total, carried)
    }
}

/// The film in one state ([`JournalBearing::film_state`]).
#[derive(Clone, Copy, Debug)]
struct FilmState {
    /// The short film's field.
    field: FilmField,
    /// The force on the journal \[N\].
    force: Vector2<f64>,
    /// Its tangential component F_t = F · t \[N\].
    f_t: f64,
    /// The finite film's flow ratio T_q, where evaluated.
    t_q: Option<f64>,
}

#[cfg(test)]
mod tests;
