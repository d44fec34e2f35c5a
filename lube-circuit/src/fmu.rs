//! [`LubricationCircuitFmu`]: the circuit as a [`Model`] of `fmi-export` — parameters, the state
//! and the state codec; its inputs (polynomials over the communication step), the experiment and
//! the clock are the instance's ([`Context`]).

use fmi_core::clock::on_clock_grid;
use fmi_core::codec::{ByteReader, ByteWriter};
use fmi_core::number::Num;
use fmi_core::signal::{InputRecord, Polynomial};
use fmi_export::checks::check_real;
use fmi_export::model::{Context, Var};
use fmi_export::{FmuError, Logger, Model, State, Step, StepOutcome};

use crate::circuit::{BearingLoads, CircuitParameters, CircuitState, substeps};
use crate::variables::{Causality, INPUTS, Kind, LOG_CATEGORIES, VARIABLES, Variable, Vr};

/// Number of parameters (value references 0 … N − 1).
const N_PARAMETERS: usize = Vr::MainBearingOilFlow as usize;
/// Most internal steps per communication step.
const MAX_STEPS: f64 = 1e8;

/// The inputs (three oil flows, three heat flows) over a communication step.
type Signal = Polynomial<[f64; 6]>;

/// The instance's inputs ([`InputRecord`]).
type Record = InputRecord<[f64; 6]>;

/// What the instance holds for the circuit: the logger, the inputs and the clock.
type Cx<'a> = Context<'a, [f64; 6]>;

/// The bearings' loads, summed, of `signal` at `t`.
fn loads(signal: &Signal, t: f64) -> BearingLoads {
    let u = signal.at(t);
    BearingLoads {
        oil_flow: u[0] + u[1] + u[2],
        heat_flow: u[3] + u[4] + u[5],
    }
}

/// The lubrication circuit behind the FMI functions.
#[derive(Clone, Debug, PartialEq)]
pub struct LubricationCircuitFmu {
    parameters: [f64; N_PARAMETERS],
    /// [p, T_s], from the end of initialization (until then the gallery's steady pressure for
    /// the inputs and the sump's initial temperature).
    state: Option<CircuitState>,
    /// Warnings since the start (the gallery emptied).
    warnings: u32,
}

fn start(vr: usize) -> f64 {
    match VARIABLES[vr].kind {
        Kind::Real { start: Some(s), .. } => s,
        _ => 0.0,
    }
}

impl LubricationCircuitFmu {
    fn circuit(&self) -> CircuitParameters {
        let p = |vr: Vr| self.parameters[vr as usize];
        CircuitParameters {
            pump_flow: p(Vr::PumpFlow),
            relief_pressure: p(Vr::ReliefPressure),
            relief_conductance: p(Vr::ReliefConductance),
            gallery_volume: p(Vr::GalleryVolume),
            bulk_modulus: p(Vr::GalleryBulkModulus),
            sump_volume: p(Vr::SumpVolume),
            density: p(Vr::OilDensity),
            specific_heat: p(Vr::OilSpecificHeat),
            cooler_effectiveness: p(Vr::CoolerEffectiveness),
            coolant_temperature: p(Vr::CoolantTemperature),
        }
    }

    /// The state: until initialization ends, the gallery's steady pressure for the inputs'
    /// oil flows and the sump at its initial temperature.
    fn state(&self, inputs: &Record) -> CircuitState {
        self.state.unwrap_or_else(|| {
            let signal = inputs.stepping();
            let oil_flow = loads(signal, signal.start).oil_flow;
            [
                self.circuit().steady_pressure(oil_flow),
                self.parameters[Vr::SumpInitialTemperature as usize],
            ]
        })
    }

    /// Warns when the gallery, not empty in the state before (`was_starved` false), is empty in
    /// the state `x` at `time` (so once per emptying), the bearings drawing `oil_flow`.
    fn check_starved(
        &mut self,
        log: &Logger,
        (was_starved, x): (bool, &CircuitState),
        time: f64,
        oil_flow: f64,
    ) {
        if x[0] <= 0.0 && !was_starved {
            self.warnings += 1;
            log.warning(&format!(
                "t = {} s: the gallery is empty (zero supply pressure): the bearings draw {} m3/s, \
                 more than pump.flow = {} m3/s",
                Num(time),
                Num(oil_flow),
                Num(self.parameters[Vr::PumpFlow as usize])
            ));
        }
    }
}

/// The circuit's time: the communication point on the clock grid \[s\].
fn time(cx: &Cx) -> f64 {
    on_clock_grid(cx.time)
}

