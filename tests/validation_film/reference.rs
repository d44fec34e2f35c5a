//! An independent finite-difference solution of the finite journal bearing, written for these
//! tests apart from the product's (`flexible_slider_crank::joint::reynolds`, which builds the
//! film tables): a uniform grid over the whole length (no symmetry), film cubes averaged between
//! nodes, Gauss–Seidel projection with a fixed over-relaxation, the side flow from the third-order
//! gradient at both ends, and the peak as the largest node.
//!
//! ```text
//! ∂/∂θ(H³ ∂P/∂θ) + ∂/∂z(H³ ∂P/∂z) = cos(θ − ψ) where P > 0,  P ≥ 0,  P(z = ±λ) = 0
//! H = 1 + ε cos θ,  θ from the thickest film,  z = axial/R,  λ = L/D
//! force (f_r, f_t) = ∫∫ P (cos θ, sin θ) dθ dz,  peak max P,  one end's flow q = ∫ H³ |∂P/∂z| dθ
//! ```
//! Its discretisation error on the grids used is below 0.5 % in force, peak and flow (measured by
//! doubling the grid, `reference_converges`).
//!
//! With an oil feed ([`solve_fed`]) the nodes inside the feed hold the supply pressure P_s, a
//! Dirichlet boundary like the ends, and the source may be scaled: 0 gives the feed's pressure
//! flow alone (∇·(H³ ∇P) = 0, nothing cavitates), 1 the turning journal's film with the feed in it.

use std::f64::consts::{PI, TAU};

use flexible_slider_crank::math::{cos, sin};

/// The dimensionless film: force (f_r, f_t), peak P and one end's side flow q.
#[derive(Clone, Copy, Debug)]
pub struct Film {
    pub force: [f64; 2],
    pub peak: f64,
    pub side_flow: f64,
}

/// The film at length-to-diameter ratio `lambda`, eccentricity ratio `eps` and squeeze direction
/// `psi` on `n` × (2m + 1) nodes (around × along, ends included).
pub fn solve(lambda: f64, eps: f64, psi: f64, n: usize, m: usize) -> Film {
    solve_fed(lambda, eps, (psi, 1.0), None, (n, m))
}

/// An oil feed for [`solve_fed`]: whether the node at (θ, z) lies in it, and its pressure P_s.
pub type Feed<'a> = (&'a dyn Fn(f64, f64) -> bool, f64);

/// The film of [`solve`] with the source cos(θ − ψ) scaled by `source` (`(psi, source)`) and
/// the nodes of `feed` held at its supply pressure.
pub fn solve_fed(
    lambda: f64,
    eps: f64,
    (psi, scale): (f64, f64),
    feed: Option<Feed>,
    (n, m): (usize, usize),
) -> Film {
    let nz = 2 * m + 1;
    let (dt, dz) = (TAU / n as f64, lambda / m as f64);
    let theta: Vec<f64> = (0..n).map(|i| i as f64 * dt).collect();
    let h3: Vec<f64> = theta
        .iter()
        .map(|&t| (1.0 + eps * cos(t)).powi(3))
        .collect();
    let east: Vec<f64> = (0..n)
        .map(|i| 0.5 * (h3[i] + h3[(i + 1) % n]) / (dt * dt))
        .collect();
    let source: Vec<f64> = theta.iter().map(|&t| -scale * cos(t - psi)).collect();
    let mut p = vec![0.0; n * nz];
    let mut fixed = vec![false; n * nz];
    if let Some((inside, supply)) = feed {
        for i in 0..n {
            for j in 1..nz - 1 {
                if inside(theta[i], -lambda + j as f64 * dz) {
                    fixed[i * nz + j] = true;
                    p[i * nz + j] = supply;
                }
            }
        }
    }
    let omega = 1.9;
    for _ in 0..100_000 {
        let mut change = 0.0f64;
        let mut largest = f64::MIN_POSITIVE;
        for i in 0..n {
            let w = (i + n - 1) % n;
            let (ce, cw, cz) = (east[i], east[w], h3[i] / (dz * dz));
            for j in 1..nz - 1 {
                let k = i * nz + j;
                if fixed[k] {
                    continue;
                }
                let sum = ce * p[((i + 1) % n) * nz + j]
                    + cw * p[w * nz + j]
                    + cz * (p[k + 1] + p[k - 1])
                    + source[i];
                let new = (p[k] + omega * (sum / (ce + cw + 2.0 * cz) - p[k])).max(0.0);
                change = change.max((new - p[k]).abs());
                largest = largest.max(new);
                p[k] = new;
            }
        }
        if change < 1e-10 * largest {
            break;
        }
    }
    let mut film = Film {
        force: [0.0; 2],
        peak: 0.0,
        side_flow: 0.0,
    };
    for i in 0..n {
        for j in 1..nz - 1 {
            let v = p[i * nz + j];
            film.force[0] += v * cos(theta[i]) * dt * dz;
            film.force[1] += v * sin(theta[i]) * dt * dz;
            film.peak = film.peak.max(v);
        }
        // both ends, by the cubic through the end and its three neighbours
        for (a, b, c) in [(1, 2, 3), (nz - 2, nz - 3, nz - 4)] {
            let gradient =
                (18.0 * p[i * nz + a] - 9.0 * p[i * nz + b] + 2.0 * p[i * nz + c]) / (6.0 * dz);
            film.side_flow += 0.5 * h3[i] * gradient * dt;
        }
    }
    film
}

/// The grid for these tests: 360 nodes around (720 above ε = 0.85), an axial spacing of about
/// 0.02 bearing radii with at least 8 intervals to each end.
pub fn film(lambda: f64, eps: f64, psi: f64) -> Film {
    let n = if eps > 0.85 { 720 } else { 360 };
    let m = ((lambda / 0.02).ceil() as usize).max(8);
    solve(lambda, eps, psi, n, m)
}

/// The steady load's squeeze direction: a journal turning at ω > 0 in a fixed bearing, ε̇ = 0.
pub const STEADY: f64 = -PI / 2.0;
