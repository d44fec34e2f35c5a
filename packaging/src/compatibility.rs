//! Compatibility information: each FMU's DefaultExperiment run through its FMI model interface
//! ([`fmi_export::reference`]), shipped inside the FMU under `extra/org.fmi-standard.fmi-ls-ref/`
//! with an FMI-LS-REF manifest, and beside it in the FMI cross-check layout
//! `compatibility/2.0/cs/<platform>/<tool>/<version>/<model>/` (the FMU, `<model>_ref.csv`,
//! `<model>_ref.opt`, `<model>_in.csv` if it has inputs, `README.md`), which
//! `fmpy.cross_check.validate_vendor_repo` validates; and the motor–crank system's run beside
//! its SSP, `compatibility/ssp/MotorCrank/`, in the same files.

use std::error::Error;
use std::path::{Path, PathBuf};

use dc_motor::fmu::DcMotorFmu;
use flexible_slider_crank::fmi::instance::SliderCrankFmu;
use fmi_export::reference::{Experiment, Results, Slave, run};
use fmi_export::{FmuError, Model};
use lube_circuit::fmu::LubricationCircuitFmu;

/// The exporting tool and its version in the cross-check layout.
pub const TOOL: (&str, &str) = ("flexible-slider-crank", env!("CARGO_PKG_VERSION"));

/// Where FMI-LS-REF keeps its files inside an FMU.
const EXTRA: &str = "extra/org.fmi-standard.fmi-ls-ref";

/// One FMU's reference files: (file name, contents).
pub struct References {
    /// The model identifier, the stem of every file name.
    pub model: &'static str,
    /// `<model>_ref.csv`, `<model>_ref.opt` and, with inputs, `<model>_in.csv`.
    pub files: Vec<(String, String)>,
    /// What the files are and how to check an import against them.
    pub readme: String,
}

/// The slider-crank's DefaultExperiment: benchmark B, two revolutions at 5000 rpm, inputs at
/// their start values.
pub fn slider_crank() -> Result<References, Box<dyn Error>> {
    let (start, stop, tolerance, step) = flexible_slider_crank::variables::DEFAULT_EXPERIMENT;
    references::<SliderCrankFmu>(
        flexible_slider_crank::fmi::MODEL_IDENTIFIER,
        &Experiment {
            start,
            stop,
            step,
            tolerance,
            inputs: Vec::new(),
        },
    )
}

/// The motor's DefaultExperiment with its load turning at 500 rad/s, below the 5000 rpm
/// set-point (at its start value): the shaft winds up and the controller answers.
pub fn motor() -> Result<References, Box<dyn Error>> {
    let description = dc_motor::variables::DESCRIPTION;
    let (start, stop, tolerance, step) = description.default_experiment;
    let set_point = description
        .variables
        .iter()
        .find(|v| v.name == "speed.setPoint")
        .and_then(|v| match v.kind {
            fmi_export::table::Kind::Real { start, .. } => start,
            _ => None,
        })
        .ok_or("speed.setPoint has no start value")?;
    references::<DcMotorFmu>(
        dc_motor::MODEL_IDENTIFIER,
        &Experiment {
            start,
            stop,
            step,
            tolerance,
            inputs: vec![("shaft.speed", 500.0), ("speed.setPoint", set_point)],
        },
    )
}

/// The lubrication circuit's DefaultExperiment (one second) with the compressor's bearings'
/// flows held: 0.6 and 0.4 cm³/s of oil through the main bearing and the crank pin, carrying
/// back 10 W and 6 W.
pub fn circuit() -> Result<References, Box<dyn Error>> {
    let (start, stop, tolerance, step) = lube_circuit::variables::DESCRIPTION.default_experiment;
    references::<LubricationCircuitFmu>(
        lube_circuit::MODEL_IDENTIFIER,
        &Experiment {
            start,
            stop,
            step,
            tolerance,
            inputs: vec![
                ("mainBearing.oilFlow", 0.6e-6),
                ("crankPin.oilFlow", 0.4e-6),
                ("mainBearing.heatFlow", 10.0),
                ("crankPin.heatFlow", 6.0),
            ],
        },
    )
}

