//! [`DcMotorFmu`]: the motor as a [`Model`] of `fmi-export` — parameters, the state and the state
//! codec; its inputs (polynomials over the communication step), the experiment and the clock are
//! the instance's ([`Context`]).

use fmi_core::clock::on_clock_grid;
use fmi_core::codec::{ByteReader, ByteWriter};
use fmi_core::number::Num;
use fmi_core::signal::{InputRecord, Polynomial};
use fmi_export::checks::check_real;
use fmi_export::model::{Context, Var};
use fmi_export::{FmuError, Logger, Model, State, Step, StepOutcome};

use crate::coupling::{self, Exchange};
use crate::motor::{MotorInputs, MotorOutputs, MotorParameters, MotorState, substeps};
use crate::variables::{Causality, Kind, LOG_CATEGORIES, VARIABLES, Variable, Vr};

/// Number of parameters (value references 0 … N − 1).
const N_PARAMETERS: usize = Vr::ShaftSpeed as usize;
/// Most internal steps per communication step.
const MAX_STEPS: f64 = 1e8;

/// The inputs (load speed, set-point) over a communication step.
type Signal = Polynomial<[f64; 2]>;

/// The instance's inputs ([`InputRecord`]).
type Record = InputRecord<[f64; 2]>;

/// What the instance holds for the motor: the logger, the inputs and the clock.
type Cx<'a> = Context<'a, [f64; 2]>;

/// The motor's inputs at `t`.
fn inputs(signal: &Signal, t: f64) -> MotorInputs {
    let [load_speed, set_point] = signal.at(t);
    MotorInputs {
        load_speed,
        set_point,
    }
}

/// The DC motor behind the FMI functions.
#[derive(Clone, Debug, PartialEq)]
pub struct DcMotorFmu {
    parameters: [f64; N_PARAMETERS],
    /// [i, ω, φ, z], from the end of initialization (until then the steady state at the
    /// set-point, which follows the inputs).
    state: Option<MotorState>,
    /// Warnings since the start (unstable communication steps).
    warnings: u32,
    /// The communication step whose coupling stability was checked last.
    checked_step: Option<f64>,
}

fn start(vr: usize) -> f64 {
    match VARIABLES[vr].kind {
        Kind::Real { start: Some(s), .. } => s,
        _ => 0.0,
    }
}

impl DcMotorFmu {
    fn motor(&self) -> MotorParameters {
        let p = |vr: Vr| self.parameters[vr as usize];
        MotorParameters {
            resistance: p(Vr::MotorResistance),
            inductance: p(Vr::MotorInductance),
            torque_constant: p(Vr::MotorTorqueConstant),
            inertia: p(Vr::MotorInertia),
            friction: p(Vr::MotorFriction),
            shaft_stiffness: p(Vr::ShaftStiffness),
            shaft_damping: p(Vr::ShaftDamping),
            gain: p(Vr::ControllerGain),
            integral_gain: p(Vr::ControllerIntegralGain),
            tracking_time: p(Vr::ControllerTrackingTime),
            voltage_limit: p(Vr::SupplyVoltageLimit),
        }
    }

    /// The state: until initialization ends, the steady state at the set-point of `inputs`.
    fn state(&self, inputs: &Record) -> MotorState {
        let inputs = inputs.stepping();
        self.state.unwrap_or_else(|| {
            let torque = self.parameters[Vr::ShaftInitialTorque as usize];
            self.motor().steady_state(inputs.value[1], torque)
        })
    }

