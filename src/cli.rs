//! The command line's definitions (clap): the options of the explorer window and the
//! subcommands, with the parsers of their values. The binary (`src/main.rs`) parses them and
//! runs the commands (`src/commands/`); the `xtask` crate generates the man pages and the shell
//! completions from [`command`], so that they say what `--help` says.
#![allow(
    rustdoc::broken_intra_doc_links,
    reason = "the doc comments here are clap's help text, printed as written: its JSON examples \
              (`[x,y,z]`) are not links, and escaping them would show in --help"
)]

use std::path::PathBuf;

use clap::{CommandFactory as _, Parser, Subcommand, ValueEnum};
use refraction_check::Renderer;
use refraction_diagram::{Animation, palette::Theme};
use refraction_i18n::Locale;
use refraction_kernel::Convention;
use refraction_kernel::api::Api;
use refraction_scene::DEFAULT_SCENE;
use refraction_tools::Precision;

use crate::app::View;

/// The whole command line as clap describes it: what `--help`, the man pages and the shell
/// completions are made from.
pub fn command() -> clap::Command {
    Cli::command()
}

/// Makes refraction visible: a trig-free refraction kernel, its four sign candidates, and an
/// interactive explorer (opened when no subcommand is given).
#[derive(Parser)]
#[command(version, about)]
pub struct Cli {
    /// The subcommand; without one, the explorer window opens.
    #[command(subcommand)]
    pub command: Option<Command>,
    /// Open the explorer on the problem in this JSON file (fields as for `solve`); without it
    /// the explorer reopens where it was last closed.
    #[arg(long, value_name = "FILE.json")]
    pub state: Option<PathBuf>,
    /// Open the explorer on a lesson deck at its first step: a built-in deck's name (see
    /// `lessons`) or a deck file (TOML). Page Down and Page Up step through it, R reveals a
    /// step's answer.
    #[arg(long, value_name = "NAME|FILE", conflicts_with = "state")]
    pub lesson: Option<String>,
    /// Open the explorer in presentation mode: full screen, everything larger, the side panels
    /// closed (F11 leaves it).
    #[arg(long)]
    pub present: bool,
    /// The explorer's view to open on (default: the one shown when it was last closed, or
    /// `one` with --state).
    #[arg(long, value_enum, value_name = "VIEW")]
    pub view: Option<ViewName>,
    /// The explorer's theme (default: the one chosen last time).
    #[arg(long, value_enum, value_name = "NAME")]
    pub theme: Option<ThemeName>,
    /// The language of the explorer and of the text `render` draws: en, de, es, fr, pt-BR or
    /// ru (default: the one chosen in the explorer last time, else the system's). The JSON of
    /// `solve` and `check` is the same in every language.
    #[arg(long, global = true, value_name = "CODE", value_parser = language)]
    pub lang: Option<Locale>,
    /// The address where the class opens the web build (`cargo xtask web`'s folder, hosted):
    /// *Copy link* and the QR code give links there (default: the one set in the explorer
    /// last time).
    #[arg(long, value_name = "URL")]
    pub web_base: Option<String>,
}

/// The language `--lang` names.
///
/// # Errors
/// A code with no translation; the message lists the known ones.
pub fn language(code: &str) -> Result<Locale, ArgError> {
    Locale::from_tag(code).ok_or_else(|| ArgError::Language(code.to_owned()))
}

/// The views as the command line names them.
#[derive(Clone, Copy, ValueEnum)]
pub enum ViewName {
    /// One interface: drag W, N and μ.
    One,
    /// A traced scene.
    Scenes,
    /// Accuracy against time.
    Accuracy,
}

impl From<ViewName> for View {
    fn from(name: ViewName) -> Self {
        match name {
            ViewName::One => Self::Interface,
            ViewName::Scenes => Self::Scenes,
            ViewName::Accuracy => Self::Accuracy,
        }
    }
}

/// The themes as the command line names them.
#[derive(Clone, Copy, ValueEnum)]
pub enum ThemeName {
    /// Soft media shading on white.
    Standard,
    /// Black on white, for a bright room.
    HighContrastLight,
    /// White on black, for a dark room.
    HighContrastDark,
}

impl From<ThemeName> for Theme {
    fn from(name: ThemeName) -> Self {
        match name {
            ThemeName::Standard => Self::Standard,
            ThemeName::HighContrastLight => Self::HighContrastLight,
            ThemeName::HighContrastDark => Self::HighContrastDark,
        }
    }
}

