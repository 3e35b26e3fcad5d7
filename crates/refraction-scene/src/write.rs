//! A scene written back as a scene file (TOML), so that a scene edited in the explorer (its
//! source moved, its shapes dragged) can be saved and opened again. It fills in the reader's own
//! file structures (with empty spans), so reading what this writes gives back an equal scene.

use toml::Spanned;

use super::spec::{
    CauchySpec, CircleSpec, EffectsSpec, LensSpec, LineSpec, MediumSpec, Numbers, Pair,
    PolygonSpec, SceneFile, SegmentSpec, SellmeierSpec, ShapeTable, SourceSpec, ViewSpec,
};
use super::{Dispersion, Effects, Light, Medium, Scene, Shape, SourceKind};
use glam::DVec2;

/// A value with no place in a file: written values carry no span.
fn unplaced<T>(value: T) -> Spanned<T> {
    Spanned::new(0..0, value)
}

fn pair(v: DVec2) -> Spanned<Pair> {
    unplaced(Numbers(v.to_array()))
}

fn medium_spec(medium: &Medium) -> MediumSpec {
    let (index, cauchy, sellmeier) = match &medium.dispersion {
        Dispersion::Constant(n) => (Some(unplaced(*n)), None, None),
        Dispersion::Cauchy { a, b, c } => (
            None,
            Some(unplaced(CauchySpec {
                a: *a,
                b: *b,
                c: *c,
            })),
            None,
        ),
        Dispersion::Sellmeier { b, c } => (
            None,
            None,
            Some(unplaced(SellmeierSpec {
                b: b.clone(),
                c: c.clone(),
            })),
        ),
    };
    MediumSpec {
        index,
        cauchy,
        sellmeier,
        absorption: Some(unplaced(medium.absorption)),
    }
}

/// Every effect written out, so that the file says what is traced.
fn effects_spec(e: &Effects) -> EffectsSpec {
    EffectsSpec {
        partial_reflection: Some(e.partial_reflection),
        fresnel: Some(e.fresnel),
        dispersion: Some(e.dispersion),
        absorption: Some(e.absorption),
        max_depth: Some(unplaced(e.max_depth)),
        min_intensity: Some(unplaced(e.min_intensity)),
    }
}

impl Scene {
    fn medium_name(&self, medium: usize) -> Spanned<String> {
        unplaced(
            self.media
                .get(medium)
                .map_or("vacuum", |m| m.name.as_str())
                .to_owned(),
        )
    }

    fn shape_spec(&self, shape: &Shape) -> ShapeTable {
        match shape {
            Shape::Line {
                point,
                normal,
                medium,
            } => ShapeTable {
                line: Some(unplaced(LineSpec {
                    point: pair(*point),
                    normal: pair(*normal),
                    medium: self.medium_name(*medium),
                })),
                ..ShapeTable::default()
            },
            Shape::Segment { from, to } => ShapeTable {
                segment: Some(unplaced(SegmentSpec {
                    from: pair(*from),
                    to: pair(*to),
                })),
                ..ShapeTable::default()
            },
            Shape::Circle {
                center,
                radius,
                medium,
            } => ShapeTable {
                circle: Some(unplaced(CircleSpec {
                    center: pair(*center),
                    radius: unplaced(*radius),
                    medium: self.medium_name(*medium),
                })),
                ..ShapeTable::default()
            },
            Shape::Polygon { points, medium } => ShapeTable {
                polygon: Some(unplaced(PolygonSpec {
                    points: unplaced(points.iter().map(|p| pair(*p)).collect()),
                    medium: self.medium_name(*medium),
                })),
                ..ShapeTable::default()
            },
            Shape::Lens { lens, medium } => ShapeTable {
                lens: Some(unplaced(LensSpec {
                    center: pair(lens.center),
                    thickness: unplaced(lens.thickness),
                    radii: unplaced(Numbers(lens.radii)),
                    medium: self.medium_name(*medium),
                })),
                ..ShapeTable::default()
            },
        }
    }

    fn source_spec(&self) -> SourceSpec {
        let s = &self.source;
        SourceSpec {
            kind: s.kind,
            origin: pair(s.origin),
            direction: pair(s.direction),
            rays: (s.kind != SourceKind::Ray).then(|| unplaced(s.rays)),
            width: (s.kind == SourceKind::Beam).then(|| unplaced(s.width)),
            spread_deg: (s.kind == SourceKind::Fan).then(|| unplaced(s.spread_deg)),
            wavelength_nm: match s.light {
                Light::Wavelength(nm) => Some(unplaced(nm)),
                Light::White => None,
            },
            white: s.light == Light::White,
        }
    }

    /// The scene as a scene file (TOML) that [`Scene::from_toml`] reads back as an equal scene.
    ///
    /// # Errors
    /// The TOML writer refused a value (it accepts every scene that loaded).
    pub fn to_toml(&self) -> Result<String, WriteError> {
        // The built-in vacuum comes first when a file defines none: leave it implicit so that
        // the media keep their order when read back.
        let implicit_vacuum = self.media.first().is_some_and(|m| *m == Medium::vacuum());
        let media = self
            .media
            .iter()
            .skip(usize::from(implicit_vacuum))
            .map(|m| (m.name.clone(), unplaced(medium_spec(m))))
            .collect();
        let file = SceneFile {
            title: self.title.clone(),
            description: self.description.clone(),
            background: Some(self.medium_name(self.background)),
            media,
            shapes: self
                .shapes
                .iter()
                .map(|s| unplaced(self.shape_spec(s)))
                .collect(),
            source: unplaced(self.source_spec()),
            effects: Some(unplaced(effects_spec(&self.effects))),
            view: self.view.map(|v| {
                unplaced(ViewSpec {
                    min: pair(v.min),
                    max: pair(v.max),
                })
            }),
        };
        toml::to_string(&file).map_err(WriteError)
    }
}

/// The TOML writer refused a scene ([`Scene::to_toml`]); it accepts every scene that loaded.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("cannot write the scene as TOML: {0}")]
pub struct WriteError(toml::ser::Error);

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    #[test]
    fn every_built_in_scene_reads_back_equal_even_after_edits() {
        for info in crate::catalogue() {
            let mut scene = Scene::embedded(info.name).unwrap();
            let text = scene.to_toml().unwrap();
            let back = Scene::from_toml(&text, "written", info.name)
                .unwrap_or_else(|e| panic!("{}: {e}\n{text}", info.name));
            assert_eq!(back, scene, "{}", info.name);
            scene.set_source_origin(DVec2::new(0.125, -0.5)).unwrap();
            scene.move_shape(0, DVec2::new(0.25, 0.0)).unwrap();
            let edited = Scene::from_toml(&scene.to_toml().unwrap(), "edited", info.name).unwrap();
            assert_eq!(edited, scene, "{} after edits", info.name);
        }
    }
}
