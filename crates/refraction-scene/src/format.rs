//! The scene file format (TOML, described in the repository README): the serde structures as
//! written, and their checked conversion into a [`Scene`]. Every error names the file, the line
//! and column, and what was expected.

use std::collections::BTreeMap;
use std::ops::Range;

use glam::DVec2;
use serde::{Deserialize, Serialize};
use toml::Spanned;

use super::bounds::Bounds;
use super::effects::Effects;
use super::medium::{Dispersion, Medium};
use super::shape::{Lens, Shape};
use super::source::{Light, Source, SourceKind};
use super::{Scene, embedded};

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
#[error("{file}{}: {message}", place(.position))]
pub struct LoadError {
    /// The file's path, or the embedded scene's name.
    pub file: String,
    /// Where in the file, when the error is about its contents.
    pub position: Option<Position>,
    /// What is wrong and what was expected.
    pub message: String,
}

/// A position as it follows the file's name in a message: `:line:column`, or nothing.
fn place(position: &Option<Position>) -> String {
    position.map_or_else(String::new, |Position { line, column }| {
        format!(":{line}:{column}")
    })
}

/// A problem at a place in the file: a byte range and a message.
struct Invalid {
    span: Range<usize>,
    message: String,
}

fn invalid<T>(span: Range<usize>, message: impl Into<String>) -> Result<T, Invalid> {
    Err(Invalid {
        span,
        message: message.into(),
    })
}

/// A scene file as written: read with spans for the error messages, and written back by
/// [`Scene::to_toml`](super::write) with empty ones.
#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SceneFile {
    pub(super) title: String,
    #[serde(default)]
    pub(super) description: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) background: Option<Spanned<String>>,
    #[serde(default)]
    pub(super) media: BTreeMap<String, Spanned<MediumSpec>>,
    #[serde(default)]
    pub(super) shapes: Vec<Spanned<ShapeSpec>>,
    pub(super) source: Spanned<SourceSpec>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) effects: Option<Spanned<Effects>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) view: Option<Spanned<ViewSpec>>,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct MediumSpec {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) index: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) cauchy: Option<CauchySpec>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) sellmeier: Option<SellmeierSpec>,
    #[serde(default)]
    pub(super) absorption: f64,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct CauchySpec {
    pub(super) a: f64,
    pub(super) b: f64,
    #[serde(default)]
    pub(super) c: f64,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SellmeierSpec {
    pub(super) b: Vec<f64>,
    pub(super) c: Vec<f64>,
}

#[derive(Deserialize, Serialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub(super) enum ShapeSpec {
    Line {
        point: [f64; 2],
        normal: [f64; 2],
        medium: Spanned<String>,
    },
    Segment {
        from: [f64; 2],
        to: [f64; 2],
    },
    Circle {
        center: [f64; 2],
        radius: f64,
        medium: Spanned<String>,
    },
    Polygon {
        points: Vec<[f64; 2]>,
        medium: Spanned<String>,
    },
    Lens {
        center: [f64; 2],
        thickness: f64,
        radii: [f64; 2],
        medium: Spanned<String>,
    },
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SourceSpec {
    pub(super) kind: SourceKind,
    pub(super) origin: [f64; 2],
    pub(super) direction: [f64; 2],
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) rays: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) width: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) spread_deg: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) wavelength_nm: Option<f64>,
    #[serde(default)]
    pub(super) white: bool,
}

#[derive(Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub(super) struct ViewSpec {
    pub(super) min: [f64; 2],
    pub(super) max: [f64; 2],
}

/// The range of vacuum wavelengths a source may have, in nm.
const WAVELENGTHS_NM: Range<f64> = 200.0..2500.0;

/// The range of indices of refraction a medium may have at the traced wavelengths.
const INDICES: Range<f64> = 0.01..100.0;

/// The default ray count of a beam or fan.
const DEFAULT_RAYS: usize = 9;

fn vector(v: [f64; 2], what: &str, span: &Range<usize>) -> Result<DVec2, Invalid> {
    let v = DVec2::from(v);
    if v.is_finite() {
        Ok(v)
    } else {
        invalid(span.clone(), format!("{what} must be two finite numbers"))
    }
}

