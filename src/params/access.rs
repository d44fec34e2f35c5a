//! [`Parameters`] by value reference: the one list that maps each parameter row of the variable
//! table to its field, from which both the getter and the setter are generated.

use super::parameters::{BENCHMARK_SPEED, DriveMode, InitialState, Parameters, RodFormulation};
use crate::integrator::Method;
use crate::joint::{
    ContactGeometry, ContactLaw, FeedLocation, FeedModel, FilmModel, JointModel, JournalStart,
    ThermalModel, ThermalStart,
};

use crate::reduction::{Boundary, Quadrature};
use crate::variables::Vr;

/// `real_parameter` and `set_real_parameter` over one list of (value reference, field), and one
/// of optional fields (value reference, field, the value read while it is not set).
macro_rules! real_fields {
    (
        fields { $($vr:ident => $($field:ident).+;)* }
        optional { $($ovr:ident => $ofield:ident unset $unset:expr;)* }
    ) => {
        /// Value of a Real parameter, None for other variables.
        pub fn real_parameter(p: &Parameters, vr: Vr) -> Option<f64> {
            match vr {
                $(Vr::$vr => Some(p.$($field).+),)*
                $(Vr::$ovr => Some(p.$ofield.unwrap_or($unset)),)*
                _ => None,
            }
        }

        /// Sets a Real parameter (value already range-checked); false if `vr` is not one.
        pub fn set_real_parameter(p: &mut Parameters, vr: Vr, value: f64) -> bool {
            match vr {
                $(Vr::$vr => p.$($field).+ = value,)*
                $(Vr::$ovr => p.$ofield = Some(value),)*
                _ => return false,
            }
            true
        }
    };
}

real_fields! {
    fields {
    RodLength => rod.length;
    RodYoungsModulus => rod.youngs_modulus;
    RodDensity => rod.density;
    RodArea => rod.area;
    RodSecondMomentOfArea => rod.second_moment_of_area;
    RodOuterFibreDistance => rod.outer_fibre_distance;
    RodStiffnessDamping => rod.stiffness_damping;
    RodDampingRatio => rod.damping_ratio;
    RodCrankEndMass => rod.crank_end_mass;
    RodSliderEndMass => rod.slider_end_mass;
    CrankLength => crank_length;
    CrankMass => crank_mass;
    CrankInertia => crank_inertia;
    CrankInitialAngle => crank_initial_angle;
    CrankCentreOfMassRatio => crank_centre_of_mass_ratio;
    SliderOffset => slider_offset;
    SliderMass => slider_mass;
    JointClearance => joint.clearance;
    JointJournalRadius => joint.journal_radius;
    JointYoungsModulus => joint.youngs_modulus;
    JointPoissonRatio => joint.poisson_ratio;
    JointRestitution => joint.restitution;
    JointFriction => joint.friction;
    JointFrictionV0 => joint.friction_v0;
    JointFrictionV1 => joint.friction_v1;
    JointViscosity => joint.viscosity;
    JointBearingLength => joint.bearing_length;
    JointSwitchEccentricity => joint.switch_eccentricity;
    CrankPinClearance => crank_pin.clearance;
    CrankPinJournalRadius => crank_pin.journal_radius;
    CrankPinYoungsModulus => crank_pin.youngs_modulus;
    CrankPinPoissonRatio => crank_pin.poisson_ratio;
    CrankPinRestitution => crank_pin.restitution;
    CrankPinFriction => crank_pin.friction;
    CrankPinFrictionV0 => crank_pin.friction_v0;
    CrankPinFrictionV1 => crank_pin.friction_v1;
    CrankPinViscosity => crank_pin.viscosity;
    CrankPinBearingLength => crank_pin.bearing_length;
    CrankPinSwitchEccentricity => crank_pin.switch_eccentricity;
    MainBearingClearance => main_bearing.clearance;
    MainBearingJournalRadius => main_bearing.journal_radius;
    MainBearingYoungsModulus => main_bearing.youngs_modulus;
    MainBearingPoissonRatio => main_bearing.poisson_ratio;
    MainBearingRestitution => main_bearing.restitution;
    MainBearingFriction => main_bearing.friction;
    MainBearingFrictionV0 => main_bearing.friction_v0;
    MainBearingFrictionV1 => main_bearing.friction_v1;
    MainBearingViscosity => main_bearing.viscosity;
    MainBearingBearingLength => main_bearing.bearing_length;
    MainBearingSwitchEccentricity => main_bearing.switch_eccentricity;
    Gravity => gravity;
    GravityAngle => gravity_angle;
    SolverRelativeTolerance => relative_tolerance;
    SolverMaxStepSize => max_step_size;
    SolverSpectralRadius => spectral_radius;
    SolverImpactErrorWeight => impact_error_weight;
    JointRoughness => joint.roughness;
    JointBoundaryFriction => joint.boundary_friction;
    JointAsperityDensityProduct => joint.asperity_density_product;
    JointAsperityRoughnessRatio => joint.asperity_roughness_ratio;
    CrankPinRoughness => crank_pin.roughness;
    CrankPinBoundaryFriction => crank_pin.boundary_friction;
    CrankPinAsperityDensityProduct => crank_pin.asperity_density_product;
    CrankPinAsperityRoughnessRatio => crank_pin.asperity_roughness_ratio;
    MainBearingRoughness => main_bearing.roughness;
    MainBearingBoundaryFriction => main_bearing.boundary_friction;
    MainBearingAsperityDensityProduct => main_bearing.asperity_density_product;
    MainBearingAsperityRoughnessRatio => main_bearing.asperity_roughness_ratio;
    OilViscosity40 => oil.viscosity40;
    OilViscosity100 => oil.viscosity100;
    OilDensity => oil.density;
    OilSpecificHeat => oil.specific_heat;
    JointHeatCapacity => joint.heat_capacity;
    JointHeatTransferCoefficient => joint.heat_transfer_coefficient;
    CrankPinHeatCapacity => crank_pin.heat_capacity;
    CrankPinHeatTransferCoefficient => crank_pin.heat_transfer_coefficient;
    MainBearingHeatCapacity => main_bearing.heat_capacity;
    MainBearingHeatTransferCoefficient => main_bearing.heat_transfer_coefficient;
    JointFeedPosition => joint.feed_position;
    JointFeedDiameter => joint.feed_diameter;
    JointFeedGrooveLength => joint.feed_groove_length;
    CrankPinFeedPosition => crank_pin.feed_position;
    CrankPinFeedDiameter => crank_pin.feed_diameter;
    CrankPinFeedGrooveLength => crank_pin.feed_groove_length;
    MainBearingFeedPosition => main_bearing.feed_position;
    MainBearingFeedDiameter => main_bearing.feed_diameter;
    MainBearingFeedGrooveLength => main_bearing.feed_groove_length;
    }
    optional {
        // Not set, the crank starts at drive.speed; its start value reads.
        CrankInitialSpeed => crank_initial_speed unset BENCHMARK_SPEED;
    }
}

