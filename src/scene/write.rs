//! A scene written back as a scene file (TOML), so that a scene edited in the explorer (its
//! source moved, its shapes dragged) can be saved and opened again. The inverse of
//! [`Scene::from_toml`]: reading what this writes gives back an equal scene.

use std::collections::BTreeMap;

use serde::Serialize;

use super::{Dispersion, Effects, Light, Medium, Scene, Shape, SourceKind};

#[derive(Serialize)]
struct FileOut<'a> {
    title: &'a str,
    description: &'a str,
    background: &'a str,
    media: BTreeMap<&'a str, MediumOut<'a>>,
    shapes: Vec<ShapeOut<'a>>,
    source: SourceOut,
    effects: Effects,
    #[serde(skip_serializing_if = "Option::is_none")]
    view: Option<ViewOut>,
}

#[derive(Serialize)]
struct MediumOut<'a> {
    #[serde(skip_serializing_if = "Option::is_none")]
    index: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    cauchy: Option<CauchyOut>,
    #[serde(skip_serializing_if = "Option::is_none")]
    sellmeier: Option<SellmeierOut<'a>>,
    absorption: f64,
}

#[derive(Serialize)]
struct CauchyOut {
    a: f64,
    b: f64,
    c: f64,
}

#[derive(Serialize)]
struct SellmeierOut<'a> {
    b: &'a [f64],
    c: &'a [f64],
}

#[derive(Serialize)]
#[serde(rename_all = "snake_case")]
enum ShapeOut<'a> {
    Line {
        point: [f64; 2],
        normal: [f64; 2],
        medium: &'a str,
    },
    Segment {
        from: [f64; 2],
        to: [f64; 2],
    },
    Circle {
        center: [f64; 2],
        radius: f64,
        medium: &'a str,
    },
    Polygon {
        points: Vec<[f64; 2]>,
        medium: &'a str,
    },
    Lens {
        center: [f64; 2],
        thickness: f64,
        radii: [f64; 2],
        medium: &'a str,
    },
}

#[derive(Serialize)]
struct SourceOut {
    kind: SourceKind,
    origin: [f64; 2],
    direction: [f64; 2],
    #[serde(skip_serializing_if = "Option::is_none")]
    rays: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    width: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    spread_deg: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    wavelength_nm: Option<f64>,
    white: bool,
}

#[derive(Serialize)]
struct ViewOut {
    min: [f64; 2],
    max: [f64; 2],
}

fn medium_out(medium: &Medium) -> MediumOut<'_> {
    let (index, cauchy, sellmeier) = match &medium.dispersion {
        Dispersion::Constant(n) => (Some(*n), None, None),
        Dispersion::Cauchy { a, b, c } => (
            None,
            Some(CauchyOut {
                a: *a,
                b: *b,
                c: *c,
            }),
            None,
        ),
        Dispersion::Sellmeier { b, c } => (None, None, Some(SellmeierOut { b, c })),
    };
    MediumOut {
        index,
        cauchy,
        sellmeier,
        absorption: medium.absorption,
    }
}

impl Scene {
    /// The scene as a scene file (TOML) that [`Scene::from_toml`] reads back as an equal scene.
    ///
    /// # Errors
    /// The TOML writer refused a value (it accepts every scene that loaded).
    pub fn to_toml(&self) -> Result<String, String> {
        let name = |m: usize| self.media.get(m).map_or("vacuum", |m| m.name.as_str());
        // The built-in vacuum comes first when a file defines none: leave it implicit so that
        // the media keep their order when read back.
        let implicit_vacuum = self.media.first().filter(|m| **m == Medium::vacuum());
        let media = self
            .media
            .iter()
            .filter(|m| !implicit_vacuum.is_some_and(|v| std::ptr::eq(*m, v)))
            .map(|m| (m.name.as_str(), medium_out(m)))
            .collect();
        let shapes = self
            .shapes
            .iter()
            .map(|shape| match shape {
                Shape::Line {
                    point,
                    normal,
                    medium,
                } => ShapeOut::Line {
                    point: point.to_array(),
                    normal: normal.to_array(),
                    medium: name(*medium),
                },
                Shape::Segment { from, to } => ShapeOut::Segment {
                    from: from.to_array(),
                    to: to.to_array(),
                },
                Shape::Circle {
                    center,
                    radius,
                    medium,
                } => ShapeOut::Circle {
                    center: center.to_array(),
                    radius: *radius,
                    medium: name(*medium),
                },
                Shape::Polygon { points, medium } => ShapeOut::Polygon {
                    points: points.iter().map(|p| p.to_array()).collect(),
                    medium: name(*medium),
                },
                Shape::Lens { lens, medium } => ShapeOut::Lens {
                    center: lens.center.to_array(),
                    thickness: lens.thickness,
                    radii: lens.radii,
                    medium: name(*medium),
                },
            })
            .collect();
        let s = &self.source;
        let source = SourceOut {
            kind: s.kind,
            origin: s.origin.to_array(),
            direction: s.direction.to_array(),
            rays: (s.kind != SourceKind::Ray).then_some(s.rays),
            width: (s.kind == SourceKind::Beam).then_some(s.width),
            spread_deg: (s.kind == SourceKind::Fan).then_some(s.spread_deg),
            wavelength_nm: match s.light {
                Light::Wavelength(nm) => Some(nm),
                Light::White => None,
            },
            white: s.light == Light::White,
        };
        let file = FileOut {
            title: &self.title,
            description: &self.description,
            background: name(self.background),
            media,
            shapes,
            source,
            effects: self.effects,
            view: self.view.map(|v| ViewOut {
                min: v.min.to_array(),
                max: v.max.to_array(),
            }),
        };
        toml::to_string(&file).map_err(|e| format!("cannot write the scene as TOML: {e}"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec2;

    #[test]
    fn every_built_in_scene_reads_back_equal_even_after_edits() {
        for info in crate::scene::catalogue() {
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
