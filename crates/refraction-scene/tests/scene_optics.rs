//! Analytic checks of the built-in scenes: each hit is one kernel call, and the paths it makes
//! agree with the textbook formulas for a slab, a prism, a droplet and a lens.

use glam::DVec2;
use refraction_kernel::refract;
use refraction_scene::{Hit, Outcome, Path, Scene, Side, Trace, traced_wavelength};

fn scene(name: &str) -> Scene {
    Scene::embedded(name).unwrap_or_else(|e| panic!("{e}"))
}

fn direction(trace: &Trace, path: &Path, which: usize) -> DVec2 {
    let s = &trace.segments[path.segments.clone()][which];
    (s.to - s.from).normalize()
}

fn last_direction(trace: &Trace, path: &Path) -> DVec2 {
    direction(trace, path, path.segments.len() - 1)
}

/// The angle between two unit vectors in degrees.
fn degrees_between(a: DVec2, b: DVec2) -> f64 {
    a.dot(b).clamp(-1.0, 1.0).acos().to_degrees()
}

#[test]
fn a_slab_shifts_the_ray_sideways_but_not_its_direction() {
    let slab = scene("slab");
    let trace = slab.trace();
    let glass = slab
        .media()
        .iter()
        .position(|m| m.name == "tinted-bk7")
        .unwrap();
    let sources: Vec<_> = trace
        .paths
        .iter()
        .filter(|p| p.parent_hit.is_none())
        .collect();
    assert_eq!(sources.len(), 5);
    for path in sources {
        let segments = &trace.segments[path.segments.clone()];
        assert_eq!(segments.len(), 3, "enter, cross, leave");
        let d_in = direction(&trace, path, 0);
        let d_out = last_direction(&trace, path);
        assert!((d_in - d_out).length() < 1e-12, "{d_in} vs {d_out}");
        let wavelength = traced_wavelength(path.light);
        let n_air = slab.media()[slab.background()].index(wavelength);
        let n_glass = slab.media()[glass].index(wavelength);
        // The faces are x = ±1 (thickness 2), normals ±x.
        let (thickness, cos_i) = (2.0, d_in.x.abs());
        let theta_i = cos_i.acos();
        let theta_t = (n_air / n_glass * theta_i.sin()).asin();
        let expected = thickness * (theta_i - theta_t).sin() / theta_t.cos();
        let entry = segments[0].from;
        let shift = (segments[2].from - entry).perp_dot(d_in).abs();
        assert!((shift - expected).abs() < 1e-12, "{shift} vs {expected}");
    }
}

#[test]
fn the_right_angle_prism_reflects_totally_where_the_critical_angle_says() {
    let mut prism = scene("right-angle-prism");
    let trace = prism.trace();
    assert_eq!(trace.counts.total_internal_reflections, 5);
    let (mut tir, mut through) = (0, 0);
    for degrees in -60..=60 {
        let angle = f64::from(degrees).to_radians() / 2.0;
        prism
            .set_source_direction(DVec2::from_angle(angle))
            .unwrap();
        for hit in prism.trace().hits.iter().filter(|h| h.side == Side::Inside) {
            let sin_i = hit.w.perp_dot(hit.n).abs();
            let critical_sin = hit.mu_t / hit.mu_i;
            if (sin_i - critical_sin).abs() < 1e-9 {
                continue;
            }
            let expect_tir = sin_i > critical_sin;
            assert_eq!(
                hit.outcome == Outcome::TotalInternalReflection,
                expect_tir,
                "{hit:?}"
            );
            if expect_tir {
                tir += 1;
            } else {
                through += 1;
            }
        }
    }
    assert!(tir > 100 && through > 100, "{tir} TIR, {through} through");
}

/// The primary rainbow's deviation at minimum: 180° + 2θi − 4θt with cos²θi = (n² − 1)/3.
fn rainbow_deviation(n: f64) -> f64 {
    let cos_i = ((n * n - 1.0) / 3.0).sqrt();
    let theta_i = cos_i.acos();
    let theta_t = (theta_i.sin() / n).asin();
    (180.0_f64.to_radians() + 2.0 * theta_i - 4.0 * theta_t).to_degrees()
}

