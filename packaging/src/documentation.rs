//! The user guides inside the FMUs (`documentation/index.html`), for someone who has only the
//! `.fmu`: generated from the same sources as the repository's documentation — the README's
//! introduction and first studies, every page of the user guide in `docs/guide/` (masters,
//! variables, sizing and bearings, solver choice, systems, validation, performance, limits,
//! platforms), and the variable tables with value references and display units from the variable
//! table. Links are kept only where they resolve inside the FMU: images are packed beside the
//! page, links into the repository keep their text and lose their target.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use flexible_slider_crank::fmi::{FMI3_SCALAR_TOKEN, FMI3_TOKEN, GUID};
use flexible_slider_crank::variables::{Causality, DESCRIPTION, ENUMERATIONS, Kind};
use fmi_export::description::Description;
use fmi_export::number::Num;
use fmi_export::table::{Enumeration, ValueReference, Variable};

/// The page's style.
const STYLE: &str = "body{font-family:sans-serif;max-width:1100px;margin:auto}\
    table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:3px 6px;font-size:90%}\
    pre{background:#f6f6f6;padding:6px}";

/// An HTML table of the variables of one causality: name, value reference, unit, display unit,
/// start, range, description.
pub fn variable_rows<V: ValueReference + Copy + PartialEq>(
    description: &Description<V>,
    enumerations: &[Enumeration],
    causality: Causality,
) -> String {
    let mut t = String::from(
        "<table><tr><th>name</th><th>value reference</th><th>unit</th><th>display unit</th>\
         <th>start</th><th>range</th><th>description</th></tr>\n",
    );
    for v in description
        .variables
        .iter()
        .filter(|v| v.causality == causality)
    {
        let (unit, start, range) = kind_columns(v, enumerations);
        let display = description
            .variable_display_units
            .iter()
            .find(|(vr, _)| *vr == v.vr)
            .map_or("", |(_, unit)| *unit);
        let _ = writeln!(
            t,
            "<tr><td><code>{}</code></td><td>{}</td><td>{unit}</td><td>{display}</td><td>{start}</td>\
             <td>{range}</td><td>{}</td></tr>",
            v.name,
            v.vr.index(),
            escape(v.description)
        );
    }
    t + "</table>\n"
}

