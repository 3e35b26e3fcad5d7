//! The JSON the `trace` command prints: the scene's shapes and bounds, each path's points with
//! its medium, wavelength and intensities, every hit, and the counts of what was computed.

use glam::DVec2;
use serde::Serialize;

use super::source::serialize_wavelength;
use super::{Bounds, Counts, Effects, End, Hit, Light, Outline, Scene, Trace};

/// One path as the report shows it: points rather than segments, media by name.
#[derive(Debug, Serialize)]
pub struct PathReport<'a> {
    /// The wavelength traced in nm, or `null` for white light traced once.
    #[serde(rename = "wavelength_nm", serialize_with = "serialize_wavelength")]
    pub light: Light,
    /// The hit it was reflected off (position in `hits`), or `null` for a source ray.
    pub parent_hit: Option<usize>,
    /// Partial reflections between it and the source.
    pub reflections: u32,
    /// Why it ends.
    pub end: End,
    /// Its start, then the end of each segment.
    pub points: Vec<DVec2>,
    /// The medium of each segment.
    pub media: Vec<&'a str>,
    /// The intensity at the start of each segment, when intensities are traced.
    pub intensities: Option<Vec<f64>>,
}

/// A medium as the report shows it.
#[derive(Debug, Serialize)]
pub struct MediumReport<'a> {
    /// Its name.
    pub name: &'a str,
    /// Its index at the reference wavelength.
    pub index_d: f64,
}

/// The whole report of one trace.
#[derive(Debug, Serialize)]
pub struct TraceReport<'a> {
    /// The scene's name.
    pub scene: &'a str,
    /// Its title.
    pub title: &'a str,
    /// The effects traced.
    pub effects: &'a Effects,
    /// The world rectangle.
    pub bounds: Bounds,
    /// The media; hits refer to them by position.
    pub media: Vec<MediumReport<'a>>,
    /// The shapes' outlines in world coordinates.
    pub outlines: Vec<Outline>,
    /// The paths.
    pub paths: Vec<PathReport<'a>>,
    /// Every kernel call.
    pub hits: &'a [Hit],
    /// What was computed.
    pub counts: Counts,
}

impl<'a> TraceReport<'a> {
    /// The report of `trace`, a trace of `scene`.
    #[must_use]
    pub fn new(scene: &'a Scene, trace: &'a Trace) -> Self {
        let paths = trace
            .paths
            .iter()
            .map(|path| {
                let segments = &trace.segments[path.segments.clone()];
                PathReport {
                    light: path.light,
                    parent_hit: path.parent_hit,
                    reflections: path.reflections,
                    end: path.end,
                    points: trace.points(path),
                    media: segments
                        .iter()
                        .map(|s| scene.media()[s.medium].name.as_str())
                        .collect(),
                    intensities: segments.iter().map(|s| s.intensity).collect(),
                }
            })
            .collect();
        Self {
            scene: scene.name(),
            title: scene.title(),
            effects: scene.effects(),
            bounds: trace.bounds,
            media: scene
                .media()
                .iter()
                .map(|m| MediumReport {
                    name: &m.name,
                    index_d: m.index(super::REFERENCE_WAVELENGTH_NM),
                })
                .collect(),
            outlines: scene.outlines(),
            paths,
            hits: &trace.hits,
            counts: trace.counts,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_hit_says_entering_or_leaving_as_a_log_does() {
        let scene = Scene::embedded("droplet").unwrap();
        let trace = scene.trace();
        let json = serde_json::to_value(TraceReport::new(&scene, &trace)).unwrap();
        let sides: Vec<&str> = json["hits"]
            .as_array()
            .unwrap()
            .iter()
            .map(|hit| hit["side"].as_str().unwrap())
            .collect();
        assert!(
            sides.contains(&"entering") && sides.contains(&"leaving"),
            "{sides:?}"
        );
        assert!(sides.iter().all(|s| ["entering", "leaving"].contains(s)));
    }
}