    /// With `shaft.loadInertia` set, checks a communication step (as `given` by the master, `h`
    /// on the clock grid, in `n` internal steps) other than the one checked last for the
    /// stability of the shaft's coupling to its load ([`coupling`]), and warns of an unstable one.
    fn check_coupling(&mut self, log: &Logger, (given, h): (f64, f64), n: u32) {
        let load_inertia = self.parameters[Vr::ShaftLoadInertia as usize];
        // The same step a master represents differently (on the clock grid, to a few ps).
        let same = |c: f64| (c - h).abs() <= 1e-9 * h;
        if load_inertia <= 0.0 || self.checked_step.is_some_and(same) {
            return;
        }
        self.checked_step = Some(h);
        let motor = self.motor();
        let jacobi = coupling::growth(&motor, load_inertia, h, n, Exchange::Jacobi);
        let motor_first = coupling::growth(&motor, load_inertia, h, n, Exchange::MotorFirst);
        if jacobi <= 1.0 && motor_first <= 1.0 {
            return;
        }
        self.warnings += 1;
        let solver_step = self.parameters[Vr::SolverStepSize as usize];
        let limit = |e| coupling::largest_stable_step(&motor, load_inertia, solver_step, e);
        log.warning(&format!(
            "communication step {} s: the shaft's coupling to its load (shaft.loadInertia = {} \
             kg.m2) with inputs held over the step grows by {} per step when both FMUs step \
             from the same point (Jacobi, stable up to {} s) and by {} when the motor steps \
             first (Gauss-Seidel, stable up to {} s); above 1 it diverges",
            Num(given),
            Num(load_inertia),
            Num(jacobi),
            Num(limit(Exchange::Jacobi)),
            Num(motor_first),
            Num(limit(Exchange::MotorFirst))
        ));
    }
}

/// The motor's time: the communication point on the clock grid \[s\].
fn time(cx: &Cx) -> f64 {
    on_clock_grid(cx.time)
}

/// The motor's inputs at the current point, as outputs read them.
fn now(cx: &Cx) -> MotorInputs {
    inputs(cx.inputs.reading(), time(cx))
}

/// The output `vr` among the motor's outputs (None for any other variable).
fn output(o: &MotorOutputs, vr: Vr) -> Option<f64> {
    match vr {
        Vr::ShaftTorque => Some(o.shaft_torque),
        Vr::MotorSpeed => Some(o.speed),
        Vr::MotorCurrent => Some(o.current),
        Vr::MotorVoltage => Some(o.voltage),
        Vr::ShaftTwist => Some(o.twist),
        _ => None,
    }
}

