//! The lubrication circuit: a fixed-displacement pump with a pressure-relief valve feeding the
//! bearings' gallery, the oil returning to a sump, and a cooler between the pump and the gallery.
//!
//! ```text
//! C_g dp/dt = Q_p − Q_r(p) − Q_b          gallery, C_g = V_g/β (its volume over the bulk modulus)
//! Q_r(p)    = k_r max(0, p − p_c)         relief valve, cracking at p_c, conductance k_r
//! ρ c_p V_s dT_s/dt = P_b − Φ_c           sump (well mixed)
//! Φ_c       = ρ c_p Q_p ε (T_s − T_c)     cooler of effectiveness ε against the coolant at T_c
//! T_supply  = T_s − ε (T_s − T_c)         the oil the gallery feeds to the bearings
//! ```
//!
//! Q_b and P_b are the bearings' oil flow and the heat their oil carries away (the slider-crank's
//! `<joint>.oilFlow` and `<joint>.heatFlow`, summed): every bearing draws its flow from the gallery
//! and returns it to the sump warmed by its heat, the relief valve returns the rest at the supply
//! temperature, so the sump gains P_b and loses to the cooler what the pump's whole flow gives up
//! there. The gallery's pressure cannot fall below zero: a gallery the bearings draw more from
//! than the pump delivers stays empty at zero gauge pressure (starved).
//!
//! Under constant flows both states relax exponentially: the pressure with the time constant
//! C_g/k_r to p* = p_c + (Q_p − Q_b)/k_r (above cracking), the sump with V_s/(Q_p ε) to
//! T* = T_c + P_b/(ρ c_p Q_p ε). Integrated by the classical Runge–Kutta method in equal steps of
//! at most an eighth of the pressure's time constant.
//!
//! # References
//! - H. E. Merritt (1967), Hydraulic Control Systems, Wiley (the hydraulic capacitance V/β of a
//!   volume of oil, and the relief valve's pressure–flow law).
//! - ISO 7902-1:2020 (the bearing's heat carried away by its oil flow, ρ c_p Q ΔT).

/// The circuit's constants.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CircuitParameters {
    /// The pump's delivery Q_p \[m³/s\].
    pub pump_flow: f64,
    /// The relief valve's cracking pressure p_c (gauge) \[Pa\].
    pub relief_pressure: f64,
    /// The relief valve's conductance k_r above cracking \[m³/(s Pa)\].
    pub relief_conductance: f64,
    /// The gallery's oil volume V_g \[m³\].
    pub gallery_volume: f64,
    /// The oil's bulk modulus β \[Pa\].
    pub bulk_modulus: f64,
    /// The sump's oil volume V_s \[m³\].
    pub sump_volume: f64,
    /// The oil's density ρ \[kg/m³\].
    pub density: f64,
    /// The oil's specific heat c_p \[J/(kg K)\].
    pub specific_heat: f64,
    /// The cooler's effectiveness ε (0: no cooling, 1: the oil leaves at the coolant's
    /// temperature).
    pub cooler_effectiveness: f64,
    /// The coolant's temperature T_c \[K\].
    pub coolant_temperature: f64,
}

/// The bearings' oil flow Q_b \[m³/s\] and the heat their oil carries away P_b \[W\], summed.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BearingLoads {
    /// Q_b \[m³/s\].
    pub oil_flow: f64,
    /// P_b \[W\].
    pub heat_flow: f64,
}

/// The state [p, T_s]: the gallery's gauge pressure \[Pa\] and the sump's temperature \[K\].
pub type CircuitState = [f64; 2];

/// Quantities a master reads.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CircuitOutputs {
    /// The gallery's gauge pressure p, the bearings' supply pressure \[Pa\].
    pub supply_pressure: f64,
    /// The supply temperature T_s − ε (T_s − T_c) \[K\].
    pub supply_temperature: f64,
    /// The sump's temperature T_s \[K\].
    pub sump_temperature: f64,
    /// The relief valve's flow Q_r \[m³/s\].
    pub relief_flow: f64,
    /// The heat the cooler takes out Φ_c \[W\].
    pub cooler_heat_flow: f64,
}

