//! The heat balance of a lubricated joint's film: one thermal state, the effective film
//! temperature T, heated by the joint's friction and cooled by the oil that flows through the
//! bearing and by the housing, after the bearing standards' effective temperature.
//!
//! ```text
//! C dT/dt = P − Φ_oil − Φ_housing
//! Φ_oil     = ρ c_p Q (T_out − T_in) = 2 ρ c_p Q (T − T_s),   T = (T_in + T_out)/2,  T_in = T_s
//! Φ_housing = k (T − T_s)
//! μ = μ(T)   (the oil's viscosity law, [`super::oil`])
//! ```
//! P is the joint's friction power (`frictionPower`: the film's viscous loss — its Couette shear taken
//! over the whole circumference, as the cavitated region carries streamers of oil, and its
//! pressure flow — the asperities' boundary friction and the dry contact's friction), Q the oil
//! flow through the bearing (`oilFlow`: the side flow out of the pressurised film), T_s the supply
//! temperature (the input `oil.supplyTemperature`), C the heat capacity that follows the film's
//! temperature (`heatCapacity`: the film and the near-surface metal of journal and shell) and k the
//! conductance to the housing at the supply temperature (`heatTransferCoefficient`). The outlet is
//! at T_out = 2T − T_s: the effective temperature is the mean of inlet and outlet, as ISO 7902-1 and
//! DIN 31652-1 take it for their adiabatic and convective heat balances. Without heat capacity the
//! film would follow each load cycle; with it, it follows the cycle's mean, as a bearing does.
//!
//! # References
//! - ISO 7902-1:2020, Hydrodynamic plain journal bearings under steady-state conditions — Circular
//!   cylindrical bearings — Part 1: Calculation procedure (heat balance, effective temperature).
//! - DIN 31652-1:2017, Hydrodynamische Radial-Gleitlager im stationären Betrieb.

use super::oil::Oil;

/// A lubricated joint's heat balance (module documentation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeatBalance {
    /// The oil.
    pub oil: Oil,
    /// Heat capacity C \[J/K\].
    pub capacity: f64,
    /// Conductance k to the housing \[W/K\].
    pub conductance: f64,
}

impl HeatBalance {
    /// The heat the oil flow `flow` carries out of the film at the effective temperature
    /// `temperature` with the supply at `supply`, Φ_oil = 2 ρ c_p Q (T − T_s) \[W\].
    pub fn heat_to_oil(&self, flow: f64, temperature: f64, supply: f64) -> f64 {
        2.0 * self.oil.volumetric_heat() * flow * (temperature - supply)
    }

    /// The heat the housing takes, Φ_housing = k (T − T_s) \[W\].
    pub fn heat_to_housing(&self, temperature: f64, supply: f64) -> f64 {
        self.conductance * (temperature - supply)
    }

    /// dT/dt = (P − Φ_oil − Φ_housing)/C for the friction power `power` \[K/s\].
    pub fn rate(&self, power: f64, flow: f64, temperature: f64, supply: f64) -> f64 {
        (power
            - self.heat_to_oil(flow, temperature, supply)
            - self.heat_to_housing(temperature, supply))
            / self.capacity
    }
}
