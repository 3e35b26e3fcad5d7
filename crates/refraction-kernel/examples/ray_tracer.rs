//! A ray through a glass ball, refracted as a ray tracer refracts it: with
//! `refraction_kernel::transmit` and the ball's outward normal both where the ray enters and
//! where it leaves (there the normal points along the ray, and the kernel turns it), and a ray
//! from a source inside the glass that total internal reflection keeps in.
//!
//! Run with `cargo run -p refraction-kernel --example ray_tracer`.
#![expect(clippy::print_stdout, reason = "an example prints what it computed")]

use glam::Vec3;

const N_AIR: f32 = 1.0;
const N_GLASS: f32 = 1.5;

/// A glass ball in air.
struct Ball {
    centre: Vec3,
    radius: f32,
}

impl Ball {
    /// How far along the unit direction `d` from `origin` the ray next crosses the surface;
    /// crossings closer than 1e-4 are skipped, so that a ray starting on the surface does not
    /// find its own starting point again.
    fn hit(&self, origin: Vec3, d: Vec3) -> Option<f32> {
        let oc = origin - self.centre;
        let half_b = oc.dot(d);
        let discriminant = half_b * half_b - (oc.length_squared() - self.radius * self.radius);
        let root = discriminant.sqrt(); // NaN when the ray misses: no root passes the test below
        [-half_b - root, -half_b + root]
            .into_iter()
            .find(|&t| t > 1e-4)
    }

    /// The outward unit normal at a point on the surface, on whichever side the ray is.
    fn normal(&self, p: Vec3) -> Vec3 {
        (p - self.centre) / self.radius
    }

    /// What a tracer's dielectric material does where the ray travelling along `d` meets the
    /// surface at `p`: the transmitted direction, or `None` on total internal reflection.
    fn refract(&self, p: Vec3, d: Vec3, inside: bool) -> Option<Vec3> {
        let n = self.normal(p); // outward, also where the ray leaves: transmit turns it
        let mu = if inside {
            N_GLASS / N_AIR
        } else {
            N_AIR / N_GLASS
        }; // n_from / n_to
        refraction_kernel::transmit(d, n, mu) // None: total internal reflection
    }
}

/// Refracts at `p` and prints what was computed: the normal's side, the angles, Snell's law.
fn step(label: &str, ball: &Ball, p: Vec3, d: Vec3, inside: bool) -> Option<Vec3> {
    let n = ball.normal(p);
    let (n_from, n_to) = if inside {
        (N_GLASS, N_AIR)
    } else {
        (N_AIR, N_GLASS)
    };
    let side = if d.dot(n) < 0.0 {
        "faces the ray"
    } else {
        "points along the ray: turned"
    };
    let theta_i = d.dot(n).abs().acos();
    println!(
        "{label} at {p:.4}: outward normal {n:.4}, d·n = {:+.4} ({side})",
        d.dot(n)
    );
    println!("  d  = {d:.4}, θi = {:.2}°", theta_i.to_degrees());
    let t = ball.refract(p, d, inside);
    if let Some(t) = t {
        let theta_t = t.dot(n).abs().acos();
        println!(
            "  T  = {t:.4}, θt = {:.2}°, |T| = {:.7}",
            theta_t.to_degrees(),
            t.length()
        );
        println!(
            "  Snell: n_from·sinθi = {:.6}, n_to·sinθt = {:.6}",
            n_from * theta_i.sin(),
            n_to * theta_t.sin()
        );
    } else {
        let reflected = d - n * (2.0 * d.dot(n));
        let critical = (n_to / n_from).asin().to_degrees();
        println!("  total internal reflection: θi > θc = {critical:.2}°");
        println!("  reflected = {reflected:.4}");
    }
    t
}

fn main() {
    let ball = Ball {
        centre: Vec3::ZERO,
        radius: 1.0,
    };
    // A ray from the left, half a radius above the centre, enters the ball ...
    let (origin, d) = (Vec3::new(-3.0, 0.5, 0.0), Vec3::X);
    let p = origin + d * ball.hit(origin, d).expect("the ray is aimed at the ball");
    let inside = step("entering", &ball, p, d, false).expect("air to glass always refracts");
    // ... crosses the glass and leaves through the far side, with the same outward normal.
    let q = p + inside * ball.hit(p, inside).expect("a ray inside meets the surface");
    let out = step("leaving", &ball, q, inside, true).expect("a ball lets out what it took in");
    println!(
        "  turned by {:.2}° in all\n",
        d.angle_between(out).to_degrees()
    );
    // A source inside the glass sends a ray at 60° to the normal: past the critical angle.
    let top = Vec3::Y;
    let d = Vec3::new(60_f32.to_radians().sin(), 60_f32.to_radians().cos(), 0.0);
    let source = top - d * 0.5;
    let at = source + d * ball.hit(source, d).expect("a ray inside meets the surface");
    let kept = step("from inside", &ball, at, d, true);
    assert!(
        kept.is_none(),
        "60° is past glass's critical angle of 41.8°"
    );
}
