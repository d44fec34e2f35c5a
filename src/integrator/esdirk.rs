//! The ESDIRK5(4)7L[2]SA₂ tableau of Kennedy & Carpenter (2016) for the implicit integrator
//! ([`super::Implicit`]): a 7-stage, 5th-order, L-stable, stiffly accurate singly diagonally
//! implicit Runge–Kutta method with an explicit first stage and a 4th-order embedded error estimate.
//!
//! ```text
//! Yᵢ = yₙ + h Σⱼ₍ⱼ<ᵢ₎ aᵢⱼ Kⱼ + hγ f(Yᵢ),   Kᵢ = f(Yᵢ),   yₙ₊₁ = Y₇ (stiffly accurate),   γ = 23/125
//! err = h Σ (bᵢ − b̂ᵢ) Kᵢ
//! ```
//! L-stability (R(∞) = 0) damps unresolved high frequencies completely. The coefficients are those
//! of the paper's table of ESDIRK5(4)7L[2]SA₂ (stage order 2, all cᵢ in [0, 1]); a unit test checks
//! every order condition.
//!
//! # References
//! - C. A. Kennedy, M. H. Carpenter (2016), Diagonally implicit Runge–Kutta methods for ordinary
//!   differential equations. A review, NASA/TM–2016–219173, §5.5 (ESDIRK5(4)7L[2]SA₂).

/// Largest number of stages of a tableau.
pub const MAX_STAGES: usize = 7;

/// An ESDIRK Butcher tableau: explicit first stage, γ on the diagonal, stiffly accurate (last row
/// of A = b), padded to the largest supported stage count.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tableau {
    /// Number of stages s.
    pub stages: usize,
    /// Diagonal coefficient γ.
    pub gamma: f64,
    /// Coefficients aᵢⱼ.
    pub a: [[f64; MAX_STAGES]; MAX_STAGES],
    /// Weights b (= last row of A).
    pub b: [f64; MAX_STAGES],
    /// Embedded weights b̂.
    pub b_hat: [f64; MAX_STAGES],
    /// Nodes cᵢ = Σⱼ aᵢⱼ.
    pub c: [f64; MAX_STAGES],
    /// Order of the embedded solution (sets the step-size exponent 1/(p̂ + 1)).
    pub embedded_order: i32,
}

/// Builds a tableau from the published strictly lower entries (rows 2 .. s − 1, columns ≥ 1),
/// γ, the nodes and the weights: b₁ and b̂₁ complete Σ = 1, the first column completes the row
/// sums cᵢ, and the last row is b.
const fn tableau(
    stages: usize,
    gamma: f64,
    lower: [[f64; MAX_STAGES]; MAX_STAGES],
    c: [f64; MAX_STAGES],
    b_tail: [f64; MAX_STAGES],
    b_hat_tail: [f64; MAX_STAGES],
    embedded_order: i32,
) -> Tableau {
    let mut b = b_tail;
    let mut b_hat = b_hat_tail;
    let (mut sum, mut sum_hat) = (0.0, 0.0);
    let mut j = 1;
    while j < stages {
        sum += b[j];
        sum_hat += b_hat[j];
        j += 1;
    }
    b[0] = 1.0 - sum;
    b_hat[0] = 1.0 - sum_hat;
    let mut a = lower;
    a[stages - 1] = b;
    let mut i = 1;
    while i < stages - 1 {
        a[i][i] = gamma;
        let mut row = 0.0;
        let mut j = 1;
        while j <= i {
            row += a[i][j];
            j += 1;
        }
        a[i][0] = c[i] - row;
        i += 1;
    }
    Tableau {
        stages,
        gamma,
        a,
        b,
        b_hat,
        c,
        embedded_order,
    }
}