/// The subcommands, for scripts and slides.
#[derive(Subcommand)]
#[expect(
    clippy::doc_markdown,
    reason = "clap prints these comments as the commands' help, where backticks would show"
)]
pub enum Command {
    /// Read refraction problems as JSON Lines on stdin; write one JSON answer per line.
    ///
    /// Input: {"w":[x,y,z],"n":[x,y,z],"mu_i":1,"mu_t":1.5} with optional
    /// "convention" ("along_ray" | "toward_origin") and "precision" ("f64" | "f32").
    /// Exit status 0 when every line was solved, 1 when any line was an error.
    Solve,
    /// Check the T your ray tracer produced, line by line and as a whole log: which mistake in
    /// your code explains the lines that are wrong, and its fix.
    ///
    /// Without --api, each line (JSON Lines from FILE or stdin, a --pattern log or --csv) has
    /// the `solve` fields "w", "n", "mu_i", "mu_t" (or "entering" with --inside and
    /// --outside), "t_yours" (your T: an array, a string such as "vec3(0.1, -0.9, 0)", or null
    /// where your code reported total internal reflection or sampled a reflection) and
    /// optionally "ratio" (the ratio your code used). With --api, each line is the call your code made in that API's own
    /// terms (glsl: I, N, eta, result; pbrt: wi, n, eta, returned, wt, etap; rtiow: uv, n,
    /// etai_over_etat, refracted, front_face; mitsuba: wi, n, eta, wo), with optional truth
    /// "from", "to", "travel", "entering".
    ///
    /// Answers each line with "ok", "matches" (chosen, wrong_side, wrong_bend, reversed,
    /// total_internal_reflection or null), "explanation" and "mistakes"; the tally and the
    /// diagnosis of the whole log go to stderr (and with --summary to a JSON file). Exit
    /// status 0 when every line is ok, 1 when any is not (or the diagnosis finds a mistake),
    /// 3 when no line was judged (nothing matched the pattern, the input was empty, a CSV held
    /// only its header), 4 when no line is wrong but the log cannot be checked (the diagnosis
    /// says "unchecked" and what to log), 2 on an error.
    Check {
        /// JSON Lines file to read (stdin when absent).
        file: Option<PathBuf>,
        /// Check calls of this API: glsl (or hlsl, wgsl, glm, glam), pbrt, rtiow, mitsuba.
        #[arg(long, value_name = "NAME", value_parser = parse_api)]
        api: Option<Api>,
        /// The index inside the object: with --outside, "entering" gives "from" and "to".
        #[arg(long, value_name = "X", requires = "outside", allow_hyphen_values = true, value_parser = parse_index)]
        inside: Option<f64>,
        /// The index outside the object.
        #[arg(long, value_name = "Y", requires = "inside", allow_hyphen_values = true, value_parser = parse_index)]
        outside: Option<f64>,
        /// The precision your code computes in, unless a line says (default: f32 for glsl,
        /// pbrt and mitsuba, f64 for rtiow and without --api).
        #[arg(long, value_name = "f32|f64", value_parser = parse_precision)]
        precision: Option<Precision>,
        /// Read printf-style log lines: each {field} takes a number or a vector as programs
        /// print it, {_} anything; lines that do not match are skipped and counted.
        #[arg(long, value_name = "PATTERN", conflicts_with = "csv")]
        pattern: Option<String>,
        /// Read CSV with a header line naming the fields.
        #[arg(long)]
        csv: bool,
        /// Also write the diagnosis of the whole log to this JSON file: {"lines", "judged",
        /// "ok", "skipped", "diagnosis": [{"code", "lines", "where", "fix"}, ...]}, the verdict
        /// first ("none" when nothing is wrong).
        /// Never the log being read; a file already there must be empty or a summary check wrote,
        /// unless --replace is given.
        #[arg(long, value_name = "FILE.json")]
        summary: Option<PathBuf>,
        /// Let --summary write over a file that is not a summary of check's (never over the log
        /// being read).
        #[arg(long, requires = "summary")]
        replace: bool,
        /// Also write the first 100 failing lines as unit tests to this file, in the language its
        /// extension names: .cpp or .py (any renderer's, or pbrt's and the book's C++), .glsl.
        /// A file already there must be empty or a test file check wrote (or the window saved).
        #[arg(long, value_name = "FILE")]
        tests: Option<PathBuf>,
        /// With --pattern, answer a line that does not match with an error instead of skipping it.
        #[arg(long, requires = "pattern")]
        strict: bool,
        /// Consecutive lines with the same "path" are one ray's hits: after each path, a
        /// summary line {"path","hits","first_wrong","exit_ok","explanation"}.
        #[arg(long, requires = "api")]
        paths: bool,
        /// Without --api: "w" points along the ray (along-ray, the default) or back toward
        /// where it came from (toward-origin, as Mitsuba's, Tungsten's and Cycles' wi), unless
        /// a line's "convention" says.
        #[arg(long, value_name = "along-ray|toward-origin", conflicts_with = "api", value_parser = parse_convention)]
        convention: Option<Convention>,
        /// Without --api: the normal of lines that print none, as +z, -z, +x... or "x y z" (a
        /// local frame's +z in Mitsuba and Tungsten), taken as the outward normal: with
        /// --inside and --outside, each ray's side follows from it.
        #[arg(long, value_name = "+z|X Y Z", conflicts_with = "api", allow_hyphen_values = true, value_parser = parse_normal)]
        normal: Option<[f64; 3]>,
        /// Whose code the log comes from, so that the fix names the line to change in it:
        /// mitsuba, tungsten, cycles, threejs, pbrt, smallpt, rtiow, glsl, glam, mitsuba-python
        /// (with --api, the API's by default; glam's for a GLSL log printing glam's `Vec3(..)`).
        #[arg(long, value_name = "NAME", value_parser = parse_renderer)]
        renderer: Option<Renderer>,
        /// Read the log's first lines and print a --pattern for them (and the command that
        /// uses it, with the other options given) instead of checking; exit status 3 when no
        /// line looks like a refraction.
        #[arg(long, conflicts_with_all = ["pattern", "csv", "paths", "strict"])]
        suggest_pattern: bool,
    },
    /// Measure what accuracy costs in time: every kernel variant at f32 and f64, timed on
    /// this machine and compared with a double-double oracle.
    Bench {
        /// A shorter run (under 20 s on 2 cores); the default run is steadier.
        #[arg(long)]
        quick: bool,
        /// Print one JSON document instead of the table.
        #[arg(long)]
        json: bool,
        /// Also draw error against time per variant (log scales) into this PNG file (checked
        /// before the measurement starts).
        #[arg(long, value_name = "FILE.png")]
        plot: Option<PathBuf>,
    },
    /// Trace a scene: a ray, beam or fan crossing interface after interface.
    ///
    /// Prints a summary and the counts of what the tracer computed; with --json, the ray paths
    /// (points, medium per segment, wavelength, intensity), every hit, the shapes' outlines,
    /// the world bounds and the counts.
    Trace {
        /// A built-in scene's name (see --list) or the path of a scene file (TOML).
        #[arg(default_value = DEFAULT_SCENE)]
        scene: String,
        /// Print the trace as one JSON object.
        #[arg(long)]
        json: bool,
        /// List the built-in scenes (name and title) and exit.
        #[arg(long)]
        list: bool,
    },
    /// Draw the explorer's diagram, or a traced scene, into a PNG or SVG file, or an animation
    /// of the diagram into a GIF, or a lesson deck into a handout (PDF) or one SVG per step,
    /// without a window.
    Render(RenderArgs),
    /// List the built-in lesson decks, one per line: NAME, TITLE and the number of steps,
    /// separated by tabs (the titles in the language of --lang).
    Lessons,
}

