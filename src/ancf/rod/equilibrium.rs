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
//! the modes carry, not the modes' truncated strains).
//!
//! With the element's shape functions S_m and nodal vectors e_m, ë_m (m = 1…4), a piece [a, b] of
//! an element adds
//! ```text
//! ΔQ = ρA (L g − Σ I_m ë_m),
//! ΔP = ρA (Σ I_m (e_m × g + r_A × ë_m) − L r_A × g − Σ J_mn e_m × ë_n),
//! ```
//! with L = b − a, I_m = ∫ S_m dx and J_mn = ∫ S_m S_n dx over the piece: constants of the piece,
//! computed once for the quarter pieces the stress scan walks (Gauss–Legendre with four points,
//! exact for the degree-6 products of cubics), so a scan costs the sixteen cross products
//! e_m × ë_n of each element and a few sums per piece.
//!
//! # References
//! - R. R. Craig, A. J. Kurdila (2006), Fundamentals of Structural Dynamics, 2nd ed., Wiley,
//!   §11.4 (mode-displacement and mode-acceleration recovery of internal forces).

use nalgebra::{Vector2, Vector4};

use super::{NormalStresses, Rod};
use crate::ancf::quarters::Piece;
use crate::ancf::shape::{shape, shape_x};

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

fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// An element's nodal vector `m` of the rod's coordinates `v`.
fn nodal(v: &[f64], j: usize, m: usize) -> Vector2<f64> {
    Vector2::new(v[4 * j + 2 * m], v[4 * j + 2 * m + 1])
}

/// A walk along the rod from its first node, carrying Q and P up to where it is: local
/// coordinate `at` of element `element`, whose cross products it holds.
struct Walk<'a> {
    rod: &'a Rod,
    e: &'a [f64],
    e_ddot: &'a [f64],
    load: &'a RodLoad,
    origin: Vector2<f64>,
    element: usize,
    at: f64,
    /// ë_m, e_m × g + r_A × ë_m and e_m × ë_n (at 4m + n) of the element.
    accelerations: [Vector2<f64>; 4],
    linear: [f64; 4],
    bilinear: [f64; 16],
    q: Vector2<f64>,
    p: f64,
}

impl<'a> Walk<'a> {
    fn new(rod: &'a Rod, e: &'a [f64], e_ddot: &'a [f64], load: &'a RodLoad) -> Self {
        let mut walk = Self {
            rod,
            e,
            e_ddot,
            load,
            origin: Vector2::new(e[0], e[1]),
            element: 0,
            at: 0.0,
            accelerations: [Vector2::zeros(); 4],
            linear: [0.0; 4],
            bilinear: [0.0; 16],
            q: Vector2::zeros(),
            p: 0.0,
        };
        walk.enter(0);
        walk
    }

    /// Enters element `j` at its start.
    fn enter(&mut self, j: usize) {
        self.element = j;
        self.at = 0.0;
        let g = self.load.gravity;
        for m in 0..4 {
            let (e_m, a_m) = (nodal(self.e, j, m), nodal(self.e_ddot, j, m));
            self.accelerations[m] = a_m;
            self.linear[m] = cross(e_m, g) + cross(self.origin, a_m);
            for n in 0..4 {
                self.bilinear[4 * m + n] = cross(e_m, nodal(self.e_ddot, j, n));
            }
        }
    }

    /// Adds the piece's ΔQ and ΔP (module documentation) of the element the walk is in.
    fn integrate(&mut self, piece: &Piece) {
        let rho_a = self.rod.properties.density * self.rod.properties.area;
        let g = self.load.gravity;
        let mut q = piece.length * g;
        let mut p = -piece.length * cross(self.origin, g);
        for m in 0..4 {
            q -= piece.single[m] * self.accelerations[m];
            p += piece.single[m] * self.linear[m];
        }
        let products = piece.double.iter().zip(&self.bilinear);
        p -= products.map(|(j, c)| j * c).sum::<f64>();
        self.q += rho_a * q;
        self.p += rho_a * p;
    }

    /// Walks on to arc length `x` (not behind where the walk is).
    fn advance(&mut self, x: f64) {
        let l = self.rod.element.length();
        let last = self.rod.n_elements - 1;
        let target = ((x / l).floor().max(0.0) as usize).min(last);
        let local = (x - target as f64 * l).clamp(0.0, l);
        while self.element < target {
            self.integrate(&Piece::new(l, self.at, l));
            self.enter(self.element + 1);
        }
        self.integrate(&Piece::new(l, self.at, local));
        self.at = self.at.max(local);
    }

    /// N and M where the walk is, the element's shape functions and their slopes there being
    /// `shape` and `slope`.
    fn resultants(&self, shape: &Vector4<f64>, slope: &Vector4<f64>) -> (f64, f64) {
        let field = |v: &[f64], s: &Vector4<f64>| {
            (0..4).fold(Vector2::zeros(), |sum, m| {
                sum + s[m] * nodal(v, self.element, m)
            })
        };
        let d = field(self.e, shape) - self.origin;
        let tangent = field(self.e, slope).normalize();
        let f_a = self.load.start_force;
        let axial = (-f_a - self.q).dot(&tangent);
        let moment = -(cross(-d, f_a) + self.load.start_moment + self.p - cross(d, self.q));
        (axial, moment)
    }

    /// N and M at local coordinate `at` of the element the walk is in.
    fn resultants_here(&self) -> (f64, f64) {
        let l = self.rod.element.length();
        self.resultants(&shape(self.at / l, l), &shape_x(self.at / l, l))
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
            let (axial, moment) = walk.resultants_here();
            visit(place, axial, moment);
        }
    }

    /// The normal stresses N/A ± |M| c/I over the rod (Euler–Bernoulli, c the outer-fibre
    /// distance) from the resultants of [`Rod::resultants`], sampled at the quarter points of every
    /// element: the largest magnitude and where it lies, the most tensile and the most compressive
    /// fibre, and the resultants at mid-span (a quarter point of some element).
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
        let mut take = |k: usize, (axial, moment): (f64, f64)| {
            let (direct, flexural) = (axial / area, moment.abs() * bending);
            if direct.abs() + flexural > stresses.largest {
                stresses.largest = direct.abs() + flexural;
                stresses.location = k as f64 / samples as f64;
            }
            stresses.max = stresses.max.max(direct + flexural);
            stresses.min = stresses.min.min(direct - flexural);
            if 2 * k == samples {
                stresses.midspan_axial_force = axial;
                stresses.midspan_moment = moment;
            }
        };
        let quarters = &self.quarters;
        let mut walk = Walk::new(self, e, e_ddot, load);
        take(0, walk.resultants(&quarters.shape[0], &quarters.slope[0]));
        for j in 0..self.n_elements {
            if j > 0 {
                walk.enter(j);
            }
            for (k, piece) in quarters.pieces.iter().enumerate() {
                walk.integrate(piece);
                let here = walk.resultants(&quarters.shape[k + 1], &quarters.slope[k + 1]);
                take(4 * j + k + 1, here);
            }
        }
        stresses
    }
}
