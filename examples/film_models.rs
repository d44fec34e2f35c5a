//! The short film against the finite one: how much more load Ocvirk's infinitely short bearing
//! carries than the finite bearing (the Reynolds solution over its length) at the same
//! eccentricity, and how much thicker a film it reports under the same steady load, over the
//! length-to-diameter ratios designers use (docs/guide/sizing.md, "Which film").
//!
//! `cargo run --release --example film_models`

use flexible_slider_crank::joint::{
    FilmModel, Joint, JointKinematics, JointModel, JointParameters, JournalBearing,
};
use nalgebra::Vector2;

/// A journal of 10 mm radius and 20 µm clearance, 0.02 Pa s, at L/D `lambda`.
fn bearing(lambda: f64, film: FilmModel) -> JournalBearing {
    let p = JointParameters {
        model: JointModel::Lubricated,
        clearance: 20e-6,
        journal_radius: 0.01,
        bearing_length: 0.02 * lambda,
        viscosity: 0.02,
        switch_eccentricity: 0.99,
        film_model: film,
        ..JointParameters::benchmark()
    };
    match Joint::new(&p) {
        Ok(Joint::Lubricated(b)) => b,
        _ => unreachable!("a lubricated joint"),
    }
}

/// The steady load at eccentricity ratio `eps`, the journal turning at 150 rad/s \[N\].
fn load(b: &JournalBearing, eps: f64) -> f64 {
    b.film_force(&JointKinematics {
        e: Vector2::new(eps * b.dry.clearance, 0.0),
        e_dot: Vector2::zeros(),
        omega_journal: 150.0,
        omega_bearing: 0.0,
        viscosity: None,
    })
    .norm()
}

/// The eccentricity ratio at which `b` carries the steady load `w`, by bisection.
fn eccentricity(b: &JournalBearing, w: f64) -> f64 {
    let (mut low, mut high) = (0.0, 0.99);
    for _ in 0..60 {
        let mid = 0.5 * (low + high);
        if load(b, mid) < w {
            low = mid;
        } else {
            high = mid;
        }
    }
    0.5 * (low + high)
}

fn main() {
    let ratios = [0.25, 0.33, 0.5, 0.67, 0.75, 1.0, 1.5, 2.0];
    let eccentricities = [0.3, 0.5, 0.7, 0.8, 0.9, 0.95];
    println!("Load of the short film over the finite film's at the same eccentricity ratio ε:");
    print!("| L/D |");
    for eps in eccentricities {
        print!(" ε = {eps} |");
    }
    println!("\n|---|{}", "---|".repeat(eccentricities.len()));
    for lambda in ratios {
        let (short, finite) = (
            bearing(lambda, FilmModel::Short),
            bearing(lambda, FilmModel::Finite),
        );
        print!("| {lambda} |");
        for eps in eccentricities {
            print!(" {:.2} |", load(&short, eps) / load(&finite, eps));
        }
        println!();
    }
    println!(
        "\nSmallest film thickness under the same steady load (the finite film's load at ε), \
         short film against finite film, in % of the clearance:"
    );
    print!("| L/D |");
    for eps in eccentricities {
        print!(" finite ε = {eps} |");
    }
    println!("\n|---|{}", "---|".repeat(eccentricities.len()));
    for lambda in ratios {
        let (short, finite) = (
            bearing(lambda, FilmModel::Short),
            bearing(lambda, FilmModel::Finite),
        );
        print!("| {lambda} |");
        for eps in eccentricities {
            let e_short = eccentricity(&short, load(&finite, eps));
            print!(
                " {:.0} vs {:.0} |",
                100.0 * (1.0 - e_short),
                100.0 * (1.0 - eps)
            );
        }
        println!();
    }
}