/// What `render` is asked for on the command line.
#[derive(clap::Args)]
pub struct RenderArgs {
    /// A scene to trace and draw instead of the single interface: a built-in scene's name
    /// (see `trace --list`) or the path of a scene file (TOML).
    pub scene: Option<String>,
    /// The file to write (replaced atomically), or - for standard output (PNG, or GIF with
    /// --animate). Its extension picks the format: .png or .svg (labels as editable text) for
    /// a picture, .gif for --animate; with --lesson, .pdf for the handout, or a folder (DIR/)
    /// for one SVG per step.
    #[arg(long, value_name = "FILE.png|FILE.svg|FILE.gif|FILE.pdf|DIR/")]
    pub out: PathBuf,
    /// Draw a lesson deck (a built-in deck's name, see `lessons`, or a deck file): a handout
    /// with one page per step (its diagram, title, question and notes; --out FILE.pdf) or each
    /// step's diagram as step-01.svg, step-02.svg, … (--out DIR/, at --width × --height).
    #[arg(
        long,
        value_name = "NAME|FILE",
        conflicts_with_all = ["scene", "state", "animate", "view"]
    )]
    pub lesson: Option<String>,
    /// With --lesson and --out FILE.pdf: the student sheet instead of the teacher's handout
    /// (each step's question and its diagram with the answer hidden, lines to write the answer
    /// on, no notes).
    #[arg(long, requires = "lesson")]
    pub students: bool,
    /// In an SVG, write the labels as editable text (exact only where Ubuntu Light is
    /// installed or the viewer honours textLength) instead of outlined glyphs, which look the
    /// same in every viewer.
    #[arg(long)]
    pub svg_text: bool,
    /// With --lesson and a .pdf handout: the address where the class opens the web build;
    /// each page then carries its step's link and QR code.
    #[arg(long, value_name = "URL", requires = "lesson")]
    pub web_base: Option<String>,
    /// Width in pixels (64 to 8192).
    #[arg(long, default_value_t = refraction_render::DEFAULT_SIZE.0)]
    pub width: u32,
    /// Height in pixels (64 to 8192).
    #[arg(long, default_value_t = refraction_render::DEFAULT_SIZE.1)]
    pub height: u32,
    /// The single-interface problem to draw, as JSON with the fields of `solve` (default: 40°
    /// from air into glass); not with SCENE.
    #[arg(long, value_name = "FILE.json")]
    pub state: Option<PathBuf>,
    /// Write an animated GIF of the diagram instead: mu (μt moves to μi, T turns into W),
    /// sweep (θi from normal incidence to grazing, from the denser medium, so that total
    /// internal reflection appears) or wavefronts (the fronts moving at c/μ, looping); not
    /// with SCENE.
    #[arg(long, value_name = "mu|sweep|wavefronts", value_parser = parse_animation)]
    pub animate: Option<Animation>,
    /// The animation's frames (2 to 600; default 36).
    #[arg(long, value_name = "N", requires = "animate")]
    pub frames: Option<usize>,
    /// The animation's frames per second (1 to 50; default 12).
    #[arg(long, value_name = "F", requires = "animate")]
    pub fps: Option<u32>,
    /// What to draw of the single interface: the diagram (the default), the Fresnel plot of
    /// its media with the cursor at its θi, or the accuracy-against-time plot of a quick
    /// measurement (as the window's views draw them); not with SCENE or --animate.
    #[arg(long, value_enum, default_value_t = ViewArg::Interface)]
    pub view: ViewArg,
}

