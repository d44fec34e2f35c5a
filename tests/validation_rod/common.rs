//! Helpers shared by the rod validation tests: tolerant comparison, a rod with fixed coordinates
//! (static Newton solve, free dynamics), eigenfrequencies on a coordinate subset, a tiny PRNG.

use faer::{Mat, MatRef, Side, linalg::solvers::Solve};
use flexible_slider_crank::ModelError;
use flexible_slider_crank::ancf::{Rod, RodProperties};
use flexible_slider_crank::integrator::{DormandPrince, OdeSystem, Tolerances};
use flexible_slider_crank::reduction::{RodModel, generalized_eigen};

/// Fails with all four numbers unless |actual − expected| ≤ max(rel·|expected|, abs).
pub fn assert_close(actual: f64, expected: f64, rel: f64, abs: f64, what: &str) {
    let err = (actual - expected).abs();
    assert!(
        err <= (rel * expected.abs()).max(abs),
        "{what}: actual {actual:.12e}, expected {expected:.12e}, |error| {err:.3e} \
         (rel tol {rel:.1e}, abs tol {abs:.1e})"
    );
}

/// Deterministic uniform numbers in [−1, 1] (64-bit LCG, Knuth's MMIX constants).
pub struct Lcg(u64);

impl Lcg {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    pub fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
}

/// A slender rod for the elastica and cantilever checks: L = 1 m, EI = 1 N m², EA = 1e7 N
/// (axial strain under the largest load ≈ 1e-6, negligible against the inextensible elastica).
pub fn slender_rod(n_elements: usize) -> Rod {
    let properties = RodProperties {
        length: 1.0,
        youngs_modulus: 1e7,
        density: 1.0,
        area: 1.0,
        second_moment_of_area: 1e-7,
        // A rectangle of that I/A: height √(12 I/A) = 1.095 mm.
        outer_fibre_distance: 5.477e-4,
        stiffness_damping: 0.0,
        damping_ratio: 0.0,
        crank_end_mass: 0.0,
        slider_end_mass: 0.0,
    };
    Rod::new(properties, n_elements).unwrap()
}

/// Indices of `n` coordinates that are not in `fixed`.
pub fn complement(n: usize, fixed: &[usize]) -> Vec<usize> {
    (0..n).filter(|i| !fixed.contains(i)).collect()
}

/// Submatrix a[rows, cols].
pub fn submatrix(a: MatRef<'_, f64>, rows: &[usize], cols: &[usize]) -> Mat<f64> {
    Mat::from_fn(rows.len(), cols.len(), |i, j| a[(rows[i], cols[j])])
}

/// Static equilibrium Q_e(p) = s·F for s = 1/steps … 1 by Newton's method, with the coordinates in
/// `fixed` held at their values in `p`. Converged when ‖Δp‖ ≤ 1e-13 (1 + ‖p‖).
pub fn solve_static(
    model: &mut RodModel,
    p: &mut [f64],
    fixed: &[usize],
    load: &[f64],
    steps: usize,
) {
    let n = p.len();
    let free = complement(n, fixed);
    let mut q = vec![0.0; n];
    let mut k = Mat::zeros(n, n);
    for step in 1..=steps {
        let s = step as f64 / steps as f64;
        let mut converged = false;
        for _ in 0..50 {
            model.internal_force(p, &vec![0.0; n], &mut q);
            model.tangent_stiffness(p, k.as_mut());
            let k_ff = submatrix(k.as_ref(), &free, &free);
            let r = Mat::from_fn(free.len(), 1, |i, _| s * load[free[i]] - q[free[i]]);
            let dp = k_ff.partial_piv_lu().solve(&r);
            let norm_dp = (0..free.len())
                .map(|i| dp[(i, 0)].powi(2))
                .sum::<f64>()
                .sqrt();
            let norm_p = p.iter().map(|v| v * v).sum::<f64>().sqrt();
            for (i, &f) in free.iter().enumerate() {
                p[f] += dp[(i, 0)];
            }
            if norm_dp <= 1e-13 * (1.0 + norm_p) {
                converged = true;
                break;
            }
        }
        assert!(
            converged,
            "Newton did not converge at load step {step}/{steps}"
        );
    }
}