impl CircuitParameters {
    /// The gallery's hydraulic capacitance C_g = V_g/β \[m³/Pa\].
    pub fn capacitance(&self) -> f64 {
        self.gallery_volume / self.bulk_modulus
    }

    /// The relief valve's flow at the gallery pressure `p` \[m³/s\].
    pub fn relief_flow(&self, p: f64) -> f64 {
        self.relief_conductance * (p - self.relief_pressure).max(0.0)
    }

    /// The heat the pump's flow gives up in the cooler per kelvin of the sump above the coolant,
    /// ρ c_p Q_p ε \[W/K\].
    pub fn cooler_conductance(&self) -> f64 {
        self.density * self.specific_heat * self.pump_flow * self.cooler_effectiveness
    }

    /// The gallery's steady pressure for the bearings' flow `oil_flow` \[Pa\]: above cracking
    /// where the pump delivers more than the bearings draw, else zero (starved).
    pub fn steady_pressure(&self, oil_flow: f64) -> f64 {
        let surplus = self.pump_flow - oil_flow;
        if surplus > 0.0 {
            self.relief_pressure + surplus / self.relief_conductance
        } else {
            0.0
        }
    }

    /// dx/dt at state `x` under the bearings' loads `loads`.
    pub fn derivative(&self, x: &CircuitState, loads: &BearingLoads) -> CircuitState {
        let [p, t] = *x;
        let flow = self.pump_flow - self.relief_flow(p) - loads.oil_flow;
        let rate = if p <= 0.0 && flow < 0.0 {
            0.0
        } else {
            flow / self.capacitance()
        };
        let heat = loads.heat_flow - self.cooler_conductance() * (t - self.coolant_temperature);
        [
            rate,
            heat / (self.density * self.specific_heat * self.sump_volume),
        ]
    }

    /// The outputs at state `x`.
    pub fn outputs(&self, x: &CircuitState) -> CircuitOutputs {
        let [p, t] = *x;
        CircuitOutputs {
            supply_pressure: p,
            supply_temperature: t - self.cooler_effectiveness * (t - self.coolant_temperature),
            sump_temperature: t,
            relief_flow: self.relief_flow(p),
            cooler_heat_flow: self.cooler_conductance() * (t - self.coolant_temperature),
        }
    }

    /// The longest internal step: an eighth of the gallery's time constant C_g/k_r \[s\] (the
    /// classical Runge–Kutta method's error per step there (h/τ)⁵/120 ≈ 2.5e-7 of the distance
    /// to the steady pressure).
    pub fn largest_step(&self) -> f64 {
        0.125 * self.capacitance() / self.relief_conductance
    }

