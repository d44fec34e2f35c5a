//! A load tied to the crank angle: the force on the slider as a periodic function of the crank
//! angle, read from a CSV table (crank angle in degrees, or in radians where its header says so;
//! force in newtons) and interpolated by a monotone piecewise cubic, so that the mechanism sees a
//! gas load in phase with its own crank, at every evaluation, whatever its speed.
//!
//! ```text
//! F(θ) on [θᵢ, θᵢ₊₁]:  the cubic Hermite through (θᵢ, Fᵢ, dᵢ), (θᵢ₊₁, Fᵢ₊₁, dᵢ₊₁),  θ = crank angle mod P
//! dᵢ = 0                                   where the secant slopes Δᵢ₋₁, Δᵢ differ in sign or vanish
//! dᵢ = (w₁ + w₂) / (w₁/Δᵢ₋₁ + w₂/Δᵢ)       otherwise,  w₁ = 2hᵢ + hᵢ₋₁,  w₂ = hᵢ + 2hᵢ₋₁
//! ```
//! (hᵢ = θᵢ₊₁ − θᵢ, Δᵢ = (Fᵢ₊₁ − Fᵢ)/hᵢ, the table continued periodically: the point after the last
//! is the first one a period on). The slopes are Fritsch–Butland's weighted harmonic means, the
//! PCHIP of Fritsch and Carlson: on each interval the interpolant stays between its end values
//! and is monotone where the data are, so a combustion pulse is not overshot, and it is C¹.
//!
//! # References
//! - F. N. Fritsch, R. E. Carlson (1980), Monotone piecewise cubic interpolation, SIAM J. Numer.
//!   Anal. 17, 238–246.
//! - F. N. Fritsch, J. Butland (1984), A method for constructing local monotone piecewise cubic
//!   interpolants, SIAM J. Sci. Stat. Comput. 5, 300–304.

use std::io::Read;
use std::path::{Path, PathBuf};

use crate::error::{ModelError, Num};
use crate::integrator::dense::cubic_hermite;

/// The largest table file read \[bytes\]: a table of a million points is far smaller, and a larger
/// file named by mistake is refused instead of read into memory.
const MAX_BYTES: u64 = 64 << 20;

/// A periodic load table of the crank angle, interpolated monotonically.
#[derive(Clone, Debug, PartialEq)]
pub struct LoadTable {
    /// The crank angles of the points \[deg\], increasing, in [0, period).
    angles: Vec<f64>,
    /// The forces there \[N\].
    forces: Vec<f64>,
    /// The interpolant's slopes there \[N/deg\].
    slopes: Vec<f64>,
    /// The period \[deg\].
    period: f64,
    /// What looks wrong in a table that was read nevertheless (angles that look like radians).
    warning: Option<String>,
}

impl LoadTable {
    /// The table of the points (crank angle \[deg\], force \[N\]) over `period` degrees; `source`
    /// names them in errors (a file). The angles must increase strictly from at least 0 and stay
    /// below the period; at least two points.
    pub fn new(points: &[(f64, f64)], period: f64, source: &str) -> Result<Self, ModelError> {
        if points.len() < 2 {
            return Err(table_error(
                source,
                &format!("{} point(s): a table needs at least two", points.len()),
            ));
        }
        for (k, &(angle, _)) in points.iter().enumerate() {
            if !(0.0..period).contains(&angle) {
                return Err(table_error(
                    source,
                    &format!(
                        "point {}: crank angle {} deg is outside [0, {}) (slider.forceTablePeriod)",
                        k + 1,
                        Num(angle),
                        Num(period)
                    ),
                ));
            }
            if k > 0 && angle <= points[k - 1].0 {
                return Err(table_error(
                    source,
                    &format!(
                        "point {}: crank angle {} deg does not follow {} deg (the angles must increase)",
                        k + 1,
                        Num(angle),
                        Num(points[k - 1].0)
                    ),
                ));
            }
        }
        let (angles, forces): (Vec<f64>, Vec<f64>) = points.iter().copied().unzip();
        let n = angles.len();
        // Interval k runs from point k to point k + 1, the last one to the first a period on.
        let width = |k: usize| {
            if k + 1 < n {
                angles[k + 1] - angles[k]
            } else {
                angles[0] + period - angles[k]
            }
        };
        let secant = |k: usize| (forces[(k + 1) % n] - forces[k]) / width(k);
        let slopes = (0..n)
            .map(|i| {
                let before = (i + n - 1) % n;
                let (d0, d1) = (secant(before), secant(i));
                if d0 * d1 <= 0.0 {
                    0.0
                } else {
                    let (h0, h1) = (width(before), width(i));
                    let (w1, w2) = (2.0 * h1 + h0, h1 + 2.0 * h0);
                    (w1 + w2) / (w1 / d0 + w2 / d1)
                }
            })
            .collect();
        Ok(Self {
            angles,
            forces,
            slopes,
            period,
            warning: None,
        })
    }

