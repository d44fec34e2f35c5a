//! Validation of [`Parameters`]. Every single-parameter range is the one the variable table
//! declares (read from it, so the library and the FMU accept exactly the same values); the rules
//! that involve several parameters are stated here, each with its reason, and name the parameter,
//! its value and the range that holds for the others.

use super::access::{integer_parameter, real_parameter};
use super::parameters::{
    EXPLICIT_MAX_TOLERANCE, GENERALIZED_ALPHA_MAX_TOLERANCE, Parameters, RodFormulation,
};
use crate::error::{ModelError, Num};
use crate::integrator::Method;
use crate::joint::finite_film::MAX_LENGTH_RATIO;
use crate::joint::{FeedModel, FilmModel, JointField, JointModel, JointParameters, JointRole};
use crate::reduction::{Quadrature, check_mode_count};
use crate::variables::{Causality, Kind, VARIABLES};

/// Largest mode count of a sampled rod (`rod.quadrature = sampled`).
pub const MAX_SAMPLED_MODES: usize = 8;

impl Parameters {
    /// Smallest slenderness L/r (r = √(I/A), the radius of gyration) of a flexible rod.
    pub const MIN_SLENDERNESS: f64 = 10.0;

    /// Largest damping ratio of the rod's first axial mode under its material damping: that of
    /// benchmark B's rod at its largest allowed damping (ω_axial/ω₁ = 8.8), so that the rule on
    /// the first bending mode alone decides for every rod of ordinary proportions.
    pub const MAX_AXIAL_DAMPING_RATIO: f64 = 9.0;

    /// The ANCF element is an Euler–Bernoulli beam (no shear deformation, no rotary inertia): a
    /// rod whose radius of gyration exceeds a tenth of its length is a block, not a beam (shear
    /// would change its first bending frequency by tens of percent). Benchmark B: L/r = 27.8.
    fn check_slenderness(&self) -> Result<(), ModelError> {
        let r = (self.rod.second_moment_of_area / self.rod.area).sqrt();
        if self.rod.length < Self::MIN_SLENDERNESS * r {
            return Err(ModelError::invalid(
                "rod.secondMomentOfArea",
                self.rod.second_moment_of_area,
                format!(
                    "(0, {}] m4 for a flexible rod with rod.area = {} m2 and rod.length = {} m: \
                     the slenderness rod.length / sqrt(I/A) = {} must be at least {} for the \
                     Euler-Bernoulli beam the ANCF element is",
                    Num(self.rod.area * (self.rod.length / Self::MIN_SLENDERNESS).powi(2)),
                    Num(self.rod.area),
                    Num(self.rod.length),
                    Num(self.rod.length / r),
                    Num(Self::MIN_SLENDERNESS)
                ),
            ));
        }
        Ok(())
    }

    /// Stiffness-proportional damping gives mode i the damping ratio ζᵢ = β ωᵢ / 2. Beyond
    /// ζ₁ = 1 the rod's first bending mode, and with it every mode, is overdamped: no structural
    /// material behaves so, and the equations become too stiff for the work integrals to follow
    /// the tolerance (measured: energy-balance residual 0.3 of the kinetic energy at ζ₁ = 76,
    /// β = 1e-2 s on benchmark B, rtol 1e-2; 8e-3 at ζ₁ = 1). So β ≤ 2/ω₁, and the first axial
    /// mode's damping ratio at most [`Self::MAX_AXIAL_DAMPING_RATIO`]: a very thin rod's bending
    /// frequency allows a damping that overdamps its axial modes by orders of magnitude
    /// (measured: a 12 cm rod with I = 1.5e-17 m⁴ and β = 1 s, ζ_axial = 7e4, energy-balance
    /// residual 1.2 of the largest energy at rtol 1e-2).
    fn check_material_damping(&self) -> Result<(), ModelError> {
        if self.rod.damping_ratio > 0.0 && self.rod.stiffness_damping > 0.0 {
            return Err(ModelError::invalid(
                "rod.dampingRatio",
                self.rod.damping_ratio,
                format!(
                    "{{0}} with rod.stiffnessDamping = {} s: the rod's damping is given either as \
                     the damping ratio of its first bending mode or as the strain-rate \
                     coefficient, not both",
                    Num(self.rod.stiffness_damping)
                ),
            ));
        }
        let beta = self.rod.damping();
        let name = if self.rod.damping_ratio > 0.0 {
            "rod.dampingRatio"
        } else {
            "rod.stiffnessDamping"
        };
        let axial = self.rod.first_axial_frequency();
        let omega = self
            .rod
            .first_bending_frequency()
            .max(axial / Self::MAX_AXIAL_DAMPING_RATIO);
        if beta * omega > 2.0 {
            let (value, range) = if self.rod.damping_ratio > 0.0 {
                let first = self.rod.first_bending_frequency();
                (
                    self.rod.damping_ratio,
                    format!("[0, {}]", Num(first / omega)),
                )
            } else {
                (beta, format!("[0, {}] s", Num(2.0 / omega)))
            };
            return Err(ModelError::invalid(
                name,
                value,
                format!(
                    "{range} for this rod: its first bending mode (ω₁ = π²/L² √(EI/ρA) = {} \
                     rad/s from rod.length, rod.youngsModulus, rod.secondMomentOfArea, \
                     rod.density, rod.area) would get the damping ratio β ω₁/2 = {} > 1, \
                     overdamping every mode, or its first axial mode (ω = π/L √(E/ρ) = {} rad/s) \
                     a damping ratio above {}",
                    Num(self.rod.first_bending_frequency()),
                    Num(0.5 * beta * self.rod.first_bending_frequency()),
                    Num(axial),
                    Num(Self::MAX_AXIAL_DAMPING_RATIO)
                ),
            ));
        }
        Ok(())
    }

