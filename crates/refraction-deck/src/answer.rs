//! What a step with a question hides until the teacher reveals it: on the one-interface view
//! the diagram leaves out T and everything that gives it away (the diagram's overlay does
//! that); in a scene, the rays past the first surface they meet.

use refraction_scene::{Path, Trace};

/// `trace` up to the first surface: each source ray's first segment and the hit that ends it,
/// no reflected ray. The counts stay those of the whole trace: the diagram's picture that asks
/// the question (`ScenePicture::asking`) words only the source's rays and colours, since the
/// others (reflections, total internal reflections, kernel calls) tell the answer.
#[must_use]
pub fn up_to_first_surface(trace: &Trace) -> Trace {
    let mut segments = Vec::new();
    let mut paths = Vec::new();
    let mut hits = Vec::new();
    for (index, path) in trace.paths.iter().enumerate() {
        if path.parent_hit.is_some() {
            continue;
        }
        let Some(mut first) = trace
            .segments
            .get(path.segments.clone())
            .and_then(<[_]>::first)
            .copied()
        else {
            continue;
        };
        let kept = paths.len();
        first.path = kept;
        segments.push(first);
        if let Some(hit) = trace.hits.iter().find(|h| h.path == index) {
            let mut hit = *hit;
            hit.path = kept;
            hits.push(hit);
        }
        paths.push(Path {
            segments: segments.len() - 1..segments.len(),
            ..path.clone()
        });
    }
    Trace {
        bounds: trace.bounds,
        segments,
        paths,
        hits,
        counts: trace.counts,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use refraction_scene::Scene;

    #[test]
    fn a_droplet_shows_its_rays_up_to_the_drop_and_no_further() {
        let scene = Scene::embedded("droplet").unwrap();
        let whole = scene.trace();
        let hidden = up_to_first_surface(&whole);
        let sources = whole
            .paths
            .iter()
            .filter(|p| p.parent_hit.is_none())
            .count();
        assert_eq!(hidden.paths.len(), sources);
        assert_eq!(hidden.segments.len(), sources, "one segment per source ray");
        assert!(hidden.hits.len() <= sources && !hidden.hits.is_empty());
        assert!(hidden.hits.len() < whole.hits.len());
        for (segment, path) in hidden.segments.iter().zip(&hidden.paths) {
            assert_eq!(hidden.segments[path.segments.clone()][0], *segment);
        }
        for hit in &hidden.hits {
            assert_eq!(
                hidden.segments[hit.path].to, hit.point,
                "the hit ends its ray"
            );
        }
    }
}