    /// What looks wrong in the table, read nevertheless: angles in degrees (no unit stated) that
    /// all lie within 2π of a cycle more than four times as long, as radians would.
    pub fn warning(&self) -> Option<&str> {
        self.warning.as_deref()
    }

    /// Reads the table from the CSV file at `path` (a relative path is looked up in the working
    /// directory, then in `resources`): one point per line, `crank angle [deg], force [N]`, blank
    /// lines and lines starting with `#` skipped, and a first line without a number taken for a
    /// header. The header may state the angles' unit in its first field, the word `deg` or `rad`
    /// (`angle [rad], force [N]`): radians are read as such; without it the angles are degrees,
    /// and a table whose angles look like radians is read with a [`LoadTable::warning`]. An
    /// error names the file, the line and what is wrong with it.
    pub fn read(path: &str, period: f64, resources: Option<&Path>) -> Result<Self, ModelError> {
        let file = locate(path, resources).ok_or_else(|| {
            let looked = match resources {
                Some(r) => format!(
                    "the working directory and the FMU's resources {}",
                    r.display()
                ),
                None => "the working directory".to_string(),
            };
            table_error(path, &format!("no such file (looked in {looked})"))
        })?;
        let mut text = String::new();
        std::fs::File::open(&file)
            .and_then(|f| f.take(MAX_BYTES + 1).read_to_string(&mut text))
            .map_err(|e| table_error(path, &format!("cannot be read: {e}")))?;
        if text.len() as u64 > MAX_BYTES {
            return Err(table_error(
                path,
                &format!("larger than {} MiB: not a load table", MAX_BYTES >> 20),
            ));
        }
        let mut points = Vec::new();
        let mut unit = None;
        for (number, line) in (1..).zip(text.lines()) {
            let line = line.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let fields: Vec<&str> = line.split([',', ';', '\t']).map(str::trim).collect();
            let values: Vec<Option<f64>> = fields.iter().map(|f| f.parse().ok()).collect();
            match values.as_slice() {
                [Some(angle), Some(force)] if angle.is_finite() && force.is_finite() => {
                    points.push((*angle, *force));
                }
                _ if points.is_empty() && !line.chars().any(|c| c.is_ascii_digit()) => {
                    unit = fields.first().and_then(|f| angle_unit(f));
                }
                _ => {
                    return Err(table_error(
                        path,
                        &format!(
                            "line {number}: \"{line}\" is not two finite numbers \
                             (crank angle [deg], force [N])"
                        ),
                    ));
                }
            }
        }
        if unit == Some(AngleUnit::Radians) {
            points
                .iter_mut()
                .for_each(|(angle, _)| *angle = angle.to_degrees());
        }
        let mut table = Self::new(&points, period, path)?;
        let last = points.last().map_or(0.0, |&(angle, _)| angle);
        let two_pi = std::f64::consts::TAU;
        if unit.is_none() && points.len() >= 3 && last <= two_pi && period > 4.0 * two_pi {
            table.warning = Some(format!(
                "slider.forceTable = \"{path}\": its crank angles run from {} to {} deg of a {} \
                 deg load cycle (slider.forceTablePeriod): they look like radians. A table's angles \
                 are degrees unless its header says otherwise: state the unit in the header's \
                 first field (angle [rad], force [N]) or write the angles in degrees",
                Num(points[0].0),
                Num(last),
                Num(period)
            ));
        }
        Ok(table)
    }