    /// Checks every parameter against its declared range (the variable table's min and max, the
    /// same bounds fmi2SetReal and fmi2SetInteger apply), then the rules between parameters.
    pub fn validate(&self) -> Result<(), ModelError> {
        self.check_declared_ranges()?;
        if self.rod_formulation == RodFormulation::CraigBampton {
            check_mode_count(self.n_elements, self.n_modes, self.boundary)?;
            if self.quadrature == Quadrature::Sampled && self.n_modes > MAX_SAMPLED_MODES {
                return Err(ModelError::invalid(
                    "rod.nModes",
                    self.n_modes as f64,
                    format!(
                        "[0, {MAX_SAMPLED_MODES}] with rod.quadrature = sampled: its points are \
                         fitted at initialization, in a time that grows with the fourth power of \
                         the mode count (0.1 s at {MAX_SAMPLED_MODES} modes and 64 elements)"
                    ),
                ));
            }
        }
        if self.rod.length <= self.crank_length {
            return Err(ModelError::invalid(
                "rod.length",
                self.rod.length,
                format!(
                    "(crank.length, inf) = ({}, inf): the rod must be longer than the crank",
                    Num(self.crank_length)
                ),
            ));
        }
        let reach = self.crank_length + self.slider_offset.abs();
        if reach >= self.rod.length {
            return Err(ModelError::invalid(
                "slider.offset",
                self.slider_offset,
                format!(
                    "(-{gap}, {gap}) = (-(rod.length - crank.length), rod.length - crank.length) \
                     with rod.length = {} m and crank.length = {} m: a full crank turn needs \
                     crank.length + |slider.offset| < rod.length",
                    Num(self.rod.length),
                    Num(self.crank_length),
                    gap = Num(((self.rod.length - self.crank_length) * 1e12).round() / 1e12),
                ),
            ));
        }
        if self.rod_formulation != RodFormulation::Rigid {
            self.check_slenderness()?;
            self.check_material_damping()?;
        }
        for (role, joint) in self.joints() {
            check_joint(role, joint)?;
        }
        // The viscosity law falls with the temperature (Walther's B > 0); equal viscosities give
        // a constant one.
        if self.oil.viscosity100 > self.oil.viscosity40 {
            return Err(ModelError::invalid(
                "oil.viscosity100",
                self.oil.viscosity100,
                format!(
                    "[1e-6, oil.viscosity40] = [1e-6, {}] Pa s: an oil is thinner at 100 degC than \
                     at 40 degC",
                    Num(self.oil.viscosity40)
                ),
            ));
        }
        if !matches!(self.slider_force_table_period, 360 | 720) {
            return Err(ModelError::invalid(
                "slider.forceTablePeriod",
                self.slider_force_table_period as f64,
                "{360, 720}: one crank turn, or two for a four-stroke cycle",
            ));
        }
        let tolerance = self.relative_tolerance;
        if self.method == Method::DormandPrince && tolerance > EXPLICIT_MAX_TOLERANCE {
            return Err(ModelError::invalid(
                "solver.relativeTolerance",
                tolerance,
                format!(
                    "[1e-12, {}] with solver.method = explicit: looser \
                     explicit runs leave the flexible rod's stiff content ringing at the edge of \
                     stability (peak ideal-joint force +25 % at 1e-3 with 8 modes)",
                    Num(EXPLICIT_MAX_TOLERANCE)
                ),
            ));
        }
        if self.method == Method::GeneralizedAlpha && tolerance > GENERALIZED_ALPHA_MAX_TOLERANCE {
            return Err(ModelError::invalid(
                "solver.relativeTolerance",
                tolerance,
                format!(
                    "[1e-12, {}] with solver.method = \
                     generalizedAlpha: looser second-order steps mis-resolve the dry impacts \
                     (rigid rod: peak joint force +60 % at 5e-2)",
                    Num(GENERALIZED_ALPHA_MAX_TOLERANCE)
                ),
            ));
        }
        Ok(())
    }
}

