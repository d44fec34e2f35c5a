//! The oil feed of a lubricated joint: a hole, a circumferential groove or an axial groove through
//! which the lubrication circuit supplies oil at the pressure p_s, and the flow that pressure
//! drives through the clearance, added to the film's own side flow as the bearing standards add
//! their pressure flow to the hydrodynamic one.
//!
//! ```text
//! Q_feed = c³ p_s S ⟨H³⟩ / (12 μ)                       hole and axial groove
//! Q_feed = c³ p_s 2π R (1 + 1.5 ε²) · 4/(L − w) / (12 μ) circumferential groove of width w
//! hole of diameter d:            S = 2π/Λ,  Λ = ½ ln(coth a · cot a),  a = π d/(4L)
//! axial groove w wide, b long:   S = 4 K(k)/K(k'),  k = sin(π (b + 7w/8)/(2L)),  k' = √(1 − k²)
//! ⟨H³⟩ = (1/2β) ∫ (1 + ε cos θ)³ dθ over θ_f ± β,  β = (3/4) L/(2R)
//!      = 1 + 3g s₁ + 1.5 ε² + 1.5 (2g² − ε²) s₂ + 0.75 ε² g s₁ + (4g³ − 3ε² g) s₃/4
//! g = ε cos θ_f = −e · u/c,   s_n = sin(nβ)/(nβ)           u the feed's direction
//! ```
//! The feed's pressure flow is that of the thin-film (Hele-Shaw) equation ∇·(h³ ∇p) = 0 over the
//! unrolled bearing, with p = p_s on the feed and p = 0 at both ends. For a circumferential groove
//! the film splits into two lands of width (L − w)/2 and the axial flow h³ p_s/(12 μ (L − w)/2)
//! out of each side, integrated around the bearing with ∫(1 + ε cos θ)³ dθ = 2π (1 + 1.5 ε²), is
//! exact. A hole or an axial groove sees the film around it: its geometric factor S is that of a
//! uniform film, scaled by the film's cube averaged over ±β around the feed (the standards take
//! the film at the feed's centre, β = 0, which over- or underestimates by 6–11 % at ε 0.5; the
//! reach β, 3/8 of the bearing's length on either side, is fitted to the reference solutions
//! below and holds them within 3.5 % for a hole at the thickest film, beside it and at the
//! thinnest film). For the uniform film:
//! the strip |z| < L/2 mapped on a half-plane by w = exp(π ζ/L) gives the potential of a source,
//! (1/2π) ln|(w + 1)/(w − 1)|, whose level at the hole's edge, averaged between its axial and its
//! circumferential radius, is Λ/(2π) (exact as d/L → 0); a groove along the bearing is a slit
//! whose half-plane problem the Schwarz–Christoffel map ∫ dt/√((k² − t²)(1 − t²)) turns into a
//! rectangle 2K(k) wide and K(k') high on each of its two sides; the groove's width w adds 7/8 of
//! itself to the slit's length (fitted to the reference solution of a 3 mm groove over 0.8 of a
//! 20 mm bearing; a 2 mm groove over 0.6 of it comes out 6.3 % low). Both are measured against a
//! finite-difference solution of the Reynolds equation with the supply pressure on the feed
//! (tests/validation_film/feed.rs).
//!
//! The feed sits in the bearing's shell or in the journal (a crank pin fed through the crankshaft's
//! drilling), at an angle in that body's frame: a hole in the journal turns with it and sees the
//! thin film once a turn. The circumferential groove's two lands also make the film two bearings
//! of width (L − w)/2 side by side ([`Feed::lands`]): about a quarter of the load capacity of the
//! ungrooved bearing, as the standards compute it. The supply pressure does not change the film's
//! force (the standards neglect it against the film's pressures; the feed fills the cavitated
//! region without lifting the load).
//!
//! # References
//! - ISO 7902-1:2020 and DIN 31652-1:2017 (the pressure flow of a lubrication hole and of
//!   circumferential and axial grooves, added to the hydrodynamic flow).
//! - B. J. Hamrock, S. R. Schmid, B. O. Jacobson (2004), Fundamentals of Fluid Film Lubrication,
//!   2nd ed., Marcel Dekker (pressure-fed journal bearings).
//! - W. R. Smythe (1968), Static and Dynamic Electricity, 3rd ed., McGraw-Hill (the conformal maps
//!   of a strip and the capacitance of a slit).

