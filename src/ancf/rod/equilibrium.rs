//! The rod's section resultants from the equilibrium of its parts: the part [0, s] from the crank
//! pin is held by the force and moment at its first node (the crank pin's, less what its eye mass
//! takes), its distributed weight and inertia (d'Alembert), and the section at s.
//!
//! ```text
//! q(x) = ρA (g − a(x)),   Q(s) = ∫₀ˢ q dx,   P(s) = ∫₀ˢ d(x) × q(x) dx
//! T(s) = −F_A − Q(s)                                   (force of the part beyond s on [0, s])
//! N(s) = T(s) · t(s)                                    (tension positive, t the unit tangent)
//! M(s) = −[−d(s) × F_A + M_A + P(s) − d(s) × Q(s)]      (positive where the rod turns left)
//! ```
//! with r(x) = S(x) e and a(x) = S(x) ë the element's positions and accelerations and
//! d(x) = r(x) − r_A the position from the first node. Where the rod's
//! momentum and angular momentum balances hold (at every evaluation of the equations of motion:
//! the crank pin's force comes from the rod's momentum, or the rod's equations carry a worn pin's
//! force, and rigid translation and rotation lie in the reduced rod's basis), the resultants at
//! the slider end are the slider pin's force and moment: the section forces and the pin forces are
//! one number, for the reduced rod as for the full one (the mode-acceleration idea: the inertia
//! the modes carry, not the modes' truncated strains). The integrals are Gauss–Legendre with four
//! points per piece, exact for the degree-6 integrand r × q of cubic elements.
//!
//! # References
//! - R. R. Craig, A. J. Kurdila (2006), Fundamentals of Structural Dynamics, 2nd ed., Wiley,
//!   §11.4 (mode-displacement and mode-acceleration recovery of internal forces).

use nalgebra::{Vector2, Vector4};

use super::{NormalStresses, Rod};
use crate::ancf::shape::{shape, shape_x};
use crate::quadrature::GAUSS_4;

/// What the rod's section resultants balance besides its inertia and weight.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RodLoad {
    /// The force on the rod's beam at its first node (the crank pin's, less its eye mass's
    /// inertia and weight) \[N\].
    pub start_force: Vector2<f64>,
    /// The moment on the rod at its first node (a worn crank pin's friction) \[N m\].
    pub start_moment: f64,
    /// Gravity \[m/s²\].
    pub gravity: Vector2<f64>,
}

/// A walk along the rod from its first node, carrying Q and P up to where it is: local
/// coordinate `at` of element `element`.
struct Walk<'a> {
    rod: &'a Rod,
    e: &'a [f64],
    e_ddot: &'a [f64],
    load: &'a RodLoad,
    element: usize,
    at: f64,
    q: Vector2<f64>,
    p: f64,
}

fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

impl<'a> Walk<'a> {
    fn new(rod: &'a Rod, e: &'a [f64], e_ddot: &'a [f64], load: &'a RodLoad) -> Self {
        Self {
            rod,
            e,
            e_ddot,
            load,
            element: 0,
            at: 0.0,
            q: Vector2::zeros(),
            p: 0.0,
        }
    }

    /// The first node's position, the origin of the moments (positions measured from it keep
    /// the moments' terms as small as the rod).
    fn origin(&self) -> Vector2<f64> {
        Vector2::new(self.e[0], self.e[1])
    }

    /// The field Σ Sₖ vₖ of element `j`'s nodal vectors in `v` for the shape functions `shape`.
    fn field(&self, v: &[f64], j: usize, shape: Vector4<f64>) -> Vector2<f64> {
        let at = 4 * j;
        (0..4).fold(Vector2::zeros(), |sum, k| {
            sum + shape[k] * Vector2::new(v[at + 2 * k], v[at + 2 * k + 1])
        })
    }