/// `integer_parameter` and `set_integer_parameter` over one list of switches (value reference,
/// field, items in the table's order) and one of counts (value reference, field).
macro_rules! integer_fields {
    (
        switches { $($svr:ident => $($sfield:ident).+: [$($item:expr),+ $(,)?];)* }
        counts { $($cvr:ident => $cfield:ident;)* }
    ) => {
        /// Value of an Integer or Enumeration parameter (a switch as its item number, from 1),
        /// None for other variables.
        pub fn integer_parameter(p: &Parameters, vr: Vr) -> Option<i32> {
            match vr {
                $(Vr::$svr => [$($item),+]
                    .iter()
                    .position(|x| *x == p.$($sfield).+)
                    .and_then(|i| i32::try_from(i + 1).ok()),)*
                $(Vr::$cvr => Some(i32::try_from(p.$cfield).unwrap_or(i32::MAX)),)*
                _ => None,
            }
        }

        /// Sets an Integer or Enumeration parameter (value already range-checked); false if
        /// `vr` is not one or the value is not representable (no item, a negative count).
        pub fn set_integer_parameter(p: &mut Parameters, vr: Vr, value: i32) -> bool {
            let item = usize::try_from(value).ok().and_then(|v| v.checked_sub(1));
            match vr {
                $(Vr::$svr => match item.and_then(|i| [$($item),+].get(i).copied()) {
                    Some(x) => p.$($sfield).+ = x,
                    None => return false,
                },)*
                $(Vr::$cvr => match usize::try_from(value) {
                    Ok(n) => p.$cfield = n,
                    Err(_) => return false,
                },)*
                _ => return false,
            }
            true
        }
    };
}

