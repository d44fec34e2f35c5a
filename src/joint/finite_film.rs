//! The finite bearing's film, fast enough for every right-hand side: the Reynolds solution of
//! [`super::reynolds`] tabulated once over the length-to-diameter ratio λ = L/D, the eccentricity
//! ratio ε and the squeeze direction ψ, as ratios to the short film of the same state, and
//! interpolated with continuous first derivatives.
//!
//! ```text
//! F_finite     = |F_short| (T_r n + T_t t)        T_r, T_t: the finite force over the short one's magnitude
//! p_max,finite = T_p p_max,short                   (both at mid-length)
//! Q_s,finite   = T_q Q_s,short = T_q c R L A       (side flow out of both ends)
//! T(λ, ε, ψ) = ( 3 f / (λ³ |I|),  2 P_max / (λ² I_p),  q / (2λ) )
//! ```
//! with f, P_max, q the dimensionless Reynolds solution (V = 1) and I = ∫ 2 sin(θ − θ₁)/(1 +
//! ε cos θ)³ (cos θ, sin θ) dθ, I_p the short film's largest sin(θ − θ₁)/(1 + ε cos θ)³
//! ([`super::short_film`]). Dividing by the short film takes out the steep growth as ε → 1 and the
//! sharp turn of the force where the pressure region's edge crosses the thinnest film (ψ near
//! ±π/2), which the short film shares; T is smooth and tends to (the short force's direction, 1,
//! 1) as λ → 0.
//!
//! The table (`film_table.bin`, written by `examples/film_table.rs`): λ_k = 2^{k/2}/64 for
//! k = 0 … 16 (1/64 … 4), σ_i = √(1 − ε_i) = 1 − 0.9 i/24 for i = 0 … 24 (ε 0 … 0.99, nodes
//! dense towards the wall), ψ_j = jπ/36 for j = 0 … 36 (ψ < 0 by mirror symmetry: T_r, T_p, T_q
//! even, T_t odd), four ratios per node as little-endian f32 after the header
//! `FSCFILM1` and the three node counts and the ratio count as u32. Each node is the Richardson
//! extrapolation of the finite-difference solution on two grids.
//!
//! For one bearing ([`FiniteFilm::new`]) the ratios are interpolated in λ by four-point Lagrange
//! interpolation in ln λ of g(λ) T, g = 1 + λ²/(1 − ε) for force and peak and its square root
//! for the flow (T falls as 1/λ² resp. 1/λ for a long bearing; g makes the interpolated
//! quantity level), and below λ₀ = 1/64 linearly in λ² towards the short film at λ = 0. Over
//! (σ, ψ) they are interpolated by bicubic Hermite patches whose slopes are those of cubic
//! splines through the nodes (periodic in ψ), so the force is continuously differentiable in
//! the state and Newton's method on it converges. Measured against direct Reynolds solutions at the
//! cells' centres (docs/design.md): force within 0.05 % up to ε = 0.95 and 0.3 % up to 0.99, side
//! flow within 0.02 %, peak pressure within 2 % (L/D 1; 0.9 % at L/D 1/2); the λ interpolation
//! adds at most 0.2 %.
//!
//! Validity: 0 < L/D ≤ 4, 0 ≤ ε ≤ 0.99 (the film is clamped at the switch eccentricity ε_b ≤ 0.99
//! above which dry contact takes over). Positive-pressure (Reynolds) cavitation, not mass
//! conserving; isoviscous, rigid surfaces, aligned journal.

use std::sync::Arc;

use super::reynolds::{self, Grid, Workspace};
use super::short_film::FilmField;
use crate::error::{ModelError, Num};
use crate::math;

/// The tabulated ratios, as written by `examples/film_table.rs`.
static TABLE: &[u8] = include_bytes!("film_table.bin");

/// The table's header.
pub const MAGIC: &[u8; 8] = b"FSCFILM1";
/// Number of λ nodes.
pub const RATIO_NODES: usize = 17;
/// Number of ε nodes.
pub const ECCENTRICITY_NODES: usize = 25;
/// Number of ψ nodes over [0, π].
pub const DIRECTION_NODES: usize = 37;
/// Ratios per node: force (radial, tangential), peak pressure, side flow.
pub const RATIOS: usize = 4;
/// The largest length-to-diameter ratio tabulated.
pub const MAX_LENGTH_RATIO: f64 = 4.0;
/// The largest eccentricity ratio tabulated.
pub const MAX_ECCENTRICITY: f64 = 0.99;

