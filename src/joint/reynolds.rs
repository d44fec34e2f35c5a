//! The finite journal bearing's film by finite differences: the Reynolds equation over the
//! bearing's length with the Reynolds (Swift–Stieber) cavitation condition, for any combination of
//! wedge and squeeze. It is the source of the tables the finite film model interpolates
//! ([`super::finite_film`], built by `examples/film_table.rs`), not part of a right-hand side.
//!
//! ```text
//! pure-squeeze velocity  v_s = ė − ω̄ ẑ × e,   ω̄ = (ω_J + ω_B)/2
//!   (n, t) components    v_s = c V (cos ψ, sin ψ),   V = √(ε̇² + (εw/2)²),  w = ω_J + ω_B − 2γ̇
//! θ from the thickest film (h = c H, H = 1 + ε cos θ), z = axial/R ∈ [−λ, λ], λ = L/D,
//! p = 12 μ V (R/c)² P:
//!   ∂/∂θ(H³ ∂P/∂θ) + ∂/∂z(H³ ∂P/∂z) = cos(θ − ψ)   where P > 0
//!   P ≥ 0 everywhere, P = 0 at z = ±λ, periodic in θ
//! force on the journal   F = 12 μ V R⁴/c² (f_r n + f_t t),   (f_r, f_t) = ∫∫ P (cos θ, sin θ) dθ dz
//! peak pressure          p_max = 12 μ V (R/c)² max P
//! side flow (both ends)  Q_s = 2 c R² V q,   q = ∫ H³ (−∂P/∂z)|_{z = λ} dθ
//! ```
//!
//! Every dynamic state of a plain journal bearing is, in the frame turning at ω̄, a pure squeeze
//! of the journal with velocity v_s (Booker's equivalence), so the dimensionless film depends on
//! λ, ε and the squeeze direction ψ only, and scales with V. ψ = 0 is a pure approach to the wall
//! (P > 0 on the thin side, θ near π), ψ = −π/2 the steady load of a turning journal (Raimondi &
//! Boyd's case: ε̇ = 0, w = ω > 0). In the short-bearing limit λ → 0,
//! P = (z² − λ²) cos(θ − ψ)/(2H³) where positive, Ocvirk's film ([`super::bearing`]).
//!
//! The cavitation condition makes this a linear complementarity problem, P ≥ 0,
//! A P − g ≥ 0, P (A P − g) = 0 (A the discrete operator with its sign turned positive definite,
//! g = −cos(θ − ψ)); its solution meets ∂P/∂n = 0 at the film's rupture, the Reynolds condition
//! Raimondi & Boyd used (Christopherson's projected over-relaxation). Discretisation: finite
//! volumes on z ∈ [0, λ] (the film is symmetric about mid-length) with nodes clustered at the
//! thinnest film by θ = ξ + κ sin ξ, ξ uniform (κ = 0.6 ε), second order, swept with Young's
//! optimal over-relaxation factor of the grid's constant-coefficient problem; a solution on a grid
//! and on the grid twice as fine are combined by Richardson extrapolation, which leaves errors of
//! order 1e-4 (measured against a grid four times finer, docs/design.md). The peak is the vertex
//! of the parabola through the largest node and its neighbours around the bearing; the side flow
//! is the second-order one-sided gradient at the bearing's end.
//!
//! # References
//! - A. A. Raimondi, J. Boyd (1958), A solution for the finite journal bearing and its
//!   application to analysis and design, ASLE Trans. 1, 159–209.
//! - C. W. Cryer (1971), The method of Christopherson for solving free boundary problems for
//!   infinite journal bearings by means of finite differences, Math. Comp. 25, 435–443.
//! - J. F. Booker (1965), Dynamically loaded journal bearings: mobility method of solution,
//!   J. Basic Eng. 87, 537–546 (the pure-squeeze equivalence).
//! - B. J. Hamrock, S. R. Schmid, B. O. Jacobson (2004), Fundamentals of Fluid Film Lubrication,
//!   2nd ed., Marcel Dekker (the Reynolds equation, finite journal bearings).