/// Unit, start and range of a variable, as the page shows them.
fn kind_columns<V>(v: &Variable<V>, enumerations: &[Enumeration]) -> (String, String, String) {
    match v.kind {
        Kind::Real {
            start,
            min,
            max,
            unit,
        } => (
            unit.to_string(),
            start.map_or(String::new(), |s| Num(s).to_string()),
            if min.is_finite() {
                format!("[{}, {}]", Num(min), Num(max))
            } else {
                String::new()
            },
        ),
        Kind::Integer { start, min, max } => (
            String::new(),
            start.map_or(String::new(), |s| s.to_string()),
            format!("[{min}, {max}]"),
        ),
        Kind::Boolean => (String::new(), String::new(), "true/false".into()),
        Kind::String { start } => (
            String::new(),
            format!("\"{}\"", escape(start)),
            "text".into(),
        ),
        Kind::Enumeration { start, type_index } => {
            let items = enumerations[type_index].items;
            let names: Vec<String> = items
                .iter()
                .enumerate()
                .map(|(i, (n, _))| format!("{}={n}", i + 1))
                .collect();
            (
                String::new(),
                items[(start - 1) as usize].0.to_string(),
                names.join(", "),
            )
        }
    }
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// The text of `markdown` from the heading `from` (a line equal to it) up to the next heading of
/// the same or a higher level, without the heading itself; an error if there is no such heading
/// (a renamed section would otherwise vanish from the FMU's documentation).
fn section(markdown: &str, from: &str) -> Result<String, String> {
    let Some(start) = markdown.find(&format!("\n{from}\n")) else {
        return Err(format!("no section \"{from}\" for the FMU's documentation"));
    };
    let level = from.chars().take_while(|&c| c == '#').count();
    let body = &markdown[start + 1..];
    let body = &body[body.find('\n').map_or(body.len(), |i| i + 1)..];
    let end = body
        .match_indices("\n#")
        .find(|(i, _)| {
            let hashes = body[i + 1..].chars().take_while(|&c| c == '#').count();
            hashes <= level && body[i + 1 + hashes..].starts_with(' ')
        })
        .map_or(body.len(), |(i, _)| i);
    Ok(body[..end].to_string())
}

/// The user guide's pages (`docs/guide/`), in the order of the FMU's documentation, with their
/// anchors there.
const GUIDE: [(&str, &str); 9] = [
    ("masters.md", "masters"),
    ("variables.md", "variables"),
    ("sizing.md", "sizing"),
    ("solver.md", "solver"),
    ("systems.md", "systems"),
    ("validation.md", "validation"),
    ("performance.md", "performance"),
    ("limits.md", "limits"),
    ("platforms.md", "platforms"),
];

/// The guide's pages as (anchor, title, body), read from `docs/guide/`; an error if a page there
/// is not in [`GUIDE`] (it would be missing from the FMU's documentation) or one is missing.
fn guide_pages(root: &Path) -> Result<Vec<(&'static str, String, String)>, String> {
    let dir = root.join("docs/guide");
    for entry in std::fs::read_dir(&dir).map_err(|e| format!("{}: {e}", dir.display()))? {
        let name = entry.map_err(|e| e.to_string())?.file_name();
        let name = name.to_string_lossy();
        if name.ends_with(".md") && !GUIDE.iter().any(|(file, _)| *file == name) {
            return Err(format!(
                "docs/guide/{name} is not in the FMU's documentation (GUIDE in documentation.rs)"
            ));
        }
    }
    GUIDE
        .iter()
        .map(|&(file, anchor)| {
            let text = std::fs::read_to_string(dir.join(file))
                .map_err(|e| format!("docs/guide/{file}: {e}"))?;
            let (title, body) = text
                .strip_prefix("# ")
                .and_then(|t| t.split_once('\n'))
                .ok_or_else(|| format!("docs/guide/{file} does not start with a title"))?;
            Ok((anchor, title.to_string(), body.to_string()))
        })
        .collect()
}

/// Markdown to HTML, headings shifted down by `shift` levels; images (files of
/// `modelDescription/documentation/`) are packed flat beside the page and appended to `images`;
/// every other link keeps its text and loses its target (none leads outside the FMU).
fn to_html(markdown: &str, shift: u8, root: &Path, images: &mut Vec<PathBuf>) -> String {
    use pulldown_cmark::{Event, HeadingLevel, Options, Parser, Tag, TagEnd, html};
    let shifted = |level: HeadingLevel| {
        HeadingLevel::try_from((level as usize + usize::from(shift)).min(6)).unwrap_or(level)
    };
    let events = Parser::new_ext(markdown, Options::ENABLE_TABLES).filter_map(|event| {
        Some(match event {
            Event::Start(Tag::Image {
                link_type,
                dest_url,
                title,
                id,
            }) => {
                let name = dest_url.rsplit('/').next().unwrap_or_default().to_string();
                let file = root.join("modelDescription/documentation").join(&name);
                if !images.contains(&file) {
                    images.push(file);
                }
                Event::Start(Tag::Image {
                    link_type,
                    dest_url: name.into(),
                    title,
                    id,
                })
            }
            Event::Start(Tag::Link { .. }) | Event::End(TagEnd::Link) => return None,
            Event::Start(Tag::Heading {
                level,
                id,
                classes,
                attrs,
            }) => Event::Start(Tag::Heading {
                level: shifted(level),
                id,
                classes,
                attrs,
            }),
            Event::End(TagEnd::Heading(level)) => Event::End(TagEnd::Heading(shifted(level))),
            other => other,
        })
    });
    let mut out = String::new();
    html::push_html(&mut out, events);
    out
}

/// Which FMU a documentation page is for: its FMI version, and for FMI 3 whether it carries the
/// rod's section arrays.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Edition {
    /// The FMI 2.0 FMU.
    Fmi2,
    /// The FMI 3.0 FMU with the rod's section arrays.
    Fmi3,
    /// The FMI 3.0 FMU without arrays and input derivatives, for masters with a scalar FMI 3
    /// import.
    Fmi3Scalar,
}

impl Edition {
    /// The page's heading after the model's name.
    fn heading(self) -> &'static str {
        match self {
            Self::Fmi2 => "FMI 2.0 co-simulation FMU",
            Self::Fmi3 => "FMI 3.0 co-simulation FMU",
            Self::Fmi3Scalar => {
                "FMI 3.0 co-simulation FMU without arrays and input derivatives (for masters with \
                 a scalar FMI 3 import)"
            }
        }
    }

    /// The FMU's identity as the master checks it: "GUID …" or "instantiation token …".
    fn identity(self, guid: &str, token: &str, scalar_token: &str) -> String {
        match self {
            Self::Fmi2 => format!("GUID <code>{guid}</code>"),
            Self::Fmi3 => format!("Instantiation token <code>{token}</code>"),
            Self::Fmi3Scalar => format!(
                "Instantiation token <code>{scalar_token}</code>. This FMU declares no arrays, no \
                 structural parameter and no input derivatives (the <code>der(…)</code> inputs), \
                 which the FMI 3.0 FMU in <code>fmi3/</code> declares: its inputs are held over \
                 each communication step; everything else is the same, bit for bit"
            ),
        }
    }
}

