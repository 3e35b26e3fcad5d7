//! The SIMD peer: ultraviolet's 8-wide `Vec3x8::refracted` (the GLSL formula), the vectorised
//! refraction a Rust ray tracer would reach for, measured beside the kernel's own variants on
//! the same rays.
//!
//! It takes its rays eight at a time as `Vec3x8` (x, y and z of eight rays per vector), so the
//! batch's blocks are repacked once, outside the timed loop. Inside it the normal is turned to
//! face the ray first, as the `glam` row does (GLSL's formula expects a facing normal), and a
//! zero T means total internal reflection, as in GLSL.

use core::hint::black_box;

use glam::Vec3;
use refraction_kernel::batch::{LANES, RayBatch, Transmissions};
use ultraviolet::{Vec3x8, f32x8};
use wide::CmpGt as _;

use crate::Subject;
use crate::timing::Pass;

/// ultraviolet's `Vec3x8::refracted` as a row of the report (f32 only: `Vec3x8` is f32).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Ultraviolet;

impl Subject<f32> for Ultraviolet {
    fn name(&self) -> &'static str {
        "ultraviolet"
    }

    fn pass<'a>(&self, rays: &'a RayBatch<f32>) -> Pass<'a> {
        let mut packed = Packed::new(rays);
        Box::new(move || {
            black_box(&mut packed).transmit_all();
            black_box(&mut packed);
        })
    }

    fn answers(&self, rays: &RayBatch<f32>) -> Transmissions<f32> {
        let mut packed = Packed::new(rays);
        packed.transmit_all();
        packed.transmissions()
    }
}

/// Rays per `Vec3x8`.
const WIDTH: usize = 8;

/// One pack of eight rays as the peer takes them: travel directions, normals, μ.
type Pack = (Vec3x8, Vec3x8, f32x8);

/// A [`RayBatch`] repacked eight rays at a time for ultraviolet, with room for its answers.
#[derive(Clone, Debug)]
pub struct Packed {
    packs: Vec<Pack>,
    out: Vec<Vec3x8>,
    len: usize,
}

/// `n` or `−n` per lane, whichever faces `d` (d·n ≤ 0), as the `glam` row turns it.
fn facing(d: Vec3x8, n: Vec3x8) -> Vec3x8 {
    let away = d.dot(n).cmp_gt(f32x8::splat(0.0));
    Vec3x8::blend(away, -n, n)
}

/// Eight lanes of a block's row, from lane `start`.
fn eight(row: &[f32; LANES], start: usize) -> f32x8 {
    let mut lanes = [0.0; WIDTH];
    lanes.copy_from_slice(&row[start..start + WIDTH]);
    f32x8::from(lanes)
}

impl Packed {
    /// Repacks `rays`, each block of [`LANES`] into packs of eight (the batch's padding lanes,
    /// which transmit harmlessly, included).
    #[must_use]
    pub fn new(rays: &RayBatch<f32>) -> Self {
        let packs: Vec<Pack> = rays
            .blocks()
            .iter()
            .flat_map(|block| {
                (0..LANES).step_by(WIDTH).map(move |start| {
                    let [dx, dy, dz] = block.d.each_ref().map(|row| eight(row, start));
                    let [nx, ny, nz] = block.n.each_ref().map(|row| eight(row, start));
                    (
                        Vec3x8::new(dx, dy, dz),
                        Vec3x8::new(nx, ny, nz),
                        eight(&block.mu, start),
                    )
                })
            })
            .collect();
        let out = vec![Vec3x8::zero(); packs.len()];
        Self {
            packs,
            out,
            len: rays.len(),
        }
    }

    /// The number of rays (not counting the padding).
    #[must_use]
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether there are no rays.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Refracts every pack, keeping the answers: the timed pass.
    pub fn transmit_all(&mut self) {
        for (t, (d, n, eta)) in self.out.iter_mut().zip(&self.packs) {
            *t = d.refracted(facing(*d, *n), *eta);
        }
    }

    /// Turns every packed normal to face its ray, once, for [`Packed::transmit_all_facing`].
    pub fn turn_normals(&mut self) {
        for (d, n, _) in &mut self.packs {
            *n = facing(*d, *n);
        }
    }

    /// [`Packed::transmit_all`] without turning the normals, which must face the rays already
    /// ([`Packed::turn_normals`]): ultraviolet's own loop alone, as fast as it gets when the
    /// caller knows which side of the surface each ray is on.
    pub fn transmit_all_facing(&mut self) {
        for (t, (d, n, eta)) in self.out.iter_mut().zip(&self.packs) {
            *t = d.refracted(*n, *eta);
        }
    }

    /// The answers of the last [`Packed::transmit_all`] as the kernel's variants give
    /// theirs: T, or total internal reflection where ultraviolet returned zero.
    #[must_use]
    pub fn transmissions(&self) -> Transmissions<f32> {
        let mut out = Transmissions::zeroed(self.len);
        let lanes = self.out.iter().flat_map(|t| {
            let [x, y, z] = [t.x, t.y, t.z].map(f32x8::to_array);
            (0..WIDTH).map(move |j| Vec3::new(x[j], y[j], z[j]))
        });
        for (i, t) in lanes.take(self.len).enumerate() {
            out.set(i, (t != Vec3::ZERO).then_some(t));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rays(count: usize) -> RayBatch<f32> {
        let mut rays = RayBatch::new();
        for i in 0..count {
            let x = i as f32 / count as f32;
            let d = Vec3::new(x, -1.0, 0.0).normalize();
            // Every third normal on the far side, every fifth ray beyond the critical angle.
            let n = if i % 3 == 0 { -Vec3::Y } else { Vec3::Y };
            let mu = if i % 5 == 0 && x > 0.8 {
                1.6
            } else {
                1.0 / 1.5
            };
            rays.push(d, n, mu);
        }
        rays
    }

    #[test]
    fn the_peer_answers_every_ray_as_glam_does_padding_aside() {
        let rays = rays(21);
        let mut peer = Packed::new(&rays);
        peer.transmit_all();
        let out = peer.transmissions();
        assert_eq!(out.len(), 21);
        let mut reflected = 0;
        for i in 0..rays.len() {
            let (d, n, mu) = rays.get(i);
            let facing = if d.dot(n) > 0.0 { -n } else { n };
            let glam = d.refract(facing, mu);
            if let Some(t) = out.get(i) {
                assert!((t - glam).length() < 1e-6, "ray {i}: {t} against {glam}");
            } else {
                assert_eq!(glam, Vec3::ZERO, "ray {i}");
                reflected += 1;
            }
        }
        assert!(reflected > 0, "the rays include total internal reflection");
        let mut turned = Packed::new(&rays);
        turned.turn_normals();
        turned.transmit_all_facing();
        assert_eq!(
            turned.transmissions(),
            out,
            "turning first gives the same answers"
        );
    }
}