/// The rules between one joint's parameters: a clearance joint needs a gap, and friction
/// develops over a speed band.
fn check_joint(role: JointRole, joint: &JointParameters) -> Result<(), ModelError> {
    let name = |field| role.parameter(field);
    if joint.model != JointModel::Ideal && joint.clearance <= 0.0 {
        return Err(ModelError::invalid(
            name(JointField::Clearance),
            joint.clearance,
            format!(
                "(0, inf) with {} = {}: a clearance joint needs a gap ({} = ideal for none)",
                name(JointField::Model),
                format!("{:?}", joint.model).to_lowercase(),
                name(JointField::Model),
            ),
        ));
    }
    let ratio = joint.length_ratio();
    if joint.model == JointModel::Lubricated
        && joint.film_model == FilmModel::Finite
        && ratio > MAX_LENGTH_RATIO
    {
        return Err(ModelError::invalid(
            name(JointField::BearingLength),
            joint.bearing_length,
            format!(
                "(0, {}] m with {} = {} m and {} = finite: the finite film is tabulated for a \
                 length-to-diameter ratio of at most {}, this bearing's is {} ({} = short for \
                 the infinitely short bearing)",
                Num(MAX_LENGTH_RATIO * 2.0 * joint.journal_radius),
                name(JointField::JournalRadius),
                Num(joint.journal_radius),
                name(JointField::FilmModel),
                Num(MAX_LENGTH_RATIO),
                Num(ratio),
                name(JointField::FilmModel),
            ),
        ));
    }
    check_feed(role, joint)?;
    if joint.friction_v1 <= joint.friction_v0 {
        return Err(ModelError::invalid(
            name(JointField::FrictionV1),
            joint.friction_v1,
            format!(
                "({}, inf) = ({}, inf)",
                name(JointField::FrictionV0),
                Num(joint.friction_v0)
            ),
        ));
    }
    Ok(())
}

/// A lubricated joint's feed fits its bearing: a hole or a groove at most half the bearing's length
/// across (the lands beside a circumferential groove at least a quarter of it each), an axial
/// groove with half its width short of the bearing's ends.
fn check_feed(role: JointRole, joint: &JointParameters) -> Result<(), ModelError> {
    if joint.model != JointModel::Lubricated || joint.feed == FeedModel::None {
        return Ok(());
    }
    let name = |field| role.parameter(field);
    let length = joint.bearing_length;
    if joint.feed_diameter > 0.5 * length {
        return Err(ModelError::invalid(
            name(JointField::FeedDiameter),
            joint.feed_diameter,
            format!(
                "(0, {}] m with {} = {} m: a feed at most half the bearing's length across",
                Num(0.5 * length),
                name(JointField::BearingLength),
                Num(length),
            ),
        ));
    }
    let reach = joint.feed_groove_length + 0.5 * joint.feed_diameter / length;
    if joint.feed == FeedModel::AxialGroove && reach >= 0.95 {
        return Err(ModelError::invalid(
            name(JointField::FeedGrooveLength),
            joint.feed_groove_length,
            format!(
                "(0, {}) with {} = {} m and {} = {} m: an axial groove stops short of the \
                 bearing's ends (its length plus half its width below 0.95 of the bearing's)",
                Num(0.95 - 0.5 * joint.feed_diameter / length),
                name(JointField::FeedDiameter),
                Num(joint.feed_diameter),
                name(JointField::BearingLength),
                Num(length),
            ),
        ));
    }
    Ok(())
}

impl Parameters {
    /// Every parameter within the [min, max] its row of the variable table declares (NaN never
    /// is); the error quotes the bounds as the FMU does. Rules between parameters are not checked
    /// (a parameter set still being entered may break them).
    pub fn check_declared_ranges(&self) -> Result<(), ModelError> {
        for v in VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Parameter)
        {
            let (value, min, max, unit) = match v.kind {
                Kind::Real { min, max, unit, .. } => (real_parameter(self, v.vr), min, max, unit),
                Kind::Integer { min, max, .. } => (
                    integer_parameter(self, v.vr).map(f64::from),
                    f64::from(min),
                    f64::from(max),
                    "",
                ),
                // A switch's value is one of its items by type; a file is checked when read.
                Kind::Enumeration { .. } | Kind::Boolean | Kind::String { .. } => continue,
            };
            if let Some(value) = value.filter(|x| !(min..=max).contains(x)) {
                return Err(ModelError::invalid(
                    v.name,
                    value,
                    format!("[{}, {}] {unit}", Num(min), Num(max))
                        .trim_end()
                        .to_string(),
                ));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests;