use std::f64::consts::{PI, TAU};

use crate::math;

/// The finite-difference grid: nodes around the bearing (uniform in ξ), intervals over half the
/// length.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Grid {
    /// Nodes around the bearing.
    pub circumferential: usize,
    /// Intervals from mid-length to the end.
    pub axial: usize,
}

impl Grid {
    /// The grid whose Richardson pair (with its doubling) keeps the extrapolated film within
    /// about 1e-4 for the length-to-diameter ratio `lambda`: 144 nodes around, an axial spacing
    /// of at most 0.07 bearing radii with 6 to 40 intervals.
    pub fn for_ratio(lambda: f64) -> Self {
        Self {
            circumferential: 144,
            axial: ((lambda / 0.07).ceil() as usize).clamp(6, 40),
        }
    }

    fn doubled(self) -> Self {
        Self {
            circumferential: 2 * self.circumferential,
            axial: 2 * self.axial,
        }
    }
}

/// The dimensionless film (module documentation): force (f_r, f_t) per unit of 12 μ V R⁴/c²,
/// peak P, side flow q of one end.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilmSolution {
    /// (f_r, f_t) = ∫∫ P (cos θ, sin θ) dθ dz over the whole length.
    pub force: [f64; 2],
    /// The largest P (at mid-length).
    pub peak: f64,
    /// q = ∫ H³ (−∂P/∂z) dθ at one end.
    pub side_flow: f64,
}

impl FilmSolution {
    /// Richardson's extrapolation of second-order results on a grid (`coarse`) and on the grid
    /// twice as fine (`self`): (4 fine − coarse)/3.
    fn extrapolated(self, coarse: Self) -> Self {
        let r = |fine: f64, coarse: f64| (4.0 * fine - coarse) / 3.0;
        Self {
            force: [
                r(self.force[0], coarse.force[0]),
                r(self.force[1], coarse.force[1]),
            ],
            peak: r(self.peak, coarse.peak),
            side_flow: r(self.side_flow, coarse.side_flow),
        }
    }
}

/// Reusable pressure fields of a Richardson pair: each solve starts from the last solution on
/// its grid (neighbouring (ε, ψ) converge in far fewer sweeps), the fine one from the coarse one.
#[derive(Clone, Debug, Default)]
pub struct Workspace {
    coarse: Vec<f64>,
    fine: Vec<f64>,
}

/// The film at length-to-diameter ratio `lambda`, eccentricity ratio `eps` ∈ [0, 1) and squeeze
/// direction `psi`, extrapolated from `grid` and its doubling.
pub fn solve(lambda: f64, eps: f64, psi: f64, grid: Grid, work: &mut Workspace) -> FilmSolution {
    let coarse = Field::new(lambda, eps, psi, grid).solve(&mut work.coarse);
    let fine_grid = grid.doubled();
    if work.fine.len() != fine_grid.circumferential * fine_grid.axial {
        work.fine = prolonged(&work.coarse, grid);
    }
    let fine = Field::new(lambda, eps, psi, fine_grid).solve(&mut work.fine);
    fine.extrapolated(coarse)
}

/// The field on `grid` twice as fine in each direction, by linear interpolation of `p` on
/// `grid` (the pressure is 0 at the end, beyond the last axial node).
fn prolonged(p: &[f64], grid: Grid) -> Vec<f64> {
    let (n, m) = (grid.circumferential, grid.axial);
    let at = |i: usize, j: usize| if j < m { p[(i % n) * m + j] } else { 0.0 };
    let mut fine = vec![0.0; 4 * n * m];
    for i in 0..2 * n {
        for j in 0..2 * m {
            let (i0, j0) = (i / 2, j / 2);
            let (i1, j1) = (i0 + i % 2, j0 + j % 2);
            fine[i * 2 * m + j] = 0.25 * (at(i0, j0) + at(i1, j0) + at(i0, j1) + at(i1, j1));
        }
    }
    fine
}