    /// The largest magnitude of the force \[N\] (a monotone interpolant's extremes are at the
    /// points).
    pub fn largest(&self) -> f64 {
        self.forces.iter().fold(0.0, |m: f64, f| m.max(f.abs()))
    }

    /// The force at the crank angle `theta` \[rad\] \[N\].
    pub fn at(&self, theta: f64) -> f64 {
        let degrees = (theta * (180.0 / std::f64::consts::PI)).rem_euclid(self.period);
        let n = self.angles.len();
        // The interval holding it: after the last point (or before the first), the one that
        // wraps around.
        let k = match self.angles.partition_point(|&a| a <= degrees) {
            0 => n - 1,
            k => k - 1,
        };
        let start = self.angles[k];
        let width = if k + 1 < n {
            self.angles[k + 1] - start
        } else {
            self.angles[0] + self.period - start
        };
        let from = if degrees >= start {
            degrees - start
        } else {
            degrees + self.period - start
        };
        // The Hermite form with h₀₀ = 1 − h₀₁: a flat interval stays exactly flat.
        let [_, b1, b2, b3] = cubic_hermite(from / width);
        let next = (k + 1) % n;
        self.forces[k]
            + b2 * (self.forces[next] - self.forces[k])
            + width * (b1 * self.slopes[k] + b3 * self.slopes[next])
    }
}

/// The unit of a table's crank angles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum AngleUnit {
    Degrees,
    Radians,
}

/// The angle unit a header's first field names, as a word of its own (`angle [rad]`,
/// `crank angle (deg)`), if any.
fn angle_unit(field: &str) -> Option<AngleUnit> {
    field
        .split(|c: char| !c.is_ascii_alphanumeric())
        .find_map(|word| match word.to_ascii_lowercase().as_str() {
            "deg" | "degree" | "degrees" => Some(AngleUnit::Degrees),
            "rad" | "radian" | "radians" => Some(AngleUnit::Radians),
            _ => None,
        })
}

/// The regular file a table's `path` names (a device or a pipe is none): as given if absolute or
/// present in the working directory, else in `resources`.
fn locate(path: &str, resources: Option<&Path>) -> Option<PathBuf> {
    let given = PathBuf::from(path);
    if given.is_file() {
        return Some(given);
    }
    resources
        .filter(|_| given.is_relative())
        .map(|r| r.join(&given))
        .filter(|p| p.is_file())
}

