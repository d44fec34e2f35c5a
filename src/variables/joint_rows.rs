//! The rows of one revolute joint ([`joint_rows!`]), the same for the three joints of
//! [`super::joints`]: its model and dry-contact parameters, its film's parameters, its state and
//! bearing-design outputs.

/// Number of rows of each joint ([`joint_rows`]).
pub(super) const JOINT_ROWS: usize = 40;

/// Every row of a revolute joint, the same for the three: its model and dry-contact parameters,
/// its film's parameters, its state and bearing-design outputs. Arguments: the variable-name
/// prefix, its name starting a description and inside one, what it joins, what its eccentricity
/// is, its journal, the journal as the film's outputs name it, the parts in contact, the default
/// joint model, and the 40 value references in the order of the rows.
macro_rules! joint_rows {
    (
        $prefix:literal,
        $label:literal,
        $name:literal,
        $joins:literal,
        $eccentricity:literal,
        $journal:literal,
        $pin:literal,
        $parts:literal,
        $model_start:literal,
        [
            $model:ident,
            $clearance:ident,
            $radius:ident,
            $youngs:ident,
            $poisson:ident,
            $restitution:ident,
            $law:ident,
            $friction:ident,
            $v0:ident,
            $v1:ident,
            $viscosity:ident,
            $length:ident,
            $switch:ident,
            $ex:ident,
            $ey:ident,
            $penetration:ident,
            $contact:ident,
            $onsets:ident,
            $total:ident,
            $start:ident,
            $geometry:ident,
            $ratio:ident,
            $thickness:ident,
            $thickness_min:ident,
            $thickness_min_start:ident,
            $pressure:ident,
            $pressure_start:ident,
            $torque:ident,
            $power:ident,
            $dissipated:ident,
            $film_model:ident,
            $oil_flow:ident,
            $thickness_cycle:ident,
            $thickness_cycle_angle:ident,
            $pressure_cycle:ident,
            $pressure_cycle_angle:ident,
            $force_cycle:ident,
            $force_cycle_angle:ident,
            $power_cycle:ident,
            $flow_cycle:ident $(,)?
        ]
    ) => {
        [
            Variable::enumeration(
                Vr::$model,
                concat!($prefix, ".model"),
                $model_start,
                JOINT_MODEL,
                concat!($label, ": joint model (", $joins, ")"),
            ),
            Variable::parameter(
                Vr::$clearance,
                concat!($prefix, ".clearance"),
                5e-4,
                0.0,
                0.1,
                "m",
                concat!(
                    $label,
                    ": radial clearance (bearing radius - journal radius)"
                ),
            ),
            Variable::parameter(
                Vr::$radius,
                concat!($prefix, ".journalRadius"),
                9.5e-3,
                1e-5,
                1.0,
                "m",
                concat!($label, ": ", $journal, " radius"),
            ),
            Variable::parameter(
                Vr::$youngs,
                concat!($prefix, ".youngsModulus"),
                207e9,
                1e6,
                1e13,
                "Pa",
                concat!($label, ": Young's modulus of ", $parts),
            ),
            Variable::parameter(
                Vr::$poisson,
                concat!($prefix, ".poissonRatio"),
                0.3,
                -0.99,
                0.499,
                "1",
                concat!($label, ": Poisson ratio of ", $parts),
            ),
            Variable::parameter(
                Vr::$restitution,
                concat!($prefix, ".restitution"),
                0.9,
                1e-3,
                1.0,
                "1",
                concat!(
                    $label,
                    ": coefficient of restitution of the dry contact (see ",
                    $prefix,
                    ".contactLaw)"
                ),
            ),
            Variable::enumeration(
                Vr::$law,
                concat!($prefix, ".contactLaw"),
                1,
                CONTACT_LAW,
                concat!($label, ": hysteresis-damping law of the dry contact force"),
            ),
            Variable::parameter(
                Vr::$friction,
                concat!($prefix, ".friction"),
                0.0,
                0.0,
                2.0,
                "1",
                concat!($label, ": Coulomb friction coefficient"),
            ),
            Variable::parameter(
                Vr::$v0,
                concat!($prefix, ".frictionV0"),
                1e-4,
                0.0,
                1.0,
                "m/s",
                concat!($label, ": slip speed below which friction vanishes"),
            ),
            Variable::parameter(
                Vr::$v1,
                concat!($prefix, ".frictionV1"),
                1e-3,
                1e-9,
                10.0,
                "m/s",
                concat!(
                    $label,
                    ": slip speed above which friction is fully developed"
                ),
            ),
            Variable::parameter(
                Vr::$viscosity,
                concat!($prefix, ".viscosity"),
                0.4,
                1e-6,
                100.0,
                "Pa.s",
                concat!($label, ": lubricant dynamic viscosity"),
            ),
            Variable::parameter(
                Vr::$length,
                concat!($prefix, ".bearingLength"),
                0.04,
                1e-5,
                10.0,
                "m",
                concat!($label, ": bearing length"),
            ),
            Variable::parameter(
                Vr::$switch,
                concat!($prefix, ".switchEccentricity"),
                0.95,
                0.01,
                0.99,
                "1",
                concat!(
                    $label,
                    ": eccentricity ratio above which dry contact takes over"
                ),
            ),
            Variable::output(
                Vr::$ex,
                concat!($prefix, ".eccentricityX"),
                "m",
                concat!($eccentricity, ", x (0 for the ideal ", $name, ")"),
            ),
            Variable::output(
                Vr::$ey,
                concat!($prefix, ".eccentricityY"),
                "m",
                concat!($eccentricity, ", y"),
            ),
            Variable::output(
                Vr::$penetration,
                concat!($prefix, ".penetration"),
                "m",
                concat!($label, " contact penetration max(|e| - c, 0)"),
            ),
            Variable {
                vr: Vr::$contact,
                name: concat!($prefix, ".inContact"),
                causality: Causality::Output,
                variability: Variability::Discrete,
                kind: Kind::Boolean,
                description: concat!($label, ": ", $parts, " in contact"),
            },
            Variable::count(
                Vr::$onsets,
                concat!($prefix, ".contactOnsets"),
                concat!(
                    "Contact onsets at the ",
                    $name,
                    " in the last communication interval"
                ),
            ),
            Variable::count(
                Vr::$total,
                concat!($prefix, ".contactOnsetsTotal"),
                concat!("Contact onsets at the ", $name, " since the start"),
            ),
            Variable::enumeration(
                Vr::$start,
                concat!($prefix, ".initialState"),
                1,
                JOURNAL_START,
                concat!("Where the journal of a clearance ", $name, " starts"),
            ),

            Variable::enumeration(
                Vr::$geometry,
                concat!($prefix, ".contactGeometry"),
                1,
                CONTACT_GEOMETRY,
                concat!(
                    $label,
                    ": geometry of the dry contact's elastic law (point: Hertz; cylinder: Johnson's line contact over ",
                    $prefix,
                    ".bearingLength); the hysteresis damping, contact energy and settled start follow it"
                ),
            ),
            Variable::output(
                Vr::$ratio,
                concat!($prefix, ".eccentricityRatio"),
                "1",
                concat!(
                    $label,
                    ": eccentricity ratio |e|/c, the actual one (above 1 in metal contact); 0 for the ideal joint"
                ),
            ),
            Variable::output(
                Vr::$thickness,
                concat!($prefix, ".filmThickness"),
                "m",
                concat!(
                    $label,
                    ": minimum oil-film thickness (gap between ",
                    $pin,
                    " and bearing) c (1 - |e|/c); 0 in metal contact (see ",
                    $prefix,
                    ".penetration) and for the ideal joint"
                ),
            ),
            Variable::peak(
                Vr::$thickness_min,
                concat!($prefix, ".filmThicknessMin"),
                "m",
                concat!(
                    "Smallest ",
                    $prefix,
                    ".filmThickness over the last communication interval (every internal step's end, and within the steps in contact or with a film)"
                ),
            ),
            Variable::peak(
                Vr::$thickness_min_start,
                concat!($prefix, ".filmThicknessMinSinceStart"),
                "m",
                concat!("Smallest ", $prefix, ".filmThickness since the start"),
            ),
            Variable::peak(
                Vr::$pressure,
                concat!($prefix, ".filmPressurePeak"),
                "Pa",
                concat!(
                    $label,
                    ": largest oil-film pressure over the last communication interval, at mid-length (short-bearing field; every internal step); 0 without a film (dry and ideal joints)"
                ),
            ),
            Variable::peak(
                Vr::$pressure_start,
                concat!($prefix, ".filmPressurePeakSinceStart"),
                "Pa",
                concat!("Largest ", $prefix, ".filmPressurePeak since the start"),
            ),
            Variable::output(
                Vr::$torque,
                concat!($prefix, ".frictionTorque"),
                "N.m",
                concat!(
                    $label,
                    ": friction moment on the ",
                    $pin,
                    " about its centre, CCW positive (dry friction and the film's shear); 0 for the ideal joint"
                ),
            ),
            Variable::output(
                Vr::$power,
                concat!($prefix, ".frictionPower"),
                "W",
                concat!(
                    $label,
                    ": rate at which the joint's friction dissipates energy, >= 0 (the oil film's viscous loss in shear and squeeze; dry and asperity friction -F_T v_T); 0 for the ideal joint"
                ),
            ),
            Variable::output(
                Vr::$dissipated,
                concat!($prefix, ".energyDissipated"),
                "J",
                concat!(
                    $label,
                    ": energy dissipated in the joint since the start (friction, contact hysteresis, film); the three joints' sum to energy.dissipated; 0 for the ideal joint"
                ),
            ),
            Variable::enumeration(
                Vr::$film_model,
                concat!($prefix, ".filmModel"),
                2,
                FILM_MODEL,
                concat!(
                    $label,
                    ": oil film of the lubricated joint (short: Ocvirk's infinitely short bearing, the benchmarks' film; finite: the Reynolds equation over ",
                    $prefix,
                    ".bearingLength with the Reynolds cavitation condition, tabulated for L/D up to 4); the film force, pressure, flow, shear, settled start and hand-over to dry contact follow it"
                ),
            ),
            Variable::output(
                Vr::$oil_flow,
                concat!($prefix, ".oilFlow"),
                "m3/s",
                concat!(
                    $label,
                    ": oil flow through the bearing: the side flow out of both ends of the pressurised film (Raimondi and Boyd's Q_s) of ",
                    $prefix,
                    ".filmModel, plus ",
                    $prefix,
                    ".feedFlow, the flow the supply pressure drives from a feed; 0 without a film (dry and ideal joints)"
                ),
            ),
            Variable::peak(
                Vr::$thickness_cycle,
                concat!($prefix, ".filmThicknessMinCycle"),
                "m",
                concat!(
                    "Smallest ",
                    $prefix,
                    ".filmThickness over the last complete load cycle (crank-angle period slider.forceTablePeriod, 360 deg without a load table; cycles bounded by its multiples of crank.angle; every internal step); until a cycle completes, over the cycle under way"
                ),
            ),
            Variable::peak(
                Vr::$thickness_cycle_angle,
                concat!($prefix, ".filmThicknessMinCycleAngle"),
                "deg",
                concat!(
                    "Crank angle within the cycle, [0, slider.forceTablePeriod) deg from its start at a multiple of the period, at which ",
                    $prefix,
                    ".filmThicknessMinCycle occurred"
                ),
            ),
            Variable::peak(
                Vr::$pressure_cycle,
                concat!($prefix, ".filmPressurePeakCycle"),
                "Pa",
                concat!(
                    "Largest ",
                    $prefix,
                    ".filmPressurePeak over the last complete load cycle (see ",
                    $prefix,
                    ".filmThicknessMinCycle)"
                ),
            ),
            Variable::peak(
                Vr::$pressure_cycle_angle,
                concat!($prefix, ".filmPressurePeakCycleAngle"),
                "deg",
                concat!(
                    "Crank angle within the cycle at which ",
                    $prefix,
                    ".filmPressurePeakCycle occurred"
                ),
            ),
            Variable::peak(
                Vr::$force_cycle,
                concat!($prefix, ".forcePeakCycle"),
                "N",
                concat!(
                    "Largest ",
                    $prefix,
                    ".force over the last complete load cycle (see ",
                    $prefix,
                    ".filmThicknessMinCycle)"
                ),
            ),
            Variable::peak(
                Vr::$force_cycle_angle,
                concat!($prefix, ".forcePeakCycleAngle"),
                "deg",
                concat!(
                    "Crank angle within the cycle at which ",
                    $prefix,
                    ".forcePeakCycle occurred"
                ),
            ),
            Variable::peak(
                Vr::$power_cycle,
                concat!($prefix, ".frictionPowerMeanCycle"),
                "W",
                concat!(
                    "Mean ",
                    $prefix,
                    ".frictionPower over the last complete load cycle: its energy over the cycle's duration (see ",
                    $prefix,
                    ".filmThicknessMinCycle)"
                ),
            ),
            Variable::peak(
                Vr::$flow_cycle,
                concat!($prefix, ".oilFlowMeanCycle"),
                "m3/s",
                concat!(
                    "Mean ",
                    $prefix,
                    ".oilFlow over the last complete load cycle: the oil volume over the cycle's duration (see ",
                    $prefix,
                    ".filmThicknessMinCycle)"
                ),
            ),
        ]
    };
}

pub(super) use joint_rows;