    /// Adds the integrals of element `j` from local coordinate `from` to `to` to Q and P.
    fn integrate(&mut self, j: usize, from: f64, to: f64) {
        let l = self.rod.element.length();
        let rho_a = self.rod.properties.density * self.rod.properties.area;
        let span = (to - from).max(0.0);
        for (node, weight) in GAUSS_4.on_unit_interval(span) {
            let s = shape((from + node * span) / l, l);
            let d = self.field(self.e, j, s) - self.origin();
            let a = self.field(self.e_ddot, j, s);
            let q = rho_a * (self.load.gravity - a);
            self.q += weight * q;
            self.p += weight * cross(d, q);
        }
    }

    /// Walks on to arc length `x` (not behind where the walk is).
    fn advance(&mut self, x: f64) {
        let l = self.rod.element.length();
        let last = self.rod.n_elements - 1;
        let target = ((x / l).floor().max(0.0) as usize).min(last);
        let local = (x - target as f64 * l).clamp(0.0, l);
        while self.element < target {
            self.integrate(self.element, self.at, l);
            self.element += 1;
            self.at = 0.0;
        }
        self.integrate(self.element, self.at, local);
        self.at = self.at.max(local);
    }

    /// N and M where the walk is.
    fn resultants(&self) -> (f64, f64) {
        let l = self.rod.element.length();
        let (j, x) = (self.element, self.at);
        let d = self.field(self.e, j, shape(x / l, l)) - self.origin();
        let tangent = self.field(self.e, j, shape_x(x / l, l)).normalize();
        let f_a = self.load.start_force;
        let axial = (-f_a - self.q).dot(&tangent);
        let moment = -(cross(-d, f_a) + self.load.start_moment + self.p - cross(d, self.q));
        (axial, moment)
    }
}

impl Rod {
    /// The axial force N and bending moment M (module documentation) at each of `places`
    /// (fractions of the rod's length, ascending), passed to `visit(place, N, M)`, for nodal
    /// coordinates `e`, their accelerations `e_ddot` and the load `load`.
    pub fn resultants(
        &self,
        e: &[f64],
        e_ddot: &[f64],
        load: &RodLoad,
        places: impl IntoIterator<Item = f64>,
        mut visit: impl FnMut(f64, f64, f64),
    ) {
        let mut walk = Walk::new(self, e, e_ddot, load);
        let length = self.properties.length;
        for place in places {
            walk.advance(place.clamp(0.0, 1.0) * length);
            let (axial, moment) = walk.resultants();
            visit(place, axial, moment);
        }
    }

    /// The normal stresses N/A ± |M| c/I over the rod (Euler–Bernoulli, c the outer-fibre
    /// distance) from the resultants of [`Rod::resultants`], sampled at the quarter points of every
    /// element: the largest magnitude and where it lies, the most tensile and the most compressive
    /// fibre, and the resultants at mid-span.
    pub fn normal_stresses(&self, e: &[f64], e_ddot: &[f64], load: &RodLoad) -> NormalStresses {
        let p = &self.properties;
        let (area, bending) = (p.area, p.outer_fibre_distance / p.second_moment_of_area);
        let mut stresses = NormalStresses {
            largest: 0.0,
            max: f64::NEG_INFINITY,
            min: f64::INFINITY,
            location: 0.0,
            midspan_axial_force: 0.0,
            midspan_moment: 0.0,
        };
        let samples = 4 * self.n_elements;
        // the samples in order, mid-span among them (it is a quarter point of some element)
        let places = (0..=samples).map(|k| k as f64 / samples as f64);
        self.resultants(e, e_ddot, load, places, |place, axial, moment| {
            let (direct, flexural) = (axial / area, moment.abs() * bending);
            if direct.abs() + flexural > stresses.largest {
                stresses.largest = direct.abs() + flexural;
                stresses.location = place;
            }
            stresses.max = stresses.max.max(direct + flexural);
            stresses.min = stresses.min.min(direct - flexural);
            if 2 * (place * samples as f64).round() as usize == samples {
                stresses.midspan_axial_force = axial;
                stresses.midspan_moment = moment;
            }
        });
        stresses
    }
}
