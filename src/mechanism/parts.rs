//! The rigid parts as the equations see them: the crank's geometry and inertia, the slider's mass
//! and its guide (docs/model.md §0, §9).

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