/// λ_k = 2^{k/2}/64.
pub fn ratio_node(k: usize) -> f64 {
    math::powf(2.0, k as f64 / 2.0) / 64.0
}

/// σ_i = √(1 − ε_i) = 1 − 0.9 i/24: the eccentricity node ε_i.
pub fn eccentricity_node(i: usize) -> f64 {
    let sigma = sigma_node(i as f64);
    1.0 - sigma * sigma
}

fn sigma_node(x: f64) -> f64 {
    1.0 - 0.9 * x / (ECCENTRICITY_NODES - 1) as f64
}

/// ψ_j = jπ/36.
pub fn direction_node(j: usize) -> f64 {
    j as f64 * std::f64::consts::PI / (DIRECTION_NODES - 1) as f64
}

/// The finite film's ratios to the short film (module documentation) at one state, from a
/// Reynolds solution with `work` as the warm start: [T_r, T_t, T_p, T_q].
pub fn ratios(lambda: f64, eps: f64, psi: f64, work: &mut Workspace) -> [f64; RATIOS] {
    let film = reynolds::solve(lambda, eps, psi, Grid::for_ratio(lambda), work);
    let short = FilmField::of_squeeze(eps, psi);
    let (f_r, f_t) = short.force();
    let scale = 3.0 / (lambda * lambda * lambda * math::hypot(f_r, f_t));
    [
        scale * film.force[0],
        scale * film.force[1],
        2.0 * film.peak / (lambda * lambda * short.peak_shape()),
        film.side_flow / (2.0 * lambda),
    ]
}

/// The table file's bytes from the ratios at every node, in the order λ, ε, ψ.
pub fn table_bytes(values: &[[f64; RATIOS]]) -> Vec<u8> {
    let mut bytes = MAGIC.to_vec();
    for count in [RATIO_NODES, ECCENTRICITY_NODES, DIRECTION_NODES, RATIOS] {
        bytes.extend_from_slice(&(count as u32).to_le_bytes());
    }
    for value in values.iter().flatten() {
        bytes.extend_from_slice(&(*value as f32).to_le_bytes());
    }
    bytes
}

/// The ratio `r` at λ node `k`, ε node `i`, ψ node `j` of the embedded table.
fn tabulated(k: usize, i: usize, j: usize, r: usize) -> Result<f64, ModelError> {
    let header = MAGIC.len() + 16;
    let at = header + 4 * (((k * ECCENTRICITY_NODES + i) * DIRECTION_NODES + j) * RATIOS + r);
    TABLE
        .get(at..at + 4)
        .and_then(|b| b.try_into().ok())
        .map(|b| f64::from(f32::from_le_bytes(b)))
        .ok_or_else(|| ModelError::Numerical("the finite film's table is truncated".into()))
}

fn check_table() -> Result<(), ModelError> {
    let counts = [RATIO_NODES, ECCENTRICITY_NODES, DIRECTION_NODES, RATIOS]
        .iter()
        .flat_map(|&c| (c as u32).to_le_bytes())
        .collect::<Vec<_>>();
    let expected =
        MAGIC.len() + 16 + 4 * RATIO_NODES * ECCENTRICITY_NODES * DIRECTION_NODES * RATIOS;
    if !TABLE.starts_with(MAGIC)
        || TABLE[MAGIC.len()..MAGIC.len() + 16] != counts[..]
        || TABLE.len() != expected
    {
        return Err(ModelError::Numerical(
            "the finite film's table does not match its format (regenerate it with examples/film_table.rs)".into(),
        ));
    }
    Ok(())
}

/// Nodes around the bearing of the interpolation grid: the ψ nodes mirrored to a full period.
const AROUND: usize = 2 * (DIRECTION_NODES - 1);

/// The finite film of one bearing (λ fixed): the ratios at every (ε, ψ) node with the slopes of
/// their bicubic Hermite patches, shared between clones (it is constant).
#[derive(Clone, Debug, PartialEq)]
pub struct FiniteFilm {
    lambda: f64,
    patches: Arc<Patches>,
}

/// Per ratio and node (σ index i, ψ index j around the full period): value, ∂/∂i, ∂/∂j, ∂²/∂i∂j
/// in index units.
#[derive(Debug, PartialEq)]
struct Patches {
    nodes: Vec<[[f64; 4]; RATIOS]>,
}

