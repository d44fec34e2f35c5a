//! A DC motor with a PI speed controller driving a load through a torsional shaft.
//!
//! ```text
//! L di/dt = u − R i − k ω                 armature (back-EMF constant = torque constant k)
//! J dω/dt = k i − τ − b ω                 rotor
//! dφ/dt   = ω − ω_L                       shaft twist (ω_L: the load's speed, an input)
//! τ       = k_s φ + d_s (ω − ω_L)         shaft torque on the load (the output)
//! v       = K_p e + K_i z,  e = ω_ref − ω  PI speed controller
//! u       = clamp(v, −U, U)                converter voltage limit
//! dz/dt   = e + (u − v) / (K_i T_t)        anti-windup by back-calculation (Åström & Hägglund)
//! ```
//! Integrated by the classical Runge–Kutta method in equal steps no longer than
//! `solver.stepSize` per communication step, with the inputs as polynomials of time over it.
//!
//! # References
//! - K. J. Åström, T. Hägglund (2006), Advanced PID Control, §3.5 (integrator windup).

/// Motor, shaft and controller constants.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MotorParameters {
    /// Armature resistance R \[Ω\].
    pub resistance: f64,
    /// Armature inductance L \[H\].
    pub inductance: f64,
    /// Torque (and back-EMF) constant k \[N m/A\].
    pub torque_constant: f64,
    /// Rotor inertia J \[kg m²\].
    pub inertia: f64,
    /// Rotor viscous friction b \[N m s/rad\].
    pub friction: f64,
    /// Shaft torsional stiffness k_s \[N m/rad\].
    pub shaft_stiffness: f64,
    /// Shaft torsional damping d_s \[N m s/rad\].
    pub shaft_damping: f64,
    /// Proportional gain K_p \[V s/rad\].
    pub gain: f64,
    /// Integral gain K_i \[V/rad\].
    pub integral_gain: f64,
    /// Anti-windup tracking time T_t \[s\].
    pub tracking_time: f64,
    /// Voltage limit U \[V\].
    pub voltage_limit: f64,
}

/// Load speed ω_L and set-point ω_ref.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MotorInputs {
    /// ω_L \[rad/s\].
    pub load_speed: f64,
    /// ω_ref \[rad/s\].
    pub set_point: f64,
}

/// The state [i, ω, φ, z].
pub type MotorState = [f64; 4];

/// Quantities a master reads.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MotorOutputs {
    /// Shaft torque τ on the load \[N m\].
    pub shaft_torque: f64,
    /// Rotor speed ω \[rad/s\].
    pub speed: f64,
    /// Armature current i \[A\].
    pub current: f64,
    /// Armature voltage u \[V\].
    pub voltage: f64,
    /// Shaft twist φ \[rad\].
    pub twist: f64,
}

impl MotorParameters {
    /// The steady state at speed ω = `speed` with shaft torque `torque` and the controller at its
    /// set-point (e = 0, the integral state holding the voltage).
    pub fn steady_state(&self, speed: f64, torque: f64) -> MotorState {
        let current = (torque + self.friction * speed) / self.torque_constant;
        let voltage = self.resistance * current + self.torque_constant * speed;
        let integral = if self.integral_gain > 0.0 {
            voltage / self.integral_gain
        } else {
            0.0
        };
        [current, speed, torque / self.shaft_stiffness, integral]
    }

    /// Shaft torque τ = k_s φ + d_s (ω − ω_L) of state `x` at load speed ω_L. Linear in both, so
    /// the same form of their rates gives its rate.
    pub fn shaft_torque(&self, x: &MotorState, load_speed: f64) -> f64 {
        self.shaft_stiffness * x[2] + self.shaft_damping * (x[1] - load_speed)
    }

    /// Controller output v and the limited voltage u.
    fn voltage(&self, x: &MotorState, set_point: f64) -> (f64, f64) {
        let v = self.gain * (set_point - x[1]) + self.integral_gain * x[3];
        (v, v.clamp(-self.voltage_limit, self.voltage_limit))
    }

    /// Time derivative of the state.
    pub fn derivative(&self, x: &MotorState, inputs: &MotorInputs) -> MotorState {
        let [i, w, _, _] = *x;
        let (v, u) = self.voltage(x, inputs.set_point);
        let torque = self.shaft_torque(x, inputs.load_speed);
        let tracking = if self.integral_gain > 0.0 {
            (u - v) / (self.integral_gain * self.tracking_time)
        } else {
            0.0
        };
        [
            (u - self.resistance * i - self.torque_constant * w) / self.inductance,
            (self.torque_constant * i - torque - self.friction * w) / self.inertia,
            w - inputs.load_speed,
            inputs.set_point - w + tracking,
        ]
    }

    /// Outputs of a state.
    pub fn outputs(&self, x: &MotorState, inputs: &MotorInputs) -> MotorOutputs {
        let (_, u) = self.voltage(x, inputs.set_point);
        MotorOutputs {
            shaft_torque: self.shaft_torque(x, inputs.load_speed),
            speed: x[1],
            current: x[0],
            voltage: u,
            twist: x[2],
        }
    }

