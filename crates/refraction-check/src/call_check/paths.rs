//! `--paths`: consecutive lines with the same `path` are one ray's hits, in order. After each
//! path one summary line says which hit is the first wrong call and whether the ray leaves in
//! the right direction: the direction the right calls give, retraced from the ray that met the
//! first hit. The retrace goes through the sphere the hits lie on when every hit logs its
//! `point` and they fit one sphere, and otherwise through the logged surfaces themselves (exact
//! for flat faces, such as a slab's or a prism's). On a closed object two wrong calls can
//! cancel: the ray goes the wrong way inside and still leaves right, and the summary says so.

use glam::DVec3;
use refraction_kernel::{Convention, Incidence, refract};
use serde::Serialize;

use super::call::Call;
use super::error::LineError;
use super::verdict::CallVerdict;
use crate::diagnosis::Code;
use refraction_tools::MATCH_ANGLE;
use refraction_tools::vector_text::{angle, short, short_vector, unit};

/// Hits kept per path for the sphere retrace; longer paths are retraced through their surfaces.
const MAX_KEPT: usize = 4096;

/// How far (relative to the radius) logged points may be from one sphere.
const SPHERE_FIT: f64 = 1e-4;

/// The summary line of one path.
#[derive(Serialize)]
struct Summary<'a> {
    path: &'a str,
    hits: usize,
    first_wrong: Option<usize>,
    exit_ok: bool,
    explanation: &'a str,
}

/// One hit as the retrace needs it.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Hit {
    point: Option<DVec3>,
    normal: DVec3,
    mu: f64,
}

/// The path being read.
#[derive(Clone, Debug, PartialEq)]
struct Path {
    id: String,
    hits: usize,
    wrong: Vec<(usize, Vec<Code>)>,
    /// The right direction retraced through the logged surfaces so far.
    through_surfaces: DVec3,
    /// The ray that met the first hit, and every hit (for the sphere), up to [`MAX_KEPT`].
    start: DVec3,
    kept: Vec<Hit>,
    /// Where the student's code sent the ray at the last hit.
    outgoing: DVec3,
}

/// The right direction after refracting `d` at a surface with normal `n` (either side, any
/// length) and μ: the transmitted ray, or the reflection on total internal reflection; `d`
/// itself for a μ the kernel refuses. The lenient `refract`, not the fast `transmit`: a logged
/// eta may be any finite number > 0, beyond the ratios `transmit` accepts.
fn right_step(d: DVec3, n: DVec3, mu: f64) -> DVec3 {
    let incidence = Incidence {
        w: d,
        n,
        mu_i: mu,
        mu_t: 1.0,
        convention: Convention::AlongRay,
    };
    refract(&incidence).map_or(d, |r| r.t().unwrap_or(r.reflected))
}

/// The sphere all hits lie on with their normals along the radius, if there is one: the centre
/// from the first hit and the first hit whose normal is not parallel to its.
fn sphere(hits: &[Hit]) -> Option<(DVec3, f64)> {
    let first = hits.first()?;
    let p1 = first.point?;
    let n1 = unit(first.normal);
    let other = hits
        .iter()
        .find(|h| unit(h.normal).cross(n1).length() > 1e-6)?;
    let (p2, n2) = (other.point?, unit(other.normal));
    // Closest points of the lines p1 + s·n1 and p2 + t·n2.
    let (w, b) = (p1 - p2, n1.dot(n2));
    let denominator = 1.0 - b * b;
    let s = (b * n2.dot(w) - n1.dot(w)) / denominator;
    let t = (n2.dot(w) - b * n1.dot(w)) / denominator;
    let centre = (p1 + n1 * s + p2 + n2 * t) * 0.5;
    let radius = (p1 - centre).length();
    let fits = |h: &Hit| {
        h.point.is_some_and(|p| {
            let r = p - centre;
            (r.length() - radius).abs() <= SPHERE_FIT * radius
                && unit(r).cross(unit(h.normal)).length() <= SPHERE_FIT.sqrt()
        })
    };
    (radius > 0.0 && radius.is_finite() && hits.iter().all(fits)).then_some((centre, radius))
}

/// The right exit direction through the sphere, from the first hit's point: the right ray
/// meets the sphere again where the geometry says, not where the student's ray did.
fn through_sphere(start: DVec3, hits: &[Hit], centre: DVec3, radius: f64) -> DVec3 {
    let mut point = hits[0].point.unwrap_or(centre);
    let mut d = start;
    for (k, hit) in hits.iter().enumerate() {
        d = right_step(d, point - centre, hit.mu);
        let along = -2.0 * (point - centre).dot(d) / d.length_squared();
        if k + 1 == hits.len() || along <= 1e-9 * radius {
            break;
        }
        point += d * along;
    }
    d
}

impl Path {
    fn new(id: String, call: &Call, verdict: &CallVerdict) -> Self {
        let start = unit(verdict.right.travel);
        Self {
            id,
            hits: 0,
            wrong: Vec::new(),
            through_surfaces: start,
            start,
            kept: Vec::new(),
            outgoing: verdict.outgoing,
        }
        .with(call, verdict)
    }