fn references<M: Model>(
    model: &'static str,
    experiment: &Experiment,
) -> Result<References, Box<dyn Error>> {
    let results = run::<M>(experiment)?;
    let mut files = vec![
        (format!("{model}_ref.csv"), results.csv()),
        (format!("{model}_ref.opt"), experiment.options()),
    ];
    if let Some(inputs) = experiment.input_csv() {
        files.push((format!("{model}_in.csv"), inputs));
    }
    let inputs = if experiment.inputs.is_empty() {
        ", with every input at its start value".to_string()
    } else {
        format!(", with the inputs of {model}_in.csv held over the run")
    };
    let readme = format!(
        "{model}: reference results\n\n\
         {model}_ref.csv holds every Real output of {model} at every communication point of the \
         experiment in {model}_ref.opt (start and stop time, communication step, relative \
         tolerance passed to fmi2SetupExperiment){inputs}. They come from the FMU's own code, run \
         the way fmpy's simulate_fmu runs it: fmi2SetupExperiment, the inputs set in \
         initialization mode and before each step, communication points at start + n step. A \
         master that runs the same experiment on the same processor gets the same bits; on \
         another processor the results agree to about 1e-12 relative.\n\n\
         The files are in extra/org.fmi-standard.fmi-ls-ref/ (FMI-LS-REF), listed in its \
         fmi-ls-manifest.xml, and in the FMI cross-check layout beside the FMU.\n"
    );
    Ok(References {
        model,
        files,
        readme,
    })
}

/// The motor–crank system of `MotorCrank.ssp` over its 24 ms DefaultExperiment: the parameters
/// the SSP binds (the crank torque-driven with a 0.02 kg m² flywheel, the motor knowing that
/// load), and every 1e-4 s the motor's shaft torque to the crank's drive torque and the crank's
/// speed to the motor's shaft speed, both FMUs then stepping from the same point (Jacobi, as
/// libcosim's fixed-step algorithm and the fmpy loop `fsc.system.run` do). Every Real output of
/// both, named `<component>.<variable>`.
pub fn system() -> Result<References, Box<dyn Error>> {
    let (stop, step): (f64, f64) = (0.024, 1e-4);
    let mut crank = started::<SliderCrankFmu>(&[("drive.mode", 2.0), ("crank.inertia", 0.02)])?;
    let mut motor = started::<DcMotorFmu>(&[("shaft.loadInertia", 0.0205)])?;
    let crank_outputs = Slave::<SliderCrankFmu>::real_outputs();
    let motor_outputs = Slave::<DcMotorFmu>::real_outputs();
    let record = |crank: &mut Slave<SliderCrankFmu>,
                  motor: &mut Slave<DcMotorFmu>,
                  t: f64|
     -> Result<(f64, Vec<f64>), Box<dyn Error>> {
        let mut row = crank.get(&crank_outputs)?;
        row.extend(motor.get(&motor_outputs)?);
        Ok((t, row))
    };
    let mut rows = vec![record(&mut crank, &mut motor, 0.0)?];
    for k in 0..(stop / step).round() as u32 {
        let t = f64::from(k) * step;
        let torque = motor.get(&["shaft.torque"])?[0];
        let speed = crank.get(&["crank.speed"])?[0];
        crank.set("drive.torque", torque)?;
        motor.set("shaft.speed", speed)?;
        crank.step(t, step)?;
        motor.step(t, step)?;
        rows.push(record(&mut crank, &mut motor, f64::from(k + 1) * step)?);
    }
    let names = crank_outputs
        .iter()
        .map(|n| format!("sliderCrank.{n}"))
        .chain(motor_outputs.iter().map(|n| format!("dcMotor.{n}")))
        .collect();
    let experiment = Experiment {
        start: 0.0,
        stop,
        step,
        tolerance: flexible_slider_crank::variables::DEFAULT_EXPERIMENT.2,
        inputs: Vec::new(),
    };
    let model = "MotorCrank";
    let readme = format!(
        "{model}: reference results\n\n\
         {model}_ref.csv holds every Real output of both components of {model}.ssp \
         (sliderCrank.*, dcMotor.*) at every communication point of its 24 ms DefaultExperiment, \
         with the parameters the SSP binds: every {step} s the motor's shaft.torque is set as the \
         crank's drive.torque and the crank's crank.speed as the motor's shaft.speed, and both \
         FMUs step from the same point (Jacobi: libcosim's fixed-step algorithm), inputs held. \
         No tolerance is passed to fmi2SetupExperiment ({model}_ref.opt gives the crank's \
         default). libcosim, from the SSP or the OSP system structure, gets the same bits on the \
         same processor.\n"
    );
    Ok(References {
        model,
        files: vec![
            (format!("{model}_ref.csv"), Results { names, rows }.csv()),
            (format!("{model}_ref.opt"), experiment.options()),
        ],
        readme,
    })
}