/// The discrete problem on one grid: per node around the bearing, the coupling to its western
/// neighbour, the axial coupling, the right-hand side g and the geometry for the integrals.
struct Field {
    grid: Grid,
    over_relaxation: f64,
    dz: f64,
    dxi: f64,
    west: Vec<f64>,
    axial: Vec<f64>,
    source: Vec<f64>,
    jacobian: Vec<f64>,
    h3: Vec<f64>,
    cos: Vec<f64>,
    sin: Vec<f64>,
}

/// Clustering of the nodes at the thinnest film, κ/ε in θ = ξ + κ sin ξ.
const CLUSTERING: f64 = 0.6;
/// Sweeps stop when no node changes by more than this fraction of the largest pressure (the
/// error is then about 1/(2 − ω) ≈ 30 times that).
const SWEEP_TOLERANCE: f64 = 1e-9;
/// A bound on the sweeps (never reached by the tables' grids: at most a few thousand).
const MAX_SWEEPS: usize = 200_000;

impl Field {
    fn new(lambda: f64, eps: f64, psi: f64, grid: Grid) -> Self {
        let (n, m) = (grid.circumferential, grid.axial);
        let kappa = CLUSTERING * eps;
        let dxi = TAU / n as f64;
        let dz = lambda / m as f64;
        let theta = |xi: f64| xi + kappa * math::sin(xi);
        let stretch = |xi: f64| 1.0 + kappa * math::cos(xi);
        let cube = |theta: f64| {
            let h = 1.0 + eps * math::cos(theta);
            h * h * h
        };
        // Young's optimal factor 2/(1 + √(1 − ρ²)) for the Jacobi radius ρ of the constant-
        // coefficient problem on the grid (periodic around, Dirichlet at one end).
        let (a, b) = ((1.0 / dxi).powi(2), (1.0 / dz).powi(2));
        let rho = (a * math::cos(PI / n as f64) + b * math::cos(PI / (2 * m) as f64)) / (a + b);
        let mut field = Self {
            grid,
            over_relaxation: 2.0 / (1.0 + (1.0 - rho * rho).sqrt()),
            dz,
            dxi,
            west: vec![0.0; n],
            axial: vec![0.0; n],
            source: vec![0.0; n],
            jacobian: vec![0.0; n],
            h3: vec![0.0; n],
            cos: vec![0.0; n],
            sin: vec![0.0; n],
        };
        for i in 0..n {
            let xi = i as f64 * dxi;
            let face = xi - 0.5 * dxi;
            field.west[i] = cube(theta(face)) / (stretch(face) * dxi * dxi);
            let (th, j) = (theta(xi), stretch(xi));
            field.h3[i] = cube(th);
            field.axial[i] = j * field.h3[i] / (dz * dz);
            field.source[i] = -j * math::cos(th - psi);
            field.jacobian[i] = j;
            (field.sin[i], field.cos[i]) = math::sin_cos(th);
        }
        field
    }

    /// Projected over-relaxation from `p` (reset to zeros unless of the grid's size) to
    /// convergence, then the film's integrals.
    fn solve(&self, p: &mut Vec<f64>) -> FilmSolution {
        let (n, m) = (self.grid.circumferential, self.grid.axial);
        if p.len() != n * m {
            *p = vec![0.0; n * m];
        }
        for _ in 0..MAX_SWEEPS {
            let (mut change, mut largest) = (0.0f64, f64::MIN_POSITIVE);
            for i in 0..n {
                let (iw, ie) = ((i + n - 1) % n, (i + 1) % n);
                let (cw, ce, cz) = (self.west[i], self.west[ie], self.axial[i]);
                let diagonal = cw + ce + 2.0 * cz;
                for j in 0..m {
                    let k = i * m + j;
                    let north = if j + 1 < m { p[k + 1] } else { 0.0 };
                    // symmetry about mid-length: the node below j = 0 mirrors j = 1
                    let south = match j {
                        0 if m > 1 => p[k + 1],
                        0 => 0.0,
                        _ => p[k - 1],
                    };
                    let residual = self.source[i]
                        + cw * p[iw * m + j]
                        + ce * p[ie * m + j]
                        + cz * (north + south);
                    let new = (p[k] + self.over_relaxation * (residual / diagonal - p[k])).max(0.0);
                    change = change.max((new - p[k]).abs());
                    largest = largest.max(new);
                    p[k] = new;
                }
            }
            if change <= SWEEP_TOLERANCE * largest {
                break;
            }
        }
        self.integrals(p)
    }

