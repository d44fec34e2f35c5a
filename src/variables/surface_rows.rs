//! The rows of one lubricated joint's rough surfaces ([`surface_rows!`]), the same for the three
//! joints of [`super::joints`]: the roughness and asperity parameters, the asperity contact's
//! outputs and its cycle results (appended to the table after the joints' first rows, so that no
//! earlier value reference moved).

/// Number of rows of each joint's surfaces ([`surface_rows`]).
pub(super) const SURFACE_ROWS: usize = 10;

/// Every row of a joint's rough surfaces. Arguments: the variable-name prefix, its name starting a
/// description, and the 10 value references in the order of the rows.
macro_rules! surface_rows {
    (
        $prefix:literal,
        $label:literal,
        [
            $roughness:ident,
            $boundary:ident,
            $density:ident,
            $ratio:ident,
            $force:ident,
            $pressure:ident,
            $power:ident,
            $film_ratio:ident,
            $force_cycle:ident,
            $metal_cycle:ident $(,)?
        ]
    ) => {
        [
            Variable::parameter(
                Vr::$roughness,
                concat!($prefix, ".roughness"),
                0.0,
                0.0,
                1e-4,
                "m",
                concat!(
                    $label,
                    ": combined RMS roughness sigma of journal and bearing, sqrt(s1^2 + s2^2), for the Greenwood-Tripp asperity contact of the lubricated joint (mixed lubrication where the film falls below about 4 sigma); 0 = smooth surfaces"
                ),
            ),
            Variable::parameter(
                Vr::$boundary,
                concat!($prefix, ".boundaryFriction"),
                0.1,
                0.0,
                2.0,
                "1",
                concat!(
                    $label,
                    ": boundary friction coefficient of the asperity contact (its slip-speed band is ",
                    $prefix,
                    ".frictionV0 to .frictionV1)"
                ),
            ),
            Variable::parameter(
                Vr::$density,
                concat!($prefix, ".asperityDensityProduct"),
                0.04,
                1e-4,
                1.0,
                "1",
                concat!(
                    $label,
                    ": sigma*beta*eta, the product of roughness, asperity summit radius and summit density (Greenwood-Tripp; usually 0.03 to 0.05)"
                ),
            ),
            Variable::parameter(
                Vr::$ratio,
                concat!($prefix, ".asperityRoughnessRatio"),
                1e-3,
                1e-6,
                1.0,
                "1",
                concat!(
                    $label,
                    ": sigma/beta, the roughness over the asperity summit radius (Greenwood-Tripp; usually 1e-4 to 1e-2)"
                ),
            ),
            Variable::output(
                Vr::$force,
                concat!($prefix, ".asperityForce"),
                "N",
                concat!(
                    $label,
                    ": normal force the rough surfaces' asperities carry (Greenwood-Tripp, over the circumference and the bearing length); 0 for smooth surfaces, dry and ideal joints"
                ),
            ),
            Variable::output(
                Vr::$pressure,
                concat!($prefix, ".asperityPressurePeak"),
                "Pa",
                concat!(
                    $label,
                    ": largest asperity contact pressure, at the thinnest film"
                ),
            ),
            Variable::output(
                Vr::$power,
                concat!($prefix, ".asperityFrictionPower"),
                "W",
                concat!(
                    $label,
                    ": power of the asperities' boundary friction (part of ",
                    $prefix,
                    ".frictionPower)"
                ),
            ),
            Variable::output(
                Vr::$film_ratio,
                concat!($prefix, ".filmRatio"),
                "1",
                concat!(
                    $label,
                    ": film ratio h_min/sigma (",
                    $prefix,
                    ".filmThickness over ",
                    $prefix,
                    ".roughness): below about 3 mixed lubrication; 0 for smooth surfaces and in metal contact"
                ),
            ),
            Variable::peak(
                Vr::$force_cycle,
                concat!($prefix, ".asperityForcePeakCycle"),
                "N",
                concat!(
                    "Largest ",
                    $prefix,
                    ".asperityForce over the last complete load cycle (at the internal steps' ends; see ",
                    $prefix,
                    ".filmThicknessMinCycle)"
                ),
            ),
            Variable::peak(
                Vr::$metal_cycle,
                concat!($prefix, ".metalContactFractionCycle"),
                "1",
                concat!(
                    "Fraction of the last complete load cycle's duration the journal spent in dry metal contact (",
                    $prefix,
                    ".inContact; see ",
                    $prefix,
                    ".filmThicknessMinCycle)"
                ),
            ),
        ]
    };
}

pub(super) use surface_rows;
