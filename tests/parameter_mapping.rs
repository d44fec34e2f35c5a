//! The parameters of the committed `modelDescription/modelDescription.xml` against the fields of
//! `Parameters` they name, written out below independently of the mapping in `params::access`:
//! setting a parameter through its value reference in the XML changes its named field, and nothing
//! else; a switch's items set distinct values.

// Test code: a failed unwrap is a failed test, with its message.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use flexible_slider_crank::Parameters;
use flexible_slider_crank::params::{
    set_integer_parameter, set_real_parameter, set_string_parameter,
};
use flexible_slider_crank::variables::{VARIABLES, Vr};

/// Restores one named field of the parameters from another set.
type Restore = fn(&mut Parameters, &Parameters);

/// Each parameter's name and the field it names.
const FIELDS: &[(&str, Restore)] = &[
    ("rod.formulation", |p, d| {
        p.rod_formulation = d.rod_formulation
    }),
    ("rod.nElements", |p, d| p.n_elements = d.n_elements),
    ("rod.nModes", |p, d| p.n_modes = d.n_modes),
    ("rod.length", |p, d| p.rod.length = d.rod.length),
    ("rod.youngsModulus", |p, d| {
        p.rod.youngs_modulus = d.rod.youngs_modulus
    }),
    ("rod.density", |p, d| p.rod.density = d.rod.density),
    ("rod.area", |p, d| p.rod.area = d.rod.area),
    ("rod.secondMomentOfArea", |p, d| {
        p.rod.second_moment_of_area = d.rod.second_moment_of_area
    }),
    ("rod.stiffnessDamping", |p, d| {
        p.rod.stiffness_damping = d.rod.stiffness_damping
    }),
    ("crank.length", |p, d| p.crank_length = d.crank_length),
    ("crank.mass", |p, d| p.crank_mass = d.crank_mass),
    ("crank.inertia", |p, d| p.crank_inertia = d.crank_inertia),
    ("crank.initialAngle", |p, d| {
        p.crank_initial_angle = d.crank_initial_angle
    }),
    ("crank.initialSpeed", |p, d| {
        p.crank_initial_speed = d.crank_initial_speed
    }),
    ("slider.mass", |p, d| p.slider_mass = d.slider_mass),
    ("joint.model", |p, d| p.joint.model = d.joint.model),
    ("joint.clearance", |p, d| {
        p.joint.clearance = d.joint.clearance
    }),
    ("joint.journalRadius", |p, d| {
        p.joint.journal_radius = d.joint.journal_radius
    }),
    ("joint.youngsModulus", |p, d| {
        p.joint.youngs_modulus = d.joint.youngs_modulus
    }),
    ("joint.poissonRatio", |p, d| {
        p.joint.poisson_ratio = d.joint.poisson_ratio
    }),
    ("joint.restitution", |p, d| {
        p.joint.restitution = d.joint.restitution
    }),
    ("joint.friction", |p, d| p.joint.friction = d.joint.friction),
    ("joint.frictionV0", |p, d| {
        p.joint.friction_v0 = d.joint.friction_v0
    }),
    ("joint.frictionV1", |p, d| {
        p.joint.friction_v1 = d.joint.friction_v1
    }),
    ("joint.viscosity", |p, d| {
        p.joint.viscosity = d.joint.viscosity
    }),
    ("joint.bearingLength", |p, d| {
        p.joint.bearing_length = d.joint.bearing_length
    }),
    ("joint.switchEccentricity", |p, d| {
        p.joint.switch_eccentricity = d.joint.switch_eccentricity
    }),
    ("drive.mode", |p, d| p.drive_mode = d.drive_mode),
    ("gravity", |p, d| p.gravity = d.gravity),
    ("solver.relativeTolerance", |p, d| {
        p.relative_tolerance = d.relative_tolerance
    }),
    ("solver.maxStepSize", |p, d| {
        p.max_step_size = d.max_step_size
    }),
    ("rod.boundary", |p, d| p.boundary = d.boundary),
    ("solver.method", |p, d| p.method = d.method),
    ("rod.initialState", |p, d| p.initial_state = d.initial_state),
    ("joint.contactLaw", |p, d| {
        p.joint.contact_law = d.joint.contact_law
    }),
    ("solver.maxStepsPerInterval", |p, d| {
        p.max_steps_per_interval = d.max_steps_per_interval
    }),
    ("solver.spectralRadius", |p, d| {
        p.spectral_radius = d.spectral_radius
    }),
    ("solver.impactErrorWeight", |p, d| {
        p.impact_error_weight = d.impact_error_weight
    }),
    ("gravityAngle", |p, d| p.gravity_angle = d.gravity_angle),
    ("rod.outerFibreDistance", |p, d| {
        p.rod.outer_fibre_distance = d.rod.outer_fibre_distance
    }),
    ("joint.initialState", |p, d| {
        p.joint.initial_state = d.joint.initial_state
    }),
    ("crankPin.model", |p, d| {
        p.crank_pin.model = d.crank_pin.model
    }),
    ("crankPin.clearance", |p, d| {
        p.crank_pin.clearance = d.crank_pin.clearance
    }),
    ("crankPin.journalRadius", |p, d| {
        p.crank_pin.journal_radius = d.crank_pin.journal_radius
    }),
    ("crankPin.youngsModulus", |p, d| {
        p.crank_pin.youngs_modulus = d.crank_pin.youngs_modulus
    }),
    ("crankPin.poissonRatio", |p, d| {
        p.crank_pin.poisson_ratio = d.crank_pin.poisson_ratio
    }),
    ("crankPin.restitution", |p, d| {
        p.crank_pin.restitution = d.crank_pin.restitution
    }),
    ("crankPin.contactLaw", |p, d| {
        p.crank_pin.contact_law = d.crank_pin.contact_law
    }),
    ("crankPin.friction", |p, d| {
        p.crank_pin.friction = d.crank_pin.friction
    }),
    ("crankPin.frictionV0", |p, d| {
        p.crank_pin.friction_v0 = d.crank_pin.friction_v0
    }),
    ("crankPin.frictionV1", |p, d| {
        p.crank_pin.friction_v1 = d.crank_pin.friction_v1
    }),
    ("crankPin.viscosity", |p, d| {
        p.crank_pin.viscosity = d.crank_pin.viscosity
    }),
    ("crankPin.bearingLength", |p, d| {
        p.crank_pin.bearing_length = d.crank_pin.bearing_length
    }),
    ("crankPin.switchEccentricity", |p, d| {
        p.crank_pin.switch_eccentricity = d.crank_pin.switch_eccentricity
    }),
    ("crankPin.initialState", |p, d| {
        p.crank_pin.initial_state = d.crank_pin.initial_state
    }),
    ("mainBearing.model", |p, d| {
        p.main_bearing.model = d.main_bearing.model
    }),
    ("mainBearing.clearance", |p, d| {
        p.main_bearing.clearance = d.main_bearing.clearance
    }),
    ("mainBearing.journalRadius", |p, d| {
        p.main_bearing.journal_radius = d.main_bearing.journal_radius
    }),
    ("mainBearing.youngsModulus", |p, d| {
        p.main_bearing.youngs_modulus = d.main_bearing.youngs_modulus
    }),
    ("mainBearing.poissonRatio", |p, d| {
        p.main_bearing.poisson_ratio = d.main_bearing.poisson_ratio
    }),
    ("mainBearing.restitution", |p, d| {
        p.main_bearing.restitution = d.main_bearing.restitution
    }),
    ("mainBearing.contactLaw", |p, d| {
        p.main_bearing.contact_law = d.main_bearing.contact_law
    }),
    ("mainBearing.friction", |p, d| {
        p.main_bearing.friction = d.main_bearing.friction
    }),
    ("mainBearing.frictionV0", |p, d| {
        p.main_bearing.friction_v0 = d.main_bearing.friction_v0
    }),
    ("mainBearing.frictionV1", |p, d| {
        p.main_bearing.friction_v1 = d.main_bearing.friction_v1
    }),
    ("mainBearing.viscosity", |p, d| {
        p.main_bearing.viscosity = d.main_bearing.viscosity
    }),
    ("mainBearing.bearingLength", |p, d| {
        p.main_bearing.bearing_length = d.main_bearing.bearing_length
    }),
    ("mainBearing.switchEccentricity", |p, d| {
        p.main_bearing.switch_eccentricity = d.main_bearing.switch_eccentricity
    }),
    ("mainBearing.initialState", |p, d| {
        p.main_bearing.initial_state = d.main_bearing.initial_state
    }),
    ("rod.quadrature", |p, d| p.quadrature = d.quadrature),
    ("joint.contactGeometry", |p, d| {
        p.joint.contact_geometry = d.joint.contact_geometry
    }),
    ("crankPin.contactGeometry", |p, d| {
        p.crank_pin.contact_geometry = d.crank_pin.contact_geometry
    }),
    ("mainBearing.contactGeometry", |p, d| {
        p.main_bearing.contact_geometry = d.main_bearing.contact_geometry
    }),
    ("joint.filmModel", |p, d| {
        p.joint.film_model = d.joint.film_model
    }),
    ("crankPin.filmModel", |p, d| {
        p.crank_pin.film_model = d.crank_pin.film_model
    }),
    ("mainBearing.filmModel", |p, d| {
        p.main_bearing.film_model = d.main_bearing.film_model
    }),
    ("crank.centreOfMassRatio", |p, d| {
        p.crank_centre_of_mass_ratio = d.crank_centre_of_mass_ratio
    }),
    ("slider.offset", |p, d| p.slider_offset = d.slider_offset),
    ("rod.dampingRatio", |p, d| {
        p.rod.damping_ratio = d.rod.damping_ratio
    }),
    ("rod.crankEndMass", |p, d| {
        p.rod.crank_end_mass = d.rod.crank_end_mass
    }),
    ("rod.sliderEndMass", |p, d| {
        p.rod.slider_end_mass = d.rod.slider_end_mass
    }),
    ("slider.forceTable", |p, d| {
        p.slider_force_table = d.slider_force_table.clone()
    }),
    ("slider.forceTablePeriod", |p, d| {
        p.slider_force_table_period = d.slider_force_table_period
    }),
    ("joint.roughness", |p, d| {
        p.joint.roughness = d.joint.roughness
    }),
    ("joint.boundaryFriction", |p, d| {
        p.joint.boundary_friction = d.joint.boundary_friction
    }),
    ("joint.asperityDensityProduct", |p, d| {
        p.joint.asperity_density_product = d.joint.asperity_density_product
    }),
    ("joint.asperityRoughnessRatio", |p, d| {
        p.joint.asperity_roughness_ratio = d.joint.asperity_roughness_ratio
    }),
    ("joint.thermalModel", |p, d| {
        p.joint.thermal_model = d.joint.thermal_model
    }),
    ("joint.thermalStart", |p, d| {
        p.joint.thermal_start = d.joint.thermal_start
    }),
    ("joint.heatCapacity", |p, d| {
        p.joint.heat_capacity = d.joint.heat_capacity
    }),
    ("joint.heatTransferCoefficient", |p, d| {
        p.joint.heat_transfer_coefficient = d.joint.heat_transfer_coefficient
    }),
    ("crankPin.roughness", |p, d| {
        p.crank_pin.roughness = d.crank_pin.roughness
    }),
    ("crankPin.boundaryFriction", |p, d| {
        p.crank_pin.boundary_friction = d.crank_pin.boundary_friction
    }),
    ("crankPin.asperityDensityProduct", |p, d| {
        p.crank_pin.asperity_density_product = d.crank_pin.asperity_density_product
    }),
    ("crankPin.asperityRoughnessRatio", |p, d| {
        p.crank_pin.asperity_roughness_ratio = d.crank_pin.asperity_roughness_ratio
    }),
    ("crankPin.thermalModel", |p, d| {
        p.crank_pin.thermal_model = d.crank_pin.thermal_model
    }),
    ("crankPin.thermalStart", |p, d| {
        p.crank_pin.thermal_start = d.crank_pin.thermal_start
    }),
    ("crankPin.heatCapacity", |p, d| {
        p.crank_pin.heat_capacity = d.crank_pin.heat_capacity
    }),
    ("crankPin.heatTransferCoefficient", |p, d| {
        p.crank_pin.heat_transfer_coefficient = d.crank_pin.heat_transfer_coefficient
    }),
    ("mainBearing.roughness", |p, d| {
        p.main_bearing.roughness = d.main_bearing.roughness
    }),
    ("mainBearing.boundaryFriction", |p, d| {
        p.main_bearing.boundary_friction = d.main_bearing.boundary_friction
    }),
    ("mainBearing.asperityDensityProduct", |p, d| {
        p.main_bearing.asperity_density_product = d.main_bearing.asperity_density_product
    }),
    ("mainBearing.asperityRoughnessRatio", |p, d| {
        p.main_bearing.asperity_roughness_ratio = d.main_bearing.asperity_roughness_ratio
    }),
    ("mainBearing.thermalModel", |p, d| {
        p.main_bearing.thermal_model = d.main_bearing.thermal_model
    }),
    ("mainBearing.thermalStart", |p, d| {
        p.main_bearing.thermal_start = d.main_bearing.thermal_start
    }),
    ("mainBearing.heatCapacity", |p, d| {
        p.main_bearing.heat_capacity = d.main_bearing.heat_capacity
    }),
    ("mainBearing.heatTransferCoefficient", |p, d| {
        p.main_bearing.heat_transfer_coefficient = d.main_bearing.heat_transfer_coefficient
    }),
    ("oil.viscosity40", |p, d| {
        p.oil.viscosity40 = d.oil.viscosity40
    }),
    ("oil.viscosity100", |p, d| {
        p.oil.viscosity100 = d.oil.viscosity100
    }),
    ("oil.density", |p, d| p.oil.density = d.oil.density),
    ("oil.specificHeat", |p, d| {
        p.oil.specific_heat = d.oil.specific_heat
    }),
    ("joint.feed", |p, d| p.joint.feed = d.joint.feed),
    ("joint.feedLocation", |p, d| {
        p.joint.feed_location = d.joint.feed_location
    }),
    ("joint.feedPosition", |p, d| {
        p.joint.feed_position = d.joint.feed_position
    }),
    ("joint.feedDiameter", |p, d| {
        p.joint.feed_diameter = d.joint.feed_diameter
    }),
    ("joint.feedGrooveLength", |p, d| {
        p.joint.feed_groove_length = d.joint.feed_groove_length
    }),
    ("crankPin.feed", |p, d| p.crank_pin.feed = d.crank_pin.feed),
    ("crankPin.feedLocation", |p, d| {
        p.crank_pin.feed_location = d.crank_pin.feed_location
    }),
    ("crankPin.feedPosition", |p, d| {
        p.crank_pin.feed_position = d.crank_pin.feed_position
    }),
    ("crankPin.feedDiameter", |p, d| {
        p.crank_pin.feed_diameter = d.crank_pin.feed_diameter
    }),
    ("crankPin.feedGrooveLength", |p, d| {
        p.crank_pin.feed_groove_length = d.crank_pin.feed_groove_length
    }),
    ("mainBearing.feed", |p, d| {
        p.main_bearing.feed = d.main_bearing.feed
    }),
    ("mainBearing.feedLocation", |p, d| {
        p.main_bearing.feed_location = d.main_bearing.feed_location
    }),
    ("mainBearing.feedPosition", |p, d| {
        p.main_bearing.feed_position = d.main_bearing.feed_position
    }),
    ("mainBearing.feedDiameter", |p, d| {
        p.main_bearing.feed_diameter = d.main_bearing.feed_diameter
    }),
    ("mainBearing.feedGrooveLength", |p, d| {
        p.main_bearing.feed_groove_length = d.main_bearing.feed_groove_length
    }),
];