impl FiniteFilm {
    /// The film of a bearing with length-to-diameter ratio `lambda` ∈ (0, [`MAX_LENGTH_RATIO`]].
    pub fn new(lambda: f64) -> Result<Self, ModelError> {
        if !(lambda > 0.0 && lambda <= MAX_LENGTH_RATIO) {
            return Err(ModelError::Numerical(format!(
                "the finite film is tabulated for a length-to-diameter ratio in (0, {}], not {}",
                Num(MAX_LENGTH_RATIO),
                Num(lambda)
            )));
        }
        check_table()?;
        let mut values = vec![[0.0; RATIOS]; ECCENTRICITY_NODES * AROUND];
        for i in 0..ECCENTRICITY_NODES {
            let eps = eccentricity_node(i);
            for j in 0..DIRECTION_NODES {
                let mut t = at_ratio(lambda, eps, i, j)?;
                if j == 0 || j == DIRECTION_NODES - 1 {
                    // ψ = 0 and π are their own mirror images: no tangential force
                    t[1] = 0.0;
                }
                // ψ_j ≥ 0 at index j + 36 of the full period, its mirror −ψ_j at 36 − j
                values[i * AROUND + (j + DIRECTION_NODES - 1) % AROUND] = t;
                let mirrored = [t[0], -t[1], t[2], t[3]];
                values[i * AROUND + (DIRECTION_NODES - 1 - j) % AROUND] = mirrored;
            }
        }
        Ok(Self {
            lambda,
            patches: Arc::new(Patches::new(&values)),
        })
    }

    /// The length-to-diameter ratio.
    pub fn length_ratio(&self) -> f64 {
        self.lambda
    }

    /// The ratios [T_r, T_t, T_p, T_q] at eccentricity ratio `eps` (≤ 0.99) and squeeze
    /// direction (cos ψ, sin ψ).
    pub fn ratios_at(&self, eps: f64, direction: (f64, f64)) -> [f64; RATIOS] {
        let (x, y) = coordinates(eps, direction);
        self.patches.at(x, y, 0)
    }

    /// The force's ratios [T_r, T_t] alone (what every right-hand side needs), as
    /// [`FiniteFilm::ratios_at`] gives them.
    pub fn force_ratios_at(&self, eps: f64, direction: (f64, f64)) -> [f64; 2] {
        let (x, y) = coordinates(eps, direction);
        self.patches.at(x, y, 0)
    }
}

/// The interpolation grid's index coordinates (x along ε, y around ψ) of a state.
fn coordinates(eps: f64, (cos, sin): (f64, f64)) -> (f64, f64) {
    let x = (1.0 - (1.0 - eps.clamp(0.0, MAX_ECCENTRICITY)).sqrt()) / 0.9
        * (ECCENTRICITY_NODES - 1) as f64;
    let psi = math::atan2(sin, cos);
    (x, (psi / std::f64::consts::PI + 1.0) * (AROUND / 2) as f64)
}

/// The ratios at λ for ε node `i` (ε = `eps`) and ψ node `j`, interpolated over the λ nodes
/// (module documentation).
fn at_ratio(lambda: f64, eps: f64, i: usize, j: usize) -> Result<[f64; RATIOS], ModelError> {
    let level = |lam: f64, r: usize| {
        let g = 1.0 + lam * lam / (1.0 - eps);
        if r == 3 { g.sqrt() } else { g }
    };
    let mut out = [0.0; RATIOS];
    let first = ratio_node(0);
    if lambda < first {
        let short = FilmField::of_squeeze(eps, direction_node(j));
        let (f_r, f_t) = short.force();
        let magnitude = math::hypot(f_r, f_t);
        let limit = [f_r / magnitude, f_t / magnitude, 1.0, 1.0];
        let s = (lambda / first) * (lambda / first);
        for (r, o) in out.iter_mut().enumerate() {
            *o = (1.0 - s) * limit[r] + s * tabulated(0, i, j, r)?;
        }
        return Ok(out);
    }
    let x = math::ln(lambda / first) / std::f64::consts::LN_2 * 2.0;
    let start = (x.floor() as usize).saturating_sub(1).min(RATIO_NODES - 4);
    for (r, o) in out.iter_mut().enumerate() {
        let mut sum = 0.0;
        for a in start..start + 4 {
            let mut weight = 1.0;
            for b in (start..start + 4).filter(|&b| b != a) {
                weight *= (x - b as f64) / (a as f64 - b as f64);
            }
            let lam = ratio_node(a);
            sum += weight * level(lam, r) * tabulated(a, i, j, r)?;
        }
        *o = sum / level(lambda, r);
    }
    Ok(out)
}