/// An error of the table `source` (slider.forceTable).
fn table_error(source: &str, what: &str) -> ModelError {
    ModelError::InvalidFile(format!("slider.forceTable = \"{source}\": {what}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn deg(x: f64) -> f64 {
        x.to_radians()
    }

    /// The interpolant goes through the points, repeats with the period, is continuous with a
    /// continuous slope across every point (the wrap-around included), stays within each
    /// interval's end values (a sharp pulse is not overshot) and is flat at a local extreme.
    #[test]
    fn the_interpolant_is_periodic_monotone_and_smooth() {
        let points = [
            (0.0, 0.0),
            (300.0, -200.0),
            (350.0, -1500.0),
            (365.0, -5000.0),
            (380.0, -4200.0),
            (450.0, -800.0),
            (700.0, -10.0),
        ];
        let t = LoadTable::new(&points, 720.0, "test").unwrap();
        for &(a, f) in &points {
            assert!((t.at(deg(a)) - f).abs() < 1e-9, "{a}");
            assert!((t.at(deg(a + 720.0)) - f).abs() < 1e-6, "{a}");
            assert!((t.at(deg(a - 1440.0)) - f).abs() < 1e-6, "{a}");
        }
        for (k, w) in points.windows(2).enumerate() {
            let (lo, hi) = (w[0].1.min(w[1].1), w[0].1.max(w[1].1));
            for j in 1..100 {
                let a = w[0].0 + (w[1].0 - w[0].0) * f64::from(j) / 100.0;
                let f = t.at(deg(a));
                assert!(f >= lo - 1e-9 && f <= hi + 1e-9, "interval {k}: {f} at {a}");
            }
        }
        let h = 1e-6;
        for a in [0.0, 300.0, 350.0, 365.0, 380.0, 700.0] {
            let left = (t.at(deg(a)) - t.at(deg(a - h))) / h;
            let right = (t.at(deg(a + h)) - t.at(deg(a))) / h;
            assert!(
                (left - right).abs() < 1e-3 * left.abs().max(1.0),
                "{a}: {left} {right}"
            );
        }
        // The pulse's tip is an extreme: zero slope there.
        assert!(((t.at(deg(365.0 + h)) - t.at(deg(365.0 - h))) / (2.0 * h)).abs() < 1e-3);
    }

    /// A constant table is that constant at every angle.
    #[test]
    fn a_constant_table_is_constant() {
        let t = LoadTable::new(
            &[(0.0, -300.0), (90.0, -300.0), (270.0, -300.0)],
            360.0,
            "c",
        )
        .unwrap();
        for k in 0..1000 {
            assert_eq!(t.at(0.0137 * f64::from(k) - 3.0), -300.0);
        }
    }

    /// Bad tables are refused with the file, the line or point, and the value.
    #[test]
    fn bad_tables_name_what_is_wrong() {
        let dir = std::env::temp_dir().join(format!("load_table_{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let write = |name: &str, text: &str| {
            let p = dir.join(name);
            std::fs::write(&p, text).unwrap();
            p.to_string_lossy().into_owned()
        };
        let message =
            |path: &str, period| LoadTable::read(path, period, None).unwrap_err().to_string();
        let unsorted = write("unsorted.csv", "angle,force\n0,1\n20,2\n10,3\n");
        assert!(
            message(&unsorted, 360.0).contains("point 3: crank angle 10 deg does not follow 20")
        );
        let outside = write("outside.csv", "0,1\n400,2\n");
        assert!(message(&outside, 360.0).contains("crank angle 400 deg is outside [0, 360)"));
        let garbled = write("garbled.csv", "# gas load\nangle,force\n0,1\n5,x\n");
        let m = message(&garbled, 360.0);
        assert!(m.contains("line 4: \"5,x\""), "{m}");
        assert!(m.contains(&garbled), "{m}");
        // A device is not a table file (nor read until memory runs out).
        assert!(message("/dev/zero", 360.0).contains("no such file"));
        let missing = message("no/such/table.csv", 360.0);
        assert!(missing.contains("slider.forceTable = \"no/such/table.csv\": no such file"));
        // A relative path is found in the resources directory.
        // Angles that look like radians warn, naming the table; a header that says so reads
        // them as radians, one that says degrees keeps them.
        let radians = "0,0\n1.5,-100\n3.1,-800\n6.2,0\n";
        let unstated = write("unstated.csv", &format!("angle,force\n{radians}"));
        let warning = LoadTable::read(&unstated, 360.0, None).unwrap();
        let warning = warning.warning().unwrap();
        assert!(warning.contains(&unstated) && warning.contains("look like radians"));
        let stated = write(
            "stated.csv",
            &format!("crank angle [rad], force [N]\n{radians}"),
        );
        let stated = LoadTable::read(&stated, 360.0, None).unwrap();
        assert!(stated.warning().is_none());
        assert!((stated.at(3.1) + 800.0).abs() < 1e-9);
        let degrees = write("degrees.csv", &format!("angle (deg),force\n{radians}"));
        let degrees = LoadTable::read(&degrees, 360.0, None).unwrap();
        assert!(degrees.warning().is_none());
        assert!((degrees.at(3.1_f64.to_radians()) + 800.0).abs() < 1e-9);
        write("in_resources.csv", "0,1\n180,-1\n");
        let found = LoadTable::read("in_resources.csv", 360.0, Some(&dir)).unwrap();
        assert_eq!(found.at(std::f64::consts::PI), -1.0);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