/// A parameter as the XML declares it: name, value reference, type and range, start.
#[derive(Debug)]
struct Declared {
    name: String,
    vr: u32,
    kind: String,
    min: f64,
    max: f64,
    start: String,
}

/// The value of attribute `key` in an element's text, if present.
fn attribute<'a>(element: &'a str, key: &str) -> Option<&'a str> {
    let at = element.find(&format!(" {key}=\""))? + key.len() + 3;
    element[at..].split('"').next()
}

/// The parameters of the committed XML, with the ranges of their declared types.
fn declared_parameters() -> Vec<Declared> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("modelDescription/modelDescription.xml");
    let xml = std::fs::read_to_string(path).unwrap();
    let range = |element: &str, declared: Option<&str>| {
        let declared = declared.map(|t| {
            let at = xml.find(&format!("<SimpleType name=\"{t}\"")).unwrap();
            xml[at..].split("</SimpleType>").next().unwrap()
        });
        let bound = |key, default| {
            attribute(element, key)
                .or_else(|| declared.and_then(|d| attribute(d, key)))
                .map_or(default, |v| v.parse().unwrap())
        };
        (bound("min", f64::NEG_INFINITY), bound("max", f64::INFINITY))
    };
    xml.split("<ScalarVariable ")
        .skip(1)
        .map(|v| format!(" {v}"))
        .filter(|v| attribute(v, "causality") == Some("parameter"))
        .map(|v| {
            let body = v.split('>').nth(1).unwrap().trim_start();
            let kind = body[1..].split(' ').next().unwrap().to_string();
            let (min, max) = range(body, attribute(body, "declaredType"));
            Declared {
                name: attribute(&v, "name").unwrap().to_string(),
                vr: attribute(&v, "valueReference").unwrap().parse().unwrap(),
                kind,
                min,
                max,
                start: attribute(body, "start").unwrap().to_string(),
            }
        })
        .collect()
}