/// A slave of `M` set up from 0 without tolerance or stop time (as `fsc.system` does), with
/// `parameters` set, initialized.
fn started<M: Model>(parameters: &[(&str, f64)]) -> Result<Slave<M>, FmuError> {
    let mut slave = Slave::<M>::new();
    slave.setup(None, 0.0, None)?;
    for (name, value) in parameters {
        slave.set(name, *value)?;
    }
    slave.enter_initialization();
    slave.exit_initialization()?;
    Ok(slave)
}

impl References {
    /// The entries to add to the FMU: the reference files and their manifest under
    /// `extra/org.fmi-standard.fmi-ls-ref/`, and `documentation/fmi-ls-ref.txt`.
    pub fn fmu_entries(&self) -> Vec<(String, Vec<u8>)> {
        let mut entries: Vec<(String, Vec<u8>)> = self
            .files
            .iter()
            .map(|(name, text)| (format!("{EXTRA}/{name}"), text.clone().into_bytes()))
            .collect();
        entries.push((
            format!("{EXTRA}/fmi-ls-manifest.xml"),
            self.manifest().into_bytes(),
        ));
        entries.push((
            "documentation/fmi-ls-ref.txt".to_string(),
            self.readme.clone().into_bytes(),
        ));
        entries
    }

    /// The FMI-LS-REF manifest naming each reference file's role.
    fn manifest(&self) -> String {
        let mut related = String::new();
        for (name, _) in &self.files {
            let (kind, role, description) = if name.ends_with("_ref.csv") {
                (
                    "text/csv",
                    "result",
                    "Every Real output at every communication point of the experiment",
                )
            } else if name.ends_with("_in.csv") {
                ("text/csv", "experiment", "Inputs of the experiment")
            } else {
                (
                    "text/plain",
                    "experiment",
                    "Start time, stop time, communication step and relative tolerance",
                )
            };
            related.push_str(&format!(
                "    <Related type=\"{kind}\" source=\"{name}\" role=\"{role}\" \
                 description=\"{description}\"/>\n"
            ));
        }
        format!(
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<fmiReferences\n    \
             xmlns:fmi-ls=\"http://fmi-standard.org/fmi-ls-manifest\"\n    \
             fmi-ls:fmi-ls-name=\"org.fmi-standard.fmi-ls-ref\"\n    \
             fmi-ls:fmi-ls-version=\"1.0.0-alpha.1\"\n    \
             fmi-ls:fmi-ls-description=\"Layered Standard providing information on related \
             files included in an FMU.\">\n{related}</fmiReferences>\n"
        )
    }

    /// Writes the cross-check folder of `fmu` for the platform of each of its `binaries`.
    pub fn write_cross_check(
        &self,
        out_dir: &Path,
        fmu: &Path,
        binaries: &[(&str, PathBuf)],
    ) -> Result<(), Box<dyn Error>> {
        for (platform, _) in binaries {
            let dir = out_dir.join("compatibility/2.0/cs").join(platform);
            self.write_folder(&dir.join(TOOL.0).join(TOOL.1), fmu)?;
        }
        Ok(())
    }

    /// Writes `compatibility/ssp/<model>/` for the system `ssp`.
    pub fn write_system(&self, out_dir: &Path, ssp: &Path) -> Result<(), Box<dyn Error>> {
        self.write_folder(&out_dir.join("compatibility/ssp"), ssp)
    }

    /// Writes `parent/<model>/`: the `archive` (FMU or SSP), the reference files and README.md.
    fn write_folder(&self, parent: &Path, archive: &Path) -> Result<(), Box<dyn Error>> {
        let dir = parent.join(self.model);
        std::fs::create_dir_all(&dir)?;
        let name = archive
            .file_name()
            .ok_or("an archive without a file name")?;
        std::fs::copy(archive, dir.join(name))?;
        for (name, text) in &self.files {
            std::fs::write(dir.join(name), text)?;
        }
        std::fs::write(dir.join("README.md"), &self.readme)?;
        Ok(())
    }
}
