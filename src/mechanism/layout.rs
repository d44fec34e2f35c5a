//! Where each quantity sits in the mechanism's state vector,
//! ```text
//! y = [θ, p, x_s, (r_G),  θ̇, ṗ, ẋ_s, (ṙ_G),  θ_d, T…, W_drive, W_joint…, W_external, (D_material)]
//!      └─ n coordinates ─┘ └── n velocities ──┘
//! ```
//! with p the rod's coordinates, whose pin A position comes first and pin B position at the rod's
//! end offset, and r_G = (x_G, y_G) the crank's centre of mass, a coordinate only when the crank
//! is free in a clearance main bearing (a fixed pivot otherwise). Every index into a state goes
//! through [`StateLayout`]. W_joint… is the work of the joint forces, one integral per clearance
//! joint (from the ground to the slider), or a single one when at most one joint has a
//! clearance. T… is the film temperature of each lubricated joint with a heat balance (from the
//! ground to the slider; none without).

use std::ops::{Range, RangeFrom};

use nalgebra::Vector2;

/// The positions of the mechanism's quantities in its state vector.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StateLayout {
    /// Number of coordinates n = 1 + n_rod + 1 (+ 2 for a free crank).
    n: usize,
    /// Number of the rod's coordinates.
    n_rod: usize,
    /// Position of pin B's x among the rod's coordinates.
    pin_b: usize,
    /// Whether the state ends with the energy dissipated by material damping.
    material_damping: bool,
    /// Whether the crank's centre of mass is a coordinate (a clearance main bearing).
    free_crank: bool,
    /// Number of joint-work integrals (at least 1).
    joint_works: usize,
    /// Number of film temperatures.
    temperatures: usize,
}

/// Position of the crank angle θ.
pub const CRANK_ANGLE: usize = 0;
/// Position of pin A's x (its y follows).
pub const PIN_A: usize = 1;

/// The 2-vector of the state components at `at` and `at + 1` (a pin's x and y, or their rates).
pub fn pair(y: &[f64], at: usize) -> Vector2<f64> {
    Vector2::new(y[at], y[at + 1])
}

impl StateLayout {
    /// The layout of a rod with `n_rod` coordinates whose pin B x is the rod coordinate `pin_b`,
    /// of a crank on a fixed pivot or, with `free_crank`, free in the main bearing, and of
    /// `clearance_joints` joints with a clearance (each with its own work integral when there
    /// are several), of which `temperatures` have a film temperature.
    pub fn new(
        n_rod: usize,
        pin_b: usize,
        material_damping: bool,
        free_crank: bool,
        (clearance_joints, temperatures): (usize, usize),
    ) -> Self {
        Self {
            n: n_rod + 2 + 2 * usize::from(free_crank),
            n_rod,
            pin_b,
            material_damping,
            free_crank,
            joint_works: clearance_joints.max(1),
            temperatures,
        }
    }

    /// Number of coordinates n.
    pub fn n_coordinates(self) -> usize {
        self.n
    }

    /// Length of the state vector: 2n + 3 + the film temperatures + the joint-work integrals,
    /// plus 1 with material damping.
    pub fn n_states(self) -> usize {
        2 * self.n + 3 + self.temperatures + self.joint_works + usize::from(self.material_damping)
    }

    /// The coordinates q.
    pub fn coordinates(self) -> Range<usize> {
        0..self.n
    }

    /// The velocities q̇.
    pub fn velocities(self) -> Range<usize> {
        self.n..2 * self.n
    }

    /// The rod's coordinates p.
    pub fn rod(self) -> Range<usize> {
        1..1 + self.n_rod
    }

    /// The rod's coordinate j.
    pub fn rod_coordinate(self, j: usize) -> usize {
        1 + j
    }

    /// The rod's rates ṗ.
    pub fn rod_rates(self) -> Range<usize> {
        self.n + 1..self.n + 1 + self.n_rod
    }

    /// The rate of the rod's coordinate j.
    pub fn rod_rate(self, j: usize) -> usize {
        self.n + 1 + j
    }