/// Sets a declared parameter to a value given as text, through the value reference in the XML.
fn set(p: &mut Parameters, declared: &Declared, value: &str) {
    let vr: Vr = VARIABLES
        .iter()
        .find(|v| v.vr as u32 == declared.vr)
        .unwrap()
        .vr;
    let set = match declared.kind.as_str() {
        "Real" => set_real_parameter(p, vr, value.parse().unwrap()),
        "Integer" => set_integer_parameter(p, vr, value.parse().unwrap()),
        "String" => set_string_parameter(p, vr, value),
        kind => panic!("{}: a {kind} parameter", declared.name),
    };
    assert!(set, "{} = {value} refused", declared.name);
}

/// Values of a declared parameter other than its start, inside its range: every other item of a
/// switch or integer range up to three values, a Real between its start and its maximum.
fn other_values(d: &Declared) -> Vec<String> {
    match d.kind.as_str() {
        "Real" => {
            let start: f64 = d.start.parse().unwrap();
            let value = if d.max.is_finite() && d.max > start {
                0.5 * (start + d.max)
            } else if d.min.is_finite() && d.min < start {
                0.5 * (start + d.min)
            } else {
                start + 1.0
            };
            vec![value.to_string()]
        }
        "Integer" => {
            let start: i64 = d.start.parse().unwrap();
            let (min, max) = (d.min as i64, d.max as i64);
            let mut values: Vec<i64> = (min..=max.min(min + 3)).collect();
            values.extend([max].iter().filter(|&&k| k > min + 3));
            values
                .into_iter()
                .filter(|&k| k != start)
                .map(|k| k.to_string())
                .collect()
        }
        _ => vec!["table.csv".to_string()],
    }
}

#[test]
fn every_declared_parameter_has_a_field() {
    let declared = declared_parameters();
    let names: Vec<&str> = declared.iter().map(|d| d.name.as_str()).collect();
    let listed: Vec<&str> = FIELDS.iter().map(|(name, _)| *name).collect();
    let missing: Vec<_> = names.iter().filter(|n| !listed.contains(n)).collect();
    let extra: Vec<_> = listed.iter().filter(|n| !names.contains(n)).collect();
    assert!(
        missing.is_empty() && extra.is_empty(),
        "{missing:?} {extra:?}"
    );
}

#[test]
fn every_parameter_sets_its_own_field_and_nothing_else() {
    let default = Parameters::default();
    for d in declared_parameters() {
        let restore = FIELDS.iter().find(|(name, _)| *name == d.name).unwrap().1;
        let mut seen = vec![default.clone()];
        for value in other_values(&d) {
            let mut p = default.clone();
            set(&mut p, &d, &value);
            assert!(!seen.contains(&p), "{} = {value} sets nothing new", d.name);
            seen.push(p.clone());
            restore(&mut p, &default);
            assert!(p == default, "{} = {value} sets another field", d.name);
        }
    }
}
