//! The scene file format (TOML, described in the repository's docs/scenes.md): the checked
//! conversion of the file as written ([`spec`](super::spec)) into a [`Scene`]. Every error names
//! the file, the line and column of the value at fault, and what was expected.

use core::ops::Range;
use std::collections::BTreeMap;

use glam::DVec2;
use toml::Spanned;

use super::bounds::Bounds;
use super::effects::Effects;
use super::medium::{Dispersion, Medium};
use super::search::first_self_crossing;
use super::shape::{Lens, Shape};
use super::source::{Light, Source, SourceKind};
use super::spec::{
    CircleSpec, EffectsSpec, LensSpec, LineSpec, MediumSpec, Pair, PolygonSpec, SceneFile,
    SegmentSpec, ShapeTable, SourceSpec, ViewSpec,
};
use super::{Scene, embedded};

/// The largest absolute coordinate a scene may use, in world units. A position is held to
/// about 1e-16 of its size, and the tracer must tell a ray leaving a surface from one crossing
/// it again: it counts crossings only beyond [`super::T_MIN`] (1e-9) along the ray. At 1e5 a
/// position's rounding (1.5e-11) is 60 times smaller than that step; a droplet at 3e6 already
/// re-hits its own surface and reflects totally where it should not.
pub const MAX_COORDINATE: f64 = 1e5;

/// The smallest size a scene may use, in world units (radii, thickness, a segment's or a
/// polygon edge's length, a beam's width, the view's sides): 1000 times the tracer's step
/// [`super::T_MIN`], so that a ray never crosses a whole shape within one step. The largest
/// size is [`MAX_COORDINATE`].
pub const MIN_SIZE: f64 = 1e-6;

/// The most shapes a scene file may have: ten times a classroom scene's few dozen. The tracer
/// tests every shape's pieces for each ray segment, so this many keep a trace of a thousand
/// rays well within its work budget.
pub const MAX_SHAPES: usize = 500;

/// The largest scene file [`crate::Scene::load`] reads: 1 MiB (the built-in scenes are under
/// 4 KiB).
pub const MAX_SCENE_FILE_BYTES: u64 = 1 << 20;

/// The most polygon points a scene file may have, over all its polygons: a prism has three or
/// four, an outline drawn by hand a few hundred. Each edge is tested against the others when
/// the file is read (a polygon must not cross itself), and against every ray segment.
pub const MAX_POINTS: usize = 2_000;

/// A line and column in a file, both counted from 1 (columns in characters).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Position {
    /// The line.
    pub line: usize,
    /// The column.
    pub column: usize,
}

impl Position {
    /// The position of byte `offset` in `text` (clamped to the text).
    #[must_use]
    pub fn of(text: &str, offset: usize) -> Self {
        let mut end = offset.min(text.len());
        while !text.is_char_boundary(end) {
            end -= 1;
        }
        let before = &text[..end];
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        Self {
            line: before.matches('\n').count() + 1,
            column: before[line_start..].chars().count() + 1,
        }
    }
}

/// Why a scene could not be loaded.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{file}{}: {message}", place(.position.as_ref()))]
pub struct LoadError {
    /// The file's path, or the embedded scene's name.
    pub file: String,
    /// Where in the file, when the error is about its contents.
    pub position: Option<Position>,
    /// What is wrong and what was expected.
    pub message: String,
}

impl LoadError {
    /// An error in `text`, the contents of `file`, at the start of `span` (`None`: about the
    /// file as a whole).
    #[must_use]
    pub fn in_text(
        text: &str,
        file: &str,
        span: Option<Range<usize>>,
        message: impl Into<String>,
    ) -> Self {
        Self {
            file: file.to_owned(),
            position: span.map(|s| Position::of(text, s.start)),
            message: message.into(),
        }
    }
}

/// Reads the TOML `text` of `file` as `T`, with the scene format's errors: malformed TOML, a
/// missing or unknown field and a value of the wrong type at their line and column, in the
/// format's words. Other formats of the explorer written in TOML (lesson decks) read with it,
/// so that every file's errors read alike.
///
/// # Errors
/// The first problem the parser finds, at its position.
pub fn parse_toml<T: serde::de::DeserializeOwned>(text: &str, file: &str) -> Result<T, LoadError> {
    toml::from_str(text).map_err(|e| match e.span() {
        Some(span) => LoadError::in_text(text, file, Some(span), toml_words(e.message())),
        // The reader's limit on nested tables comes without a place: the deepest key has it.
        None if e.message().contains("recursion limit") => LoadError::in_text(
            text,
            file,
            deepest_key(text),
            "the keys nest too deeply: a dotted key or a table's name has too many parts"
                .to_owned(),
        ),
        None => LoadError::in_text(text, file, None, toml_words(e.message())),
    })
}

/// The line whose key (before `=`, or a table's name in brackets) has the most dotted parts,
/// as the bytes of that key: where a file's tables nest deepest.
fn deepest_key(text: &str) -> Option<Range<usize>> {
    let mut start = 0;
    let mut deepest: Option<(usize, Range<usize>)> = None;
    for line in text.split_inclusive('\n') {
        let trimmed = line.trim_start();
        let key = if trimmed.starts_with('[') {
            trimmed.split(']').next().unwrap_or(trimmed)
        } else {
            trimmed.split('=').next().unwrap_or("")
        };
        let parts = key.matches('.').count();
        let at = start + (line.len() - trimmed.len());
        if deepest.as_ref().is_none_or(|(most, _)| parts > *most) {
            deepest = Some((parts, at..at + key.trim_end().len()));
        }
        start += line.len();
    }
    deepest.map(|(_, span)| span)
}