/// `v` as a unit direction. A vector already unit to rounding is kept as written, so that a
/// scene written back ([`Scene::to_toml`]) reads back bit for bit.
fn direction(v: [f64; 2], what: &str, span: &Range<usize>) -> Result<DVec2, Invalid> {
    let v = vector(v, what, span)?;
    if (v.length_squared() - 1.0).abs() <= 4.0 * f64::EPSILON {
        return Ok(v);
    }
    v.try_normalize().map_or_else(
        || invalid(span.clone(), format!("{what} must not be [0, 0]")),
        Ok,
    )
}

fn positive(x: f64, what: &str, span: &Range<usize>) -> Result<f64, Invalid> {
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        invalid(
            span.clone(),
            format!("{what} is {x}: expected a finite number > 0"),
        )
    }
}

/// The media by name, with their position in the scene's list.
struct MediaTable {
    media: Vec<Medium>,
}

impl MediaTable {
    fn build(specs: &BTreeMap<String, Spanned<MediumSpec>>) -> Result<Self, Invalid> {
        let mut media = Vec::with_capacity(specs.len() + 1);
        if !specs.contains_key("vacuum") {
            media.push(Medium::vacuum());
        }
        for (name, spec) in specs {
            let absorption = spec.get_ref().absorption;
            if !(absorption.is_finite() && absorption >= 0.0) {
                return invalid(
                    spec.span(),
                    format!(
                        "medium `{name}`: absorption is {absorption}: expected a finite number ≥ 0"
                    ),
                );
            }
            media.push(Medium {
                name: name.clone(),
                dispersion: dispersion(spec)?,
                absorption,
            });
        }
        Ok(Self { media })
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
    fn check_indices(
        &self,
        specs: &BTreeMap<String, Spanned<MediumSpec>>,
        wavelengths: &[f64],
    ) -> Result<(), Invalid> {
        for medium in &self.media {
            for &nm in wavelengths {
                let n = medium.index(nm);
                if !INDICES.contains(&n) {
                    let span = specs.get(&medium.name).map_or(0..0, Spanned::span);
                    return invalid(
                        span,
                        format!(
                            "medium `{}` has index {n} at {nm} nm: expected a number from {} to \
                             {} (check its coefficients and units: λ in µm)",
                            medium.name, INDICES.start, INDICES.end
                        ),
                    );
                }
            }
        }
        Ok(())
    }
}

fn dispersion(spec: &Spanned<MediumSpec>) -> Result<Dispersion, Invalid> {
    let span = spec.span();
    let m = spec.get_ref();
    let all_finite = |xs: &[f64]| xs.iter().all(|x| x.is_finite());
    match (m.index, &m.cauchy, &m.sellmeier) {
        (Some(n), None, None) => Ok(Dispersion::Constant(n)),
        (None, Some(c), None) if all_finite(&[c.a, c.b, c.c]) => Ok(Dispersion::Cauchy {
            a: c.a,
            b: c.b,
            c: c.c,
        }),
        (None, None, Some(s))
            if s.b.len() == s.c.len()
                && !s.b.is_empty()
                && all_finite(&s.b)
                && all_finite(&s.c) =>
        {
            Ok(Dispersion::Sellmeier {
                b: s.b.clone(),
                c: s.c.clone(),
            })
        }
        (None, Some(_), None) => invalid(span, "cauchy coefficients must be finite numbers"),
        (None, None, Some(_)) => invalid(
            span,
            "sellmeier needs `b` and `c` lists of the same non-zero length, of finite numbers",
        ),
        _ => invalid(
            span,
            "a medium needs exactly one of `index`, `cauchy` or `sellmeier`",
        ),
    }
}

fn shape(spec: &Spanned<ShapeSpec>, media: &MediaTable) -> Result<Shape, Invalid> {
    let span = spec.span();
    Ok(match spec.get_ref() {
        ShapeSpec::Line {
            point,
            normal,
            medium,
        } => Shape::Line {
            point: vector(*point, "a line's `point`", &span)?,
            normal: direction(*normal, "a line's `normal`", &span)?,
            medium: media.find(medium)?,
        },
        ShapeSpec::Segment { from, to } => {
            let (from, to) = (
                vector(*from, "a segment's `from`", &span)?,
                vector(*to, "a segment's `to`", &span)?,
            );
            if from == to {
                return invalid(span, "a segment's `from` and `to` must differ");
            }
            Shape::Segment { from, to }
        }
        ShapeSpec::Circle {
            center,
            radius,
            medium,
        } => Shape::Circle {
            center: vector(*center, "a circle's `center`", &span)?,
            radius: positive(*radius, "a circle's `radius`", &span)?,
            medium: media.find(medium)?,
        },
        ShapeSpec::Polygon { points, medium } => Shape::Polygon {
            points: polygon(points, &span)?,
            medium: media.find(medium)?,
        },
        ShapeSpec::Lens {
            center,
            thickness,
            radii,
            medium,
        } => {
            let lens = Lens {
                center: vector(*center, "a lens's `center`", &span)?,
                thickness: positive(*thickness, "a lens's `thickness`", &span)?,
                radii: [
                    positive(radii[0], "a lens's first radius", &span)?,
                    positive(radii[1], "a lens's second radius", &span)?,
                ],
            };
            if lens.thickness >= 2.0 * radii[0].min(radii[1]) {
                return invalid(
                    span,
                    "a lens's `thickness` must be less than twice its smaller radius \
                     (or its surfaces do not meet in a rim)",
                );
            }
            Shape::Lens {
                lens,
                medium: media.find(medium)?,
            }
        }
    })
}

/// The vertices, checked and turned counter-clockwise so that edge normals point outward.
fn polygon(points: &[[f64; 2]], span: &Range<usize>) -> Result<Vec<DVec2>, Invalid> {
    if points.len() < 3 {
        return invalid(span.clone(), "a polygon needs at least 3 points");
    }
    let mut points = points
        .iter()
        .map(|&p| vector(p, "every polygon point", span))
        .collect::<Result<Vec<_>, _>>()?;
    let twice_area: f64 = points
        .iter()
        .zip(points.iter().cycle().skip(1))
        .map(|(a, b)| a.perp_dot(*b))
        .sum();
    if !(twice_area.is_finite() && twice_area != 0.0) {
        return invalid(span.clone(), "a polygon must enclose a non-zero area");
    }
    if twice_area < 0.0 {
        points.reverse();
    }
    Ok(points)
}

fn source(spec: &Spanned<SourceSpec>) -> Result<Source, Invalid> {
    let span = spec.span();
    let s = spec.get_ref();
    let misplaced = [
        (
            "rays",
            s.rays.is_some() && s.kind == SourceKind::Ray,
            "a beam or a fan",
        ),
        (
            "width",
            s.width.is_some() && s.kind != SourceKind::Beam,
            "a beam",
        ),
        (
            "spread_deg",
            s.spread_deg.is_some() && s.kind != SourceKind::Fan,
            "a fan",
        ),
    ];
    if let Some((field, _, owner)) = misplaced.iter().find(|m| m.1) {
        return invalid(span, format!("`{field}` applies to {owner} only"));
    }
    let rays = s.rays.unwrap_or(if s.kind == SourceKind::Ray {
        1
    } else {
        DEFAULT_RAYS
    });
    if !(1..=Source::MAX_RAYS).contains(&rays) {
        return invalid(
            span,
            format!("`rays` is {rays}: expected 1 to {}", Source::MAX_RAYS),
        );
    }
    let width = match (s.kind, s.width) {
        (SourceKind::Beam, None) => return invalid(span, "a beam needs a `width`"),
        (_, width) => width.map_or(Ok(0.0), |w| positive(w, "`width`", &span))?,
    };
    let spread_deg = match (s.kind, s.spread_deg) {
        (SourceKind::Fan, None) => return invalid(span, "a fan needs a `spread_deg`"),
        (_, Some(d)) if !(d.is_finite() && d > 0.0 && d <= 360.0) => {
            return invalid(
                span,
                format!("`spread_deg` is {d}: expected 0 < angle ≤ 360"),
            );
        }
        (_, spread) => spread.unwrap_or(0.0),
    };
    let light = match (s.white, s.wavelength_nm) {
        (true, Some(_)) => {
            return invalid(
                span,
                "give either `white = true` or `wavelength_nm`, not both",
            );
        }
        (true, None) => Light::White,
        (false, None) => Light::Wavelength(super::REFERENCE_WAVELENGTH_NM),
        (false, Some(nm)) if WAVELENGTHS_NM.contains(&nm) => Light::Wavelength(nm),
        (false, Some(nm)) => {
            return invalid(
                span,
                format!(
                    "`wavelength_nm` is {nm}: expected {} to {} nm",
                    WAVELENGTHS_NM.start, WAVELENGTHS_NM.end
                ),
            );
        }
    };
    Ok(Source {
        kind: s.kind,
        origin: vector(s.origin, "the source's `origin`", &span)?,
        direction: direction(s.direction, "the source's `direction`", &span)?,
        rays,
        width,
        spread_deg,
        light,
    })
}

fn view(spec: &Spanned<ViewSpec>) -> Result<Bounds, Invalid> {
    let span = spec.span();
    let min = vector(spec.get_ref().min, "the view's `min`", &span)?;
    let max = vector(spec.get_ref().max, "the view's `max`", &span)?;
    if min.cmplt(max).all() {
        Ok(Bounds { min, max })
    } else {
        invalid(span, "the view's `min` must be below and left of its `max`")
    }
}

fn build(file: SceneFile, name: &str) -> Result<Scene, Invalid> {
    let media = MediaTable::build(&file.media)?;
    let background = match &file.background {
        Some(name) => media.find(name)?,
        // Vacuum is always defined: built in unless the file defines its own.
        None => media.position("vacuum").unwrap_or(0),
    };
    let shapes = file
        .shapes
        .iter()
        .map(|s| shape(s, &media))
        .collect::<Result<Vec<_>, _>>()?;
    let source = source(&file.source)?;
    media.check_indices(&file.media, &source.wavelengths())?;
    let effects = match &file.effects {
        Some(effects) => {
            let e = *effects.get_ref();
            if let Err(message) = e.check() {
                return invalid(effects.span(), message.to_string());
            }
            e
        }
        None => Effects::default(),
    };
    Ok(Scene {
        name: name.to_owned(),
        title: file.title,
        description: file.description,
        media: media.media,
        background,
        shapes,
        source,
        effects,
        view: file.view.as_ref().map(view).transpose()?,
    })
}

impl Scene {
    /// Reads a scene from TOML text. `file` names it in errors; `name` is what
    /// [`Scene::name`] will return.
    ///
    /// # Errors
    /// A [`LoadError`] at the line and column of the first problem: malformed TOML, a missing
    /// or unknown field, a value of the wrong type, an unknown medium, or a number out of range.
    pub fn from_toml(text: &str, file: &str, name: &str) -> Result<Self, LoadError> {
        let fail = |span: Option<Range<usize>>, message: String| LoadError {
            file: file.to_owned(),
            position: span.map(|s| Position::of(text, s.start)),
            message,
        };
        let parsed: SceneFile =
            toml::from_str(text).map_err(|e| fail(e.span(), e.message().trim_end().to_owned()))?;
        build(parsed, name).map_err(|e| fail(Some(e.span), e.message))
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

    /// An embedded scene by name, or else a scene file by path.
    ///
    /// # Errors
    /// The file cannot be read or fails to load.
    pub fn load(name_or_path: &str) -> Result<Self, LoadError> {
        if embedded::text(name_or_path).is_some() {
            return Self::embedded(name_or_path);
        }
        let path = std::path::Path::new(name_or_path);
        let text = std::fs::read_to_string(path).map_err(|e| LoadError {
            file: name_or_path.to_owned(),
            position: None,
            message: format!(
                "cannot read: {e} (expected a scene file or one of {})",
                embedded::names().join(", ")
            ),
        })?;
        let name = path.file_stem().map_or_else(
            || name_or_path.to_owned(),
            |s| s.to_string_lossy().into_owned(),
        );
        Self::from_toml(&text, name_or_path, &name)
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
