//! A load tied to the crank angle (`slider.forceTable`): a constant table is the constant input
//! bit for bit, a varying table is the load a master would feed at the crank angle it reads, in
//! either drive mode, and its work closes the energy balance.

use super::balance::output_balance_residual;
use super::*;
use flexible_slider_crank::Inputs;
use flexible_slider_crank::load_table::LoadTable;

/// A table file in a directory of this test process; its path.
fn table_file(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("fsc_load_table_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.to_string_lossy().into_owned()
}

/// A gas load over one crank turn: a sharp compression pulse near the outer dead centre
/// (crank angle 0) and a light suction load for the rest \[deg, N\].
const GAS_LOAD: &str = "# crank angle [deg], force [N]\n\
    crank angle,force\n\
    0,-900\n15,-2400\n35,-1500\n80,-400\n150,-120\n220,-60\n300,-150\n345,-500\n";

/// A table of the same value at every angle runs the model that the same constant
/// `slider.force` runs: every output equal, bit for bit, over a revolution of benchmark B.
#[test]
fn a_constant_table_is_the_constant_slider_force() {
    let table = Parameters {
        slider_force_table: table_file("constant.csv", "0,-300\n120,-300\n240,-300\n"),
        ..Parameters::default()
    };
    let input = Inputs {
        slider_force: -300.0,
        ..Inputs::at_start(&table)
    };
    let rows = |p: Parameters, inputs: Inputs| {
        let mut sim = Simulation::with_inputs(p, inputs).unwrap();
        (1..=50)
            .map(|i| {
                sim.advance_to(REVOLUTION * f64::from(i) / 50.0).unwrap();
                sim.outputs().unwrap()
            })
            .collect::<Vec<_>>()
    };
    let by_table = rows(table.clone(), Inputs::at_start(&table));
    let by_input = rows(Parameters::default(), input);
    assert_eq!(by_table, by_input);
    assert!(by_table.iter().all(|o| o.slider_applied_force == -300.0));
}

/// The largest differences (joint force, axial force at the slider pin, crank speed) over one
/// revolution between a run with the table and one whose master feeds the same load: at every
/// communication point, `h` apart, it reads crank.angle and sets slider.force to the table's
/// value there, held over the step; with the largest values of the table run and that run's
/// outputs every 40 µs.
fn against_a_master_feed(
    p: &Parameters,
    inputs: Inputs,
    path: &str,
    h: f64,
) -> ([f64; 3], [f64; 3], Vec<Outputs>) {
    let load = LoadTable::read(path, 360.0, None).unwrap();
    let n = (REVOLUTION / h).round() as usize;
    let every = (40e-6 / h).round() as usize;
    let mut by_table = Simulation::with_inputs(
        Parameters {
            slider_force_table: path.to_string(),
            ..p.clone()
        },
        inputs,
    )
    .unwrap();
    let first = Inputs {
        slider_force: load.at(0.0),
        ..inputs
    };
    let mut fed = Simulation::with_inputs(p.clone(), first).unwrap();
    let mut fed_inputs = *fed.inputs();
    let values = |o: &Outputs| [o.joint_force, o.rod_axial_force_slider_pin, o.crank_speed];
    let (mut worst, mut largest) = ([0.0f64; 3], [0.0f64; 3]);
    let mut rows = vec![by_table.outputs().unwrap()];
    let mut angle = fed.outputs().unwrap().crank_angle;
    for i in 1..=n {
        let t = REVOLUTION * i as f64 / n as f64;
        fed_inputs.value.slider_force = load.at(angle);
        fed.advance_with(&fed_inputs, t).unwrap();
        by_table.advance_to(t).unwrap();
        let (a, b) = (by_table.outputs().unwrap(), fed.outputs().unwrap());
        angle = b.crank_angle;
        for (k, (x, y)) in values(&a).into_iter().zip(values(&b)).enumerate() {
            worst[k] = worst[k].max((x - y).abs());
            largest[k] = largest[k].max(x.abs());
        }
        if i % every == 0 {
            rows.push(a);
        }
    }
    (worst, largest, rows)
}

/// The table against the load a master feeds at the crank angle it reads (see
/// [`against_a_master_feed`]). With the flexible rod (4 modes) and ideal joints, in the speed
/// drive and in the torque drive (where the crank's speed varies, so that no time table would
/// stay in phase): at a 2 µs step (0.06° at 5000 rpm) the joint force, the rod's axial force at
/// the slider pin and the crank speed agree within 0.5 % of their largest values over one
/// revolution; the difference halves (within 20 %) with the step from 4 µs (the crank speed's
/// in the torque drive: the speed drive prescribes it), as the master's
/// hold error does, so the table is the limit of a finer and finer feed; and the table's runs
/// close their energy balance (its work is in energy.sliderWork).
#[test]
fn a_table_is_the_load_a_master_feeds_at_the_crank_angle() {
    let path = table_file("gas.csv", GAS_LOAD);
    let names = [
        "joint force",
        "axial force at the slider pin",
        "crank speed",
    ];
    for (drive_mode, torque) in [(DriveMode::Speed, 0.0), (DriveMode::Torque, 2.0)] {
        let p = Parameters {
            drive_mode,
            joint: JointParameters {
                model: JointModel::Ideal,
                ..JointParameters::benchmark()
            },
            relative_tolerance: 1e-8,
            ..Parameters::default()
        };
        let inputs = Inputs {
            drive_torque: torque,
            ..Inputs::at_start(&p)
        };
        let (coarse, _, _) = against_a_master_feed(&p, inputs, &path, 4e-6);
        let (fine, largest, rows) = against_a_master_feed(&p, inputs, &path, 2e-6);
        for k in 0..3 {
            let ratio = coarse[k] / fine[k];
            println!(
                "{drive_mode:?} drive, {}: table vs master's feed {:.3} % of {:.1} at 2 µs, \
                 {:.3} % at 4 µs (ratio {ratio:.2})",
                names[k],
                100.0 * fine[k] / largest[k],
                largest[k],
                100.0 * coarse[k] / largest[k],
            );
            assert!(fine[k] < 5e-3 * largest[k], "{drive_mode:?}, {}", names[k]);
            if drive_mode == DriveMode::Torque || k < 2 {
                assert!(
                    (1.6..2.4).contains(&ratio),
                    "{drive_mode:?}, {}: {ratio}",
                    names[k]
                );
            }
        }
        let applied = rows
            .iter()
            .fold(0.0f64, |m, o| m.min(o.slider_applied_force));
        assert!(applied < -2000.0, "{applied}");
        let residual = output_balance_residual(&rows);
        println!("{drive_mode:?} drive: energy balance residual {residual:.1e}");
        assert!(residual < 1e-6, "{residual:e}");
    }
}

/// A table whose file is missing, or whose period is neither one turn nor two, is refused when
/// the model is built, with the parameter, the file or the value in the message.
#[test]
fn a_bad_table_is_refused_when_the_model_is_built() {
    let missing = Parameters {
        slider_force_table: "no/such/gas.csv".into(),
        ..Parameters::default()
    };
    let message = Simulation::new(missing).unwrap_err().to_string();
    assert!(
        message.contains("slider.forceTable = \"no/such/gas.csv\": no such file"),
        "{message}"
    );
    let period = Parameters {
        slider_force_table: table_file("period.csv", GAS_LOAD),
        slider_force_table_period: 500,
        ..Parameters::default()
    };
    let message = Simulation::new(period).unwrap_err().to_string();
    assert!(
        message.contains("slider.forceTablePeriod = 500 is outside"),
        "{message}"
    );
}

/// A table written in radians without saying so (its angles within 2π of a 360° cycle) warns
/// when the model is built, naming the table and the likely mistake; the same table with its
/// unit in the header is read in radians, silently, and is the degrees table's load.
#[test]
fn a_table_in_radians_says_so_or_warns() {
    let points: Vec<(f64, f64)> = GAS_LOAD
        .lines()
        .filter_map(|l| l.split_once(','))
        .filter_map(|(a, f)| Some((a.parse::<f64>().ok()?.to_radians(), f.parse::<f64>().ok()?)))
        .collect();
    let rows: String = points.iter().map(|(a, f)| format!("{a},{f}\n")).collect();
    let run = |name: &str, header: &str| {
        let table = table_file(name, &format!("{header}\n{rows}"));
        let mut sim = Simulation::new(Parameters {
            slider_force_table: table.clone(),
            ..Parameters::default()
        })
        .unwrap();
        let warnings = sim.take_warnings();
        (table, warnings, sim.outputs().unwrap().slider_applied_force)
    };
    let (table, warnings, _) = run("unstated.csv", "crank angle,force");
    assert!(
        warnings
            .iter()
            .any(|w| w.contains(&table) && w.contains("look like radians")),
        "{warnings:?}"
    );
    let (_, warnings, radians) = run("radians.csv", "crank angle [rad],force [N]");
    assert!(warnings.is_empty(), "{warnings:?}");
    let mut degrees = Simulation::new(Parameters {
        slider_force_table: table_file("degrees.csv", GAS_LOAD),
        ..Parameters::default()
    })
    .unwrap();
    let degrees = degrees.outputs().unwrap().slider_applied_force;
    assert!(
        (radians - degrees).abs() < 1e-9 * degrees.abs(),
        "{radians} {degrees}"
    );
}