impl Model for DcMotorFmu {
    const GUID: &'static str = crate::GUID;
    const FMI3_TOKENS: [&'static str; 2] = [crate::FMI3_TOKEN, crate::FMI3_SCALAR_TOKEN];
    type Vr = Vr;
    type Inputs = [f64; 2];
    const VARIABLES: &'static [Variable] = VARIABLES;
    const MAX_INPUT_DERIVATIVE_ORDER: u32 =
        crate::variables::DESCRIPTION.max_input_derivative_order;
    const LOG_CATEGORIES: &'static [(&'static str, &'static str)] = LOG_CATEGORIES;
    const STATE_MAGIC: [u8; 4] = *b"DCMS";
    const STATE_VERSION: u32 = 5;

    fn new() -> Self {
        Self {
            parameters: std::array::from_fn(start),
            state: None,
            warnings: 0,
            checked_step: None,
        }
    }

    /// The motor starts in steady state at the set-point the inputs have now.
    fn exit_initialization(&mut self, cx: &Cx) -> Result<(), FmuError> {
        let x = self.state(cx.inputs);
        self.state = Some(x);
        cx.log.event(&format!(
            "motor initialised in steady state: current {} A, speed {} rad/s",
            Num(x[0]),
            Num(x[1])
        ));
        Ok(())
    }

    /// The motor has no events: every step reaches the communication point.
    fn do_step(&mut self, cx: &Cx, step: &Step) -> Result<StepOutcome, FmuError> {
        let (t, h) = (step.t, step.h);
        // On the clock grid, every master's representation of the same points gives the same
        // step.
        let (t, end) = (on_clock_grid(t), on_clock_grid(t + h));
        let n = substeps(end - t, self.parameters[Vr::SolverStepSize as usize]);
        if f64::from(n) > MAX_STEPS {
            return Err(FmuError::Invalid(format!(
                "communicationStepSize = {} s is more than {} solver.stepSize",
                Num(h),
                Num(MAX_STEPS)
            )));
        }
        self.check_coupling(cx.log, (h, end - t), n);
        let mut x = self.state(cx.inputs);
        let signal = Signal {
            start: t,
            ..*cx.inputs.stepping()
        };
        self.motor()
            .advance(&mut x, end - t, n, |tau| inputs(&signal, t + tau));
        self.state = Some(x);
        Ok(StepOutcome::Completed { time: end })
    }

    fn get_real(&mut self, cx: &Cx, vars: &[Var<Vr>], values: &mut [f64]) -> Result<(), FmuError> {
        for (&v, value) in vars.iter().zip(values.iter_mut()) {
            let read = match (v.causality, v.vr) {
                (Causality::Parameter, vr) => Some(self.parameters[vr as usize]),
                (Causality::Input, Vr::ShaftSpeed) => Some(cx.inputs.reading().value[0]),
                (Causality::Input, _) => Some(cx.inputs.reading().value[1]),
                (_, vr) => {
                    let x = self.state(cx.inputs);
                    output(&self.motor().outputs(&x, &now(cx)), vr)
                }
            };
            *value = read.ok_or_else(|| FmuError::Invalid(format!("{} cannot be read", v.name)))?;
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

    fn get_real_output_derivatives(
        &mut self,
        cx: &Cx,
        vars: &[Var<Vr>],
        orders: &[i32],
        values: &mut [f64],
    ) -> Result<(), FmuError> {
        let x = self.state(cx.inputs);
        let motor = self.motor();
        let now = now(cx);
        let load_rate = cx.inputs.reading().rate(time(cx))[0];
        let d = motor.derivative(&x, &now);
        for ((&v, &order), value) in vars.iter().zip(orders).zip(values.iter_mut()) {
            *value = match (v.vr, order) {
                (Vr::ShaftTorque, 1) => motor.shaft_torque(&d, load_rate),
                (Vr::MotorSpeed, 1) => d[1],
                (Vr::MotorCurrent, 1) => d[0],
                (Vr::ShaftTwist, 1) => d[2],
                _ => {
                    return Err(FmuError::Invalid(format!(
                        "{} has no derivative of order {order} \
                         (order 1 exists for shaft.torque, motor.speed, motor.current and \
                         shaft.twist)",
                        v.name
                    )));
                }
            };
        }
        Ok(())
    }

    /// ∂y/∂u from the motor's equations (`MotorParameters::output_derivatives`).
    fn output_sensitivity(
        &mut self,
        cx: &Cx,
        known: Var<Vr>,
        unknowns: &[Var<Vr>],
        column: &mut [f64],
    ) -> Result<(), FmuError> {
        let set_point = known.vr == Vr::SpeedSetPoint;
        let x = self.state(cx.inputs);
        let d = self.motor().output_derivatives(&x, &now(cx), set_point);
        for (v, c) in unknowns.iter().zip(column.iter_mut()) {
            *c = output(&d, v.vr)
                .ok_or_else(|| FmuError::Invalid(format!("{} is not an output", v.name)))?;
        }
        Ok(())
    }

    /// The parameters, the state (NaN before initialization), the warnings count and the last
    /// checked step (NaN if none).
    fn save(&self, out: &mut Vec<u8>) {
        let mut w = ByteWriter(out);
        self.parameters.iter().for_each(|&p| w.f64(p));
        let x = self.state.unwrap_or([f64::NAN; 4]);
        x.iter().for_each(|&v| w.f64(v));
        w.u32(self.warnings);
        w.f64(self.checked_step.unwrap_or(f64::NAN));
    }

    fn load(&mut self, _cx: &Cx, bytes: &[u8], apply: bool) -> Result<(), FmuError> {
        let bad = |what: &str| Err(FmuError::Invalid(format!("FMU state rejected: {what}")));
        let mut r = ByteReader::new(bytes);
        let mut parameters = [0.0; N_PARAMETERS];
        for (v, p) in VARIABLES.iter().zip(parameters.iter_mut()) {
            *p = r.f64()?;
            check_real(v, *p)?;
        }
        let state = [r.f64()?, r.f64()?, r.f64()?, r.f64()?];
        let initialised = state.iter().all(|v| v.is_finite());
        let (warnings, checked) = (r.u32()?, r.f64()?);
        if r.remaining() != 0 {
            return bad(&format!("{} bytes too many", r.remaining()));
        }
        if !((initialised || state.iter().all(|v| v.is_nan())) && !checked.is_infinite()) {
            return bad("a non-finite state or checked step");
        }
        if apply {
            self.parameters = parameters;
            self.state = initialised.then_some(state);
            self.warnings = warnings;
            self.checked_step = (!checked.is_nan()).then_some(checked);
        }
        Ok(())
    }
}