/// Angular frequencies ω [rad/s] of (k, m) restricted to the coordinates `keep`, ascending.
pub fn frequencies(k: MatRef<'_, f64>, m: MatRef<'_, f64>, keep: &[usize]) -> Vec<f64> {
    let modes = generalized_eigen(
        submatrix(k, keep, keep).as_ref(),
        submatrix(m, keep, keep).as_ref(),
    )
    .unwrap();
    modes
        .eigenvalues
        .iter()
        .map(|l| l.max(0.0).sqrt())
        .collect()
}

/// Free motion of a rod with some coordinates held fixed, under a constant load in model
/// coordinates: state y = [p_free, ṗ_free], M_ff p̈_f = F_f − Q_f(p, ṗ).
pub struct HeldRod {
    pub model: RodModel,
    free: Vec<usize>,
    p: Vec<f64>,
    p_dot: Vec<f64>,
    q: Vec<f64>,
    load: Vec<f64>,
    mass_ff: Mat<f64>,
    mass_llt: faer::linalg::solvers::Llt<f64>,
}

impl HeldRod {
    /// `p0`: initial model coordinates (the fixed ones keep these values).
    pub fn new(model: RodModel, fixed: &[usize], p0: &[f64], load: Vec<f64>) -> Self {
        let n = model.n_coordinates();
        let free = complement(n, fixed);
        let mass_ff = submatrix(model.mass_matrix(), &free, &free);
        let mass_llt = mass_ff.llt(Side::Lower).unwrap();
        Self {
            model,
            free,
            p: p0.to_vec(),
            p_dot: vec![0.0; n],
            q: vec![0.0; n],
            load,
            mass_ff,
            mass_llt,
        }
    }

    /// State vector from full model coordinates and velocities.
    pub fn state(&self, p: &[f64], p_dot: &[f64]) -> Vec<f64> {
        self.free
            .iter()
            .map(|&i| p[i])
            .chain(self.free.iter().map(|&i| p_dot[i]))
            .collect()
    }

    /// Full model coordinates of a state.
    pub fn coordinates(&mut self, y: &[f64]) -> Vec<f64> {
        self.scatter(y);
        self.p.clone()
    }

    fn scatter(&mut self, y: &[f64]) {
        let nf = self.free.len();
        for (i, &f) in self.free.iter().enumerate() {
            self.p[f] = y[i];
            self.p_dot[f] = y[nf + i];
        }
    }

    /// y' = [ṗ_f, M_ff⁻¹(F_f − Q_f)].
    fn derivative(&mut self, y: &[f64], dy: &mut [f64]) {
        let nf = self.free.len();
        self.scatter(y);
        self.model.internal_force(&self.p, &self.p_dot, &mut self.q);
        dy[..nf].copy_from_slice(&y[nf..]);
        let mut rhs = Mat::from_fn(nf, 1, |i, _| self.load[self.free[i]] - self.q[self.free[i]]);
        self.mass_llt.solve_in_place(rhs.as_mut());
        for i in 0..nf {
            dy[nf + i] = rhs[(i, 0)];
        }
    }

    /// Total energy ½ ṗᵀM ṗ + U(p) − Fᵀp (the constant load has potential −Fᵀp).
    pub fn energy(&mut self, y: &[f64]) -> f64 {
        let nf = self.free.len();
        self.scatter(y);
        let v = Mat::from_fn(nf, 1, |i, _| y[nf + i]);
        let kinetic = 0.5 * (v.transpose() * &self.mass_ff * &v)[(0, 0)];
        let work: f64 = self.load.iter().zip(&self.p).map(|(f, p)| f * p).sum();
        kinetic + self.model.strain_energy(&self.p) - work
    }

    /// Integrates from 0 to each time in `times` with the given relative tolerance, returning the
    /// states there.
    pub fn simulate(&mut self, y0: &[f64], times: &[f64], rtol: f64) -> Vec<Vec<f64>> {
        let tolerances = Tolerances {
            relative: rtol,
            absolute: rtol * 1e-3,
            max_step: 1.0,
            min_step: 1e-14,
        };
        let mut dp = DormandPrince::new(y0.len(), tolerances).unwrap();
        let (mut t, mut y) = (0.0, y0.to_vec());
        let mut out = Vec::with_capacity(times.len());
        for &t_out in times {
            dp.advance(self, &mut t, &mut y, t_out).unwrap();
            out.push(y.clone());
        }
        out
    }
}

impl OdeSystem for HeldRod {
    fn rhs(&mut self, _t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), ModelError> {
        self.derivative(y, dy);
        Ok(())
    }
}