/// ESDIRK5(4)7L\[2\]SA₂ (Kennedy & Carpenter 2016): 5th order, 6 implicit stages, γ = 23/125.
pub const ESDIRK54: Tableau = {
    let mut lower = [[0.0; MAX_STAGES]; MAX_STAGES];
    lower[2][1] = 791_020_047_304.0 / 3_561_426_431_547.0;
    lower[3][1] = -158_159_076_358.0 / 11_257_294_102_345.0;
    lower[3][2] = -85_517_644_447.0 / 5_003_708_988_389.0;
    lower[4][1] = -1_653_327_111_580.0 / 4_048_416_487_981.0;
    lower[4][2] = 1_514_767_744_496.0 / 9_099_671_765_375.0;
    lower[4][3] = 14_283_835_447_591.0 / 12_247_432_691_556.0;
    lower[5][1] = -4_540_011_970_825.0 / 8_418_487_046_959.0;
    lower[5][2] = -1_790_937_573_418.0 / 7_393_406_387_169.0;
    lower[5][3] = 10_819_093_665_085.0 / 7_266_595_846_747.0;
    lower[5][4] = 4_109_463_131_231.0 / 7_386_972_500_302.0;
    tableau(
        7,
        23.0 / 125.0,
        lower,
        [
            0.0,
            46.0 / 125.0,
            7_121_331_996_143.0 / 11_335_814_405_378.0,
            49.0 / 353.0,
            3_706_679_970_760.0 / 5_295_570_149_437.0,
            347.0 / 382.0,
            1.0,
        ],
        [
            0.0,
            -188_593_204_321.0 / 4_778_616_380_481.0,
            2_809_310_203_510.0 / 10_304_234_040_467.0,
            1_021_729_336_898.0 / 2_364_210_264_653.0,
            870_612_361_811.0 / 2_470_410_392_208.0,
            -1_307_970_675_534.0 / 8_059_683_598_661.0,
            23.0 / 125.0,
        ],
        [
            0.0,
            -582_099_335_757.0 / 7_214_068_459_310.0,
            615_023_338_567.0 / 3_362_626_566_945.0,
            3_192_122_436_311.0 / 6_174_152_374_399.0,
            6_156_034_052_041.0 / 14_430_468_657_929.0,
            -1_011_318_518_279.0 / 9_693_750_372_484.0,
            1_914_490_192_573.0 / 13_754_262_428_401.0,
        ],
        4,
    )
};

#[cfg(test)]
mod tests {
    use super::*;

    /// The published coefficients satisfy every order condition: the 17 of order ≤ 5 for b and
    /// the 8 of order ≤ 4 for b̂ (rooted trees, Butcher), to round-off of 13-digit rationals.
    #[test]
    fn tableau_satisfies_the_order_conditions() {
        const S: usize = 7;
        let t = &ESDIRK54;
        assert_eq!(t.stages, S);
        let (a, b, b_hat) = (t.a, t.b, t.b_hat);
        let dot = |u: &[f64; S], v: &[f64; S]| (0..S).map(|i| u[i] * v[i]).sum::<f64>();
        let mul = |u: &[f64; S], v: &[f64; S]| -> [f64; S] { std::array::from_fn(|i| u[i] * v[i]) };
        let apply = |v: &[f64; S]| -> [f64; S] {
            std::array::from_fn(|i| (0..S).map(|j| a[i][j] * v[j]).sum())
        };
        let one = [1.0; S];
        let c = apply(&one);
        for (i, (sum, node)) in c.iter().zip(&t.c).enumerate() {
            assert!((sum - node).abs() < 1e-15, "row sum {i}");
        }
        let c2 = mul(&c, &c);
        let c3 = mul(&c2, &c);
        let ac = apply(&c);
        let ac2 = apply(&c2);
        let aac = apply(&ac);
        // (tree value, 1/γ(t)) for all rooted trees up to order 4.
        let order4 = |w: &[f64; S]| {
            [
                (dot(w, &one), 1.0),
                (dot(w, &c), 1.0 / 2.0),
                (dot(w, &c2), 1.0 / 3.0),
                (dot(w, &ac), 1.0 / 6.0),
                (dot(w, &c3), 1.0 / 4.0),
                (dot(w, &mul(&c, &ac)), 1.0 / 8.0),
                (dot(w, &ac2), 1.0 / 12.0),
                (dot(w, &aac), 1.0 / 24.0),
            ]
        };
        for (value, expected) in order4(&b).into_iter().chain(order4(&b_hat)) {
            assert!((value - expected).abs() < 1e-12, "{value} vs {expected}");
        }
        let order5 = [
            (dot(&b, &mul(&c3, &c)), 1.0 / 5.0),
            (dot(&b, &mul(&c2, &ac)), 1.0 / 10.0),
            (dot(&b, &mul(&c, &ac2)), 1.0 / 15.0),
            (dot(&b, &mul(&c, &aac)), 1.0 / 30.0),
            (dot(&b, &mul(&ac, &ac)), 1.0 / 20.0),
            (dot(&b, &apply(&c3)), 1.0 / 20.0),
            (dot(&b, &apply(&mul(&c, &ac))), 1.0 / 40.0),
            (dot(&b, &apply(&ac2)), 1.0 / 60.0),
            (dot(&b, &apply(&aac)), 1.0 / 120.0),
        ];
        for (value, expected) in order5 {
            assert!((value - expected).abs() < 1e-12, "{value} vs {expected}");
        }
        // Stiffly accurate (last row = b, hence R(∞) = 0 with γ on the diagonal), and an embedded
        // solution that differs.
        assert_eq!(a[S - 1], b);
        assert!((1..S).all(|i| a[i][i] == t.gamma));
        assert!(b_hat.iter().zip(&b).any(|(x, y)| x != y));
    }
}