/// documentation/index.html of the slider-crank's `edition`, and the images it shows (files to
/// pack beside it): the README's introduction, demo plot and first studies, then every page of
/// the user guide, the variable tables with value references and display units from the variable
/// table; an error if a section it shows is missing.
pub fn slider_crank(root: &Path, edition: Edition) -> Result<(String, Vec<PathBuf>), String> {
    let readme = std::fs::read_to_string(root.join("README.md")).map_err(|e| e.to_string())?;
    let mut images = Vec::new();
    let intro = readme
        .split("\n## ")
        .next()
        .unwrap_or_default()
        .lines()
        .skip_while(|line| line.starts_with("# ") || line.is_empty())
        .collect::<Vec<_>>()
        .join("\n");
    // The demo plot and its caption (the README shows them before the first study).
    let demo = readme
        .split("\n\n")
        .skip_while(|paragraph| !paragraph.contains("documentation/demo.png"))
        .take(2)
        .collect::<Vec<_>>()
        .join("\n\n");
    let quick_start = format!(
        "{}\n{}",
        section(&readme, "## A first study in fmpy")?,
        section(&readme, "## A first study in a system")?
    );
    let mut html = |markdown: &str, shift| to_html(markdown, shift, root, &mut images);
    let (intro, demo, quick_start) = (html(&intro, 0), html(&demo, 0), html(&quick_start, 1));
    let mut contents = String::from(r##"<a href="#quick-start">Quick start</a>"##);
    let mut pages = String::new();
    for (anchor, title, body) in guide_pages(root)? {
        let title = html(&title, 0);
        let title = title
            .trim()
            .trim_start_matches("<p>")
            .trim_end_matches("</p>");
        let _ = write!(contents, r##" · <a href="#{anchor}">{title}</a>"##);
        let body = if anchor == "variables" {
            variable_page(&body, &mut html)?
        } else {
            html(&body, 1)
        };
        let _ = write!(pages, "<h2 id=\"{anchor}\">{title}</h2>\n{body}");
    }
    let heading = edition.heading();
    let identity = edition.identity(GUID, FMI3_TOKEN, FMI3_SCALAR_TOKEN);
    let page = format!(
        r##"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>FlexibleSliderCrank</title>
<style>{STYLE}</style></head>
<body>
<h1>FlexibleSliderCrank — {heading}</h1>
{intro}
<p>{identity}. Contents: {contents}</p>
{demo}
<h2 id="quick-start">Quick start</h2>
{quick_start}
{pages}</body></html>
"##
    );
    Ok((page, images))
}

/// The guide's page of the variables in HTML, each Markdown table replaced by the variable
/// table's own, with value references and display units.
fn variable_page(body: &str, html: &mut impl FnMut(&str, u8) -> String) -> Result<String, String> {
    let tables = [
        (
            "## Parameters (fixed: set before fmi2ExitInitializationMode)",
            Causality::Parameter,
        ),
        ("## Calculated parameter", Causality::CalculatedParameter),
        (
            "## Inputs (continuous, settable at every communication point)",
            Causality::Input,
        ),
        ("## Outputs", Causality::Output),
    ];
    let mut markdown = String::new();
    for line in body.lines().filter(|line| !line.starts_with('|')) {
        markdown.push_str(line);
        markdown.push('\n');
        if let Some(k) = tables.iter().position(|(heading, _)| line == *heading) {
            let _ = write!(markdown, "\nVARIABLE-TABLE-{k}\n");
        }
    }
    let mut page = html(&markdown, 1);
    for (k, &(heading, causality)) in tables.iter().enumerate() {
        let marker = format!("<p>VARIABLE-TABLE-{k}</p>");
        if !page.contains(&marker) {
            return Err(format!(
                "docs/guide/variables.md has no section \"{heading}\""
            ));
        }
        page = page.replace(
            &marker,
            &variable_rows(&DESCRIPTION, ENUMERATIONS, causality),
        );
    }
    Ok(page)
}

/// documentation/index.html of the DC motor's `edition` (it has no arrays: its FMI 3.0 FMU serves
/// every master).
pub fn motor(edition: Edition) -> String {
    use dc_motor::variables::DESCRIPTION as MOTOR;
    let rows = |causality| variable_rows(&MOTOR, &[], causality);
    let heading = edition.heading();
    let identity = edition.identity(
        dc_motor::GUID,
        dc_motor::FMI3_TOKEN,
        dc_motor::FMI3_SCALAR_TOKEN,
    );
    format!(
        r#"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>DcMotor</title>
<style>{STYLE}</style></head>
<body>
<h1>DcMotor — {heading}</h1>
<p>{}</p>
<pre>
L di/dt = u - R i - k w            armature (back-EMF constant = torque constant k)
J dw/dt = k i - tau - b w          rotor
dphi/dt = w - w_L                  shaft twist (w_L = shaft.speed, the load's speed)
tau     = k_s phi + d_s (w - w_L)  shaft.torque on the load
v       = Kp e + Ki z, e = w_ref - w,  u = clamp(v, -U, U),  dz/dt = e + (u - v)/(Ki Tt)
</pre>
<p>Starts in steady state at speed.setPoint holding shaft.initialTorque (controller at its set-point).
Classical Runge-Kutta in equal steps of at most solver.stepSize per communication step; inputs can be
interpolated (first and second derivatives, for one communication step). With shaft.loadInertia set
(the inertia J_L of the load at the shaft's driven end), every new communication step h is checked: the
motor and a load J_L dw_L/dt = tau, exchanging w_L and tau held over h, form a linear map per step, and if
its spectral radius exceeds 1 for either exchange order (both FMUs from the same point, or the motor first)
the FMU logs a warning with both largest stable steps and counts it in solver.warnings. Directional
derivatives: d shaft.torque/d shaft.speed = -d_s, d motor.voltage/d speed.setPoint = Kp inside the voltage
limit. Reference results of the DefaultExperiment (load at 500 rad/s) are in
extra/org.fmi-standard.fmi-ls-ref/. {identity}.</p>
<h2>Parameters</h2>{}
<h2>Inputs</h2>{}
<h2>Outputs</h2>{}
</body></html>
"#,
        MOTOR.description,
        rows(Causality::Parameter),
        rows(Causality::Input),
        rows(Causality::Output)
    )
}

/// The lubrication circuit's documentation/index.html for `edition`.
pub fn circuit(edition: Edition) -> String {
    use lube_circuit::variables::DESCRIPTION as CIRCUIT;
    let rows = |causality| variable_rows(&CIRCUIT, &[], causality);
    let heading = edition.heading();
    let identity = edition.identity(
        lube_circuit::GUID,
        lube_circuit::FMI3_TOKEN,
        lube_circuit::FMI3_SCALAR_TOKEN,
    );
    format!(
        r#"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>LubricationCircuit</title>
<style>{STYLE}</style></head>
<body>
<h1>LubricationCircuit — {heading}</h1>
<p>{}</p>
<pre>
C_g dp/dt = Q_p - Q_r(p) - Q_b            gallery, C_g = gallery.volume/gallery.bulkModulus, p >= 0
Q_r(p)    = k_r max(0, p - p_c)           relief valve (relief.conductance, relief.pressure)
rho c_p V_s dT_s/dt = P_b - Phi_c         sump (sump.volume)
Phi_c     = rho c_p Q_p eps (T_s - T_c)   cooler.heatFlow (cooler.effectiveness, cooler.coolantTemperature)
T_supply  = T_s - eps (T_s - T_c)         oil.supplyTemperature; p is oil.supplyPressure
</pre>
<p>Q_b is the sum of the bearings' oil flows (the slider-crank's mainBearing.oilFlow, crankPin.oilFlow,
joint.oilFlow), P_b the sum of the heat their oil carries back to the sump (their heatFlow outputs); the
relief valve returns the pump's surplus at the supply temperature. Starts with the gallery at its steady
pressure for the bearings' flows and the sump at sump.initialTemperature. Classical Runge-Kutta in equal
steps of at most an eighth of the gallery's time constant C_g/k_r per communication step; inputs can be
interpolated (first and second derivatives, for one communication step). No output depends directly on an
input (its directional derivatives are zero), so the loop with the slider-crank (whose oil flows depend on
the supply pressure) has no algebraic loop. A gallery the bearings draw more from
than the pump delivers stays at zero pressure, and the FMU warns (solver.warnings). Reference results of
the DefaultExperiment (the compressor's bearings' flows) are in extra/org.fmi-standard.fmi-ls-ref/.
{identity}.</p>
<h2>Parameters</h2>{}
<h2>Inputs</h2>{}
<h2>Outputs</h2>{}
</body></html>
"#,
        CIRCUIT.description,
        rows(Causality::Parameter),
        rows(Causality::Input),
        rows(Causality::Output)
    )
}
