//! Gauss–Legendre quadrature on an interval.
//!
//! An n-point rule integrates polynomials of degree 2n − 1 exactly.
//!
//! # References
//! - M. Abramowitz, I. Stegun (1964), Handbook of Mathematical Functions, Table 25.4.

/// A Gauss–Legendre rule on the reference interval [−1, 1].
#[derive(Clone, Copy, Debug)]
pub struct GaussRule {
    /// Abscissae on [−1, 1].
    pub points: &'static [f64],
    /// Weights (they sum to 2).
    pub weights: &'static [f64],
}

/// 2 points, exact to degree 3.
pub const GAUSS_2: GaussRule = GaussRule {
    points: &[-0.577_350_269_189_625_8, 0.577_350_269_189_625_8],
    weights: &[1.0, 1.0],
};

/// 3 points, exact to degree 5.
pub const GAUSS_3: GaussRule = GaussRule {
    points: &[-0.774_596_669_241_483_4, 0.0, 0.774_596_669_241_483_4],
    weights: &[5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0],
};

/// 4 points, exact to degree 7.
pub const GAUSS_4: GaussRule = GaussRule {
    points: &[
        -0.861_136_311_594_052_6,
        -0.339_981_043_584_856_3,
        0.339_981_043_584_856_3,
        0.861_136_311_594_052_6,
    ],
    weights: &[
        0.347_854_845_137_453_9,
        0.652_145_154_862_546_1,
        0.652_145_154_862_546_1,
        0.347_854_845_137_453_9,
    ],
};

/// 5 points, exact to degree 9.
pub const GAUSS_5: GaussRule = GaussRule {
    points: &[
        -0.906_179_845_938_664,
        -0.538_469_310_105_683_1,
        0.0,
        0.538_469_310_105_683_1,
        0.906_179_845_938_664,
    ],
    weights: &[
        0.236_926_885_056_189_1,
        0.478_628_670_499_366_5,
        0.568_888_888_888_888_9,
        0.478_628_670_499_366_5,
        0.236_926_885_056_189_1,
    ],
};

impl GaussRule {
    /// Abscissae ξ ∈ [0, 1] and weights scaled to an interval of length `l`: ∫₀ˡ f dx ≈ Σ wᵢ f(ξᵢ l).
    pub fn on_unit_interval(&self, l: f64) -> impl Iterator<Item = (f64, f64)> + '_ {
        (0..self.points.len()).map(move |i| self.unit_node(i, l))
    }

    /// The `i`-th abscissa mapped to ξ ∈ [0, 1] and its weight scaled to an interval of length `l`.
    pub fn unit_node(&self, i: usize, l: f64) -> (f64, f64) {
        (0.5 * (self.points[i] + 1.0), 0.5 * self.weights[i] * l)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ∫₀¹ ξᵏ dξ = 1/(k+1) exactly up to the rule's degree; the next degree is not exact.
    #[test]
    fn rules_are_exact_to_their_degree() {
        for (rule, n) in [(GAUSS_2, 2), (GAUSS_3, 3), (GAUSS_4, 4), (GAUSS_5, 5)] {
            for k in 0..2 * n {
                let q: f64 = rule.on_unit_interval(1.0).map(|(x, w)| w * x.powi(k)).sum();
                let exact = 1.0 / f64::from(k + 1);
                assert!(
                    (q - exact).abs() < 1e-15,
                    "{n}-pt rule, degree {k}: {q} vs {exact}"
                );
            }
            let k = 2 * n;
            let q: f64 = rule.on_unit_interval(1.0).map(|(x, w)| w * x.powi(k)).sum();
            assert!(
                (q - 1.0 / f64::from(k + 1)).abs() > 1e-8,
                "{n}-pt rule exact beyond degree"
            );
        }
    }
}