    /// ∂y/∂u: the outputs' partial derivatives at state `x` with respect to the set-point
    /// (`set_point` true) or the load speed. The shaft torque c φ + d (ω − ω_L) reacts to the
    /// load speed with −d; the voltage u = clamp(K_p (ω_set − ω) + K_i z) to the set-point with
    /// K_p while the controller output is inside the voltage limit, else not at all; speed,
    /// current and twist are states.
    pub fn output_derivatives(
        &self,
        x: &MotorState,
        inputs: &MotorInputs,
        set_point: bool,
    ) -> MotorOutputs {
        let (v, _) = self.voltage(x, inputs.set_point);
        let inside = v.abs() < self.voltage_limit;
        MotorOutputs {
            shaft_torque: if set_point { 0.0 } else { -self.shaft_damping },
            speed: 0.0,
            current: 0.0,
            voltage: if set_point && inside { self.gain } else { 0.0 },
            twist: 0.0,
        }
    }

    /// Advances `x` over `h` in `n` classical Runge–Kutta steps, with the inputs of `inputs(τ)` at
    /// τ ∈ [0, h] after the start.
    pub fn advance(&self, x: &mut MotorState, h: f64, n: u32, inputs: impl Fn(f64) -> MotorInputs) {
        let dt = h / f64::from(n);
        let add = |x: &MotorState, k: &MotorState, c: f64| -> MotorState {
            [
                x[0] + c * k[0],
                x[1] + c * k[1],
                x[2] + c * k[2],
                x[3] + c * k[3],
            ]
        };
        for step in 0..n {
            let t = dt * f64::from(step);
            let k1 = self.derivative(x, &inputs(t));
            let k2 = self.derivative(&add(x, &k1, 0.5 * dt), &inputs(t + 0.5 * dt));
            let k3 = self.derivative(&add(x, &k2, 0.5 * dt), &inputs(t + 0.5 * dt));
            let k4 = self.derivative(&add(x, &k3, dt), &inputs(t + dt));
            for j in 0..4 {
                x[j] += dt / 6.0 * (k1[j] + 2.0 * (k2[j] + k3[j]) + k4[j]);
            }
        }
    }
}

/// The number of equal Runge–Kutta steps no longer than `solver_step` over a communication
/// step `h` (the margin keeps n · solver_step = h from rounding up to n + 1 steps).
pub fn substeps(h: f64, solver_step: f64) -> u32 {
    (h / solver_step * (1.0 - 1e-9)).ceil().max(1.0) as u32
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// The motor of the motor–crank system (the FMU's start values).
    pub(crate) fn motor() -> MotorParameters {
        MotorParameters {
            resistance: 0.2,
            inductance: 5e-4,
            torque_constant: 0.2,
            inertia: 0.01,
            friction: 1e-4,
            shaft_stiffness: 2e4,
            shaft_damping: 2.0,
            gain: 2.0,
            integral_gain: 40.0,
            tracking_time: 0.05,
            voltage_limit: 200.0,
        }
    }

    /// The steady state is an equilibrium when the load turns at the set-point speed.
    #[test]
    fn steady_state_is_an_equilibrium() {
        let m = motor();
        let x = m.steady_state(500.0, 12.0);
        let inputs = MotorInputs {
            load_speed: 500.0,
            set_point: 500.0,
        };
        let d = m.derivative(&x, &inputs);
        assert!(d.iter().all(|v| v.abs() < 1e-9), "{d:?}");
        assert!((m.outputs(&x, &inputs).shaft_torque - 12.0).abs() < 1e-12);
    }

    /// A step in the load torque is rejected: the PI controller brings the speed back to its
    /// set-point (integral action), and the energy balance of the armature closes.
    #[test]
    fn controller_rejects_a_load_step() {
        let m = motor();
        let mut x = m.steady_state(500.0, 0.0);
        // A load that brakes with 20 N m: the load end is held at a twist rate that makes the
        // shaft torque 20 N m, i.e. a load turning slower than the rotor until the twist builds.
        let mut load_angle_rate = 500.0;
        for _ in 0..200_000 {
            let torque = m
                .outputs(
                    &x,
                    &MotorInputs {
                        load_speed: load_angle_rate,
                        set_point: 500.0,
                    },
                )
                .shaft_torque;
            // The load: inertia 0.05 kg m² braked by 20 N m, driven by the shaft.
            load_angle_rate += 1e-5 * (torque - 20.0) / 0.05;
            let w = load_angle_rate;
            m.advance(&mut x, 1e-5, 1, |_| MotorInputs {
                load_speed: w,
                set_point: 500.0,
            });
        }
        assert!((x[1] - 500.0).abs() < 0.05, "speed {}", x[1]);
        let torque = m.shaft_stiffness * x[2];
        assert!((torque - 20.0).abs() < 0.5, "shaft torque {torque}");
    }

    /// Beyond the voltage limit the integral state stops winding up: after a large set-point step
    /// the voltage sits at the limit and the integral term tracks it.
    #[test]
    fn anti_windup_holds_the_integral_at_the_limit() {
        let m = motor();
        let mut x = m.steady_state(100.0, 0.0);
        let inputs = |_| MotorInputs {
            load_speed: 100.0,
            set_point: 2000.0,
        };
        m.advance(&mut x, 0.5, 50_000, inputs);
        let (v, u) = m.voltage(&x, 2000.0);
        assert_eq!(u, m.voltage_limit);
        // Back-calculation: v − u settles where e = (v − u)/(K_i T_t).
        let e = 2000.0 - x[1];
        assert!(
            ((v - u) / (m.integral_gain * m.tracking_time) - e).abs() < 1e-3 * e.abs().max(1.0),
            "v − u = {}, e = {e}",
            v - u
        );
    }
}