/// The views `render --view` draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum ViewArg {
    /// The interface diagram.
    Interface,
    /// Reflectance and transmittance against θi.
    Fresnel,
    /// Error against time per ray, measured now (the quick set).
    Accuracy,
}

/// The animation named `name` on the command line.
///
/// # Errors
/// An unknown name; the message lists the animations.
pub fn parse_animation(name: &str) -> Result<Animation, ArgError> {
    Animation::from_name(name).ok_or_else(|| ArgError::Animation(name.to_owned()))
}

/// Reads `--api NAME`.
///
/// # Errors
/// An unknown name; the message lists the known ones.
pub fn parse_api(name: &str) -> Result<Api, ArgError> {
    Api::from_name(name).ok_or_else(|| ArgError::Api(name.to_owned()))
}

/// Reads `--convention along-ray|toward-origin` (or with an underscore).
///
/// # Errors
/// Anything else.
pub fn parse_convention(name: &str) -> Result<Convention, ArgError> {
    Convention::from_name(&name.replace('-', "_"))
        .ok_or_else(|| ArgError::Convention(name.to_owned()))
}

/// Reads `--normal`: an axis (`+z`, `-z`, `x`...) or a vector as programs print it.
///
/// # Errors
/// Anything else, or the zero vector.
pub fn parse_normal(text: &str) -> Result<[f64; 3], ArgError> {
    let axis = |i: usize, sign: f64| {
        let mut v = [0.0; 3];
        v[i] = sign;
        v
    };
    let trimmed = text.trim().to_ascii_lowercase();
    let (sign, name) = match trimmed.strip_prefix('-') {
        Some(rest) => (-1.0, rest),
        None => (1.0, trimmed.strip_prefix('+').unwrap_or(&trimmed)),
    };
    if let Some(i) = ["x", "y", "z"].iter().position(|a| *a == name) {
        return Ok(axis(i, sign));
    }
    let v = refraction_tools::vector_text::parse_vector(text)
        .map_err(ArgError::Normal)?
        .value;
    if !v.iter().all(|c| c.is_finite()) || v == [0.0; 3] {
        return Err(ArgError::ZeroNormal(text.to_owned()));
    }
    // Scaled by the largest component first, so that the length neither underflows nor
    // overflows on the way.
    let largest = v.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
    let length = largest * glam::DVec3::from_array(v.map(|c| c / largest)).length();
    // Shorter, its dot product with a ray's direction underflows (every ray read as
    // entering): issue 40. Taken at unit length, so that every line's dot product is exact.
    if length < MIN_NORMAL_LENGTH {
        return Err(ArgError::ShortNormal(text.to_owned()));
    }
    Ok(v.map(|c| c / length))
}

