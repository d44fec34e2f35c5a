//! Sparse non-negative least squares: the active-set method of Lawson and Hanson, stopped as soon
//! as the residual is small enough.
//!
//! ```text
//! min ‖G x − b‖₂   subject to x ≥ 0
//! ```
//! Starting from x = 0, each outer iteration frees the column with the largest gradient
//! component w = Gᵀ(b − G x) and solves the unconstrained problem on the free set P; if a free
//! variable would turn negative, the step is shortened to the boundary and that variable is
//! fixed at 0 again. Stopped at ‖G x − b‖ ≤ τ ‖b‖, the solution has few non-zero entries: this is
//! what energy-conserving sampling and weighting uses to pick quadrature points.
//!
//! # References
//! - C. L. Lawson, R. J. Hanson (1974), Solving Least Squares Problems, ch. 23 (algorithm NNLS).
//! - C. Farhat, T. Chapman, P. Avery (2015), Int. J. Numer. Meth. Eng. 102, 1077–1110 (the
//!   early stop for sparse ECSW weights).

use faer::linalg::solvers::SolveLstsq;
use faer::{Mat, MatRef};

/// The free variables' unconstrained least-squares solution z_P of ‖G_P z − b‖.
fn free_solution(g: MatRef<'_, f64>, b: &[f64], free: &[usize]) -> Vec<f64> {
    let g_free = Mat::from_fn(g.nrows(), free.len(), |i, k| g[(i, free[k])]);
    let rhs = Mat::from_fn(b.len(), 1, |i, _| b[i]);
    let z = g_free.qr().solve_lstsq(&rhs);
    (0..free.len()).map(|k| z[(k, 0)]).collect()
}

/// b − G x.
fn residual(g: MatRef<'_, f64>, b: &[f64], x: &[f64]) -> Vec<f64> {
    let gx = g * MatRef::from_column_major_slice(x, x.len(), 1);
    (0..g.nrows()).map(|i| b[i] - gx[(i, 0)]).collect()
}

/// Relative residual ‖G x − b‖ / ‖b‖.
pub fn relative_residual(g: MatRef<'_, f64>, b: &[f64], x: &[f64]) -> f64 {
    let norm = |v: &[f64]| v.iter().map(|v| v * v).sum::<f64>().sqrt();
    norm(&residual(g, b, x)) / norm(b)
}

/// The sparse x ≥ 0 found by Lawson–Hanson's active-set iterations (see the module docs),
/// stopped at ‖G x − b‖ ≤ `tolerance` ‖b‖ or at the constrained optimum, whichever comes first;
/// returned with its relative residual.
pub fn nnls(g: MatRef<'_, f64>, b: &[f64], tolerance: f64) -> (Vec<f64>, f64) {
    let n = g.ncols();
    let mut x = vec![0.0; n];
    let mut free: Vec<usize> = Vec::new();
    // Columns whose entry failed in round-off (their free solution not positive) since x last
    // changed.
    let mut refused: Vec<usize> = Vec::new();
    for _ in 0..3 * n {
        if relative_residual(g, b, &x) <= tolerance {
            break;
        }
        let r = residual(g, b, &x);
        let gradient = g.transpose() * MatRef::from_column_major_slice(&r, r.len(), 1);
        let entering = (0..n)
            .filter(|j| !free.contains(j) && !refused.contains(j))
            .map(|j| (j, gradient[(j, 0)]))
            .filter(|&(_, w)| w > 0.0)
            .max_by(|a, b| a.1.total_cmp(&b.1));
        let Some((j, _)) = entering else {
            break;
        };
        free.push(j);
        if free_solution(g, b, &free).last().is_none_or(|&z| z <= 0.0) {
            free.pop();
            refused.push(j);
            continue;
        }
        refused.clear();
        // Each pass fixes at least one free variable at 0, or ends.
        while !free.is_empty() {
            let z = free_solution(g, b, &free);
            if z.iter().all(|&v| v > 0.0) {
                for (&k, &v) in free.iter().zip(&z) {
                    x[k] = v;
                }
                break;
            }
            // Step from x towards z until the first free variable reaches 0, and fix it there.
            let Some((first, alpha)) = free
                .iter()
                .zip(&z)
                .filter(|&(_, &v)| v <= 0.0)
                .map(|(&k, &v)| (k, x[k] / (x[k] - v)))
                .min_by(|a, b| a.1.total_cmp(&b.1))
            else {
                break;
            };
            for (&k, &v) in free.iter().zip(&z) {
                x[k] += alpha * (v - x[k]);
            }
            x[first] = 0.0;
            free.retain(|&k| x[k] > 0.0);
            for (k, xk) in x.iter_mut().enumerate() {
                if !free.contains(&k) {
                    *xk = 0.0;
                }
            }
        }
    }
    let reached = relative_residual(g, b, &x);
    (x, reached)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn matrix() -> Mat<f64> {
        let rows = [
            [1.0, 0.0, 1.0],
            [0.0, 1.0, 1.0],
            [1.0, 1.0, 0.0],
            [2.0, 0.0, 1.0],
        ];
        Mat::from_fn(4, 3, |i, j| rows[i][j])
    }

    fn product(g: MatRef<'_, f64>, x: &[f64]) -> Vec<f64> {
        (0..g.nrows())
            .map(|i| (0..g.ncols()).map(|j| g[(i, j)] * x[j]).sum())
            .collect()
    }

    /// An exactly solvable problem with a positive solution is solved to round-off.
    #[test]
    fn a_positive_solution_is_found() {
        let g = matrix();
        let x_true = [0.5, 2.0, 1.0];
        let (x, reached) = nnls(g.as_ref(), &product(g.as_ref(), &x_true), 1e-12);
        assert!(reached <= 1e-12, "{reached}");
        for (a, e) in x.iter().zip(x_true) {
            assert!((a - e).abs() < 1e-10, "{x:?}");
        }
    }

    /// When the unconstrained solution has a negative entry, the result is the best x ≥ 0: the
    /// same as the best over every choice of free set, found by enumeration.
    #[test]
    fn a_bound_solution_is_the_constrained_optimum() {
        let g = matrix();
        let b = product(g.as_ref(), &[1.0, -1.0, 0.0]);
        let (x, reached) = nnls(g.as_ref(), &b, 0.0);
        assert!(
            x.iter().all(|&v| v >= 0.0) && reached > 0.1,
            "{x:?} {reached}"
        );
        let best = (1..8usize)
            .filter_map(|mask| {
                let free: Vec<usize> = (0..3).filter(|j| mask & (1 << j) != 0).collect();
                let z = free_solution(g.as_ref(), &b, &free);
                z.iter().all(|&v| v >= 0.0).then(|| {
                    let mut x = vec![0.0; 3];
                    for (&k, &v) in free.iter().zip(&z) {
                        x[k] = v;
                    }
                    relative_residual(g.as_ref(), &b, &x)
                })
            })
            .fold(f64::INFINITY, f64::min);
        assert!((reached - best).abs() < 1e-12, "{reached} vs {best}");
    }
}