    fn integrals(&self, p: &[f64]) -> FilmSolution {
        let (n, m) = (self.grid.circumferential, self.grid.axial);
        let (mut force, mut side_flow) = ([0.0; 2], 0.0);
        for i in 0..n {
            let around = self.dxi * self.jacobian[i];
            for j in 0..m {
                // trapezoidal over [0, λ] (P = 0 at the end), doubled for the whole length
                let w = 2.0 * around * self.dz * if j == 0 { 0.5 } else { 1.0 };
                force[0] += w * p[i * m + j] * self.cos[i];
                force[1] += w * p[i * m + j] * self.sin[i];
            }
            let last = p[i * m + m - 1];
            let before = if m > 1 { p[i * m + m - 2] } else { 0.0 };
            side_flow += around * self.h3[i] * (4.0 * last - before) / (2.0 * self.dz);
        }
        FilmSolution {
            force,
            peak: self.peak(p),
            side_flow,
        }
    }

    /// The vertex of the parabola (in ξ) through the largest mid-length node and its two
    /// neighbours around the bearing.
    fn peak(&self, p: &[f64]) -> f64 {
        let (n, m) = (self.grid.circumferential, self.grid.axial);
        let mid = |i: usize| p[(i % n) * m];
        let top = (0..n)
            .max_by(|&a, &b| mid(a).total_cmp(&mid(b)))
            .unwrap_or(0);
        let (w, c, e) = (mid(top + n - 1), mid(top), mid(top + 1));
        let curvature = w - 2.0 * c + e;
        if curvature < 0.0 {
            c - 0.125 * (e - w) * (e - w) / curvature
        } else {
            c
        }
    }
}

/// Raimondi & Boyd's Sommerfeld number S = (R/c)² μN/(W/(LD)) of a steadily loaded bearing
/// (ψ = −π/2) from the dimensionless force of its film: S = λ/(3π ε |f|).
pub fn sommerfeld_number(lambda: f64, eps: f64, solution: &FilmSolution) -> f64 {
    lambda / (3.0 * PI * eps * math::hypot(solution.force[0], solution.force[1]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The short-bearing limit: at λ = 1/64 the film is Ocvirk's, whose force is
    /// (2/3) λ³ ∫ (−cos(θ − ψ))⁺ (cos θ, sin θ)/H³ dθ and whose side flow is q = 2λ (to 1e-3:
    /// the finite film's correction is of order λ²/(1 − ε)).
    #[test]
    fn a_very_short_bearing_has_ocvirks_film() {
        let (lambda, eps, psi) = (1.0 / 64.0, 0.5, -1.2);
        let s = solve(
            lambda,
            eps,
            psi,
            Grid::for_ratio(lambda),
            &mut Workspace::default(),
        );
        let k = 200_000;
        let mut f = [0.0; 2];
        for i in 0..k {
            let th = (i as f64 + 0.5) * TAU / k as f64;
            let h = 1.0 + eps * math::cos(th);
            let p = (-math::cos(th - psi)).max(0.0) / (h * h * h) * TAU / k as f64;
            f[0] += p * math::cos(th);
            f[1] += p * math::sin(th);
        }
        let scale = 2.0 / 3.0 * lambda.powi(3);
        let magnitude = scale * math::hypot(f[0], f[1]);
        for c in 0..2 {
            assert!(
                (s.force[c] - scale * f[c]).abs() < 1e-3 * magnitude,
                "{:?} vs {:?}",
                s.force,
                f
            );
        }
        assert!((s.side_flow - 2.0 * lambda).abs() < 1e-3 * 2.0 * lambda);
    }
}