use std::f64::consts::{PI, TAU};

use nalgebra::Vector2;

use crate::math;

/// What feeds the oil.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FeedModel {
    /// No feed: the film's side flow alone.
    None,
    /// A lubrication hole of diameter d at mid-length.
    Hole,
    /// A groove around the whole circumference, of width w at mid-length: two lands.
    CircumferentialGroove,
    /// A groove along the bearing, w wide around it and a fraction of the length long, centred.
    AxialGroove,
}

/// The body a feed sits in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FeedLocation {
    /// The bearing's shell: the feed stays where the shell is.
    Shell,
    /// The journal (a drilling through the crankshaft): the feed turns with it.
    Journal,
}

/// Where a feed lets the oil in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Opening {
    /// All around the journal (a circumferential groove), `width` w wide \[m\].
    AllAround {
        /// The groove's width w \[m\].
        width: f64,
    },
    /// At one place (a hole, an axial groove).
    At {
        /// Its direction in its body's frame, (cos φ, sin φ) of its angle φ from the body's
        /// axis.
        direction: (f64, f64),
        /// The reach's sines s₁, s₂, s₃ of the film's average (module documentation).
        reach: [f64; 3],
    },
}

/// A joint's oil feed (module documentation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Feed {
    /// The body it sits in.
    pub location: FeedLocation,
    /// Where it lets the oil in.
    pub opening: Opening,
    /// The geometric factor: S of a hole or an axial groove, 2π R · 4/(L − w) of a
    /// circumferential groove \[m/m\].
    pub shape: f64,
}

impl Feed {
    /// The feed `model` of size `size` (a hole's diameter, a groove's width) \[m\] at the angle
    /// `angle` in the body `location`, an axial groove `groove_length` of the bearing's length
    /// `length` long around a journal of radius `radius`; None for [`FeedModel::None`]. Sizes
    /// validated beforehand (size ≤ L/2, an axial groove short of the bearing's ends).
    pub fn new(
        model: FeedModel,
        location: FeedLocation,
        angle: f64,
        (size, groove_length): (f64, f64),
        (length, radius): (f64, f64),
    ) -> Option<Self> {
        let shape = match model {
            FeedModel::None => return None,
            FeedModel::Hole => hole_shape(size / length),
            FeedModel::CircumferentialGroove => {
                return Some(Self {
                    location,
                    opening: Opening::AllAround { width: size },
                    shape: TAU * radius * 4.0 / (length - size),
                });
            }
            FeedModel::AxialGroove => slot_shape((groove_length + 0.875 * size) / length),
        };
        let (sin, cos) = math::sin_cos(angle);
        let beta = 0.375 * length / radius;
        let reach = [1.0, 2.0, 3.0].map(|n: f64| math::sin(n * beta) / (n * beta));
        Some(Self {
            location,
            opening: Opening::At {
                direction: (cos, sin),
                reach,
            },
            shape,
        })
    }

    /// The film's lands: how many bearings side by side and each one's width, for a bearing of
    /// length `length` (two of (L − w)/2 for a circumferential groove, else one of L).
    pub fn lands(feed: Option<&Self>, length: f64) -> (f64, f64) {
        match feed.map(|f| f.opening) {
            Some(Opening::AllAround { width }) => (2.0, 0.5 * (length - width)),
            _ => (1.0, length),
        }
    }

