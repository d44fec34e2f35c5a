//! The parts as the equations see them: the crank's geometry and inertia, the slider's mass and its
//! guide, and what the equations use of the rod besides its body (docs/model.md §0, §9).

use crate::ancf::RodProperties;

/// The crank.
#[derive(Clone, Debug)]
pub(super) struct Crank {
    /// Length r_c from the pivot to the pin \[m\].
    pub length: f64,
    /// Distance a from the pivot to the centre of mass along the crank (towards the pin; negative
    /// beyond the pivot) \[m\].
    pub centre: f64,
    /// That distance as a fraction of the crank length.
    pub centre_ratio: f64,
    /// The pin's distance d from the crank's reference point: r_c from the fixed pivot, r_c − a
    /// from the free crank's centre of mass \[m\].
    pub arm: f64,
    /// Mass \[kg\].
    pub mass: f64,
    /// Inertia in the crank's rotation θ: about the fixed pivot, or about the free crank's centre
    /// of mass \[kg m²\].
    pub inertia: f64,
}

/// The slider on its guide.
#[derive(Clone, Debug)]
pub(super) struct Slider {
    /// Mass \[kg\].
    pub mass: f64,
    /// The guide line's distance from the crank pivot along +y \[m\].
    pub offset: f64,
}

/// What the equations use of the rod besides its body ([`super::rod_body::RodBody`]).
#[derive(Clone, Debug)]
pub(super) struct RodData {
    /// Length between the pins \[m\].
    pub length: f64,
    /// Whole mass, its end masses included \[kg\].
    pub mass: f64,
    /// Material and section (the rigid rod's stress).
    pub section: RodProperties,
    /// M t for the rigid translations t along x and y of the rod's coordinates: m a_G = (M t)ᵀ p̈
    /// is the rate of the rod's linear momentum (see [`super::loads`]).
    pub translation: [Vec<f64>; 2],
    /// M_rod⁻¹ e_j for j ∈ {A_x, A_y, B_x, B_y}, column-major (n_rod × 4).
    pub compliance: Vec<f64>,
    /// The rod's weight as generalised forces on its coordinates.
    pub gravity: Vec<f64>,
}
