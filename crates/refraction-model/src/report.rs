//! What the `bench` command measured: accuracy against time for every kernel variant, as its
//! table prints it and the accuracy plot draws it. The measurement itself lives in the bench
//! crate; the figures live here, below both the measurement and the drawing.

use serde::Serialize;

/// One line of the report: a variant at a precision.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Row {
    /// The variant's name.
    pub variant: &'static str,
    /// `"f32"` or `"f64"`.
    pub precision: &'static str,
    /// Median time per ray in the in-cache set, in nanoseconds.
    pub ns_per_ray: f64,
    /// 1e9 / `ns_per_ray`.
    pub rays_per_second: f64,
    /// Largest angular error (radians) on the random set.
    pub max_err_random: f64,
    /// Median angular error (radians) on the random set.
    pub median_err_random: f64,
    /// Largest angular error (radians) on the hard set.
    pub max_err_hard: f64,
    /// Median angular error (radians) on the hard set.
    pub median_err_hard: f64,
    /// Largest hard-set error as a multiple of ε·κ.
    pub max_err_hard_eps_kappa: f64,
    /// Total internal reflection decisions that disagree with the oracle, both sets.
    pub tir_mismatches: usize,
}

/// Everything a run measured.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Report {
    /// One row per variant and precision.
    pub rows: Vec<Row>,
    /// Problems in the random set.
    pub rays: usize,
    /// Problems in the hard set.
    pub hard_rays: usize,
    /// The streaming figure (f32 batch against the memory limit).
    pub streaming: Streaming,
    /// The processor the figures were measured on.
    pub cpu: String,
}

impl Report {
    /// The fastest row whose hard-set error is within 10× of the best: the one the verdict
    /// names. `None` for a report without rows.
    #[must_use]
    pub fn fastest_accurate(&self) -> Option<&Row> {
        let best = self
            .rows
            .iter()
            .map(|r| r.max_err_hard_eps_kappa)
            .fold(f64::INFINITY, f64::min);
        self.rows
            .iter()
            .filter(|r| r.max_err_hard_eps_kappa <= 10.0 * best)
            .min_by(|a, b| a.ns_per_ray.total_cmp(&b.ns_per_ray))
    }

    /// The fastest variant whose largest hard-set error is within 10× of the most accurate
    /// one's, as a sentence.
    #[must_use]
    pub fn verdict(&self) -> String {
        self.fastest_accurate().map_or_else(String::new, |r| {
            format!(
                "Fastest within 10x of the best accuracy: {} {} at {:.2} ns per ray \
                     (hard-set error {:.1} eps*kappa).",
                r.variant, r.precision, r.ns_per_ray, r.max_err_hard_eps_kappa
            )
        })
    }

    /// The report as an aligned text table with the streaming figure and the verdict below.
    #[must_use]
    pub fn table(&self) -> String {
        let mut text = format!(
            "{:<11} {:<4} {:>8} {:>11} {:>10} {:>10} {:>10} {:>10} {:>11} {:>5}\n",
            "variant",
            "prec",
            "ns/ray",
            "rays/s",
            "max rand",
            "med rand",
            "max hard",
            "med hard",
            "hard eps*k",
            "TIR!"
        );
        for r in &self.rows {
            text.push_str(&format!(
                "{:<11} {:<4} {:>8.2} {:>11.3e} {:>10.2e} {:>10.2e} {:>10.2e} {:>10.2e} {:>11.1} {:>5}\n",
                r.variant,
                r.precision,
                r.ns_per_ray,
                r.rays_per_second,
                r.max_err_random,
                r.median_err_random,
                r.max_err_hard,
                r.median_err_hard,
                r.max_err_hard_eps_kappa,
                r.tir_mismatches
            ));
        }
        let s = &self.streaming;
        text.push_str(&format!(
            "\nstreaming {} rays (f32): batch {:.2} ns/ray, memory limit {:.2} ns/ray ({:.2}x)\n",
            s.rays,
            s.batch_ns_per_ray,
            s.memory_limit_ns_per_ray,
            s.batch_ns_per_ray / s.memory_limit_ns_per_ray
        ));
        text.push_str(&format!(
            "{} random and {} hard problems on {}\n{}\n",
            self.rays,
            self.hard_rays,
            self.cpu,
            self.verdict()
        ));
        text
    }
}

/// What streaming many more rays than fit in cache costs.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Streaming {
    /// Rays per pass.
    pub rays: usize,
    /// The batch kernel's time per ray, f32.
    pub batch_ns_per_ray: f64,
    /// The time per ray of reading the same W, N, μ and writing T and the TIR flag with no
    /// refraction arithmetic: the memory limit.
    pub memory_limit_ns_per_ray: f64,
}