/// The bytes of `file` as text, which TOML is: `what` names the kind of file in the error
/// (`a scene file`).
///
/// # Errors
/// Bytes that are not UTF-8, at the line and column of the first bad byte.
pub fn toml_text<'a>(bytes: &'a [u8], file: &str, what: &str) -> Result<&'a str, LoadError> {
    core::str::from_utf8(bytes).map_err(|e| {
        let good = &bytes[..e.valid_up_to()];
        // The prefix is valid UTF-8 by the definition of `valid_up_to`.
        let good = core::str::from_utf8(good).unwrap_or_default();
        LoadError {
            file: file.to_owned(),
            position: Some(Position::of(good, good.len())),
            message: format!("not UTF-8 text: {what} is TOML, which is UTF-8"),
        }
    })
}

/// A position as it follows the file's name in a message: `:line:column`, or nothing.
fn place(position: Option<&Position>) -> String {
    position.map_or_else(String::new, |Position { line, column }| {
        format!(":{line}:{column}")
    })
}

/// The TOML parser's message in the words of the scene format's own messages: an array holds
/// values and an inline table entries, never "elements" (serde's word, which the format's
/// messages avoid).
fn toml_words(message: &str) -> String {
    message
        .trim_end()
        .replace("array elements", "the array's values")
        .replace("inline table element", "inline table entry")
}

/// A problem at a place in a TOML file: a byte range and a message (the scene format's and
/// the lesson decks' checks after parsing say what they find with it).
#[derive(Debug)]
pub struct Invalid {
    /// The bytes the problem is about.
    pub span: Range<usize>,
    /// What is wrong, in words.
    pub message: String,
}

/// The problem `message` about the bytes `span`, as an error.
///
/// # Errors
/// Always: it is the error.
pub fn invalid<T>(span: Range<usize>, message: impl Into<String>) -> Result<T, Invalid> {
    Err(Invalid {
        span,
        message: message.into(),
    })
}

/// The range of vacuum wavelengths a source may have, in nm, both ends included, as the message
/// says.
const WAVELENGTHS_NM: core::ops::RangeInclusive<f64> = 200.0..=2500.0;

/// The range of indices of refraction a medium may have at the traced wavelengths, both ends
/// included, as the message says.
const INDICES: core::ops::RangeInclusive<f64> = 0.01..=100.0;

/// The default ray count of a beam or fan.
const DEFAULT_RAYS: usize = 9;