    /// Advances `x` over `h` in `n` equal classical Runge–Kutta steps with the loads `loads(τ)`
    /// at the time τ into the step, the pressure kept at or above zero.
    pub fn advance(
        &self,
        x: &mut CircuitState,
        h: f64,
        n: u32,
        loads: impl Fn(f64) -> BearingLoads,
    ) {
        let dt = h / f64::from(n);
        let add = |x: &CircuitState, k: &CircuitState, c: f64| [x[0] + c * k[0], x[1] + c * k[1]];
        for step in 0..n {
            let t = dt * f64::from(step);
            let middle = loads(t + 0.5 * dt);
            let k1 = self.derivative(x, &loads(t));
            let k2 = self.derivative(&add(x, &k1, 0.5 * dt), &middle);
            let k3 = self.derivative(&add(x, &k2, 0.5 * dt), &middle);
            let k4 = self.derivative(&add(x, &k3, dt), &loads(t + dt));
            for i in 0..2 {
                x[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            }
            x[0] = x[0].max(0.0);
        }
    }
}

/// Equal internal steps over `h` of at most `largest` \[s\].
pub fn substeps(h: f64, largest: f64) -> u32 {
    (h / largest * (1.0 - 1e-9)).ceil().max(1.0) as u32
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The FMU's start values.
    fn circuit() -> CircuitParameters {
        CircuitParameters {
            pump_flow: 5e-6,
            relief_pressure: 2e5,
            relief_conductance: 1e-10,
            gallery_volume: 2e-5,
            bulk_modulus: 1.5e9,
            sump_volume: 5e-4,
            density: 870.0,
            specific_heat: 2000.0,
            cooler_effectiveness: 0.5,
            coolant_temperature: 308.15,
        }
    }

    /// The sump's steady temperature T* = T_c + P_b/(ρ c_p Q_p ε) for the bearings' heat
    /// `heat_flow` \[K\].
    fn steady_temperature(c: &CircuitParameters, heat_flow: f64) -> f64 {
        c.coolant_temperature + heat_flow / c.cooler_conductance()
    }

    fn run(c: &CircuitParameters, x: &mut CircuitState, loads: BearingLoads, time: f64) {
        let n = substeps(time, c.largest_step());
        c.advance(x, time, n, |_| loads);
    }

    /// Under constant loads both states follow their first-order solutions
    /// x* + (x₀ − x*) exp(−t/τ) within 1e-6 of their change, the pressure above cracking with
    /// τ = C_g/k_r, the sump with τ = V_s/(Q_p ε).
    #[test]
    fn the_states_follow_their_first_order_solutions() {
        let c = circuit();
        let loads = BearingLoads {
            oil_flow: 1e-6,
            heat_flow: 30.0,
        };
        let (p_star, t_star) = (c.steady_pressure(1e-6), steady_temperature(&c, 30.0));
        let x0 = [p_star + 3e4, 300.0];
        let tau_p = c.capacitance() / c.relief_conductance;
        let tau_t = c.sump_volume / (c.pump_flow * c.cooler_effectiveness);
        for time in [0.3 * tau_p, tau_p, 3.0 * tau_p] {
            let mut x = x0;
            run(&c, &mut x, loads, time);
            let p = p_star + (x0[0] - p_star) * libm::exp(-time / tau_p);
            assert!((x[0] - p).abs() < 1e-6 * 3e4, "{} vs {p}", x[0]);
        }
        let mut x = x0;
        run(&c, &mut x, loads, tau_t);
        let t = t_star + (x0[1] - t_star) * libm::exp(-1.0);
        assert!(
            (x[1] - t).abs() < 1e-6 * (t_star - x0[1]),
            "{} vs {t}",
            x[1]
        );
    }

    /// In steady state the pump's flow is the bearings' and the relief valve's, and the cooler
    /// takes out the bearings' heat; the supply lies between the sump and the coolant.
    #[test]
    fn the_steady_state_balances_flow_and_heat() {
        let c = circuit();
        let x = [c.steady_pressure(2e-6), steady_temperature(&c, 40.0)];
        let o = c.outputs(&x);
        assert!((o.relief_flow + 2e-6 - c.pump_flow).abs() < 1e-12 * c.pump_flow);
        assert!((o.cooler_heat_flow - 40.0).abs() < 1e-9);
        assert!(o.supply_temperature < o.sump_temperature);
        assert!(o.supply_temperature > c.coolant_temperature);
        let d = c.derivative(
            &x,
            &BearingLoads {
                oil_flow: 2e-6,
                heat_flow: 40.0,
            },
        );
        assert!(d[0].abs() < 1e-6 && d[1].abs() < 1e-12);
    }

    /// Bearings that draw more than the pump delivers empty the gallery: its pressure falls to
    /// zero and stays there.
    #[test]
    fn a_starved_gallery_stays_at_zero_pressure() {
        let c = circuit();
        assert_eq!(c.steady_pressure(2.0 * c.pump_flow), 0.0);
        let mut x = [1e5, 320.0];
        let loads = BearingLoads {
            oil_flow: 2.0 * c.pump_flow,
            heat_flow: 0.0,
        };
        run(&c, &mut x, loads, 1.0);
        assert_eq!(x[0], 0.0);
    }
}