#[test]
fn the_droplet_reaches_the_primary_rainbow_angle_for_each_wavelength() {
    assert!((rainbow_deviation(1.331) - 137.6).abs() < 0.1);
    let mut droplet = scene("droplet");
    droplet.set_ray_count(2000).unwrap();
    let mut effects = *droplet.effects();
    effects.min_intensity = 0.0;
    droplet.set_effects(effects).unwrap();
    let trace = droplet.trace();
    let water = droplet
        .media()
        .iter()
        .position(|m| m.name == "water")
        .unwrap();
    assert_eq!(trace.counts.wavelengths, 7);
    let mut minima = std::collections::BTreeMap::<u64, f64>::new();
    for path in &trace.paths {
        // Reflected once inside, off the back of the drop, by a ray straight from the source;
        // then out through the front.
        let Some(parent) = path.parent_hit.map(|h| &trace.hits[h]) else {
            continue;
        };
        let parent_path = &trace.paths[parent.path];
        if path.reflections != 1
            || parent.side != Side::Inside
            || parent_path.parent_hit.is_some()
            || path.segments.len() != 2
        {
            continue;
        }
        let deviation = degrees_between(DVec2::X, last_direction(&trace, path));
        let key = traced_wavelength(path.light).to_bits();
        let min = minima.entry(key).or_insert(f64::INFINITY);
        *min = min.min(deviation);
    }
    assert_eq!(minima.len(), 7);
    for (bits, deviation) in minima {
        let wavelength = f64::from_bits(bits);
        let n = droplet.media()[water].index(wavelength)
            / droplet.media()[droplet.background()].index(wavelength);
        let expected = rainbow_deviation(n);
        assert!(
            (deviation - expected).abs() < 0.2,
            "{wavelength} nm: {deviation}° vs {expected}°"
        );
    }
}

#[test]
fn leaving_the_droplet_the_outward_normal_is_turned_by_the_kernel() {
    let trace = scene("droplet").trace();
    let leaving: Vec<&Hit> = trace
        .hits
        .iter()
        .filter(|h| h.side == Side::Inside)
        .collect();
    assert!(!leaving.is_empty());
    for hit in leaving {
        assert!(hit.w.dot(hit.n) > 0.0);
        let r = refract(&hit.incidence()).unwrap();
        assert!(r.normal_flipped);
    }
}

#[test]
fn every_hit_conserves_energy() {
    for name in ["droplet", "slab"] {
        let trace = scene(name).trace();
        assert!(!trace.hits.is_empty());
        for hit in &trace.hits {
            let f = hit.fresnel.unwrap();
            assert!((f.rs + f.ts - 1.0).abs() <= 4.0 * f64::EPSILON, "{f:?}");
            assert!((f.rp + f.tp - 1.0).abs() <= 4.0 * f64::EPSILON, "{f:?}");
            if hit.outcome == Outcome::TotalInternalReflection {
                assert_eq!((f.rs, f.rp), (1.0, 1.0));
            }
        }
    }
}

#[test]
fn each_hit_is_the_kernel_answer_for_its_own_w_n_and_indices() {
    for name in ["droplet", "lens", "dispersing-prism", "fibre"] {
        let trace = scene(name).trace();
        for (i, hit) in trace.hits.iter().enumerate() {
            assert_ne!(hit.mu_i, hit.mu_t);
            let kernel = refract(&hit.incidence()).unwrap();
            let path = &trace.paths[hit.path];
            // The segment that starts at this hit on the same path goes the kernel's way.
            let next = trace.segments[path.segments.clone()]
                .iter()
                .find(|s| s.from == hit.point)
                .unwrap_or_else(|| panic!("{name}: hit {i} has no continuation"));
            let expected = kernel.t().unwrap_or(kernel.reflected).truncate();
            let actual = (next.to - next.from).normalize();
            assert!((actual - expected).length() < 1e-9, "{name} hit {i}");
        }
    }
}

#[test]
fn the_lens_brings_paraxial_rays_to_the_lensmakers_focus() {
    let mut lens = scene("lens");
    lens.set_ray_count(1).unwrap();
    lens.set_source_origin(DVec2::new(-3.0, 3e-3)).unwrap();
    let trace = lens.trace();
    assert_eq!(trace.counts.kernel_calls, 2);
    let glass = lens.media().iter().position(|m| m.name == "bk7").unwrap();
    let wavelength = traced_wavelength(trace.paths[0].light);
    let n =
        lens.media()[glass].index(wavelength) / lens.media()[lens.background()].index(wavelength);
    // Lensmaker's equation for a thick lens, R1 = 4, R2 = −4, d = 1; back vertex at x = 0.5.
    let (r, d) = (4.0, 1.0);
    let power = (n - 1.0) * (2.0 / r - (n - 1.0) * d / (n * r * r));
    let back_focus = 0.5 + (1.0 - (n - 1.0) * d / (n * r)) / power;
    let exit = &trace.segments[2];
    let d_out = (exit.to - exit.from).normalize();
    let crossing = exit.from.x - exit.from.y * d_out.x / d_out.y;
    assert!(
        (crossing - back_focus).abs() < 1e-4,
        "{crossing} vs {back_focus}"
    );
}