/// A number as a message shows it: in exponent form when very large or very small.
fn shown(x: f64) -> String {
    if x != 0.0 && !(1e-4..1e6).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// Two finite numbers.
fn finite(v: &Spanned<Pair>, what: &str) -> Result<DVec2, Invalid> {
    let p = DVec2::from(v.get_ref().0);
    if p.is_finite() {
        Ok(p)
    } else {
        invalid(v.span(), format!("{what} must be two finite numbers"))
    }
}

/// A position: two finite numbers within ±[`MAX_COORDINATE`].
fn point(v: &Spanned<Pair>, what: &str) -> Result<DVec2, Invalid> {
    let p = finite(v, what)?;
    if p.abs().max_element() <= MAX_COORDINATE {
        Ok(p)
    } else {
        invalid(
            v.span(),
            format!(
                "{what} is [{}, {}]: coordinates must lie within ±{} (farther out, rounding \
                 makes rays re-hit the surface they leave)",
                shown(p.x),
                shown(p.y),
                shown(MAX_COORDINATE)
            ),
        )
    }
}

/// A size from [`MIN_SIZE`] to [`MAX_COORDINATE`].
fn size(x: f64, span: Range<usize>, what: &str) -> Result<f64, Invalid> {
    if (MIN_SIZE..=MAX_COORDINATE).contains(&x) {
        Ok(x)
    } else {
        invalid(
            span,
            format!(
                "{what} is {}: expected a size from {} to {}",
                shown(x),
                shown(MIN_SIZE),
                shown(MAX_COORDINATE)
            ),
        )
    }
}

/// A length of at least [`MIN_SIZE`] (between two positions, so at most twice the range).
fn long_enough(length: f64, span: Range<usize>, what: &str) -> Result<f64, Invalid> {
    if length >= MIN_SIZE {
        Ok(length)
    } else {
        invalid(
            span,
            format!(
                "{what} is {}: expected at least {}",
                shown(length),
                shown(MIN_SIZE)
            ),
        )
    }
}

/// `v` as a unit direction. A vector already unit to rounding is kept as written, so that a
/// scene written back ([`Scene::to_toml`]) reads back bit for bit; any other is scaled by its
/// largest component first, so that neither a huge nor a tiny one over- or underflows.
fn direction(v: &Spanned<Pair>, what: &str) -> Result<DVec2, Invalid> {
    let d = finite(v, what)?;
    if (d.length_squared() - 1.0).abs() <= 4.0 * f64::EPSILON {
        return Ok(d);
    }
    (d / d.abs().max_element()).try_normalize().map_or_else(
        || invalid(v.span(), format!("{what} must not be [0, 0]")),
        Ok,
    )
}

/// The media by name, with their position in the scene's list and where each was given.
struct MediaTable {
    media: Vec<Medium>,
    /// Per medium, the span of its index, dispersion formula or table (empty for the built-in
    /// vacuum).
    spans: Vec<Range<usize>>,
}

impl MediaTable {
    fn build(specs: &BTreeMap<String, Spanned<MediumSpec>>) -> Result<Self, Invalid> {
        let mut table = Self {
            media: Vec::with_capacity(specs.len() + 1),
            spans: Vec::with_capacity(specs.len() + 1),
        };
        if !specs.contains_key("vacuum") {
            table.media.push(Medium::vacuum());
            table.spans.push(0..0);
        }
        for (name, spec) in specs {
            let absorption = match &spec.get_ref().absorption {
                None => 0.0,
                Some(a) if a.get_ref().is_finite() && *a.get_ref() >= 0.0 => *a.get_ref(),
                Some(a) => {
                    return invalid(
                        a.span(),
                        format!(
                            "medium `{name}`: absorption is {}: expected a finite number ≥ 0",
                            a.get_ref()
                        ),
                    );
                }
            };
            let (dispersion, span) = dispersion(spec)?;
            table.media.push(Medium {
                name: name.clone(),
                dispersion,
                absorption,
            });
            table.spans.push(span);
        }
        Ok(table)
    }

    fn position(&self, name: &str) -> Option<usize> {
        self.media.iter().position(|m| m.name == name)
    }

    fn find(&self, name: &Spanned<String>) -> Result<usize, Invalid> {
        self.position(name.get_ref()).map_or_else(
            || {
                let known: Vec<_> = self.media.iter().map(|m| m.name.as_str()).collect();
                invalid(
                    name.span(),
                    format!(
                        "no medium named `{}`: expected one of {} (define it under [media])",
                        name.get_ref(),
                        known.join(", ")
                    ),
                )
            },
            Ok,
        )
    }

    /// Checks that every medium has a sensible index at every wavelength the source may use.
    fn check_indices(&self, wavelengths: &[f64]) -> Result<(), Invalid> {
        for (medium, span) in self.media.iter().zip(&self.spans) {
            for &nm in wavelengths {
                let n = medium.index(nm);
                if !INDICES.contains(&n) {
                    return invalid(
                        span.clone(),
                        format!(
                            "medium `{}` has index {n} at {nm} nm: expected a number from {} to \
                             {} (check its coefficients and units: λ in µm)",
                            medium.name,
                            INDICES.start(),
                            INDICES.end()
                        ),
                    );
                }
            }
        }
        Ok(())
    }
}

/// The medium's dispersion and the span of what gives it.
fn dispersion(spec: &Spanned<MediumSpec>) -> Result<(Dispersion, Range<usize>), Invalid> {
    let m = spec.get_ref();
    let all_finite = |xs: &[f64]| xs.iter().all(|x| x.is_finite());
    match (&m.index, &m.cauchy, &m.sellmeier) {
        (Some(n), None, None) => Ok((Dispersion::Constant(*n.get_ref()), n.span())),
        (None, Some(c), None) => {
            let (a, b, c2) = (c.get_ref().a, c.get_ref().b, c.get_ref().c);
            if all_finite(&[a, b, c2]) {
                Ok((Dispersion::Cauchy { a, b, c: c2 }, c.span()))
            } else {
                invalid(c.span(), "cauchy coefficients must be finite numbers")
            }
        }
        (None, None, Some(s)) => {
            let (b, c) = (&s.get_ref().b, &s.get_ref().c);
            if b.len() == c.len() && !b.is_empty() && all_finite(b) && all_finite(c) {
                let (b, c) = (b.clone(), c.clone());
                Ok((Dispersion::Sellmeier { b, c }, s.span()))
            } else {
                invalid(
                    s.span(),
                    "sellmeier needs `b` and `c` lists of the same non-zero length, of finite \
                     numbers",
                )
            }
        }
        _ => invalid(
            spec.span(),
            "a medium needs exactly one of `index`, `cauchy` or `sellmeier`",
        ),
    }
}

/// The shape a `[[shapes]]` table gives: exactly one of its keys.
fn shape(table: &Spanned<ShapeTable>, media: &MediaTable) -> Result<Shape, Invalid> {
    let t = table.get_ref();
    let given: Vec<(&str, Range<usize>)> = [
        ("line", t.line.as_ref().map(Spanned::span)),
        ("segment", t.segment.as_ref().map(Spanned::span)),
        ("circle", t.circle.as_ref().map(Spanned::span)),
        ("polygon", t.polygon.as_ref().map(Spanned::span)),
        ("lens", t.lens.as_ref().map(Spanned::span)),
    ]
    .into_iter()
    .filter_map(|(name, span)| span.map(|s| (name, s)))
    .collect();
    // In the order of the file, so that the second one written is the one pointed at.
    let mut given = given;
    given.sort_by_key(|(_, span)| span.start);
    match given.as_slice() {
        [] => {
            return invalid(
                table.span(),
                "a [[shapes]] table needs one shape: `line`, `segment`, `circle`, `polygon` \
                 or `lens`",
            );
        }
        [(first, _), (second, span), ..] => {
            return invalid(
                span.clone(),
                format!(
                    "a [[shapes]] table holds one shape, this one has `{first}` and `{second}`: \
                     give each its own [[shapes]]"
                ),
            );
        }
        [_] => {}
    }
    match t {
        ShapeTable { line: Some(l), .. } => line(l.get_ref(), media),
        ShapeTable {
            segment: Some(s), ..
        } => segment(s.get_ref()),
        ShapeTable {
            circle: Some(c), ..
        } => circle(c.get_ref(), media),
        ShapeTable {
            polygon: Some(p), ..
        } => Ok(Shape::Polygon {
            points: polygon(p.get_ref())?,
            medium: media.find(&p.get_ref().medium)?,
        }),
        ShapeTable { lens: Some(l), .. } => lens(l.get_ref(), media),
        ShapeTable { .. } => unreachable!("one shape is given (matched above)"),
    }
}

fn line(spec: &LineSpec, media: &MediaTable) -> Result<Shape, Invalid> {
    Ok(Shape::Line {
        point: point(&spec.point, "a line's `point`")?,
        normal: direction(&spec.normal, "a line's `normal`")?,
        medium: media.find(&spec.medium)?,
    })
}

fn segment(spec: &SegmentSpec) -> Result<Shape, Invalid> {
    let from = point(&spec.from, "a segment's `from`")?;
    let to = point(&spec.to, "a segment's `to`")?;
    long_enough(from.distance(to), spec.to.span(), "a segment's length")?;
    Ok(Shape::Segment { from, to })
}

fn circle(spec: &CircleSpec, media: &MediaTable) -> Result<Shape, Invalid> {
    Ok(Shape::Circle {
        center: point(&spec.center, "a circle's `center`")?,
        radius: size(
            *spec.radius.get_ref(),
            spec.radius.span(),
            "a circle's `radius`",
        )?,
        medium: media.find(&spec.medium)?,
    })
}

fn lens(spec: &LensSpec, media: &MediaTable) -> Result<Shape, Invalid> {
    let [left, right] = spec.radii.get_ref().0;
    let thickness = *spec.thickness.get_ref();
    let lens = Lens {
        center: point(&spec.center, "a lens's `center`")?,
        thickness: size(thickness, spec.thickness.span(), "a lens's `thickness`")?,
        radii: [
            size(left, spec.radii.span(), "a lens's first radius")?,
            size(right, spec.radii.span(), "a lens's second radius")?,
        ],
    };
    if lens.thickness >= 2.0 * left.min(right) {
        return invalid(
            spec.thickness.span(),
            "a lens's `thickness` must be less than twice its smaller radius \
             (or its surfaces do not meet in a rim)",
        );
    }
    Ok(Shape::Lens {
        lens,
        medium: media.find(&spec.medium)?,
    })
}

/// The vertices, checked and turned counter-clockwise so that edge normals point outward:
/// at least 3, each within range and at least [`MIN_SIZE`] from the one before, enclosing an
/// area, and never crossing or touching itself (a crossing polygon would be filled by winding
/// and traced even-odd, and the two would disagree about its inside).
fn polygon(spec: &PolygonSpec) -> Result<Vec<DVec2>, Invalid> {
    let written = spec.points.get_ref();
    if written.len() < 3 {
        return invalid(spec.points.span(), "a polygon needs at least 3 points");
    }
    let mut points = written
        .iter()
        .enumerate()
        .map(|(i, p)| point(p, &format!("polygon point {}", i + 1)))
        .collect::<Result<Vec<_>, _>>()?;
    for (i, p) in points.iter().enumerate() {
        let before = points[(i + points.len() - 1) % points.len()];
        let what = format!(
            "the edge from polygon point {} to point {}",
            (i + points.len() - 1) % points.len() + 1,
            i + 1
        );
        long_enough(before.distance(*p), written[i].span(), &what)?;
    }
    let twice_area: f64 = points
        .iter()
        .zip(points.iter().cycle().skip(1))
        .map(|(a, b)| a.perp_dot(*b))
        .sum();
    if twice_area == 0.0 {
        return invalid(spec.points.span(), "a polygon must enclose a non-zero area");
    }
    let crossing = first_self_crossing(&points).map_err(|tests| Invalid {
        span: spec.points.span(),
        message: format!(
            "a polygon whose edges overlap this much cannot be checked for crossing itself \
             within {tests} tests: use fewer points"
        ),
    })?;
    if let Some((i, j)) = crossing {
        let n = points.len();
        return invalid(
            written[j].span(),
            format!(
                "a polygon must not cross or touch itself: its edge from point {} to point {} \
                 meets the edge from point {} to point {}",
                j + 1,
                (j + 1) % n + 1,
                i + 1,
                (i + 1) % n + 1
            ),
        );
    }
    if twice_area < 0.0 {
        points.reverse();
    }
    Ok(points)
}

/// Refuses a field given to a kind of source it does not apply to, at the field.
fn fields_fit_kind(s: &SourceSpec) -> Result<(), Invalid> {
    let misplaced = [
        (
            "rays",
            s.rays.as_ref().map(Spanned::span),
            s.kind == SourceKind::Ray,
            "a beam or a fan",
        ),
        (
            "width",
            s.width.as_ref().map(Spanned::span),
            s.kind != SourceKind::Beam,
            "a beam",
        ),
        (
            "spread_deg",
            s.spread_deg.as_ref().map(Spanned::span),
            s.kind != SourceKind::Fan,
            "a fan",
        ),
    ];
    for (field, span, wrong_kind, owner) in misplaced {
        if let (Some(span), true) = (span, wrong_kind) {
            return invalid(span, format!("`{field}` applies to {owner} only"));
        }
    }
    Ok(())
}

fn source_light(spec: &Spanned<SourceSpec>) -> Result<Light, Invalid> {
    let s = spec.get_ref();
    match (s.white, &s.wavelength_nm) {
        (true, Some(_)) => invalid(
            spec.span(),
            "give either `white = true` or `wavelength_nm`, not both",
        ),
        (true, None) => Ok(Light::White),
        (false, None) => Ok(Light::Wavelength(super::REFERENCE_WAVELENGTH_NM)),
        (false, Some(nm)) if WAVELENGTHS_NM.contains(nm.get_ref()) => {
            Ok(Light::Wavelength(*nm.get_ref()))
        }
        (false, Some(nm)) => invalid(
            nm.span(),
            format!(
                "`wavelength_nm` is {}: expected {} to {} nm",
                shown(*nm.get_ref()),
                WAVELENGTHS_NM.start(),
                WAVELENGTHS_NM.end()
            ),
        ),
    }
}

fn source(spec: &Spanned<SourceSpec>) -> Result<Source, Invalid> {
    let span = spec.span();
    let s = spec.get_ref();
    fields_fit_kind(s)?;
    let rays = match &s.rays {
        None if s.kind == SourceKind::Ray => 1,
        None => DEFAULT_RAYS,
        Some(r) if (1..=Source::MAX_RAYS).contains(r.get_ref()) => *r.get_ref(),
        Some(r) => {
            return invalid(
                r.span(),
                format!(
                    "`rays` is {}: expected 1 to {}",
                    r.get_ref(),
                    Source::MAX_RAYS
                ),
            );
        }
    };
    let width = match (s.kind, &s.width) {
        (SourceKind::Beam, None) => return invalid(span, "a beam needs a `width`"),
        (_, None) => 0.0,
        (_, Some(w)) => size(*w.get_ref(), w.span(), "`width`")?,
    };
    let spread_deg = match (s.kind, &s.spread_deg) {
        (SourceKind::Fan, None) => return invalid(span, "a fan needs a `spread_deg`"),
        (_, None) => 0.0,
        (_, Some(d)) if *d.get_ref() > 0.0 && *d.get_ref() <= 360.0 => *d.get_ref(),
        (_, Some(d)) => {
            return invalid(
                d.span(),
                format!(
                    "`spread_deg` is {}: expected 0 < angle ≤ 360",
                    shown(*d.get_ref())
                ),
            );
        }
    };
    Ok(Source {
        kind: s.kind,
        origin: point(&s.origin, "the source's `origin`")?,
        direction: direction(&s.direction, "the source's `direction`")?,
        rays,
        width,
        spread_deg,
        light: source_light(spec)?,
    })
}

fn effects(spec: &Spanned<EffectsSpec>) -> Result<Effects, Invalid> {
    let e = spec.get_ref();
    let default = Effects::default();
    let mut effects = Effects {
        partial_reflection: e.partial_reflection.unwrap_or(default.partial_reflection),
        fresnel: e.fresnel.unwrap_or(default.fresnel),
        dispersion: e.dispersion.unwrap_or(default.dispersion),
        absorption: e.absorption.unwrap_or(default.absorption),
        ..default
    };
    // Each limit checked on its own, so that the message points at its value.
    if let Some(depth) = &e.max_depth {
        effects.max_depth = *depth.get_ref();
        effects
            .check()
            .or_else(|m| invalid(depth.span(), m.to_string()))?;
    }
    if let Some(min) = &e.min_intensity {
        effects.min_intensity = *min.get_ref();
        effects
            .check()
            .or_else(|m| invalid(min.span(), m.to_string()))?;
    }
    Ok(effects)
}

fn view(spec: &ViewSpec) -> Result<Bounds, Invalid> {
    let min = point(&spec.min, "the view's `min`")?;
    let max = point(&spec.max, "the view's `max`")?;
    if !min.cmplt(max).all() {
        return invalid(
            spec.max.span(),
            "the view's `min` must be below and left of its `max`",
        );
    }
    long_enough(
        (max - min).min_element(),
        spec.max.span(),
        "the view's width or height",
    )?;
    Ok(Bounds { min, max })
}

/// The shapes, within [`MAX_SHAPES`] and [`MAX_POINTS`].
fn shapes(specs: &[Spanned<ShapeTable>], media: &MediaTable) -> Result<Vec<Shape>, Invalid> {
    if let Some(extra) = specs.get(MAX_SHAPES) {
        return invalid(
            extra.span(),
            format!("more than {MAX_SHAPES} shapes: a scene file has at most {MAX_SHAPES}"),
        );
    }
    // Counted before any is built, so that a huge file is refused before the work.
    let mut points = 0;
    for spec in specs {
        if let Some(p) = &spec.get_ref().polygon {
            points += p.get_ref().points.get_ref().len();
            if points > MAX_POINTS {
                return invalid(
                    p.get_ref().points.span(),
                    format!(
                        "more than {MAX_POINTS} polygon points: a scene file has at most \
                         {MAX_POINTS} over all its polygons"
                    ),
                );
            }
        }
    }
    specs.iter().map(|spec| shape(spec, media)).collect()
}

fn build(file: SceneFile, name: &str) -> Result<Scene, Invalid> {
    let media = MediaTable::build(&file.media)?;
    let background = match &file.background {
        Some(name) => media.find(name)?,
        // Vacuum is always defined: built in unless the file defines its own.
        None => media.position("vacuum").unwrap_or(0),
    };
    let shapes = shapes(&file.shapes, &media)?;
    let source = source(&file.source)?;
    media.check_indices(&source.wavelengths())?;
    let effects = file
        .effects
        .as_ref()
        .map_or_else(|| Ok(Effects::default()), effects)?;
    Ok(Scene {
        name: name.to_owned(),
        title: file.title,
        description: file.description,
        media: media.media,
        background,
        shapes,
        source,
        effects,
        view: file.view.as_ref().map(|v| view(v.get_ref())).transpose()?,
    })
}

impl Scene {
    /// Reads a scene from TOML text. `file` names it in errors; `name` is what
    /// [`Scene::name`] will return.
    ///
    /// # Errors
    /// A [`LoadError`] at the line and column of the first problem: malformed TOML, a missing
    /// or unknown field, a value of the wrong type, an unknown medium, a number out of range
    /// (see [`MAX_COORDINATE`], [`MIN_SIZE`]), too many shapes or points ([`MAX_SHAPES`],
    /// [`MAX_POINTS`]), or a polygon that crosses itself.
    pub fn from_toml(text: &str, file: &str, name: &str) -> Result<Self, LoadError> {
        let parsed: SceneFile = parse_toml(text, file)?;
        build(parsed, name).map_err(|e| LoadError::in_text(text, file, Some(e.span), e.message))
    }

    /// [`Self::from_toml`] of the bytes of a file, which must be UTF-8.
    ///
    /// # Errors
    /// Bytes that are not UTF-8 (at the line and column of the first bad byte), or any error
    /// of [`Self::from_toml`].
    pub fn from_bytes(bytes: &[u8], file: &str, name: &str) -> Result<Self, LoadError> {
        Self::from_toml(toml_text(bytes, file, "a scene file")?, file, name)
    }

    /// The scene built into the binary under `name` (see [`super::catalogue`]).
    ///
    /// # Errors
    /// No embedded scene has that name (the message lists them), or it fails to load.
    pub fn embedded(name: &str) -> Result<Self, LoadError> {
        let text = embedded::text(name).ok_or_else(|| LoadError {
            file: name.to_owned(),
            position: None,
            message: format!(
                "no built-in scene of that name: expected a file path or one of {}",
                embedded::names().join(", ")
            ),
        })?;
        Self::from_toml(text, &format!("{name} (built in)"), name)
    }

    /// An embedded scene by name, or else a scene file by path (at most
    /// [`crate::MAX_SCENE_FILE_BYTES`] long).
    ///
    /// # Errors
    /// The file cannot be read, is too long, or fails to load.
    pub fn load(name_or_path: &str) -> Result<Self, LoadError> {
        if embedded::text(name_or_path).is_some() {
            return Self::embedded(name_or_path);
        }
        let path = std::path::Path::new(name_or_path);
        let bytes = refraction_files::read_capped_bytes(path, MAX_SCENE_FILE_BYTES, "a scene file")
            .map_err(|e| LoadError {
                file: name_or_path.to_owned(),
                position: None,
                message: if e.kind() == std::io::ErrorKind::FileTooLarge {
                    format!("cannot read: {e}")
                } else {
                    format!(
                        "cannot read: {e} (expected a scene file or one of {})",
                        embedded::names().join(", ")
                    )
                },
            })?;
        let name = path.file_stem().map_or_else(
            || name_or_path.to_owned(),
            |s| s.to_string_lossy().into_owned(),
        );
        Self::from_bytes(&bytes, name_or_path, &name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const MINIMAL: &str = r#"
title = "t"
[source]
kind = "ray"
origin = [0, 0]
direction = [1, 0]
"#;

    fn error(text: &str) -> LoadError {
        Scene::from_toml(text, "x.toml", "x").unwrap_err()
    }

    #[test]
    fn the_ends_of_the_ranges_the_messages_give_are_taken() {
        // Issue 23: `index = 100` was refused while the message said "0.01 to 100".
        let edges = format!(
            "{MINIMAL}wavelength_nm = 2500\n[media.dense]\nindex = 100\n[media.thin]\nindex = 0.01\n"
        );
        Scene::from_toml(&edges, "x.toml", "x").unwrap_or_else(|e| panic!("{e}"));
    }

    #[test]
    fn a_minimal_file_loads_with_defaults() {
        let scene = Scene::from_toml(MINIMAL, "x.toml", "x").unwrap();
        assert_eq!(scene.media()[scene.background()].name, "vacuum");
        assert_eq!(*scene.effects(), Effects::default());
        assert_eq!(scene.source().rays, 1);
    }

    #[test]
    fn positions_count_lines_and_characters_from_one() {
        assert_eq!(
            Position::of("ab\ncdé f", 7),
            Position { line: 2, column: 4 }
        );
        assert_eq!(Position::of("", 10), Position { line: 1, column: 1 });
    }

    #[test]
    fn syntax_errors_name_file_line_and_column() {
        let e = error("title = \"t\"\n[source\n");
        assert_eq!(e.file, "x.toml");
        assert_eq!(e.position.map(|p| p.line), Some(2));
    }

    #[test]
    fn an_unknown_field_is_named_with_the_expected_ones() {
        let e = error(&format!("{MINIMAL}[effects]\nfresnell = true\n"));
        assert_eq!(e.position, Some(Position { line: 8, column: 1 }));
        assert!(
            e.message.contains("fresnell") && e.message.contains("fresnel"),
            "{e}"
        );
    }

    #[test]
    fn an_unknown_medium_points_at_its_name() {
        let e = error(&format!(
            "{MINIMAL}[[shapes]]\ncircle = {{ center = [0, 0], radius = 1, medium = \"glas\" }}\n"
        ));
        assert_eq!(e.position.map(|p| p.line), Some(8));
        assert!(
            e.message.contains("`glas`") && e.message.contains("vacuum"),
            "{e}"
        );
        assert!(e.to_string().starts_with("x.toml:8:"), "{e}");
    }

    #[test]
    fn bad_numbers_are_refused_where_they_stand() {
        for (extra, expected) in [
            ("[media.g]\nindex = nan\n", "index NaN"),
            (
                "[media.g]\nsellmeier = { b = [1.0], c = [0.36] }\n",
                "at 587.56 nm",
            ),
            (
                "[media.g]\nindex = 1.5\ncauchy = { a = 1.5, b = 0.004 }\n",
                "exactly one",
            ),
            (
                "[[shapes]]\ncircle = { center = [0, inf], radius = 1, medium = \"vacuum\" }\n",
                "finite",
            ),
            (
                "[[shapes]]\npolygon = { points = [[0, 0], [1, 1], [2, 2]], medium = \"vacuum\" }\n",
                "area",
            ),
            (
                "[[shapes]]\nlens = { center = [0, 0], thickness = 3, radii = [1, 5], medium = \"vacuum\" }\n",
                "twice",
            ),
            ("[effects]\nmax_depth = 100000\n", "max_depth"),
            ("[view]\nmin = [1, 1]\nmax = [0, 2]\n", "below and left"),
        ] {
            let e = error(&format!("{MINIMAL}{extra}"));
            assert!(e.position.is_some_and(|p| p.line >= 7), "{e}");
            assert!(e.message.contains(expected), "{extra}: {e}");
        }
    }

    #[test]
    fn source_fields_must_fit_its_kind() {
        let with = |body: &str| error(&format!("title = \"t\"\n[source]\n{body}"));
        assert!(
            with("kind = \"ray\"\norigin = [0, 0]\ndirection = [1, 0]\nwidth = 1\n")
                .message
                .contains("`width` applies to a beam only")
        );
        assert!(
            with("kind = \"fan\"\norigin = [0, 0]\ndirection = [1, 0]\n")
                .message
                .contains("spread_deg")
        );
        assert!(
            with("kind = \"ray\"\norigin = [0, 0]\ndirection = [0, 0]\n")
                .message
                .contains("[0, 0]")
        );
        assert!(
            with("kind = \"laser\"\norigin = [0, 0]\ndirection = [1, 0]\n")
                .message
                .contains("ray")
        );
        let e = with(
            "kind = \"ray\"\norigin = [0, 0]\ndirection = [1, 0]\nwhite = true\nwavelength_nm = 500\n",
        );
        assert_eq!(e.position, Some(Position { line: 2, column: 1 }), "{e}");
    }

    /// The error of `MINIMAL` plus `extra`, with the line and column it points at.
    fn error_at(extra: &str) -> (String, usize, usize) {
        let e = error(&format!("{MINIMAL}{extra}"));
        let p = e.position.unwrap_or_else(|| panic!("no position: {e}"));
        (e.message, p.line, p.column)
    }

    #[test]
    fn a_third_coordinate_is_refused_not_dropped() {
        let (message, line, column) = error_at(
            "[[shapes]]\ncircle = { center = [0, 0, 1], radius = 1, medium = \"vacuum\" }\n",
        );
        assert!(message.contains("two numbers [x, y], found 3"), "{message}");
        assert_eq!((line, column), (8, 21), "{message}");
        let (message, ..) = error_at("[view]\nmin = [0]\nmax = [1, 1]\n");
        assert!(message.contains("two numbers"), "{message}");
    }

    #[test]
    fn the_parsers_syntax_errors_are_worded_as_the_formats_own() {
        let (message, line, _) = error_at("[view]\nmin = [[0] [0]]\nmax = [1, 1]\n");
        assert!(
            message.contains("missing comma between the array's values"),
            "{message}"
        );
        assert!(!message.contains("element"), "{message}");
        assert_eq!(line, 8);
        assert_eq!(
            toml_words("invalid inline table element\n"),
            "invalid inline table entry"
        );
    }

    #[test]
    fn a_shape_table_must_hold_exactly_one_shape() {
        let (message, line, _) = error_at("[[shapes]]\n");
        assert!(
            message.contains("needs one shape: `line`, `segment`"),
            "{message}"
        );
        assert!(!message.contains("element"), "{message}");
        assert_eq!(line, 7);
        let (message, line, _) = error_at(
            "[[shapes]]\ncircle = { center = [0, 0], radius = 1, medium = \"vacuum\" }\n\
             segment = { from = [0, 0], to = [1, 0] }\n",
        );
        assert!(message.contains("`circle` and `segment`"), "{message}");
        assert_eq!(line, 9);
    }

    #[test]
    fn a_polygon_that_crosses_itself_is_refused_at_the_crossing_edge() {
        let (message, line, column) = error_at(
            "[[shapes]]\npolygon = { points = [[0, 0], [2, 2], [2, 0], [0, 1]], \
             medium = \"vacuum\" }\n",
        );
        assert!(
            message.contains("must not cross or touch itself"),
            "{message}"
        );
        assert!(message.contains("point 3 to point 4"), "{message}");
        assert_eq!((line, column), (8, 39), "{message}");
        let (message, ..) = error_at(
            "[[shapes]]\npolygon = { points = [[0, 0], [1, 0], [1, 0], [0, 1]], \
             medium = \"vacuum\" }\n",
        );
        assert!(
            message.contains("from polygon point 2 to point 3 is 0"),
            "{message}"
        );
    }

    #[test]
    fn range_errors_point_at_the_value_not_the_table() {
        // The value each error must point at: the last occurrence of the needle.
        for (extra, expected, needle) in [
            (
                "[[shapes]]\ncircle = { center = [0, 0], radius = -1, medium = \"vacuum\" }\n",
                "radius",
                "-1",
            ),
            (
                "[[shapes]]\nlens = { center = [0, 0], thickness = 3, radii = [1, 5], \
                 medium = \"vacuum\" }\n",
                "twice",
                "3, radii",
            ),
            (
                "[media.g]\nindex = 1\nabsorption = -1\n",
                "absorption",
                "-1",
            ),
            ("[media.g]\nindex = 1000\n", "index 1000", "1000"),
            ("[media.g]\nindex = 100.5\n", "index 100.5", "100.5"),
            (
                "[effects]\nfresnel = true\nmax_depth = 100000\n",
                "max_depth",
                "100000",
            ),
            ("[effects]\nmin_intensity = 2\n", "min_intensity", "2"),
        ] {
            let text = format!("{MINIMAL}{extra}");
            let e = error(&text);
            assert!(e.message.contains(expected), "{extra}: {e}");
            let at = Position::of(&text, text.rfind(needle).unwrap());
            assert_eq!(e.position, Some(at), "{extra}: {e}");
        }
        let source = |body: &str| {
            let e = error(&format!("title = \"t\"\n[source]\n{body}"));
            let p = e.position.unwrap();
            (e.message, p.line, p.column)
        };
        let beam = "kind = \"beam\"\norigin = [0, 0]\ndirection = [1, 0]\n";
        let (message, line, column) = source(&format!("{beam}width = 1\nrays = 0\n"));
        assert!(message.contains("`rays` is 0"), "{message}");
        assert_eq!((line, column), (7, 8));
        let (message, line, column) = source(&format!("{beam}width = 1e9\n"));
        assert!(message.contains("`width` is 1e9"), "{message}");
        assert_eq!((line, column), (6, 9));
        let (message, line, _) = source(&format!("{beam}width = 1\nwavelength_nm = 20\n"));
        assert!(message.contains("wavelength_nm"), "{message}");
        assert_eq!(line, 7);
    }

    #[test]
    fn numbers_whose_arithmetic_cannot_hold_are_refused_where_they_stand() {
        let circle = |center: &str, radius: &str| {
            format!(
                "[[shapes]]\ncircle = {{ center = {center}, radius = {radius}, medium = \
                 \"vacuum\" }}\n"
            )
        };
        for (extra, expected) in [
            (circle("[0, 0]", "1e200"), "a circle's `radius` is 1e200"),
            (circle("[0, 0]", "1e-300"), "expected a size from 1e-6"),
            (circle("[1e8, 1e8]", "1"), "within ±100000"),
            (
                "[[shapes]]\nlens = { center = [0, 0], thickness = 0.5, radii = [1e200, 1], \
                 medium = \"vacuum\" }\n"
                    .to_owned(),
                "first radius is 1e200",
            ),
            (
                "[[shapes]]\npolygon = { points = [[-1e200, -1e200], [1e200, -1e200], \
                 [0, 1e200]], medium = \"vacuum\" }\n"
                    .to_owned(),
                "polygon point 1 is [-1e200, -1e200]",
            ),
            (
                "[view]\nmin = [0, 0]\nmax = [1e-9, 1]\n".to_owned(),
                "width or height",
            ),
        ] {
            let (message, line, _) = error_at(&extra);
            assert!(message.contains(expected), "{extra}: {message}");
            assert!(line >= 7, "{extra}: {message}");
        }
        let far = "title = \"t\"\n[source]\nkind = \"ray\"\norigin = [-1.7e308, 0]\n\
                   direction = [1, 0]\n";
        let e = error(far);
        assert!(e.message.contains("within ±100000"), "{e}");
        assert_eq!(
            e.position,
            Some(Position {
                line: 4,
                column: 10
            })
        );
        let huge_direction = MINIMAL.replace("direction = [1, 0]", "direction = [1e300, 1e300]");
        let scene = Scene::from_toml(&huge_direction, "x.toml", "x").unwrap();
        let d = scene.source().direction;
        assert!((d.length() - 1.0).abs() < 1e-15 && d.x > 0.7, "{d}");
    }

    #[test]
    fn text_that_is_not_utf8_is_refused_with_its_line_and_column() {
        let mut bytes = MINIMAL.as_bytes().to_vec();
        bytes.extend_from_slice(b"# caf\xe9\n");
        let e = Scene::from_bytes(&bytes, "x.toml", "x").unwrap_err();
        assert_eq!(e.position, Some(Position { line: 7, column: 6 }), "{e}");
        assert!(e.to_string().starts_with("x.toml:7:6: not UTF-8"), "{e}");
    }

    #[test]
    fn too_many_shapes_or_points_are_refused_at_the_first_one_too_many() {
        let media = MediaTable::build(&BTreeMap::new()).unwrap_or_else(|e| panic!("{}", e.message));
        let tables: Vec<Spanned<ShapeTable>> = (0..=MAX_SHAPES)
            .map(|i| Spanned::new(i..i + 1, ShapeTable::default()))
            .collect();
        let e = shapes(&tables, &media).unwrap_err();
        assert_eq!(e.span, MAX_SHAPES..MAX_SHAPES + 1);
        assert!(e.message.contains("more than 500 shapes"), "{}", e.message);
        let polygon = |n: usize, at: usize| {
            let points = (0..n)
                .map(|_| Spanned::new(0..0, crate::Numbers([0.0, 0.0])))
                .collect();
            Spanned::new(
                at..at,
                ShapeTable {
                    polygon: Some(Spanned::new(
                        at..at,
                        PolygonSpec {
                            points: Spanned::new(at..at + 1, points),
                            medium: Spanned::new(0..0, "vacuum".to_owned()),
                        },
                    )),
                    ..ShapeTable::default()
                },
            )
        };
        let many = [polygon(MAX_POINTS / 2, 1), polygon(MAX_POINTS / 2 + 1, 2)];
        let e = shapes(&many, &media).unwrap_err();
        assert_eq!(e.span, 2..3);
        assert!(
            e.message.contains("more than 2000 polygon points"),
            "{}",
            e.message
        );
    }

    /// Issue 23: the limits were out of reach of a 1 MiB file (1,000,000 points, 100,000
    /// shapes); a file at each limit fits and loads.
    #[test]
    fn a_file_at_each_limit_fits_under_the_size_cap_and_loads() {
        use core::fmt::Write as _;
        let mut points = String::from(MINIMAL);
        points.push_str("[media.g]\nindex = 1.5\n");
        let per = MAX_POINTS / 5;
        for k in 0..5 {
            let corners: Vec<String> = (0..per)
                .map(|i| {
                    let a = core::f64::consts::TAU * i as f64 / per as f64;
                    let x = 300.0 * f64::from(k) + 100.0 * a.cos();
                    format!("[{x:.2},{:.2}]", 100.0 * a.sin())
                })
                .collect();
            let _ = writeln!(
                points,
                "[[shapes]]\npolygon = {{ points = [{}], medium = \"g\" }}",
                corners.join(",")
            );
        }
        let mut circles = format!("{MINIMAL}[media.g]\nindex = 1.5\n");
        for k in 0..MAX_SHAPES {
            let (x, y) = (k % 100, k / 100);
            let _ = writeln!(
                circles,
                "[[shapes]]\ncircle = {{ center = [{x}, {y}], radius = 0.25, medium = \"g\" }}"
            );
        }
        for text in [points, circles] {
            assert!(
                text.len() as u64 <= MAX_SCENE_FILE_BYTES,
                "{} bytes",
                text.len()
            );
            Scene::from_toml(&text, "x.toml", "x").unwrap_or_else(|e| panic!("{e}"));
        }
    }

    #[test]
    fn a_missing_file_names_the_path() {
        let e = Scene::load("/nonexistent/scene.toml").unwrap_err();
        assert!(
            e.to_string()
                .starts_with("/nonexistent/scene.toml: cannot read"),
            "{e}"
        );
    }
}