    /// Pin B's x (its y follows).
    pub fn pin_b(self) -> usize {
        1 + self.pin_b
    }

    /// The slider abscissa x_s.
    pub fn slider(self) -> usize {
        1 + self.n_rod
    }

    /// The crank's centre of mass x_G (y_G follows), if the crank is free in the main bearing.
    pub fn crank_centre(self) -> Option<usize> {
        self.free_crank.then_some(2 + self.n_rod)
    }

    /// The velocity of the coordinate at `position` (< n).
    pub fn rate_of(self, position: usize) -> usize {
        self.n + position
    }

    /// The crank speed θ̇.
    pub fn crank_speed(self) -> usize {
        self.rate_of(CRANK_ANGLE)
    }

    /// The slider velocity ẋ_s.
    pub fn slider_velocity(self) -> usize {
        self.rate_of(self.slider())
    }

    /// The drive angle θ_d (integral of the prescribed speed).
    pub fn drive_angle(self) -> usize {
        2 * self.n
    }

    /// The film temperatures, from the ground to the slider.
    pub fn temperatures(self) -> Range<usize> {
        2 * self.n + 1..2 * self.n + 1 + self.temperatures
    }

    /// The work of the drive.
    pub fn drive_work(self) -> usize {
        2 * self.n + 1 + self.temperatures
    }

    /// The works of the joint forces: one per clearance joint, from the ground to the slider (a
    /// single one with at most one clearance joint).
    pub fn joint_works(self) -> Range<usize> {
        self.drive_work() + 1..self.drive_work() + 1 + self.joint_works
    }

    /// The work of the external slider force.
    pub fn external_work(self) -> usize {
        self.joint_works().end
    }

    /// The energy dissipated by material damping (present only with material damping).
    pub fn material_damping(self) -> usize {
        self.external_work() + 1
    }

    /// The work and energy integrals, every state after the film temperatures.
    pub fn integrals(self) -> RangeFrom<usize> {
        self.drive_work()..
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every state has exactly one place: the named positions and ranges tile 0..len.
    #[test]
    fn positions_tile_the_state() {
        for (n_rod, pin_b, damping, free, joints, temperatures) in [
            (4, 2, false, false, 1, 0),
            (20, 10, true, false, 0, 0),
            (36, 32, false, true, 3, 2),
            (12, 8, true, true, 2, 1),
        ] {
            let l = StateLayout::new(n_rod, pin_b, damping, free, (joints, temperatures));
            let mut seen = vec![0; l.n_states()];
            let mut mark = |i: usize| seen[i] += 1;
            mark(CRANK_ANGLE);
            l.rod().for_each(&mut mark);
            mark(l.slider());
            mark(l.crank_speed());
            l.rod_rates().for_each(&mut mark);
            mark(l.slider_velocity());
            if let Some(g) = l.crank_centre() {
                [g, g + 1, l.rate_of(g), l.rate_of(g) + 1]
                    .into_iter()
                    .for_each(&mut mark);
            }
            mark(l.drive_angle());
            l.temperatures().for_each(&mut mark);
            assert_eq!(l.temperatures().len(), temperatures);
            assert_eq!(l.temperatures().start, l.drive_angle() + 1);
            (l.drive_work()..l.n_states()).for_each(&mut mark);
            assert!(seen.iter().all(|&k| k == 1), "{seen:?}");
            assert_eq!(l.integrals().start, l.drive_work());
            assert_eq!(l.joint_works().start, l.drive_work() + 1);
            assert_eq!(l.joint_works().len(), joints.max(1));
            assert_eq!(l.external_work(), l.joint_works().end);
            assert_eq!(l.material_damping() < l.n_states(), damping);
            assert_eq!(l.rate_of(l.pin_b()), l.rod_rate(pin_b));
            assert_eq!(l.rod_coordinate(pin_b), l.pin_b());
            assert_eq!(l.coordinates().end, l.velocities().start);
        }
    }
}
