//! The user guides inside the FMUs (`documentation/index.html`), for someone who has only the
//! `.fmu`: generated from the same sources as the repository's documentation — the README's
//! sections for a user of the FMU (what it is, a quick start in fmpy, libcosim, Rust and other
//! masters, the behaviour a master can rely on, the choices, the validation, performance and
//! limits) and the variable tables with value references and display units from the variable
//! table. Links are kept only where they resolve inside the FMU: images are packed beside the
//! page, links into the repository keep their text and lose their target.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use flexible_slider_crank::fmi::GUID;
use flexible_slider_crank::variables::{Causality, DESCRIPTION, ENUMERATIONS, Kind};
use fmi2_slave::description::Description;
use fmi2_slave::number::Num;
use fmi2_slave::table::{Enumeration, ValueReference, Variable};

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

/// The README's text from the heading `from` (a line starting with it) up to the next heading of
/// the same or a higher level, without the heading itself; an error if the README has no such
/// heading (a renamed section would otherwise vanish from the FMU's documentation).
fn readme_section(readme: &str, from: &str) -> Result<String, String> {
    let Some(start) = readme.find(&format!("\n{from}")) else {
        return Err(format!(
            "README.md has no section \"{from}\" for the FMU's documentation"
        ));
    };
    let level = from.chars().take_while(|&c| c == '#').count();
    let body = &readme[start + 1..];
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

/// documentation/index.html of the slider-crank, and the images it shows (files to pack beside
/// it); an error if the README lacks one of the sections it shows.
pub fn slider_crank(root: &Path) -> Result<(String, Vec<PathBuf>), String> {
    let readme = std::fs::read_to_string(root.join("README.md")).map_err(|e| e.to_string())?;
    let section = |heading: &str| readme_section(&readme, heading);
    let mut images = Vec::new();
    let intro = readme
        .split("\n## ")
        .next()
        .unwrap_or_default()
        .lines()
        .skip_while(|line| line.starts_with("# ") || line.is_empty())
        .collect::<Vec<_>>()
        .join("\n");
    // The demo plot and its caption (the README shows them before "Using the FMU").
    let demo = readme
        .split("\n\n")
        .skip_while(|paragraph| !paragraph.contains("documentation/demo.png"))
        .take(2)
        .collect::<Vec<_>>()
        .join("\n\n");
    let mut html = |markdown: &str, shift| to_html(markdown, shift, root, &mut images);
    let intro = html(&intro, 0);
    let demo = html(&demo, 0);
    let quick_start = html(
        section("## Using the FMU")?
            .split("\n### ")
            .next()
            .unwrap_or_default(),
        0,
    );
    let behaviour = html(&section("### Behaviour a master can rely on")?, 0);
    let frame = html(&section("### Frame and signs")?, 0);
    let ranges = html(&section("#### Why the ranges are what they are")?, 0);
    // The README's output table is the variable table's; the notes after it are kept.
    let output_notes = html(
        &section("#### Outputs")?
            .lines()
            .filter(|line| !line.starts_with('|'))
            .collect::<Vec<_>>()
            .join("\n"),
        0,
    );
    let choosing = html(
        &section("### Choosing `rod.nModes`, `rod.boundary`, `rod.quadrature`, `solver.*`")?,
        0,
    );
    let own_machine = html(
        &section(
            "### Your own machine: counterweight, offset cylinder, rod eyes, gas load, damping, fatigue stress",
        )?,
        0,
    );
    let mut sections = |headings: [&str; 3], shift| -> Result<[String; 3], String> {
        let [a, b, c] = headings.map(&section);
        Ok([html(&a?, shift), html(&b?, shift), html(&c?, shift)])
    };
    let [sizing, clearance, bearings] = sections(
        [
            "### Sizing parts: loads at every joint, stress in the rod, clean starts",
            "### Clearance at every joint",
            "### Bearing design: film thickness, film pressure, friction loss",
        ],
        0,
    )?;
    let [validation, performance, limits] =
        sections(["## Validation", "## Performance", "## Current limits"], 1)?;
    let rows = |causality| variable_rows(&DESCRIPTION, ENUMERATIONS, causality);
    let page = format!(
        r##"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>FlexibleSliderCrank</title>
<style>{STYLE}</style></head>
<body>
<h1>FlexibleSliderCrank — FMI 2.0 co-simulation FMU</h1>
{intro}
<p>GUID <code>{GUID}</code>. Contents: <a href="#quick-start">Quick start</a> ·
<a href="#behaviour">Behaviour a master can rely on</a> · <a href="#frame">Frame and signs</a> ·
<a href="#variables">Variables</a> ·
<a href="#sizing">Sizing parts</a> · <a href="#clearance">Clearance at every joint</a> ·
<a href="#bearings">Bearing design</a> · <a href="#own-machine">Your own machine</a> ·
<a href="#choosing">Choosing the model and solver</a> · <a href="#validation">Validation</a> ·
<a href="#performance">Performance</a> · <a href="#limits">Current limits</a></p>
{demo}
<h2 id="quick-start">Quick start</h2>
{quick_start}
<h2 id="behaviour">Behaviour a master can rely on</h2>
{behaviour}
<h2 id="frame">Frame and signs</h2>
{frame}
<h2 id="variables">Variables</h2>
<p>Value references as in modelDescription.xml; the display unit is the one a master shows by default.
Switches are Integer parameters whose items are listed in the range column.</p>
<h3>Parameters (fixed: set before fmi2ExitInitializationMode)</h3>{}
<h4>Why the ranges are what they are</h4>{ranges}
<h3>Calculated parameter</h3>{}
<h3>Inputs (continuous, settable at every communication point)</h3>{}
<h3>Outputs</h3>{}
{output_notes}
<h2 id="sizing">Sizing parts: loads at every joint, stress in the rod, clean starts</h2>
{sizing}
<h2 id="clearance">Clearance at every joint</h2>
{clearance}
<h2 id="bearings">Bearing design: film thickness, film pressure, friction loss</h2>
{bearings}
<h2 id="own-machine">Your own machine: counterweight, offset cylinder, rod eyes, gas load, damping, fatigue stress</h2>
{own_machine}
<h2 id="choosing">Choosing the model and solver</h2>
{choosing}
<h2 id="validation">Validation</h2>
{validation}
<h2 id="performance">Performance</h2>
{performance}
<h2 id="limits">Current limits</h2>
{limits}
</body></html>
"##,
        rows(Causality::Parameter),
        rows(Causality::CalculatedParameter),
        rows(Causality::Input),
        rows(Causality::Output)
    );
    Ok((page, images))
}

/// documentation/index.html of the DC motor.
pub fn motor() -> String {
    use dc_motor::variables::DESCRIPTION as MOTOR;
    let rows = |causality| variable_rows(&MOTOR, &[], causality);
    format!(
        r#"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>DcMotor</title>
<style>{STYLE}</style></head>
<body>
<h1>DcMotor — FMI 2.0 co-simulation FMU</h1>
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
extra/org.fmi-standard.fmi-ls-ref/. GUID <code>{}</code>.</p>
<h2>Parameters</h2>{}
<h2>Inputs</h2>{}
<h2>Outputs</h2>{}
</body></html>
"#,
        MOTOR.description,
        dc_motor::GUID,
        rows(Causality::Parameter),
        rows(Causality::Input),
        rows(Causality::Output)
    )
}