integer_fields! {
    switches {
        RodFormulation => rod_formulation:
            [RodFormulation::Rigid, RodFormulation::Ancf, RodFormulation::CraigBampton];
        JointModel => joint.model: [JointModel::Ideal, JointModel::Dry, JointModel::Lubricated];
        DriveMode => drive_mode: [DriveMode::Speed, DriveMode::Torque];
        RodBoundary => boundary: [Boundary::Pins, Boundary::PositionsAndSlopes];
        RodQuadrature => quadrature: [Quadrature::Full, Quadrature::Sampled];
        SolverMethod => method: [Method::Esdirk, Method::DormandPrince, Method::GeneralizedAlpha];
        RodInitialState => initial_state: [InitialState::Equilibrated, InitialState::Straight];
        JointContactLaw => joint.contact_law:
            [ContactLaw::LankaraniNikravesh, ContactLaw::Flores, ContactLaw::HuGuo];
        JointInitialState => joint.initial_state: [JournalStart::Centred, JournalStart::Settled];
        CrankPinModel => crank_pin.model:
            [JointModel::Ideal, JointModel::Dry, JointModel::Lubricated];
        CrankPinContactLaw => crank_pin.contact_law:
            [ContactLaw::LankaraniNikravesh, ContactLaw::Flores, ContactLaw::HuGuo];
        MainBearingModel => main_bearing.model:
            [JointModel::Ideal, JointModel::Dry, JointModel::Lubricated];
        MainBearingContactLaw => main_bearing.contact_law:
            [ContactLaw::LankaraniNikravesh, ContactLaw::Flores, ContactLaw::HuGuo];
        CrankPinInitialState => crank_pin.initial_state:
            [JournalStart::Centred, JournalStart::Settled];
        MainBearingInitialState => main_bearing.initial_state:
            [JournalStart::Centred, JournalStart::Settled];
        JointContactGeometry => joint.contact_geometry:
            [ContactGeometry::Point, ContactGeometry::Cylinder];
        CrankPinContactGeometry => crank_pin.contact_geometry:
            [ContactGeometry::Point, ContactGeometry::Cylinder];
        MainBearingContactGeometry => main_bearing.contact_geometry:
            [ContactGeometry::Point, ContactGeometry::Cylinder];
        JointFilmModel => joint.film_model: [FilmModel::Short, FilmModel::Finite];
        CrankPinFilmModel => crank_pin.film_model: [FilmModel::Short, FilmModel::Finite];
        MainBearingFilmModel => main_bearing.film_model: [FilmModel::Short, FilmModel::Finite];
        JointThermalModel => joint.thermal_model:
            [ThermalModel::Isoviscous, ThermalModel::HeatBalance];
        JointThermalStart => joint.thermal_start: [ThermalStart::Supply, ThermalStart::Settled];
        CrankPinThermalModel => crank_pin.thermal_model:
            [ThermalModel::Isoviscous, ThermalModel::HeatBalance];
        CrankPinThermalStart => crank_pin.thermal_start: [ThermalStart::Supply, ThermalStart::Settled];
        MainBearingThermalModel => main_bearing.thermal_model:
            [ThermalModel::Isoviscous, ThermalModel::HeatBalance];
        MainBearingThermalStart => main_bearing.thermal_start: [ThermalStart::Supply, ThermalStart::Settled];
        JointFeed => joint.feed:
            [
                FeedModel::None,
                FeedModel::Hole,
                FeedModel::CircumferentialGroove,
                FeedModel::AxialGroove,
            ];
        JointFeedLocation => joint.feed_location: [FeedLocation::Shell, FeedLocation::Journal];
        CrankPinFeed => crank_pin.feed:
            [
                FeedModel::None,
                FeedModel::Hole,
                FeedModel::CircumferentialGroove,
                FeedModel::AxialGroove,
            ];
        CrankPinFeedLocation => crank_pin.feed_location: [FeedLocation::Shell, FeedLocation::Journal];
        MainBearingFeed => main_bearing.feed:
            [
                FeedModel::None,
                FeedModel::Hole,
                FeedModel::CircumferentialGroove,
                FeedModel::AxialGroove,
            ];
        MainBearingFeedLocation => main_bearing.feed_location: [FeedLocation::Shell, FeedLocation::Journal];
    }
    counts {
        SliderForceTablePeriod => slider_force_table_period;
        RodNElements => n_elements;
        RodNModes => n_modes;
        SolverMaxStepsPerInterval => max_steps_per_interval;
    }
}

/// Value of a String parameter, None for other variables.
pub fn string_parameter(p: &Parameters, vr: Vr) -> Option<&str> {
    match vr {
        Vr::SliderForceTable => Some(&p.slider_force_table),
        _ => None,
    }
}

/// Sets a String parameter; false if `vr` is not one.
pub fn set_string_parameter(p: &mut Parameters, vr: Vr, value: &str) -> bool {
    match vr {
        Vr::SliderForceTable => p.slider_force_table = value.to_string(),
        _ => return false,
    }
    true
}
