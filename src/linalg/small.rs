//! Cholesky solve of a symmetric positive definite system of at most six rows, on the stack.
//!
//! ```text
//! S = L Lᵀ,   S x = r  ⇔  L y = r,  Lᵀ x = y
//! ```
//! Used for the mechanism's constraint (Schur-complement) system C W Cᵀ λ = r, whose size is the
//! number of active constraint rows.
//!
//! # References
//! - G. H. Golub, C. F. Van Loan (2013), Matrix Computations, 4th ed., §4.2.5 (Algorithm 4.2.1).

use crate::error::ModelError;

/// Largest system size.
pub const MAX: usize = 6;

/// Solves S x = r for the leading k × k block of `s` (k ≤ [`MAX`]) in place of `r`; entries of
/// `r` beyond k are left as they are. Fails if S is not numerically positive definite, with
/// `singular` as the message.
pub fn cholesky_solve(
    s: &[[f64; MAX]; MAX],
    k: usize,
    r: &mut [f64; MAX],
    singular: &str,
) -> Result<(), ModelError> {
    let mut l = [[0.0; MAX]; MAX];
    for i in 0..k {
        for j in 0..=i {
            let sum = s[i][j] - (0..j).map(|m| l[i][m] * l[j][m]).sum::<f64>();
            if i == j {
                if !(sum > 0.0 && sum.is_finite()) {
                    return Err(ModelError::Numerical(singular.into()));
                }
                l[i][i] = sum.sqrt();
            } else {
                l[i][j] = sum / l[j][j];
            }
        }
    }
    for i in 0..k {
        r[i] = (r[i] - (0..i).map(|m| l[i][m] * r[m]).sum::<f64>()) / l[i][i];
    }
    for i in (0..k).rev() {
        r[i] = (r[i] - (i + 1..k).map(|m| l[m][i] * r[m]).sum::<f64>()) / l[i][i];
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_leading_block_and_refuses_a_singular_one() {
        // S = [[4, 2], [2, 3]], r = [2, 1] → x = [0.5, 0].
        let mut s = [[0.0; MAX]; MAX];
        s[0][0] = 4.0;
        s[0][1] = 2.0;
        s[1][0] = 2.0;
        s[1][1] = 3.0;
        let mut r = [2.0, 1.0, 7.0, 0.0, 0.0, 0.0];
        cholesky_solve(&s, 2, &mut r, "singular").unwrap();
        assert!((r[0] - 0.5).abs() < 1e-15 && r[1].abs() < 1e-15);
        assert_eq!(r[2], 7.0);
        s[1][1] = 1.0;
        let message = cholesky_solve(&s, 2, &mut r, "singular").unwrap_err();
        assert_eq!(message.to_string(), "singular");
    }
}