/// The shortest `--normal` taken: √(the smallest normal f64), below which products with it
/// lose their digits.
const MIN_NORMAL_LENGTH: f64 = 1.5e-154;

/// Reads `--renderer NAME`.
///
/// # Errors
/// An unknown name; the message lists the known ones.
pub fn parse_renderer(name: &str) -> Result<Renderer, ArgError> {
    Renderer::from_name(name).ok_or_else(|| ArgError::Renderer(name.to_owned()))
}

/// Reads `--precision f32|f64`.
///
/// # Errors
/// Anything else.
pub fn parse_precision(name: &str) -> Result<Precision, ArgError> {
    match name {
        "f32" | "float" => Ok(Precision::F32),
        "f64" | "double" => Ok(Precision::F64),
        _ => Err(ArgError::Precision(name.to_owned())),
    }
}

/// Reads `--inside` and `--outside`: an index of refraction, a finite number > 0.
///
/// # Errors
/// Anything else; the message says what was given.
pub fn parse_index(text: &str) -> Result<f64, ArgError> {
    match text.trim().parse::<f64>() {
        Ok(x) if x.is_finite() && x > 0.0 => Ok(x),
        Ok(x) => Err(ArgError::Index(x)),
        Err(source) => Err(ArgError::NotANumber {
            text: text.to_owned(),
            source,
        }),
    }
}

/// Why a value on the command line was refused. Worded by its `Display` in English, as clap's
/// own messages around it are; each names the value given and what is expected.
#[derive(Debug, thiserror::Error)]
pub enum ArgError {
    /// `--lang` with no translation.
    #[error("no translation for `{0}`: choose one of {known}", known = names(Locale::ALL.iter().map(|l| l.code())))]
    Language(String),
    /// An unknown animation.
    #[error("no animation is called {0:?}: the animations are {known}", known = names(Animation::ALL.iter().map(|a| a.name())))]
    Animation(String),
    /// An unknown `--api`.
    #[error(
        "unknown API \"{0}\": expected glsl (or hlsl, wgsl, glm, glam), pbrt, rtiow or mitsuba"
    )]
    Api(String),
    /// An unknown `--convention`.
    #[error("unknown convention \"{0}\": expected along-ray or toward-origin")]
    Convention(String),
    /// A `--normal` that is neither an axis nor a vector.
    #[error("--normal: {0}: expected +z, -z, +x... or three numbers")]
    Normal(#[source] refraction_tools::VectorError),
    /// A `--normal` of zero length or with a component that is not finite.
    #[error("--normal must be a finite vector other than zero, not {0}")]
    ZeroNormal(String),
    /// A `--normal` too short for its products with a direction to keep their digits.
    #[error(
        "--normal {0} is too short to tell a side by (its length is under 1.5e-154): give \
         the normal at about unit length"
    )]
    ShortNormal(String),
    /// An unknown `--renderer`.
    #[error("unknown renderer \"{0}\": expected one of {known}", known = names(Renderer::ALL.iter().map(|r| r.name())))]
    Renderer(String),
    /// An unknown `--precision`.
    #[error("unknown precision \"{0}\": expected f32 or f64")]
    Precision(String),
    /// An index of refraction that is not finite or not above 0.
    #[error("an index of refraction must be a finite number > 0, not {0}")]
    Index(f64),
    /// An index of refraction that is not a number.
    #[error("\"{text}\" is not a number: {source}")]
    NotANumber {
        /// The text given.
        text: String,
        /// Why it does not parse.
        source: core::num::ParseFloatError,
    },
}

/// The known names, comma-separated.
fn names<'a>(all: impl Iterator<Item = &'a str>) -> String {
    all.collect::<Vec<_>>().join(", ")
}