    /// The pressure-fed flow \[m³/s\] (module documentation) of the supply pressure `pressure`
    /// \[Pa\] through the clearance `clearance` at the eccentricity `e`, the oil of viscosity
    /// `viscosity`, the body carrying the feed with its axis along `axis` (a unit vector in the
    /// ground frame).
    pub fn flow(
        &self,
        clearance: f64,
        e: Vector2<f64>,
        axis: Vector2<f64>,
        viscosity: f64,
        pressure: f64,
    ) -> f64 {
        let eps = (e.norm() / clearance).min(1.0);
        let e2 = eps * eps;
        let cube = match self.opening {
            Opening::AllAround { .. } => 1.0 + 1.5 * e2,
            Opening::At { direction, reach } => {
                let (cos, sin) = direction;
                let u = Vector2::new(axis.x * cos - axis.y * sin, axis.y * cos + axis.x * sin);
                let g = (-e.dot(&u) / clearance).clamp(-eps, eps);
                let [s1, s2, s3] = reach;
                1.0 + 3.0 * g * s1
                    + 1.5 * e2
                    + 1.5 * (2.0 * g * g - e2) * s2
                    + 0.75 * e2 * g * s1
                    + 0.25 * (4.0 * g * g * g - 3.0 * e2 * g) * s3
            }
        };
        clearance.powi(3) * pressure / (12.0 * viscosity) * self.shape * cube
    }
}

/// The geometric factor S = 2π/Λ of a hole `ratio` = d/L of the bearing's length across
/// (module documentation).
fn hole_shape(ratio: f64) -> f64 {
    let a = 0.25 * PI * ratio;
    let e2 = math::exp(2.0 * a);
    let (sin, cos) = math::sin_cos(a);
    let log = 0.5 * math::ln((e2 + 1.0) / (e2 - 1.0) * cos / sin);
    TAU / log
}

/// The geometric factor S = 4 K(k)/K(k') of a slit `ratio` of the bearing's length long, across
/// the middle of the bearing's length (module documentation).
fn slot_shape(ratio: f64) -> f64 {
    let (k, k_prime) = math::sin_cos(0.5 * PI * ratio);
    4.0 * elliptic_k(k_prime) / elliptic_k(k)
}

/// The complete elliptic integral of the first kind K(k) = π/(2 M(1, k')), M the
/// arithmetic–geometric mean (Abramowitz & Stegun 17.6), from the complementary modulus
/// k' = √(1 − k²).
fn elliptic_k(k_prime: f64) -> f64 {
    let (mut a, mut b) = (1.0, k_prime);
    while (a - b).abs() > 1e-15 * a {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    0.5 * PI / a
}

#[cfg(test)]
mod tests {
    use super::*;

    /// K(k) against its series at small k and against K(1/√2) = Γ(1/4)²/(4√π).
    #[test]
    fn the_elliptic_integral_is_right() {
        let k: f64 = 0.1;
        let series =
            0.5 * PI * (1.0 + k * k / 4.0 + 9.0 * k.powi(4) / 64.0 + 25.0 * k.powi(6) / 256.0);
        assert!((elliptic_k((1.0 - k * k).sqrt()) / series - 1.0).abs() < 1e-8);
        let r = std::f64::consts::FRAC_1_SQRT_2;
        let gamma_quarter = 3.625_609_908_221_908;
        let exact = gamma_quarter * gamma_quarter / (4.0 * PI.sqrt());
        assert!((elliptic_k(r) / exact - 1.0).abs() < 1e-13);
    }

    /// A small hole's factor tends to the source's 2π/ln(4L/(π d)); a slit that is short against
    /// the length to that of a hole of half its length (a segment's and a disc's capacities).
    #[test]
    fn small_feeds_tend_to_a_point_source() {
        for ratio in [1e-3, 1e-4] {
            let source = TAU / math::ln(4.0 / (PI * ratio));
            assert!((hole_shape(ratio) / source - 1.0).abs() < 1e-5);
            assert!((slot_shape(2.0 * ratio) / source - 1.0).abs() < 1e-5);
        }
    }
}