impl Patches {
    /// The patches through `values` (ε nodes × the full period of ψ nodes).
    fn new(values: &[[f64; RATIOS]]) -> Self {
        let (rows, cols) = (ECCENTRICITY_NODES, AROUND);
        let mut nodes = vec![[[0.0; 4]; RATIOS]; rows * cols];
        for r in 0..RATIOS {
            let value = |i: usize, j: usize| values[i * cols + j][r];
            let mut d_i = vec![0.0; rows * cols];
            let mut d_j = vec![0.0; rows * cols];
            let mut d_ij = vec![0.0; rows * cols];
            for j in 0..cols {
                let column: Vec<f64> = (0..rows).map(|i| value(i, j)).collect();
                for (i, s) in spline_slopes(&column, false).into_iter().enumerate() {
                    d_i[i * cols + j] = s;
                }
            }
            for i in 0..rows {
                let row: Vec<f64> = (0..cols).map(|j| value(i, j)).collect();
                let row_i = &d_i[i * cols..(i + 1) * cols];
                for (j, (s, c)) in spline_slopes(&row, true)
                    .into_iter()
                    .zip(spline_slopes(row_i, true))
                    .enumerate()
                {
                    d_j[i * cols + j] = s;
                    d_ij[i * cols + j] = c;
                }
            }
            for (k, node) in nodes.iter_mut().enumerate() {
                node[r] = [values[k][r], d_i[k], d_j[k], d_ij[k]];
            }
        }
        Self { nodes }
    }

    /// The bicubic Hermite interpolant of the `N` ratios from `first` at index coordinates
    /// (x, y), x ∈ [0, 24], y periodic with period 72.
    fn at<const N: usize>(&self, x: f64, y: f64, first: usize) -> [f64; N] {
        let cols = AROUND;
        let i = (x.floor().max(0.0) as usize).min(ECCENTRICITY_NODES - 2);
        let u = x - i as f64;
        let y = y.rem_euclid(cols as f64);
        let j = (y.floor() as usize).min(cols - 1);
        let v = y - j as f64;
        let basis = |t: f64| {
            let (t2, t3) = (t * t, t * t * t);
            [
                [2.0 * t3 - 3.0 * t2 + 1.0, t3 - 2.0 * t2 + t],
                [-2.0 * t3 + 3.0 * t2, t3 - t2],
            ]
        };
        let (bu, bv) = (basis(u), basis(v));
        let mut out = [0.0; N];
        for (a, bu) in bu.iter().enumerate() {
            for (b, bv) in bv.iter().enumerate() {
                let node = &self.nodes[(i + a) * cols + (j + b) % cols][first..first + N];
                for (o, [f, f_i, f_j, f_ij]) in out.iter_mut().zip(node) {
                    *o += bu[0] * (bv[0] * f + bv[1] * f_j) + bu[1] * (bv[0] * f_i + bv[1] * f_ij);
                }
            }
        }
        out
    }
}

/// The slopes (per unit node spacing) of the cubic spline through equally spaced `y`: periodic,
/// or with the end slopes of the cubic through the four end nodes.
fn spline_slopes(y: &[f64], periodic: bool) -> Vec<f64> {
    let n = y.len();
    let at = |i: isize| y[i.rem_euclid(n as isize) as usize];
    let mut s: Vec<f64> = (0..n as isize)
        .map(|i| 0.5 * (at(i + 1) - at(i - 1)))
        .collect();
    let interior = if periodic {
        0..n
    } else {
        s[0] = (-11.0 * y[0] + 18.0 * y[1] - 9.0 * y[2] + 2.0 * y[3]) / 6.0;
        s[n - 1] = (11.0 * y[n - 1] - 18.0 * y[n - 2] + 9.0 * y[n - 3] - 2.0 * y[n - 4]) / 6.0;
        1..n - 1
    };
    // s_{i−1} + 4 s_i + s_{i+1} = 3 (y_{i+1} − y_{i−1}): diagonally dominant, Gauss–Seidel
    // contracts by 1/2 per sweep at least.
    let scale = y
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()))
        .max(f64::MIN_POSITIVE);
    for _ in 0..200 {
        let mut change = 0.0f64;
        for i in interior.clone() {
            let (w, e) = ((i + n - 1) % n, (i + 1) % n);
            let new = (3.0 * (y[e] - y[w]) - s[w] - s[e]) / 4.0;
            change = change.max((new - s[i]).abs());
            s[i] = new;
        }
        if change <= 1e-15 * scale {
            break;
        }
    }
    s
}

#[cfg(test)]
mod tests;