    fn with(mut self, call: &Call, verdict: &CallVerdict) -> Self {
        self.hits += 1;
        if !verdict.ok && self.wrong.len() < MAX_KEPT {
            self.wrong.push((self.hits, verdict.mistakes.clone()));
        }
        let hit = Hit {
            point: call.point,
            normal: verdict.right.normal,
            mu: verdict.right.mu,
        };
        // Where the logged ray still is the right one, the retrace takes it up: rounding in
        // the logged numbers then cannot pile up over a long path, and a ray already sent wrong
        // (much farther off than that) is still followed on its own.
        let incoming = unit(verdict.right.travel);
        if angle(incoming, self.through_surfaces) <= MATCH_ANGLE / 4.0 {
            self.through_surfaces = incoming;
        }
        self.through_surfaces = right_step(self.through_surfaces, hit.normal, hit.mu);
        if self.kept.len() < MAX_KEPT {
            self.kept.push(hit);
        } else {
            self.kept.clear();
        }
        self.outgoing = verdict.outgoing;
        self
    }

    /// The summary line, and whether the ray leaves right.
    fn summary(&self) -> (String, bool) {
        let sphere = (self.kept.len() == self.hits)
            .then(|| sphere(&self.kept))
            .flatten();
        let (right, how) = match sphere {
            Some((centre, radius)) => (
                through_sphere(self.start, &self.kept, centre, radius),
                format!(
                    "retraced through the sphere the hits lie on (centre {}, radius {})",
                    short_vector(centre.to_array()),
                    short(radius)
                ),
            ),
            None => (
                self.through_surfaces,
                "retraced through the logged surfaces".to_owned(),
            ),
        };
        let off = angle(self.outgoing, right);
        let exit_ok = self.outgoing.is_finite() && off <= MATCH_ANGLE;
        let explanation = self.explanation(exit_ok, off, &how);
        let line = Summary {
            path: &self.id,
            hits: self.hits,
            first_wrong: self.wrong.first().map(|w| w.0),
            exit_ok,
            explanation: &explanation,
        };
        (refraction_tools::json_line(&line), exit_ok)
    }

    fn explanation(&self, exit_ok: bool, off: f64, how: &str) -> String {
        let hits: Vec<String> = self.wrong.iter().map(|(k, _)| k.to_string()).collect();
        let named = |(k, codes): &(usize, Vec<Code>)| {
            let codes: Vec<&str> = codes.iter().map(|c| c.name()).collect();
            format!(
                "hit {k}: {}",
                if codes.is_empty() {
                    "unexplained".to_owned()
                } else {
                    codes.join(", ")
                }
            )
        };
        let first = self.wrong.first().map(named).unwrap_or_default();
        match (self.wrong.len(), exit_ok) {
            (0, true) => format!(
                "All {} calls are right and the ray leaves in the right direction ({how}).",
                self.hits
            ),
            (0, false) => format!(
                "Every call is right, yet the ray leaves {} degrees from the right direction \
                 ({how}): these lines are not one ray's path in order (a hit missing?).",
                short(off.to_degrees())
            ),
            (1, true) => format!(
                "Hit {} is wrong ({first}), yet the ray leaves in the right direction ({how}): \
                 on this closed object the wrong way inside comes out right, so a picture can \
                 hide the bug.",
                hits[0]
            ),
            (_, true) => format!(
                "Hits {} are wrong, yet the ray leaves in the right direction ({how}): the wrong \
                 calls cancel on this closed object after the ray went the wrong way inside, so a \
                 picture can hide the bugs; fix {first}.",
                hits.join(", ")
            ),
            (_, false) => format!(
                "The first wrong call is {first}; the ray leaves {} degrees from the right \
                 direction ({how}).",
                short(off.to_degrees())
            ),
        }
    }
}

/// The paths of one run.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Paths {
    current: Option<Path>,
    /// Whether every path finished so far left in the right direction.
    pub all_exit_ok: bool,
}

impl Paths {
    /// No path read yet.
    #[must_use]
    pub(crate) fn new() -> Self {
        Self {
            current: None,
            all_exit_ok: true,
        }
    }

    /// Adds one judged hit; returns the summary of the path it ends, if it starts a new one.
    ///
    /// # Errors
    /// The hit has no `path`.
    pub(crate) fn hit(
        &mut self,
        call: &Call,
        verdict: &CallVerdict,
    ) -> Result<Option<String>, LineError> {
        let id = call.path.clone().ok_or(LineError::NoPath)?;
        let (current, ended) = match self.current.take() {
            Some(path) if path.id == id => (path.with(call, verdict), None),
            previous => (Path::new(id, call, verdict), previous),
        };
        self.current = Some(current);
        Ok(ended.map(|path| self.close(&path)))
    }

    fn close(&mut self, path: &Path) -> String {
        let (line, exit_ok) = path.summary();
        self.all_exit_ok &= exit_ok;
        line
    }

    /// The summary of the last path, at the end of the input.
    pub(crate) fn finish(&mut self) -> Option<String> {
        let path = self.current.take()?;
        Some(self.close(&path))
    }
}