impl Model for LubricationCircuitFmu {
    const GUID: &'static str = crate::GUID;
    const FMI3_TOKENS: [&'static str; 2] = [crate::FMI3_TOKEN, crate::FMI3_SCALAR_TOKEN];
    type Vr = Vr;
    type Inputs = [f64; 6];
    const VARIABLES: &'static [Variable] = VARIABLES;
    const MAX_INPUT_DERIVATIVE_ORDER: u32 =
        crate::variables::DESCRIPTION.max_input_derivative_order;
    const LOG_CATEGORIES: &'static [(&'static str, &'static str)] = LOG_CATEGORIES;
    const STATE_MAGIC: [u8; 4] = *b"LUBE";
    const STATE_VERSION: u32 = 1;

    fn new() -> Self {
        Self {
            parameters: std::array::from_fn(start),
            state: None,
            warnings: 0,
        }
    }

    /// The gallery starts at its steady pressure for the bearings' flows, the sump at its
    /// initial temperature.
    fn exit_initialization(&mut self, cx: &Cx) -> Result<(), FmuError> {
        let x = self.state(cx.inputs);
        self.state = Some(x);
        let oil_flow = loads(cx.inputs.stepping(), time(cx)).oil_flow;
        self.check_starved(cx.log, (false, &x), time(cx), oil_flow);
        cx.log.event(&format!(
            "circuit initialised: supply pressure {} Pa, sump at {} K",
            Num(x[0]),
            Num(x[1])
        ));
        Ok(())
    }

    /// The circuit has no events: every step reaches the communication point.
    fn do_step(&mut self, cx: &Cx, step: &Step) -> Result<StepOutcome, FmuError> {
        // On the clock grid, every master's representation of the same points gives the same
        // step.
        let (t, end) = (on_clock_grid(step.t), on_clock_grid(step.t + step.h));
        let circuit = self.circuit();
        let n = substeps(end - t, circuit.largest_step());
        if f64::from(n) > MAX_STEPS {
            return Err(FmuError::Invalid(format!(
                "communicationStepSize = {} s is more than {} internal steps of an eighth of the \
                 gallery's time constant (gallery.volume/gallery.bulkModulus/relief.conductance)",
                Num(step.h),
                Num(MAX_STEPS)
            )));
        }
        let mut x = self.state(cx.inputs);
        let was_starved = x[0] <= 0.0;
        let signal = Signal {
            start: t,
            ..*cx.inputs.stepping()
        };
        circuit.advance(&mut x, end - t, n, |tau| loads(&signal, t + tau));
        self.state = Some(x);
        self.check_starved(cx.log, (was_starved, &x), end, loads(&signal, end).oil_flow);
        Ok(StepOutcome::Completed { time: end })
    }

    fn get_real(&mut self, cx: &Cx, vars: &[Var<Vr>], values: &mut [f64]) -> Result<(), FmuError> {
        let o = self.circuit().outputs(&self.state(cx.inputs));
        for (&v, value) in vars.iter().zip(values.iter_mut()) {
            *value = match (v.causality, v.vr) {
                (Causality::Parameter, vr) => self.parameters[vr as usize],
                (Causality::Input, vr) => {
                    cx.inputs.reading().value[vr as usize - INPUTS[0] as usize]
                }
                (_, Vr::SupplyPressure) => o.supply_pressure,
                (_, Vr::SupplyTemperature) => o.supply_temperature,
                (_, Vr::SumpTemperature) => o.sump_temperature,
                (_, Vr::ReliefFlow) => o.relief_flow,
                (_, Vr::CoolerHeatFlow) => o.cooler_heat_flow,
                _ => return Err(FmuError::Invalid(format!("{} cannot be read", v.name))),
            };
        }
        Ok(())
    }

    /// The parameters (the inputs are the instance's).
    fn set_real(
        &mut self,
        _state: State,
        vars: &[Var<Vr>],
        values: &[f64],
    ) -> Result<(), FmuError> {
        for (&v, &value) in vars.iter().zip(values) {
            self.parameters[v.vr as usize] = value;
            self.state = None;
        }
        Ok(())
    }

    /// fmi2GetInteger: solver.warnings, the one Integer variable.
    fn get_integer(
        &mut self,
        _cx: &Cx,
        _vars: &[Var<Vr>],
        values: &mut [i32],
    ) -> Result<(), FmuError> {
        values.fill(i32::try_from(self.warnings).unwrap_or(i32::MAX));
        Ok(())
    }

    /// ∂y/∂u = 0: no output depends directly on an input (the pressure and the temperatures are
    /// states, the relief flow and the cooler's heat follow from them).
    fn output_sensitivity(
        &mut self,
        _cx: &Cx,
        _known: Var<Vr>,
        _unknowns: &[Var<Vr>],
        column: &mut [f64],
    ) -> Result<(), FmuError> {
        column.fill(0.0);
        Ok(())
    }

    /// The parameters, the state (NaN before initialization) and the warnings count.
    fn save(&self, out: &mut Vec<u8>) {
        let mut w = ByteWriter(out);
        self.parameters.iter().for_each(|&p| w.f64(p));
        let x = self.state.unwrap_or([f64::NAN; 2]);
        x.iter().for_each(|&v| w.f64(v));
        w.u32(self.warnings);
    }

    fn load(&mut self, _cx: &Cx, bytes: &[u8], apply: bool) -> Result<(), FmuError> {
        let bad = |what: &str| Err(FmuError::Invalid(format!("FMU state rejected: {what}")));
        let mut r = ByteReader::new(bytes);
        let mut parameters = [0.0; N_PARAMETERS];
        for (v, p) in VARIABLES.iter().zip(parameters.iter_mut()) {
            *p = r.f64()?;
            check_real(v, *p)?;
        }
        let state = [r.f64()?, r.f64()?];
        let initialised = state.iter().all(|v| v.is_finite());
        let warnings = r.u32()?;
        if r.remaining() != 0 {
            return bad(&format!("{} bytes too many", r.remaining()));
        }
        if !(initialised || state.iter().all(|v| v.is_nan())) || state[0] < 0.0 {
            return bad("a non-finite state or a negative pressure");
        }
        if apply {
            self.parameters = parameters;
            self.state = initialised.then_some(state);
            self.warnings = warnings;
        }
        Ok(())
    }
}
